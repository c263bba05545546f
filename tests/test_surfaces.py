"""Generated surfaces against their defining properties (eqs. 1–3, 6, 15)."""

import math
import tracemalloc

import numpy as np
import pytest

from roughcontact import surfaces
from roughcontact.models import paper
from roughcontact.surfaces import roughness

LENGTH = 2.5


@pytest.mark.parametrize("n", [64, 65])
@pytest.mark.parametrize("hurst", [0.05, 0.3, 0.7, 1.2])
def test_mean_zero_and_rms_exact(n, hurst):
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=LENGTH, seed=7)
    assert abs(z.mean()) <= 1e-12 * 3e-3, "mean height is not zero"
    assert np.sqrt(np.mean(z**2)) == pytest.approx(3e-3, rel=1e-12), "rms height != h_rms"


@pytest.mark.parametrize("n", [64, 65])
def test_real_and_hermitian(n):
    z = surfaces.self_affine(n, hurst=0.7, h_rms=1.0, length=LENGTH, seed=3)
    assert z.dtype == np.float64 and np.all(np.isfinite(z)), "heights are not finite reals"
    spectrum = np.fft.fft2(z)
    mirrored = np.roll(np.flip(spectrum), 1, axis=(0, 1))
    # A real surface has a Hermitian spectrum, so it is smooth across the
    # periodic boundary in the sense of its Fourier series (no hidden imaginary part).
    assert np.allclose(spectrum, np.conj(mirrored), atol=1e-12 * np.abs(spectrum).max()), \
        "spectrum is not Hermitian"


