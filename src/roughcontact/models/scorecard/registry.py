"""The registry of the scorecard's models: what a model reads (:class:`Surface`), what it is
(:class:`Model`, with the optional sweep axes it models and its stated range of validity,
:class:`Range`) and :func:`register`.

The optional sweep axes (:mod:`roughcontact.study.config.axes`: ``exponent``, ``rolloff``, ``cutoff``,
``hardness``, ``work_of_adhesion`` and any registered later) are named here by string only: the
models sit below the study and do not import it.
"""
from __future__ import annotations

import dataclasses
import math
import types
from typing import Callable, Mapping

from ..._registry import add

__all__ = ["Surface", "Range", "Model", "MODELS", "register", "PERSSON_BINS_PER_DECADE", "SELF_AFFINE"]

#: logarithmic bins per decade of a spectrum for the models that integrate over it (the grid's
#: shells merged above the lowest modes: 130-220 bins for 129²-1025², Persson's stiffness within
#: 2e-7 of all shells)
PERSSON_BINS_PER_DECADE = 100


@dataclasses.dataclass(frozen=True)
class Surface:
    """What a model of the scorecard may read about a rough body pressed into a half-space.

    Units are the caller's, consistent: lengths in one unit, ``e_star`` a pressure, forces
    ``e_star * length²`` and stiffnesses ``e_star * length``.

    Attributes
    ----------
    hurst, h_rms : float
        Hurst exponent and rms height of the roughness (generated, or fitted to a scan).
    radius : float
        Body radius ``R``; ``inf``: a nominally flat surface of side ``length``.
    length, n : float, int
        System size ``L`` and grid points per side (the grid's spectrum, MDR's profiles).
    e_star : float
        Effective modulus ``E*``.
    exponent : float
        Body of revolution ``z = (R/m)(r/R)^m`` (2: the paraboloid).
    rolloff, cutoff : float or None
        Roll-off and cutoff wavelengths of the generated spectrum (``None``: none).
    zeta_fit : float
        ζ of eq. 11 fitted on the same study (NaN: none).
    spectrum : roughcontact.surfaces.spectra.Spectrum or None
        A measured spectrum: models that integrate over a spectrum read it instead of the
        grid's own self-affine one.
    moments : roughcontact.surfaces.moments.SpectralMoments or None
        The measured spectrum's moments (asperity statistics) instead of the self-affine ones.
    axes : Mapping[str, float]
        Every optional sweep axis of the combination by name, as its merged-file coordinate
        (:meth:`roughcontact.study.config.axes.Axis.coordinate`: a roll-off at the paper's setting is
        ``length``, a cutoff 0, a hardness ``inf``), read-only; the scorecards fill it, so a
        model that declares an axis registered after this class was written reads its value
        here. An axis the mapping lacks is at the paper's setting.
    """

    hurst: float
    h_rms: float
    radius: float
    length: float
    n: int
    e_star: float
    exponent: float = 2.0
    rolloff: float | None = None
    cutoff: float | None = None
    zeta_fit: float = math.nan
    spectrum: object = None
    moments: object = None
    axes: Mapping[str, float] = dataclasses.field(default_factory=dict, hash=False)

    def __post_init__(self):
        object.__setattr__(self, "axes", types.MappingProxyType({str(k): float(v) for k, v in self.axes.items()}))

    @property
    def flat(self) -> bool:
        """A nominally flat surface (``radius = inf``)."""
        return math.isinf(self.radius)

    @property
    def pure_self_affine(self) -> bool:
        """No roll-off and no cutoff: the spectrum eqs. 11-17 are written for."""
        return self.rolloff is None and self.cutoff is None

    def grid_spectrum(self, *, band: bool = True):
        """The spectrum a model integrates over: the measured one, else the grid's own
        self-affine spectrum with its roll-off and cutoff (``band=False``: without, the pure
        self-affine reference), on :data:`PERSSON_BINS_PER_DECADE` bins per decade."""
        from ...surfaces.spectra import self_affine_spectrum

        if self.spectrum is not None:
            return self.spectrum.rebinned(PERSSON_BINS_PER_DECADE)
        extra = {"rolloff": self.rolloff, "cutoff": self.cutoff} if band else {}
        return self_affine_spectrum(hurst=self.hurst, h_rms=self.h_rms, length=self.length, n=self.n,
                                    **extra).rebinned(PERSSON_BINS_PER_DECADE)


