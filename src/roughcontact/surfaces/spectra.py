"""One representation of an isotropic power spectrum, shared by the models.

A :class:`Spectrum` is a list of wavenumbers ``q`` (rad per length unit) and the
contribution ``variance`` of each wavenumber (or radial bin) to the height
variance, ``h_rms² = Σ variance``, together with the system size ``L``
(``q0 = 2π/L``). Every integral over the spectrum is a sum over these bins:
``∫ d²q C(q) g(|q|) = Σ variance · g(q)``. Three kinds of spectra are built:

* the discrete modes of a periodic grid (:func:`from_heights`,
  :func:`self_affine_spectrum` with ``n``): one bin per shell of equal ``|q|``;
* a continuous self-affine band discretised on a fine logarithmic grid
  (:func:`self_affine_spectrum` without ``n``);
* a tabulated isotropic PSD (:func:`from_psd`).

Conventions
-----------
Persson's spectrum (B. N. J. Persson, J. Chem. Phys. 115, 3840 (2001),
doi:10.1063/1.1388626) is ``C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}``, so
``h_rms² = ∫ d²q C = 2π ∫ q C(q) dq`` and the rms slope is
``h'² = 2π ∫ q³ C(q) dq``. SurfaceTopography (Jacobs, Junge & Pastewka,
Surf. Topogr.: Metrol. Prop. 5, 013001 (2017), doi:10.1088/2051-672X/aa51f8)
normalises ``C_iso = A⁻¹|A/N · FFT(h)|²`` so that ``h_rms² = (2π)⁻² ∫ d²q C_iso``:
``C_iso = (2π)² C_Persson``.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .._validate import check_finite_positive, check_grid_size, check_hurst
from .psd import check_table
from .roughness import band, wavevectors

__all__ = ["Spectrum", "from_heights", "from_psd", "self_affine_spectrum"]

#: Relative slack with which a grid mode counts as lying on ``q_r`` or ``q_c``
#: (the rule of :func:`roughcontact.surfaces.self_affine`).
_SLACK = 1e-9
_CONVENTIONS = {"persson": 1.0, "surfacetopography": (2.0 * np.pi) ** -2}


def _readonly(values) -> np.ndarray:
    array = np.array(values, dtype=float)
    array.setflags(write=False)
    return array


@dataclasses.dataclass(frozen=True)
class Spectrum:
    """Isotropic power spectrum as bins of wavenumber and variance.

    Attributes
    ----------
    q : numpy.ndarray
        Wavenumbers (rad/length), strictly ascending, all ``≥ q0 = 2π/L``.
    variance : numpy.ndarray
        Contribution of each bin to ``h_rms²`` (length²), ``≥ 0``.
    length : float
        System size ``L`` (length); ``q0 = 2π/L``.
    source : str
        Short description of where the spectrum comes from.
    bin_area : numpy.ndarray, optional
        Area of each bin in the ``(q_x, q_y)`` plane (rad²/length²), used only
        by :meth:`persson_c`. Grid shells: number of modes × ``(2π/L)²``;
        otherwise ``2π q Δq`` of the bin. ``None`` (default): ``2π q² Δln q``
        with ``Δln q`` the trapezoid weights of ``ln q``.
    """

    q: np.ndarray
    variance: np.ndarray
    length: float
    source: str = ""
    bin_area: np.ndarray | None = None

    def __post_init__(self):
        check_finite_positive("length", self.length)
        q = np.asarray(self.q, dtype=float)
        variance = np.asarray(self.variance, dtype=float)
        if q.ndim != 1 or q.shape != variance.shape or q.size == 0:
            raise ValueError(f"q and variance must be 1-D arrays of one non-zero length, got "
                             f"shapes {q.shape} and {variance.shape}")
        if not (np.all(np.isfinite(q)) and np.all(np.isfinite(variance))):
            raise ValueError("q and variance must be finite")
        if np.any(variance < 0):
            raise ValueError("variance must be >= 0 in every bin")
        if np.any(np.diff(q) <= 0):
            raise ValueError("q must be strictly ascending")
        q0 = 2.0 * np.pi / self.length
        if q[0] < q0 * (1.0 - _SLACK):
            raise ValueError(f"q must be >= q0 = 2*pi/length = {q0!r}, got q[0] = {q[0]!r}")
        area = _log_trapezoid_area(q) if self.bin_area is None else self.bin_area
        area = np.asarray(area, dtype=float)
        if area.shape != q.shape or not np.all(np.isfinite(area)) or np.any(area <= 0):
            raise ValueError("bin_area must be finite, > 0 and of the shape of q")
        object.__setattr__(self, "q", _readonly(q))
        object.__setattr__(self, "variance", _readonly(variance))
        object.__setattr__(self, "bin_area", _readonly(area))
        object.__setattr__(self, "length", float(self.length))

    @property
    def q0(self) -> float:
        """Smallest wavenumber of the system, ``2π/L`` (rad/length)."""
        return 2.0 * np.pi / self.length

    def moment(self, k: float) -> float:
        """``Σ q^k variance = ∫ d²q q^k C(q)`` (length^(2−k))."""
        return float(np.sum(self.q**k * self.variance))

    @property
    def h_rms(self) -> float:
        """Root-mean-square height ``√Σ variance`` (length)."""
        return math.sqrt(self.moment(0))

    @property
    def rms_slope(self) -> float:
        """Root-mean-square gradient ``|∇h|``, ``√Σ q² variance`` (dimensionless)."""
        return math.sqrt(self.moment(2))

    def structure_function(self, lag) -> np.ndarray:
        """Mean square height difference at distance *lag*, averaged over directions (length²).

        ``SF(r) = ⟨(h(x + r) − h(x))²⟩ = Σ_bins 2 variance (1 − J0(q r))`` for an isotropic
        spectrum (J0: Bessel function of the first kind); ``SF → 2 h_rms²`` for lags much longer
        than the longest wavelength. Vectorised over *lag*.
        """
        from scipy.special import j0   # here: scipy.special costs every job that imports the package 0.2 s

        lag = np.asarray(lag, dtype=float)
        return 2.0 * np.sum(self.variance * (1.0 - j0(np.multiply.outer(lag, self.q))), axis=-1)

    def rebinned(self, bins_per_decade: int = 100) -> "Spectrum":
        """The same spectrum on at most ``bins_per_decade`` logarithmic bins per decade of ``q``.

        Bins of the grid's many high-``q`` shells are merged: their variances and areas add, and
        the merged wavenumber is ``√(Σ q² variance / Σ variance)`` (areas' mean where the
        variance is zero), so ``h_rms`` and the rms slope are kept exactly; a bin that holds one
        shell (the lowest modes of a finite cell) stays as it is. For the models whose cost grows
        with the number of bins (:mod:`roughcontact.models.persson`).
        """
        if isinstance(bins_per_decade, bool) or not isinstance(bins_per_decade, int) or bins_per_decade < 1:
            raise ValueError(f"bins_per_decade must be a positive integer, got {bins_per_decade!r}")
        edges = np.floor(np.log10(self.q / self.q0) * bins_per_decade).astype(int)
        groups, index = np.unique(edges, return_inverse=True)
        variance = np.bincount(index, weights=self.variance, minlength=groups.size)
        area = np.bincount(index, weights=self.bin_area, minlength=groups.size)
        second = np.bincount(index, weights=self.q**2 * self.variance, minlength=groups.size)
        mean_q = np.bincount(index, weights=self.q * self.bin_area, minlength=groups.size) / area
        with np.errstate(invalid="ignore", divide="ignore"):
            q = np.where(variance > 0, np.sqrt(second / np.where(variance > 0, variance, 1.0)), mean_q)
        return Spectrum(q=q, variance=variance, length=self.length, bin_area=area,
                        source=f"{self.source}, {bins_per_decade} bins per decade")

    def persson_c(self) -> np.ndarray:
        """Persson's ``C(q)`` on the bins, ``variance / bin_area`` (length⁴).

        Normalisation: ``C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}``,
        ``h_rms² = 2π ∫ q C dq`` (Persson, J. Chem. Phys. 115, 3840 (2001)).
        Multiply by ``(2π)²`` for SurfaceTopography's ``C_iso``.
        """
        return self.variance / self.bin_area


def _log_trapezoid_area(q: np.ndarray) -> np.ndarray:
    """``2π q² Δln q`` with ``Δln q`` the trapezoid weights of ``ln q`` (half at the ends)."""
    if q.size == 1:
        return np.array([np.pi * q[0] ** 2])
    log_q = np.log(q)
    weight = np.empty_like(q)
    weight[1:-1] = 0.5 * (log_q[2:] - log_q[:-2])
    weight[0] = 0.5 * (log_q[1] - log_q[0])
    weight[-1] = 0.5 * (log_q[-1] - log_q[-2])
    return 2.0 * np.pi * q**2 * weight


def _grid_shells(n: int, length: float):
    """Shell index ``i² + j²`` of every mode of the ``n × n`` FFT grid, and the sorted shells.

    Returns ``(index, squares, counts)``: ``index`` maps every mode to its shell
    (``-1`` for ``q = 0``), ``squares`` the shells' ``i² + j²`` (ascending, > 0).
    """
    k = np.rint(np.fft.fftfreq(n) * n).astype(np.int64)
    squares_map = k[:, None] ** 2 + k[None, :] ** 2
    squares, index = np.unique(squares_map, return_inverse=True)
    index = index.reshape(n, n) - 1          # shell 0 is q = 0
    counts = np.bincount(index[index >= 0].ravel())
    return index, squares[1:], counts


def _shell_spectrum(power: np.ndarray, n: int, length: float, source: str) -> Spectrum:
    """Sum the per-mode ``power`` (``Σ = variance``) over shells of equal ``|q|``."""
    index, squares, counts = _grid_shells(n, length)
    nonzero = index >= 0
    variance = np.bincount(index[nonzero], weights=power[nonzero], minlength=squares.size)
    q0 = 2.0 * np.pi / length
    return Spectrum(q=q0 * np.sqrt(squares), variance=variance, length=length, source=source,
                    bin_area=counts * q0**2)


def from_heights(heights, *, length: float) -> Spectrum:
    """Discrete spectrum of a periodic ``n × n`` height map on the grid's own modes.

    ``ĥ(q) = FFT(h − mean h)/n²`` and ``variance(shell) = Σ_{|q| = shell} |ĥ(q)|²``
    (Parseval: ``Σ variance = mean((h − mean h)²)``, up to round-off). Shells are
    the distinct ``|q| = (2π/L)√(i² + j²)`` with ``(i, j)`` numpy's FFT indices
    (the Nyquist row of an even grid at ``|i| = n/2``); the ``q = 0`` mode is
    dropped. Shells with no power are kept, with zero variance.

    Parameters
    ----------
    heights : array_like
        ``(n, n)`` heights (length), periodic over ``length``.
    length : float
        Side ``L`` of the map (length).

    Returns
    -------
    Spectrum
        One bin per shell; ``bin_area`` = number of modes × ``(2π/L)²``.
    """
    heights = np.asarray(heights, dtype=float)
    if heights.ndim != 2 or heights.shape[0] != heights.shape[1]:
        raise ValueError(f"heights must be a square 2-D array, got shape {heights.shape}")
    n = heights.shape[0]
    check_grid_size(n)
    check_finite_positive("length", length)
    if not np.all(np.isfinite(heights)):
        raise ValueError("heights must be finite")
    power = np.abs(np.fft.fft2(heights - heights.mean()) / n**2) ** 2
    return _shell_spectrum(power, n, length, f"heights {n}x{n}")


def _power_integral(exponent: float, lower, upper):
    """``∫_lower^upper q^exponent dq`` (elementwise)."""
    if abs(exponent + 1.0) < 1e-12:
        return np.log(upper / lower)
    return (upper ** (exponent + 1.0) - lower ** (exponent + 1.0)) / (exponent + 1.0)


def self_affine_spectrum(*, hurst: float, h_rms: float, length: float, n: int | None = None,
                         rolloff: float | None = None, cutoff: float | None = None,
                         points_per_decade: int = 100) -> Spectrum:
    """Spectrum of self-affine roughness, ``C ∝ q^(−2−2H)``, scaled to ``h_rms``.

    ``C(q) = C(q_r)`` for ``q0 ≤ q < q_r = 2π/rolloff`` (plateau),
    ``C ∝ q^(−2−2H)`` for ``q_r ≤ q ≤ q_c = 2π/cutoff``, zero above ``q_c``;
    the amplitude is fixed by ``Σ variance = h_rms²`` exactly.

    * With ``n``: the modes of the ``n × n`` grid exactly as
      :func:`roughcontact.surfaces.self_affine` builds them (same plateau,
      cutoff and ``1e-9`` slack rules), grouped into shells of equal ``|q|``.
      That generator randomises only the phases, so this equals
      ``from_heights(self_affine(n, ...), length=length)`` for every seed up to
      round-off (and hence in expectation), and exactly in total variance.
      ``cutoff=None`` keeps every mode of the grid.
    * Without ``n``: the continuous band ``q0 = 2π/L ≤ q ≤ q1 = 2π/cutoff``
      (``cutoff`` is then required), split into logarithmic bins
      (``points_per_decade``; ``q_r`` is a bin edge). Each bin's variance is
      the exact integral ``2π ∫ q C dq`` over the bin, and its wavenumber is
      ``q_i = (∫ q³ C dq / ∫ q C dq)^(1/2)`` over the bin, so ``h_rms`` and
      the rms slope equal their closed-form integrals up to round-off.

    Parameters
    ----------
    hurst : float
        Hurst exponent ``H``, ``0 < H < 2``.
    h_rms : float
        Rms height (length).
    length : float
        System size ``L`` (length).
    n : int, optional
        Grid points per side (≥ 8) for the grid's discrete modes.
    rolloff : float, optional
        Roll-off wavelength ``2π/q_r`` (length), ``≤ L``; ``None``: ``L``.
    cutoff : float, optional
        Short-wavelength cutoff ``2π/q_c`` (length), ``< rolloff``.
    points_per_decade : int
        Logarithmic bins per decade of the continuous band (without ``n``).

    Returns
    -------
    Spectrum
    """
    check_hurst(hurst)
    check_finite_positive("h_rms", h_rms)
    check_finite_positive("length", length)
    if n is not None:
        check_grid_size(n)
        q_r, q_c = band(length, rolloff=rolloff, cutoff=cutoff, n=n)
        q = wavevectors(n, length)
        power = np.zeros_like(q)
        nonzero = q > 0
        power[nonzero] = q[nonzero] ** (-2.0 * hurst - 2.0)
        if q_r is not None:
            power[nonzero & (q < q_r * (1.0 - _SLACK))] = q_r ** (-2.0 * hurst - 2.0)
        if q_c is not None:
            power[q > q_c * (1.0 + _SLACK)] = 0.0
        power *= h_rms**2 / power.sum()
        return _shell_spectrum(power, n, length, f"self-affine H={hurst:g} on {n}x{n} grid")
    if cutoff is None:
        raise ValueError("cutoff is required without n: it sets the upper end q1 = 2*pi/cutoff "
                         "of the continuous band")
    if isinstance(points_per_decade, bool) or not isinstance(points_per_decade, int) \
            or points_per_decade < 1:
        raise ValueError(f"points_per_decade must be an integer >= 1, got {points_per_decade!r}")
    q_r, q_c = band(length, rolloff=rolloff, cutoff=cutoff)
    q0 = 2.0 * np.pi / length
    segments = [(q0, q_c)] if q_r is None or q_r <= q0 * (1 + _SLACK) else [(q0, q_r), (q_r, q_c)]
    lower, upper, plateau = [], [], []
    for index, (start, stop) in enumerate(segments):
        count = max(1, math.ceil(points_per_decade * math.log10(stop / start)))
        edges = np.geomspace(start, stop, count + 1)
        lower.append(edges[:-1])
        upper.append(edges[1:])
        plateau.append(np.full(count, index == 0 and len(segments) == 2))
    lower, upper, plateau = map(np.concatenate, (lower, upper, plateau))
    exponent = -2.0 - 2.0 * hurst
    q_flat = q_r if q_r is not None else q0
    # Unnormalised C0 = 1: C = q^exponent in the band, q_r^exponent on the plateau.
    m0 = np.where(plateau, q_flat**exponent * (upper**2 - lower**2) / 2.0,
                  _power_integral(exponent + 1.0, lower, upper))
    m2 = np.where(plateau, q_flat**exponent * (upper**4 - lower**4) / 4.0,
                  _power_integral(exponent + 3.0, lower, upper))
    scale = h_rms**2 / m0.sum()
    return Spectrum(q=np.sqrt(m2 / m0), variance=m0 * scale, length=length,
                    source=f"self-affine H={hurst:g} band q0..2pi/{cutoff:g}",
                    bin_area=np.pi * (upper**2 - lower**2))


def from_psd(q, c, *, length: float, convention: str = "persson") -> Spectrum:
    """Spectrum from a tabulated isotropic PSD ``C(q)``, zero outside ``[q[0], q[-1]]``.

    ``h_rms² = 2π ∫ q C dq = 2π ∫ q² C d(ln q)`` is taken by the trapezoid
    rule in ``ln q`` (exact for a power law ``q² C ∝ q^m`` as the spacing goes
    to zero, and well suited to log-spaced tables): ``variance_i = C_i ·
    bin_area_i`` with ``bin_area_i = 2π q_i² Δln q_i``, so :meth:`Spectrum.persson_c`
    returns the table back.

    Parameters
    ----------
    q : array_like
        Wavenumbers (rad/length), finite, > 0, strictly ascending, ``≥ 2π/L``,
        at least two.
    c : array_like
        PSD at ``q``, finite and ≥ 0 (length⁴).
    length : float
        System size ``L`` (length).
    convention : {"persson", "surfacetopography"}
        ``"persson"``: ``h_rms² = 2π ∫ q C dq``; ``"surfacetopography"``:
        SurfaceTopography's ``C_iso = (2π)² C_Persson``
        (``h_rms² = (2π)⁻¹ ∫ q C_iso dq``).

    Returns
    -------
    Spectrum
    """
    if convention not in _CONVENTIONS:
        raise ValueError(f"convention must be one of {sorted(_CONVENTIONS)}, got {convention!r}")
    check_finite_positive("length", length)
    q, c = check_table(q, c, zero_c=True)
    area = _log_trapezoid_area(q)
    return Spectrum(q=q, variance=c * _CONVENTIONS[convention] * area, length=length,
                    source=f"tabulated PSD ({convention})", bin_area=area)