def radial_psd_slope(n, hurst, seeds, length=1.0):
    q = surfaces.wavevectors(n, length)
    qmin = 2 * np.pi / length
    # Log-spaced annuli between 2 qmin and the largest q inside the circle.
    edges = np.geomspace(2 * qmin, qmin * (n // 2), 12)
    psd = np.zeros(len(edges) - 1)
    bins = [(q >= lo) & (q < hi) for lo, hi in zip(edges[:-1], edges[1:])]
    for seed in seeds:
        z = surfaces.self_affine(n, hurst=hurst, h_rms=1.0, length=length, seed=seed)
        power = np.abs(np.fft.fft2(z)) ** 2
        psd += [power[annulus].mean() for annulus in bins]
    # Each annulus is placed at the geometric mean |q| of the modes it holds.
    centres = np.array([np.exp(np.log(q[annulus]).mean()) for annulus in bins])
    return np.polyfit(np.log(centres), np.log(psd / len(seeds)), 1)[0]


@pytest.mark.parametrize("hurst", [0.05, 0.3, 0.7, 1.2])
@pytest.mark.parametrize("n", [128, 127])
def test_power_spectrum_slope(hurst, n):
    """C2D ∝ q^(−2H−2) (eq. 1): the radially averaged spectrum over 8 seeds.

    The average of q^(−2H−2) over an annulus exceeds its value at the modes'
    geometric-mean |q| by a factor that varies slowly from bin to bin (the bins
    are log-spaced and hold few modes at small q), biasing the fitted slope by
    < 0.01 on these grids; ±0.05 is the issue's bound.
    """
    slope = radial_psd_slope(n, hurst, seeds=range(8))
    assert slope == pytest.approx(-2 * hurst - 2, abs=0.05), f"PSD slope {slope} for H={hurst}"


def test_same_seed_identical_bytes():
    a = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    b = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    assert a.tobytes() == b.tobytes(), "same seed gave different bytes"


def test_different_seed_differs():
    a = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    b = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=12)
    assert np.abs(a - b).max() > 1e-3, "different seeds gave the same surface"


@pytest.mark.parametrize("n", [64, 65])
def test_paraboloid_apex_and_curvature(n):
    z = surfaces.paraboloid(n, radius=0.5, length=1.0)
    assert z[n // 2, n // 2] == 0.0, "apex is not at the centre node"
    dx = 1.0 / n
    assert z[n // 2 + 3, n // 2] == pytest.approx((3 * dx) ** 2 / (2 * 0.5), rel=1e-14), \
        "paraboloid is not r^2/(2R)"


def test_rough_sphere_is_sum():
    kw = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=5)
    z = surfaces.rough_sphere(33, radius=0.5, **kw)
    expected = surfaces.paraboloid(33, radius=0.5, length=1.0) + surfaces.self_affine(33, **kw)
    assert np.array_equal(z, expected), "rough sphere is not paraboloid + roughness"


def test_equivalent_profile_eq15():
    n, hurst, h, zeta = 65, 0.7, 9e-3, 1.0
    z = paper.equivalent_profile(n, radius=0.5, hurst=hurst, h_rms=h, length=1.0, zeta=zeta)
    r = 10 / n
    q3d = (2 / zeta) ** (hurst + 1) * (hurst + 1) * h / (2 * hurst * paper.kappa(hurst))
    assert z[n // 2 + 10, n // 2] == pytest.approx(r**2 / 1.0 + q3d * r**hurst, rel=1e-13), \
        "profile differs from eq. 15"


def test_equivalent_profile_flat_has_no_parabola():
    z = paper.equivalent_profile(65, radius=np.inf, hurst=0.5, h_rms=1e-2, length=1.0)
    q3d = paper.profile_prefactor(0.5, h_rms=1e-2, length=1.0, zeta=paper.zeta_estimate(0.5))
    assert z[32 + 4, 32] == pytest.approx(q3d * (4 / 65) ** 0.5, rel=1e-13), "z_s != Q3D r^H"


@pytest.mark.parametrize("kwargs, name", [
    (dict(n=7, hurst=0.7, h_rms=1.0), "n"),
    (dict(n=8.0, hurst=0.7, h_rms=1.0), "n"),
    (dict(n=16, hurst=0.0, h_rms=1.0), "hurst"),
    (dict(n=16, hurst=2.0, h_rms=1.0), "hurst"),
    (dict(n=16, hurst=float("nan"), h_rms=1.0), "hurst"),
    (dict(n=16, hurst=0.7, h_rms=0.0), "h_rms"),
    (dict(n=16, hurst=0.7, h_rms=float("inf")), "h_rms"),
    (dict(n=16, hurst=0.7, h_rms=1.0, length=-1.0), "length"),
    (dict(n=16, hurst=0.7, h_rms=1.0, seed=1.5), "seed"),
])
def test_bad_arguments_name_themselves(kwargs, name):
    n = kwargs.pop("n")
    with pytest.raises(ValueError, match=name):
        surfaces.self_affine(n, **kwargs)


def test_bad_radius_names_itself():
    with pytest.raises(ValueError, match="radius"):
        surfaces.paraboloid(16, radius=-0.5)


# --- the defaults give today's surfaces -----------------------------------------------------

#: Heights of ``self_affine`` and ``rough_sphere`` (R = 0.5, h_rms = 9e-3, L = 1) per (n, H, seed)
#: at the nodes :func:`_nodes` (17 significant digits), recorded on 2026-11-24 with the code of
#: commit 4bed618, whose whole-array SHA-256 hashes matched, on the AVX2 machine they were recorded
#: on (2026-11-23), those of the whole-array code of commit 5e5989f (before roll-off, cutoff,
#: exponent and the block-wise generation); hashes of float arrays failed on AVX-512 machines.
#: A change of the seed's use, the phase convention, the spectrum or the normalisation moves
#: them by O(h_rms); another CPU or libm moves them by FFT round-off only.
REFERENCE_HEIGHTS = {
    (64, 0.3, 0): ((-4.0308930319849379e-03, -3.3447459905336084e-03, 2.5245407929771033e-03, 7.1063601130851878e-03),
                   (4.9596910696801516e-01, 1.2385251963446636e-01, 2.3714368141797709e-01, 2.4172550073808519e-01)),
    (64, 0.3, 3): ((1.4030038065487979e-03, -1.6931378713159416e-03, 1.0532004211323109e-02, 7.1874488788469960e-03),
                   (5.0140300380654890e-01, 1.2550412775368402e-01, 2.4515114483632311e-01, 2.4180658950384701e-01)),
    (64, 0.7, 0): ((-2.6952721361344413e-03, -4.3751088845616027e-03, 8.5194665803636563e-03, 6.5180615214655794e-03),
                   (4.9730472786386565e-01, 1.2282215674043837e-01, 2.4313860720536365e-01, 2.4113720214646558e-01)),
    (64, 0.7, 3): ((9.6206535397307008e-05, 1.7620380271712388e-03, 1.4005041647543359e-02, 2.3551387370588117e-03),
                   (5.0009620653539744e-01, 1.2895930365217120e-01, 2.4862418227254335e-01, 2.3697427936205881e-01)),
    (64, 1.2, 0): ((-9.8602303741126564e-04, -3.9528886191485856e-03, 1.2586426530391367e-02, 2.7711144075172798e-03),
                   (4.9901397696258887e-01, 1.2324437700585139e-01, 2.4720556715539138e-01, 2.3739025503251729e-01)),
    (64, 1.2, 3): ((-7.1244022215069481e-04, 5.4313863001460875e-03, 1.3944006502802012e-02, -1.6563872804974495e-03),
                   (4.9928755977784944e-01, 1.3262865192514606e-01, 2.4856314712780200e-01, 2.3296275334450256e-01)),
    (65, 0.3, 0): ((-1.1867747248973399e-02, 6.0413153937363181e-03, -2.1708123882327471e-02, 4.1407726039083582e-03),
                   (4.7286598056167761e-01, 1.2012415563042270e-01, 2.2065874002299801e-01, 2.4650763650923382e-01)),
    (65, 0.3, 3): ((-1.2429873626848550e-02, -2.2750266060453861e-03, -9.8614234392333973e-03, 4.0092458446503269e-03),
                   (4.7230385418380244e-01, 1.1180781363064100e-01, 2.3250544046609206e-01, 2.4637610974997579e-01)),
    (65, 0.7, 0): ((-4.6538067602350363e-03, 8.6869015951987691e-03, -2.2483875533659683e-02, 3.8571868273363260e-03),
                   (4.8007992105041597e-01, 1.2276974183188516e-01, 2.1988298837166578e-01, 2.4622405073266179e-01)),
    (65, 0.7, 3): ((-1.3871835032238555e-02, -1.9393711939677686e-03, -7.8548717822488085e-03, 3.9632468254862351e-03),
                   (4.7086189277841245e-01, 1.1214346904271862e-01, 2.3451199212307666e-01, 2.4633011073081171e-01)),
    (65, 1.2, 0): ((1.4857811144666636e-03, 1.0864508924729418e-02, -2.1846796329917598e-02, 4.7670923997733010e-03),
                   (4.8621950892511767e-01, 1.2494734916141580e-01, 2.2052006757540787e-01, 2.4713395630509877e-01)),
    (65, 1.2, 3): ((-1.3877664625881346e-02, -1.3490455565502162e-03, -6.4932596347343332e-03, 4.3740446415366906e-03),
                   (4.7085606318476964e-01, 1.1273379468013617e-01, 2.3587360427059115e-01, 2.4674090854686215e-01)),
    (385, 0.3, 0): ((1.4533097450864993e-03, -2.9344893555114989e-03, -6.0514035957411972e-03, 5.2802235685793671e-04),
                    (4.9885928039781047e-01, 1.1392164152659340e-01, 2.4265158173062076e-01, 2.4923100768321990e-01)),
    (385, 0.3, 3): ((8.7305586703094722e-03, 2.2169048017228691e-02, 4.7283577875072433e-03, 2.7744206922447651e-03),
                    (5.0613652932303344e-01, 1.3902517889933358e-01, 2.5343134311386922e-01, 2.5147740601860674e-01)),
    (385, 0.7, 0): ((-4.1194485245626454e-03, -4.4779519713493881e-03, -1.8499087357027901e-03, 2.3953345303592741e-03),
                    (4.9328652212816132e-01, 1.1237817891075551e-01, 2.4685307659065917e-01, 2.5109831985672121e-01)),
    (385, 0.7, 3): ((7.7228035308941432e-03, 2.1729883813572447e-02, 1.5251114806606109e-03, 7.7855006324638650e-03),
                    (5.0512877418361812e-01, 1.3858601469567733e-01, 2.5022809680702257e-01, 2.5648848595882584e-01)),
    (385, 1.2, 0): ((-8.0719138003597594e-03, -4.1521851958054370e-03, 2.5731166997262943e-04, 2.4399766518288578e-03),
                    (4.8933405685236420e-01, 1.1270394568629946e-01, 2.4896029699633460e-01, 2.5114296197819080e-01)),
    (385, 1.2, 3): ((5.3609286845339391e-03, 1.9896672253137661e-02, -1.2495768709566560e-03, 9.7446122178601515e-03),
                    (5.0276689933725793e-01, 1.3675280313524255e-01, 2.4745340845540531e-01, 2.5844759754422209e-01)),
    (513, 0.3, 0): ((-3.6507404467966418e-03, -1.0567159547026821e-03, 1.7645433269114320e-02, -9.7309567869882218e-03),
                    (4.9440184173423535e-01, 1.1651412255591218e-01, 2.6667172435963027e-01, 2.3929533430352773e-01)),
    (513, 0.3, 3): ((-1.4559567309471314e-03, 8.7390582175887795e-03, 2.5532588200365544e-03, 5.7084596715822472e-03),
                    (4.9659662545008487e-01, 1.2630989672820364e-01, 2.5157954991055248e-01, 2.5473475076209817e-01)),
    (513, 0.7, 0): ((-8.5574934490473542e-03, 3.6842821114798207e-03, 1.9900334423677807e-02, -9.3865895742017910e-03),
                    (4.8949508873198466e-01, 1.2125512062209468e-01, 2.6892662551419377e-01, 2.3963970151631414e-01)),
    (513, 0.7, 3): ((-2.7301316366846601e-03, 4.7150334100085891e-03, 3.0033203325167943e-03, 3.3634298475208593e-03),
                    (4.9532245054434731e-01, 1.2228587192062344e-01, 2.5202961142303271e-01, 2.5238972093803680e-01)),
    (513, 1.2, 0): ((-1.0022741394622781e-02, 5.1787798543006958e-03, 1.9237978507573059e-02, -9.6717680463785632e-03),
                    (4.8802984078640921e-01, 1.2274961836491555e-01, 2.6826426959808902e-01, 2.3935452304413737e-01)),
    (513, 1.2, 3): ((-4.6790161189518616e-03, 1.8755280585725466e-03, 1.0244115394266262e-03, 3.5262424450254811e-03),
                    (4.9337356606208010e-01, 1.1944636656918740e-01, 2.5005070262994256e-01, 2.5255253353554141e-01)),
}
#: The same for ``self_affine(n, hurst=H, h_rms=3e-3, length=2.5, seed=11)``.
REFERENCE_HEIGHTS_LENGTH = {
    (64, 0.7): (-2.6558602530783485e-03, -1.8308102117918393e-03, 1.0368726514498863e-03, -1.6436115615057857e-04),
    (65, 0.5): (2.3045154742666312e-03, 4.4222609387404872e-03, -5.8619139351781336e-03, -3.7411171293424831e-04),
}
#: Tolerance of the recorded heights, relative to h_rms: each height is a sum of n² modes, whose
#: round-off differs between CPUs and FFT builds by a few ulps times log2(n) of the largest
#: terms (below 1e-14 h_rms for these grids); 1e-10 leaves room and still fails for any change
#: of the defaults, which moves heights by O(h_rms).
HEIGHT_TOLERANCE = 1e-10


def _nodes(n: int) -> list[tuple[int, int]]:
    """Four nodes spread over the grid, corner and edges included (odd and even n alike)."""
    return [(0, 0), (n // 3, n // 5), (n - 1, n // 2), (n // 2, n - 1)]


def _heights_at(z: np.ndarray) -> np.ndarray:
    return np.array([z[i, j] for i, j in _nodes(z.shape[0])])


def whole_array_self_affine(n, hurst, h_rms, length, seed):
    """``self_affine`` as it was written before the block-wise version (eqs. 1–3)."""
    q = surfaces.wavevectors(n, length)
    amplitude = np.zeros_like(q)
    nonzero = q > 0
    amplitude[nonzero] = q[nonzero] ** (-hurst - 1.0)
    phase = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, size=(n, n))
    phase = phase - np.roll(np.flip(phase, axis=(0, 1)), shift=1, axis=(0, 1))
    heights = np.fft.ifft2(amplitude * np.exp(1j * phase)).real
    heights -= heights.mean()
    return heights * (h_rms / np.sqrt(np.mean(heights**2)))


@pytest.mark.parametrize("n, hurst, seed", sorted(REFERENCE_HEIGHTS))
@pytest.mark.parametrize("body", ["self_affine", "rough_sphere"])
def test_defaults_give_the_recorded_surfaces(n, hurst, seed, body):
    kw = dict(hurst=hurst, h_rms=9e-3, length=1.0, seed=seed)
    z = surfaces.self_affine(n, **kw) if body == "self_affine" else surfaces.rough_sphere(n, radius=0.5, **kw)
    recorded = np.array(REFERENCE_HEIGHTS[n, hurst, seed][body == "rough_sphere"])
    error = np.abs(_heights_at(z) - recorded).max() / kw["h_rms"]
    assert error < HEIGHT_TOLERANCE, f"{body} heights moved by {error:.2e} h_rms from the recorded ones"


@pytest.mark.parametrize("n, hurst", sorted(REFERENCE_HEIGHTS_LENGTH))
def test_defaults_give_the_recorded_surfaces_other_length(n, hurst):
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=2.5, seed=11)
    error = np.abs(_heights_at(z) - np.array(REFERENCE_HEIGHTS_LENGTH[n, hurst])).max() / 3e-3
    assert error < HEIGHT_TOLERANCE, f"self_affine heights moved by {error:.2e} h_rms from the recorded ones"


@pytest.mark.parametrize("block_cells", [1, 1000, roughness._BLOCK_CELLS])
@pytest.mark.parametrize("n", [64, 65, 385])
def test_same_bytes_as_whole_array_algorithm(n, block_cells, monkeypatch):
    """Block-wise generation (one row per block with ``block_cells = 1``) equals the
    whole-array algorithm: the same 1-D transforms line by line, so equal to round-off
    (1e-13 h_rms allows a few ulps of the sums on any CPU)."""
    monkeypatch.setattr(roughness, "_BLOCK_CELLS", block_cells)
    kw = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=3)
    expected = whole_array_self_affine(n, **kw)
    error = np.abs(surfaces.self_affine(n, **kw) - expected).max() / kw["h_rms"]
    assert error < 1e-13, f"self_affine differs from the whole-array algorithm by {error:.2e} h_rms"


def test_rolloff_equal_to_length_is_no_rolloff():
    kw = dict(hurst=0.7, h_rms=9e-3, length=LENGTH, seed=4)
    error = np.abs(surfaces.self_affine(65, rolloff=LENGTH, **kw) - surfaces.self_affine(65, **kw)).max()
    assert error < 1e-13 * kw["h_rms"], f"rolloff = L changed the surface by {error / kw['h_rms']:.2e} h_rms"


@pytest.mark.parametrize("name", ["self_affine", "rough_sphere"])
def test_peak_memory_per_cell(name):
    """Issue #8: at most 40 B per grid cell at the peak (tracemalloc sees numpy's arrays).

    Expected 24 B: the complex spectrum, transformed in place (16), and the result (8);
    the row-block temporaries (about 6 MB) are freed before that peak."""
    n = 1025
    kw = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=0)
    if name == "rough_sphere":
        kw["radius"] = 0.5
    tracemalloc.start()
    try:
        getattr(surfaces, name)(n, **kw)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak / n**2 <= 40.0, f"{name} peaked at {peak / n**2:.1f} B/cell"


# --- roll-off and cutoff ----------------------------------------------------------------------

BANDS = [(LENGTH / 8, LENGTH / 32), (None, LENGTH / 32), (LENGTH / 8, None)]


def band_masks(n, rolloff, cutoff):
    """Grid modes on the plateau, in the self-affine band, above the cutoff (as documented)."""
    q = surfaces.wavevectors(n, LENGTH)
    q_r = 2 * np.pi / (LENGTH if rolloff is None else rolloff)
    q_c = np.inf if cutoff is None else 2 * np.pi / cutoff
    plateau = (q > 0) & (q < q_r * (1 - 1e-9))
    above = q > q_c * (1 + 1e-9)
    return q, q_r, plateau, (q > 0) & ~plateau & ~above, above


@pytest.mark.parametrize("rolloff, cutoff", BANDS)
@pytest.mark.parametrize("n", [128, 127])
@pytest.mark.parametrize("hurst", [0.3, 1.2])
def test_spectrum_per_mode(rolloff, cutoff, n, hurst):
    """Only the phases are random: the power of every mode is C2D(q) times one constant.

    FFT round-off on a mode is about ε log2(n²) max|Z| / |Z(q)| ≤ 1e-16 · 14 · 4^2.2 ≈ 3e-14
    relative here (the band spans a factor 4 in q), so ratios hold to 1e-10; above q_c the
    power is zero up to (1e-12 max|Z|)².
    """
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=LENGTH, seed=2,
                             rolloff=rolloff, cutoff=cutoff)
    q, q_r, plateau, band, above = band_masks(n, rolloff, cutoff)
    power = np.abs(np.fft.fft2(z)) ** 2
    scaled = power[band] * q[band] ** (2 * hurst + 2)          # C2D ∝ q^(−2H−2), eq. 1
    assert scaled.max() / scaled.min() - 1 <= 1e-10, "band is not q^(-2H-2)"
    if rolloff is not None:
        flat = power[plateau]
        assert flat.max() / flat.min() - 1 <= 1e-10, "plateau is not flat"
        continuity = flat.mean() * q_r ** (2 * hurst + 2) / scaled.mean()
        assert continuity == pytest.approx(1, abs=1e-10), "amplitude jumps at q_r"
    if cutoff is not None:
        assert power[above].max() <= 1e-24 * power.max(), "power above q_c"
        on_cutoff = power[32, 0] * q[32, 0] ** (2 * hurst + 2) / scaled.mean()
        assert on_cutoff == pytest.approx(1, abs=1e-10), "the mode on q_c is not in the band"