@dataclasses.dataclass(frozen=True)
class Range:
    """A model's stated range of one parameter: ``low ≤ value ≤ high``.

    Attributes
    ----------
    name : str
        A field of :class:`Surface` (``hurst``, ``h_rms``, ``radius``, ...) or an optional axis
        by name, as the scorecards pass them (:meth:`Model.outside`).
    low, high : float
        The closed bounds (``-inf``/``inf``: none).
    source : str
        Where the range is stated (the paper's equation, the calibration's presets).
    """

    name: str
    low: float
    high: float
    source: str = ""

    def violated(self, value: float) -> str:
        """``""`` if *value* lies in the range (or is NaN: not known), else why it does not
        (``"hurst = 1.4 outside [0, 1] (eq. 13)"``)."""
        if math.isnan(value) or self.low <= value <= self.high:
            return ""
        why = f" ({self.source})" if self.source else ""
        return f"{self.name} = {value:g} outside [{self.low:g}, {self.high:g}]{why}"


#: the range of the self-affine fractal surface eqs. 11-17 of Pohrt & Popov are written for
#: (fractal dimension D = 3 - H between 2 and 3); the bound 0 is never reached by a sweep
SELF_AFFINE = (Range("hurst", 0.0, 1.0, "self-affine fractal, 0 < H <= 1"),)


@dataclasses.dataclass(frozen=True)
class Model:
    """One model of the scorecard.

    Attributes
    ----------
    name : str
        Its name in ``models.csv``, the NetCDF files and the figures.
    summary : str
        One sentence for the report's lead paragraph.
    predict : callable
        ``predict(force, surface) -> k``: stiffness at each force (NaN where it has no
        solution), or ``None`` where the model does not apply to *surface*.
    reference : str
        Where the model comes from (a DOI or the module that derives it).
    axes : tuple of str
        The optional sweep axes the model declares, by name (``hurst``, ``radius`` and
        ``h_rms`` are always read and not listed). An axis is declared when the model's
        prediction takes its value into account (reads it from the :class:`Surface`: a field,
        :meth:`Surface.grid_spectrum` or :attr:`Surface.axes`) or explicitly declines it
        (returns ``None`` off its paper value). On a combination off the paper value of an
        axis the model does not declare, the scorecards keep its deviations but do not score
        it (:meth:`undeclared`; column ``not_modelled``).
    ranges : tuple of Range
        The model's stated range of validity (e.g. :data:`SELF_AFFINE`, or the parameters its
        constants were calibrated on): a combination or a scan outside it keeps its row and its
        deviations, but the row names why in the column ``outside_range``
        (:meth:`outside`) and the row is never the recommended model
        (:mod:`roughcontact.study.analysis.decision`). Empty: no stated range.
    precomputable : bool
        The prediction reads only the surface's parameters, never what a study measures
        (:attr:`Surface.zeta_fit`): the workflow may compute it once from the configuration,
        before the runs end (rule ``model_curves``, :mod:`roughcontact.study.analysis.model_curves`),
        for the scorecard to read. ``False`` (the default): computed where the scorecard is.
    """

    name: str
    summary: str
    predict: Callable
    reference: str = ""
    axes: tuple[str, ...] = ()
    ranges: tuple[Range, ...] = ()
    precomputable: bool = False

    def __post_init__(self):
        if isinstance(self.axes, str) or not all(isinstance(a, str) for a in self.axes):
            raise TypeError(f"model {self.name!r}: axes must be a tuple of axis names, got {self.axes!r}")
        object.__setattr__(self, "axes", tuple(self.axes))
        if not all(isinstance(r, Range) for r in self.ranges):
            raise TypeError(f"model {self.name!r}: ranges must be a tuple of Range, got {self.ranges!r}")
        object.__setattr__(self, "ranges", tuple(self.ranges))

    def outside(self, values: Mapping[str, float]) -> str:
        """Why a combination or scan lies outside the model's stated :attr:`ranges`.

        Parameters
        ----------
        values : Mapping[str, float]
            Parameter name -> value (a sweep combination, or a scan's fitted ``hurst`` and
            ``h_rms``); a parameter the mapping lacks is not checked.

        Returns
        -------
        str
            ``"; "``-joined :meth:`Range.violated` texts; ``""`` inside every range.
        """
        return "; ".join(why for r in self.ranges if r.name in values
                         for why in [r.violated(float(values[r.name]))] if why)

    def undeclared(self, off_paper: Mapping[str, float]) -> dict[str, float]:
        """The optional axes off the paper's value that the model does not declare.

        Parameters
        ----------
        off_paper : Mapping[str, float]
            Optional axes off the paper's value, name -> coordinate (e.g.
            :func:`roughcontact.study.config.axes.off_paper`).

        Returns
        -------
        dict of str to float
            The entries of *off_paper* whose axis is not in :attr:`axes`, in the order given.
        """
        return {name: value for name, value in off_paper.items() if name not in self.axes}


#: every registered model, in registration order
MODELS: dict[str, Model] = {}


def register(model: Model) -> Model:
    """Add *model* to :data:`MODELS` (a second model of the same name is an error)."""
    return add(MODELS, model.name, model, "model")
