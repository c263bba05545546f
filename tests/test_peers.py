"""roughcontact against the peer codes ContactMechanics and tamaas on the same rough sphere.

Both peers use the same discrete operator (Love's kernel, zero-padded DC-FFT)
as roughcontact, so a converged solve of the same heights at the same force
must give the same depth and the same contact set; the adapters that map the
conventions live in ``benchmarks/peers.py``.
"""

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("ContactMechanics")

from roughcontact import bem
from roughcontact import surfaces  # noqa: E402

N = 128
LENGTH = 1.0
E_STAR = 1.0
RADIUS = 0.5
HURST = 0.7
H_RMS = 9e-3
SEED = 1
TOL = 1e-8
FORCES = (1e-4, 1e-3)          # F/(E* L²)

#: Relative depth agreement required of two solves converged to TOL·d.
DEPTH_RTOL = 1e-6
#: Our exact tangent stiffness against the peer's central difference quotient
#: at F(1 ± 1e-3): the quotient's error from the depth tolerance is about
#: TOL/(2·1e-3·(2/3)) ≈ 1e-5, and a contact set that changes inside the step
#: adds to it.
STIFFNESS_RTOL = 1e-4


def _load_peers():
    path = Path(__file__).resolve().parents[1] / "benchmarks" / "peers.py"
    spec = importlib.util.spec_from_file_location("roughcontact_benchmark_peers", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module          # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


peers = _load_peers()


@pytest.fixture(scope="module")
def heights():
    return surfaces.rough_sphere(N, radius=RADIUS, hurst=HURST, h_rms=H_RMS,
                                 length=LENGTH, seed=SEED)


@pytest.fixture(scope="module")
def ours(heights):
    return {force: bem.solve(heights, force=force * E_STAR * LENGTH**2, length=LENGTH,
                                 e_star=E_STAR, tol=TOL)
            for force in FORCES}


@pytest.fixture(scope="module")
def contact_mechanics(heights):
    peer = peers.ContactMechanicsPeer(heights, length=LENGTH, e_star=E_STAR, tol=TOL)
    return {force: peer.solve(force * E_STAR * LENGTH**2) for force in FORCES}


@pytest.mark.parametrize("force", FORCES)
def test_depth_matches_contact_mechanics(ours, contact_mechanics, force):
    state, peer = ours[force], contact_mechanics[force]
    assert state.converged, f"roughcontact did not converge at F={force:g}"
    relative = abs(state.depth / peer.depth - 1)
    assert relative <= DEPTH_RTOL, (
        f"F={force:g}: depth {state.depth!r} vs ContactMechanics {peer.depth!r} "
        f"(relative difference {relative:.2e} > {DEPTH_RTOL:g})")


@pytest.mark.parametrize("force", FORCES)
def test_contact_set_matches_contact_mechanics(ours, contact_mechanics, force):
    state, peer = ours[force], contact_mechanics[force]
    differing = int(np.count_nonzero(state.contact != peer.contact))
    assert differing == 0, (
        f"F={force:g}: {differing} of {int(peer.contact.sum())} contact cells differ "
        f"from ContactMechanics")


@pytest.mark.parametrize("force", FORCES)
def test_force_matches_target(ours, force):
    state = ours[force]
    relative = abs(state.force / (force * E_STAR * LENGTH**2) - 1)
    assert relative <= 1e-12, f"F={force:g}: total force off by {relative:.2e}"


@pytest.mark.parametrize("force", FORCES)
def test_stiffness_matches_contact_mechanics_difference_quotient(heights, ours, force):
    peer = peers.ContactMechanicsPeer(heights, length=LENGTH, e_star=E_STAR, tol=TOL)
    (point,) = peers.load_path(peer, [force * E_STAR * LENGTH**2], rel_step=1e-3)
    tangent = bem.stiffness(ours[force])
    relative = abs(tangent / point.stiffness - 1)
    assert relative <= STIFFNESS_RTOL, (
        f"F={force:g}: tangent stiffness {tangent!r} vs ContactMechanics difference "
        f"quotient {point.stiffness!r} (relative difference {relative:.2e} > {STIFFNESS_RTOL:g})")


@pytest.fixture(scope="module")
def tamaas(heights):
    pytest.importorskip("tamaas")
    peer = peers.TamaasPeer(heights, length=LENGTH, e_star=E_STAR, tol=TOL)
    return {force: peer.solve(force * E_STAR * LENGTH**2) for force in FORCES}


@pytest.mark.parametrize("force", FORCES)
def test_depth_matches_tamaas(ours, tamaas, force):
    state, peer = ours[force], tamaas[force]
    relative = abs(state.depth / peer.depth - 1)
    assert relative <= DEPTH_RTOL, (
        f"F={force:g}: depth {state.depth!r} vs tamaas {peer.depth!r} "
        f"(relative difference {relative:.2e} > {DEPTH_RTOL:g})")


@pytest.mark.parametrize("force", FORCES)
def test_contact_set_matches_tamaas(ours, tamaas, force):
    state, peer = ours[force], tamaas[force]
    differing = int(np.count_nonzero(state.contact != peer.contact))
    assert differing == 0, (
        f"F={force:g}: {differing} of {int(peer.contact.sum())} contact cells differ "
        f"from tamaas")