def radial_slope(power, q, lo, hi, bins=4):
    """Slope of log(annulus-mean power) against log(geometric-mean |q|), annuli in [lo, hi)."""
    edges = np.geomspace(lo, hi, bins + 1)
    annuli = [(q >= a) & (q < b) for a, b in zip(edges[:-1], edges[1:])]
    centres = [np.exp(np.log(q[m]).mean()) for m in annuli]
    return np.polyfit(np.log(centres), np.log([power[m].mean() for m in annuli]), 1)[0]


@pytest.mark.parametrize("n", [128, 127])
@pytest.mark.parametrize("hurst", [0.3, 0.7, 1.2])
def test_radially_averaged_spectrum(n, hurst):
    """Plateau below q_r = 8·2π/L (slope 0), slope −2H−2 from q_r to q_c = 32·2π/L.

    The plateau is exact per mode, so its slope is 0 to round-off (1e-9). In the band the
    annulus mean of q^(−2H−2) differs from its value at the geometric-mean |q| by a factor
    that varies slowly between log-spaced annuli: a bias < 0.01 on the slope, bound 0.05
    as in test_power_spectrum_slope.
    """
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=LENGTH, seed=6,
                             rolloff=LENGTH / 8, cutoff=LENGTH / 32)
    q = surfaces.wavevectors(n, LENGTH)
    q_l = 2 * np.pi / LENGTH
    power = np.abs(np.fft.fft2(z)) ** 2
    assert radial_slope(power, q, q_l, 8 * q_l * (1 - 1e-9)) == pytest.approx(0, abs=1e-9), \
        "plateau slope"
    assert radial_slope(power, q, 8 * q_l, 32 * q_l * (1 + 1e-9)) == \
        pytest.approx(-2 * hurst - 2, abs=0.05), "band slope"


