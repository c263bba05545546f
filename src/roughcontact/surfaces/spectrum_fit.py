"""Power-spectrum analysis of a topography: H and h_rms of a self-affine fit, the rms slope.

:func:`fit_spectrum` takes one height map or a list of equal tiles (sub-windows of one scan,
:func:`roughcontact.surfaces.tiles`), computes the radially averaged power spectrum (a
:class:`~roughcontact.surfaces.spectra.Spectrum`, Persson's normalisation), fits the power law
``C(q) = A q^(−2H−2)`` over a stated band ``[q_min, q_max]`` and reports H, the rms height of
the fitted self-affine spectrum on the window's grid, the measured rms height and the rms slope
(from the heights and from the spectrum), each with a 95 % interval: a percentile bootstrap over
the tiles, or, for a single window, a residual bootstrap of the fit (H and the fitted h_rms
only). The residual interval sees the misfit of the binned spectrum only, not the scatter of
one realisation's spectrum: it is narrower than the spread over realisations; prefer tiles.

The method is that of Jacobs, Junge & Pastewka, Surf. Topogr.: Metrol. Prop. 5, 013001 (2017),
doi:10.1088/2051-672X/aa51f8: the radially averaged PSD of a windowed scan (Hann for
non-periodic scans), averaged over logarithmic bins and fitted in log–log over the band where
the surface is self-affine. Here the fitted model is each bin's expected mean (the power law
averaged over the bin's modes and convolved with the window's three DFT taps), so that a pure
power law on a periodic grid is recovered to round-off, the lowest bins included.

Default band (:data:`Q_MIN_FACTOR`, :data:`Q_MAX_FRACTION`): ``q_min = 2 q0`` (wavelengths up to
``L/2``, ``q0 = 2π/L``) and ``q_max = q_N/4`` (down to ``8 Δ``, ``q_N = π/Δ`` the Nyquist
wavenumber). Below ``2 q0`` a grid has one shell of four modes, which the levelling of a scan
(its removed tilt) distorts most; above ``q_N/4`` pixel averaging, the AFM tip's radius and
the window's leakage floor bend a measured spectrum away from the power law (Jacobs et al.
2017). A scan that rolls off inside this band (``di-6.di``: near ``L/20``) fits H ≤ 0 there
and raises: pass the band where it is self-affine.
"""
from __future__ import annotations

import dataclasses
import math
import numbers

import numpy as np

from .._validate import check_finite_positive, check_grid_size, is_finite_number
from ..errors import RoughContactError
from .moments import SpectralMoments, _moments_from_spectrum
from .roughness import wavevectors
from .spectra import Spectrum, _shell_spectrum

__all__ = ["Interval", "SpectrumFit", "SpectrumFitError", "fit_spectrum", "Q_MIN_FACTOR",
           "Q_MAX_FRACTION", "WINDOWS", "DETREND"]

#: Default band: from ``Q_MIN_FACTOR · 2π/L`` to ``Q_MAX_FRACTION · π/Δ`` (the Nyquist wavenumber).
Q_MIN_FACTOR, Q_MAX_FRACTION = 2.0, 0.25
#: Window functions applied before the FFT (``None``: none, for periodic maps).
WINDOWS = (None, "hann")
#: Levelling of each window: ``"mean"`` only, or ``"height"`` (also its plane of least rms height).
DETREND = ("mean", "height")
#: Fewest logarithmic bins with modes that the band must hold for a fit with residuals.
MIN_BINS, _SLACK = 4, 1e-9


class SpectrumFitError(RoughContactError, ValueError):
    """A spectrum that cannot be fitted: bad input, too few points in the band, or H outside (0, 2)."""


@dataclasses.dataclass(frozen=True)
class Interval:
    """A confidence interval ``[low, high]`` (NaN, NaN where none could be formed); ``x in it``."""
    low: float
    high: float

    def __contains__(self, value) -> bool:
        return bool(self.low <= value <= self.high)