@pytest.mark.parametrize("rolloff, cutoff", BANDS)
@pytest.mark.parametrize("n", [64, 65])
def test_band_mean_zero_and_rms_exact(rolloff, cutoff, n):
    z = surfaces.self_affine(n, hurst=0.7, h_rms=3e-3, length=LENGTH, seed=7,
                             rolloff=rolloff, cutoff=cutoff)
    assert abs(z.mean()) <= 1e-12 * 3e-3, "mean height is not zero"
    assert np.sqrt(np.mean(z**2)) == pytest.approx(3e-3, rel=1e-12), "rms height != h_rms"


@pytest.mark.parametrize("kwargs, name", [
    (dict(rolloff=0.0), "rolloff"),
    (dict(rolloff=float("nan")), "rolloff"),
    (dict(rolloff=1.01 * LENGTH), "rolloff"),
    (dict(cutoff=float("inf")), "cutoff"),
    (dict(cutoff=1.9 * LENGTH / 64), "cutoff"),
    (dict(cutoff=LENGTH), "cutoff"),
    (dict(rolloff=LENGTH / 8, cutoff=LENGTH / 8), "cutoff"),
    (dict(rolloff=LENGTH / 8, cutoff=LENGTH / 4), "cutoff"),
])
def test_bad_band_names_itself(kwargs, name):
    with pytest.raises(ValueError, match=f"^{name} must be"):
        surfaces.self_affine(64, hurst=0.7, h_rms=1.0, length=LENGTH, **kwargs)