@dataclasses.dataclass(frozen=True, eq=False)
class SpectrumFit:
    """The spectrum of a topography, its self-affine fit and its rms quantities (:func:`fit_spectrum`).

    Lengths are in the unit of the heights; wavenumbers in rad per length unit.

    Attributes
    ----------
    spectrum : Spectrum
        Radially averaged PSD on the grid's shells, mean over the windows, windowed as
        ``window`` says (Persson's ``C = spectrum.persson_c()``, length⁴).
    hurst : float
        Fitted Hurst exponent ``H`` (``C ∝ q^(−2H−2)``), ``0 < H < 2``.
    prefactor : float
        ``A`` of ``C(q) = A q^(−2H−2)`` (length^(2−2H), Persson's ``C``).
    q_min, q_max : float
        The band of the fit (rad/length).
    h_rms_fit : float
        Rms height of the fitted self-affine spectrum on every mode ``q ≠ 0`` of the window's
        ``n × n`` grid (length): the ``h_rms`` that :func:`roughcontact.surfaces.self_affine`
        would need for this spectrum (:meth:`h_rms_for` for another grid).
    h_rms : float
        Measured rms height of each levelled window, pooled as ``√(mean Sq²)`` (length).
    rms_slope : float
        Measured rms gradient from forward differences, ``√(⟨Δ_x h²⟩ + ⟨Δ_y h²⟩)/Δ`` per
        window (SurfaceTopography's Sdq), pooled as ``√(mean Sdq²)`` (dimensionless).
    rms_slope_spectrum : float
        ``√(Σ q² variance)`` of ``spectrum`` (continuum derivative, the slope the models see;
        dimensionless). It exceeds ``rms_slope`` where the grid's shortest wavelengths carry
        the slope: the difference quotient's symbol is ``(2/Δ) sin(qΔ/2)``, ``2/π`` of ``q``
        at the Nyquist wavenumber.
    hurst_ci, h_rms_fit_ci, h_rms_ci, rms_slope_ci, rms_slope_spectrum_ci : Interval
        Intervals (``interval`` says how); NaN for the measured values of a single window.
    moments : SpectralMoments
        Profile spectral moments ``m0, m2, m4`` of ``spectrum`` (Nayak 1971; for
        Greenwood–Tripp's summit statistics).
    fit_q, fit_c, fit_model : numpy.ndarray
        The log-binned points of the fit: each bin's geometric-mean wavenumber (rad/length),
        its mean measured ``C`` and the fitted model's expectation of it (length⁴).
    length, n, windows : float, int, int
        Side (length) and grid points per side of each window; number of windows averaged.
    window : str or None
        Window function applied to each window before the FFT.
    interval : str
        How the intervals were formed, at the level ``confidence``.
    confidence : float
    """

    spectrum: Spectrum
    hurst: float
    prefactor: float
    q_min: float
    q_max: float
    h_rms_fit: float
    h_rms: float
    rms_slope: float
    rms_slope_spectrum: float
    hurst_ci: Interval
    h_rms_fit_ci: Interval
    h_rms_ci: Interval
    rms_slope_ci: Interval
    rms_slope_spectrum_ci: Interval
    moments: SpectralMoments
    fit_q: np.ndarray
    fit_c: np.ndarray
    fit_model: np.ndarray
    length: float
    n: int
    windows: int
    window: str | None
    interval: str
    confidence: float

    def power_law(self, q) -> np.ndarray:
        """The fitted ``C(q) = A q^(−2H−2)`` (length⁴) at ``q`` (rad/length)."""
        return self.prefactor * np.asarray(q, dtype=float) ** (-2.0 * self.hurst - 2.0)

    def h_rms_for(self, length: float, n: int) -> float:
        """Rms height of the fitted power law on every mode ``q ≠ 0`` of an ``n × n`` grid of side
        ``length`` (length): extrapolates the fit to another system size or resolution."""
        check_finite_positive("length", length)
        check_grid_size(n)
        squares, counts = _grid_squares(n)
        return _h_rms(self.prefactor, 2.0 * self.hurst + 2.0, length, squares, counts)


def _grid_squares(n: int):
    """Distinct ``i² + j² > 0`` of the ``n × n`` FFT grid's modes and how many modes each has."""
    k = np.rint(np.fft.fftfreq(n) * n).astype(np.int64)
    squares, counts = np.unique((k[:, None] ** 2 + k[None, :] ** 2).ravel(), return_counts=True)
    return squares[1:].astype(float), counts[1:].astype(float)


def _h_rms(prefactor, alpha, length, squares, counts):
    """``√(Σ_modes A q^(−α) q0²)`` over the grid's shells ``q = q0 √squares``."""
    q0 = 2.0 * np.pi / length
    return math.sqrt(prefactor * q0**2 * float(np.sum(counts * (q0 * np.sqrt(squares)) ** -alpha)))


def _windows(heights, length, detrend="mean"):
    """The input as a ``(count, n, n)`` float array (each window levelled) and the windows' side."""
    items = list(heights) if isinstance(heights, (list, tuple)) else [heights]
    if not items:
        raise SpectrumFitError("heights is an empty list: give at least one window")
    lengths = {float(item.length) for item in items if hasattr(item, "length")}
    if length is None and (len(lengths) != 1 or not all(hasattr(i, "length") for i in items)):
        raise SpectrumFitError("length is required unless every window carries one (MeasuredSurface tiles of one size)")
    length = lengths.pop() if length is None else length
    arrays = [np.asarray(getattr(item, "heights", item), dtype=float) for item in items]
    shape = arrays[0].shape
    if len(shape) != 2 or shape[0] != shape[1] or any(a.shape != shape for a in arrays):
        raise SpectrumFitError(f"heights must be square 2-D arrays of one shape, got "
                               f"{sorted({a.shape for a in arrays})}")
    if shape[0] < 8 or not (isinstance(length, numbers.Real) and math.isfinite(length) and length > 0):
        raise SpectrumFitError(f"windows need n >= 8 a side, length > 0: got n = {shape[0]}, length = {length!r}")
    stack = np.stack(arrays)
    if not np.all(np.isfinite(stack)):
        raise SpectrumFitError("heights must be finite (fill missing pixels first)")
    stack = stack - stack.mean(axis=(1, 2), keepdims=True)
    x = np.arange(shape[0]) - (shape[0] - 1) / 2.0
    for basis in ((x[:, None], x[None, :]) if detrend == "height" else ()):     # orthogonal tilts
        stack = stack - basis * (np.sum(stack * basis, axis=(1, 2), keepdims=True) / (shape[0] * np.sum(x**2)))
    if np.any(np.sqrt(np.mean(stack**2, axis=(1, 2))) == 0.0):
        raise SpectrumFitError("a window has constant heights: no roughness to fit")
    return stack, float(length)


def _power(stack, window):
    """Per-mode variance ``|FFT(w h)/n²|² / mean(w²)`` of each window, ``(count, n, n)``."""
    n = stack.shape[-1]
    if window == "hann":
        w1 = 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(n) / n)     # periodic Hann
        w = np.outer(w1, w1)
        stack = stack * (w / math.sqrt(np.mean(w**2)))
    return np.abs(np.fft.fft2(stack, axes=(1, 2)) / n**2) ** 2


def _band(band, length, n):
    q0, q_nyquist = 2.0 * np.pi / length, np.pi * n / length
    if band is None:
        return Q_MIN_FACTOR * q0, Q_MAX_FRACTION * q_nyquist
    if isinstance(band, str) or np.shape(band) != (2,):
        raise SpectrumFitError(f"band must be (q_min, q_max) in rad/length, got {band!r}")
    q_min, q_max = (float(b) for b in band)
    if not (math.isfinite(q_min) and math.isfinite(q_max) and q0 * (1 - _SLACK) <= q_min < q_max
            <= math.sqrt(2.0) * q_nyquist * (1 + _SLACK)):
        raise SpectrumFitError(f"band must satisfy 2*pi/length = {q0:.6g} <= q_min < q_max <= "
                               f"sqrt(2)*pi*n/length = {math.sqrt(2) * q_nyquist:.6g}, got {band!r}")
    return q_min, q_max