# --- bodies of revolution ---------------------------------------------------------------------

@pytest.mark.parametrize("n", [64, 65])
def test_body_exponent_two_is_paraboloid(n):
    r = surfaces.radial_distance(n, 1.3)
    body = surfaces.body_of_revolution(n, radius=0.37, exponent=2, length=1.3)
    assert body.tobytes() == (r**2 / (2 * 0.37)).tobytes(), "m = 2 is not r^2/(2R) bit for bit"
    assert surfaces.paraboloid(n, radius=0.37, length=1.3).tobytes() == body.tobytes(), \
        "paraboloid is not the body with m = 2"


@pytest.mark.parametrize("n", [64, 65])
def test_body_exponent_one_is_cone_of_slope_one(n):
    cone = surfaces.body_of_revolution(n, radius=0.3, exponent=1, length=LENGTH)
    assert np.array_equal(cone, surfaces.radial_distance(n, LENGTH)), "m = 1 is not z = r"


def test_body_exponent_four():
    n, radius = 65, 0.5
    z = surfaces.body_of_revolution(n, radius=radius, exponent=4.0, length=1.0)
    r = math.hypot(7, 3) / n
    assert z[n // 2 + 7, n // 2 - 3] == pytest.approx(radius / 4 * (r / radius) ** 4, rel=1e-14), \
        "z != (R/m)(r/R)^m"


@pytest.mark.parametrize("exponent", [1.0, 2.0, 4.0])
def test_rough_body_is_sum(exponent):
    kw = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=5)
    z = surfaces.rough_sphere(33, radius=0.5, exponent=exponent, **kw)
    expected = (surfaces.body_of_revolution(33, radius=0.5, exponent=exponent, length=1.0)
                + surfaces.self_affine(33, **kw))
    assert np.array_equal(z, expected), "rough body is not body + roughness"


@pytest.mark.parametrize("kwargs, name", [
    (dict(radius=0.0, exponent=2.0), "radius"),
    (dict(radius=float("inf"), exponent=2.0), "radius"),
    (dict(radius=0.5, exponent=0.0), "exponent"),
    (dict(radius=0.5, exponent=float("nan")), "exponent"),
    (dict(radius=0.5, exponent=True), "exponent"),
])
def test_bad_body_arguments_name_themselves(kwargs, name):
    with pytest.raises(ValueError, match=f"^{name} must be"):
        surfaces.body_of_revolution(16, **kwargs)
    with pytest.raises(ValueError, match=f"^{name} must be"):
        surfaces.rough_sphere(16, hurst=0.7, h_rms=1.0, **kwargs)