#: Power weights of the periodic Hann window's DFT taps ``(−¼, ½, −¼)``, squared over
#: ``mean(w²) = 3/8`` per axis: the expected windowed spectrum is the true one convolved with them.
_TAPS = {None: {0: 1.0}, "hann": {-1: 1.0 / 6.0, 0: 2.0 / 3.0, 1: 1.0 / 6.0}}
#: Exponents α = 2H + 2 tabulated for the fit (H from −0.5 to 2.5, refined between nodes).
_ALPHAS = np.linspace(1.0, 7.0, 301)


class _Bins:
    """Logarithmic bins of the band over the grid's modes and the expected (windowed) power law in each."""

    def __init__(self, n, length, q_min, q_max, bins_per_decade, window):
        self.q0 = 2.0 * np.pi / length
        k = np.rint(np.fft.fftfreq(n) * n).astype(np.int64)
        s = (k[:, None] ** 2 + k[None, :] ** 2).ravel()
        q = self.q0 * np.sqrt(s)
        inside = (q >= q_min * (1 - _SLACK)) & (q <= q_max * (1 + _SLACK)) & (s > 0)
        raw = np.floor(np.log10(np.maximum(q[inside], q_min) / q_min) * bins_per_decade + _SLACK)
        last = max(0, math.ceil(math.log10(q_max / q_min) * bins_per_decade - _SLACK) - 1)
        groups, index = np.unique(np.minimum(raw, last).astype(int), return_inverse=True)
        self.inside, self.index, self.size = inside, index, groups.size
        self.modes = np.bincount(index, minlength=self.size).astype(float)
        self.log_q = np.bincount(index, weights=np.log(q[inside]), minlength=self.size) / self.modes
        rows, cols = np.divmod(np.flatnonzero(inside), n)
        keys, weights = [], []
        for di, wi in _TAPS[window].items():
            for dj, wj in _TAPS[window].items():
                square = k[(rows + di) % n] ** 2 + k[(cols + dj) % n] ** 2
                keys.append(index * (2 * n * n + 1) + square)
                weights.append(np.full(index.size, wi * wj))
        keys, inverse = np.unique(np.concatenate(keys), return_inverse=True)
        weight = np.bincount(inverse, weights=np.concatenate(weights))
        self.pair_bin, square = np.divmod(keys, 2 * n * n + 1)
        keep = square > 0
        self.pair_bin, self.pair_q = self.pair_bin[keep], self.q0 * np.sqrt(square[keep])
        self.pair_weight = weight[keep] / self.modes[self.pair_bin]
        self.table = np.array([self.log_model(a) for a in _ALPHAS])

    def log_model(self, alpha):
        """``log`` of each bin's expected mean ``C`` for ``C = q^(−α)`` (``A = 1``)."""
        return np.log(np.bincount(self.pair_bin, weights=self.pair_weight * self.pair_q**-alpha,
                                  minlength=self.size))

    def mean_c(self, power):
        """Mean Persson ``C`` per bin from per-mode variances ``(count, n, n)`` → ``(count, bins)``."""
        flat = power.reshape(power.shape[0], -1)[:, self.inside]
        sums = np.stack([np.bincount(self.index, weights=row, minlength=self.size) for row in flat])
        return sums / (self.modes * self.q0**2)

    def fit(self, log_c):
        """``(α, log A)`` of least ``Σ (log C − log A − log model(α))²``: the best node of the α table,
        then parabolas' vertices at steps 1, 10⁻³, 10⁻⁶ (NaN, NaN at the table's end)."""
        resid = log_c - self.table
        sse = np.sum((resid - resid.mean(axis=1, keepdims=True)) ** 2, axis=1)
        best = int(np.argmin(sse))
        if best in (0, _ALPHAS.size - 1):
            return math.nan, math.nan
        alpha = _ALPHAS[best] + _vertex(*sse[best - 1:best + 2]) * (_ALPHAS[1] - _ALPHAS[0])
        for step in (1e-3, 1e-6):
            alpha += step * _vertex(*(float(np.var(log_c - self.log_model(alpha + d * step))) for d in (-1, 0, 1)))
        return float(alpha), float(np.mean(log_c - self.log_model(alpha)))


def _vertex(low, mid, high):
    """Offset (in steps, within ±1) of the vertex of the parabola through three equally spaced values."""
    curvature = low - 2.0 * mid + high
    return float(np.clip(0.5 * (low - high) / curvature, -1.0, 1.0)) if curvature > 0 else 0.0


def _percentile(samples, confidence):
    finite = samples[np.isfinite(samples)]
    if finite.size < max(2, samples.size // 2):
        return Interval(math.nan, math.nan)
    return Interval(*(float(v) for v in np.percentile(finite, [50 * (1 - confidence), 50 * (1 + confidence)])))


def _check_options(window, detrend, bins_per_decade, resamples, confidence, seed):
    if window not in WINDOWS:
        raise SpectrumFitError(f"window must be one of {WINDOWS}, got {window!r}")
    if detrend not in DETREND:
        raise SpectrumFitError(f"detrend must be one of {DETREND}, got {detrend!r}")
    for name, value, minimum in (("bins_per_decade", bins_per_decade, 1), ("resamples", resamples, 10),
                                 ("seed", 0 if seed is None else seed, 0)):
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
            raise SpectrumFitError(f"{name} must be an integer >= {minimum}, got {value!r}")
    if not is_finite_number(confidence) or not 0 < confidence < 1:
        raise SpectrumFitError(f"confidence must be a number with 0 < confidence < 1, got {confidence!r}")


def fit_spectrum(heights, *, length: float | None = None, band=None, window: str | None = "hann",
                 detrend: str = "height", bins_per_decade: int = 10, resamples: int = 1000,
                 confidence: float = 0.95, seed: int | None = 0) -> SpectrumFit:
    """Radially averaged PSD of a topography and its self-affine fit over a band (module docstring).

    Parameters
    ----------
    heights : array_like or list
        One ``(n, n)`` height map (length unit), or a list of equal ``(n, n)`` windows (tiles of
        one scan); :class:`~roughcontact.surfaces.MeasuredSurface` objects are accepted for
        either. Each window is levelled as ``detrend`` says (the measured rms values too); level
        a whole scan as read (:func:`~roughcontact.surfaces.from_topography`). The sign does
        not matter (a spectrum and rms values are the same for ``h`` and ``−h``).
    length : float, optional
        Side of each window (length unit); default the windows' own ``length``.
    band : (float, float), optional
        ``(q_min, q_max)`` of the fit (rad/length); default ``(2 q0, q_N/4)``, ``q0 = 2π/L``,
        ``q_N = π n/L`` (module docstring for why).
    window : {"hann", None}
        Window before the FFT, normalised to keep the variance: ``"hann"`` (default) for
        non-periodic scans (whose edge step leaks power ``∝ q⁻³``); ``None`` for periodic maps.
    detrend : {"height", "mean"}
        Levelling of each window: ``"height"`` (default) removes its plane of least rms height
        (a tile's tilt is roughness longer than the tile, which the window would leak into the
        lowest bins); ``"mean"`` only its mean (periodic maps; then ``window=None`` fits the
        grid spectrum of :func:`~roughcontact.surfaces.self_affine` exactly).
    bins_per_decade : int
        Logarithmic bins per decade of ``q`` for the fit.
    resamples, confidence, seed : int, float, int or None
        Bootstrap resamples (over tiles; over the fit's residuals for one window), level of the
        percentile intervals, and seed of ``numpy.random.default_rng``.

    Returns
    -------
    SpectrumFit
        Raises :class:`SpectrumFitError` (one line) on bad input, a band with fewer than
        :data:`MIN_BINS` bins holding modes, or a fitted H outside ``(0, 2)``.
    """
    _check_options(window, detrend, bins_per_decade, resamples, confidence, seed)
    stack, length = _windows(heights, length, detrend)
    count, n = stack.shape[0], stack.shape[1]
    q_min, q_max = _band(band, length, n)
    bins = _Bins(n, length, q_min, q_max, bins_per_decade, window)
    if bins.size < MIN_BINS:
        raise SpectrumFitError(f"the band [{q_min:.6g}, {q_max:.6g}] rad/length holds {bins.size} "
                               f"logarithmic bins with modes, need >= {MIN_BINS}: widen the band "
                               f"or raise bins_per_decade")
    power = _power(stack, window)
    spectrum = _shell_spectrum(power.mean(axis=0), n, length, f"{count} window(s) {n}x{n}, {window} window")
    c_tiles = bins.mean_c(power)
    mean_c = c_tiles.mean(axis=0)
    alpha, log_a = bins.fit(np.log(mean_c))
    hurst = alpha / 2.0 - 1.0
    if not 0.0 < hurst < 2.0:
        shown = f"{hurst:.4g}" if math.isfinite(hurst) else "outside (-0.5, 2.5)"
        raise SpectrumFitError(f"fitted H = {shown} over the band [{q_min:.6g}, {q_max:.6g}] "
                               f"rad/length is outside (0, 2): not self-affine there, choose another band")
    squares, counts = _grid_squares(n)
    sq = np.sqrt(np.mean(stack**2, axis=(1, 2)))
    sdq = np.sqrt(np.mean(np.diff(stack, axis=1) ** 2, axis=(1, 2))
                  + np.mean(np.diff(stack, axis=2) ** 2, axis=(1, 2))) * (n / length)
    slope2 = np.sum(power * wavevectors(n, length) ** 2, axis=(1, 2))
    pooled = {"h_rms": float(np.sqrt(np.mean(sq**2))), "rms_slope": float(np.sqrt(np.mean(sdq**2)))}
    rng = np.random.default_rng(seed)
    if count > 1:
        picks = rng.integers(0, count, size=(resamples, count))
        boot = [bins.fit(np.log(c_tiles[p].mean(axis=0)))[:2] for p in picks]
        text = f"percentile bootstrap over the {count} windows, {resamples} resamples (seed {seed})"
        measured = {"h_rms_ci": _percentile(np.sqrt(np.mean(sq[picks] ** 2, axis=1)), confidence),
                    "rms_slope_ci": _percentile(np.sqrt(np.mean(sdq[picks] ** 2, axis=1)), confidence),
                    "rms_slope_spectrum_ci": _percentile(np.sqrt(slope2[picks].mean(axis=1)), confidence)}
    else:
        fitted = log_a + bins.log_model(alpha)
        residuals = np.log(mean_c) - fitted
        residuals = (residuals - residuals.mean()) * math.sqrt(bins.size / (bins.size - 2))
        picks = rng.integers(0, bins.size, size=(resamples, bins.size))
        boot = [bins.fit(fitted + residuals[p])[:2] for p in picks]
        text = (f"residual bootstrap of the single window's log-binned fit ({bins.size} bins), "
                f"{resamples} resamples (seed {seed}); none for the measured rms values")
        measured = dict.fromkeys(("h_rms_ci", "rms_slope_ci", "rms_slope_spectrum_ci"), Interval(math.nan, math.nan))
    boot = np.array(boot)
    boot_h = np.array([_h_rms(math.exp(b), a, length, squares, counts) if math.isfinite(a) else math.nan
                       for a, b in boot])
    return SpectrumFit(
        spectrum=spectrum, hurst=float(hurst), prefactor=math.exp(log_a), q_min=q_min, q_max=q_max,
        h_rms_fit=_h_rms(math.exp(log_a), alpha, length, squares, counts), **pooled,
        rms_slope_spectrum=spectrum.rms_slope,
        hurst_ci=_percentile(boot[:, 0] / 2.0 - 1.0, confidence),
        h_rms_fit_ci=_percentile(boot_h, confidence), **measured,
        moments=_moments_from_spectrum(spectrum.q, spectrum.variance),
        fit_q=np.exp(bins.log_q), fit_c=mean_c, fit_model=np.exp(log_a + bins.log_model(alpha)),
        length=length, n=n, windows=count, window=window, interval=text, confidence=float(confidence))
