"""Smooth bodies of revolution z = (R/m)(r/R)^m through the BEM against eq. 7 with H → m.

For a rigid axisymmetric indenter z = Q r^m (Q = R^(1−m)/m) at contact radius a
(Sneddon; the method of dimensionality reduction behind the paper's eq. 7):

    d = κ(m) Q a^m,   F = 2 E* m κ(m) Q a^(m+1)/(m+1),   k = 2 E* a,

with κ of eq. 8. Cone of slope 1 (m = 1, κ = π/2, Q = 1): d = π a/2, F = π E* a²/2,
so d(F) = (π F/(2E*))^(1/2). Quartic (m = 4, κ = 8/3, Q = 1/(4R³)): d = 2a⁴/(3R³),
F = 16 E* a⁵/(15 R³). Each solve is force-controlled at the F of a = 0.12 L, about
31 cells on the 256 and 257 grids (free half-space, L = 1).

Tolerances. Depth and force are integrals over the contact, whose discretisation error
is O((Δ/a)²) ≈ 1e-3; the cone's pressure has a logarithmic singularity at the tip, which
adds a factor ln(a/Δ) ≈ 3.4 on the apex cell: 5e-3 covers both (measured ≤ 1e-4). The
contact radius from the contact area √(A/π), and the tangent stiffness k ∝ a with it,
depend on which cells along the edge touch: a digitised disc of 31 cells' radius is off
by O((a/Δ)^(2/3)) ≈ 10 of its ≈ 3000 cells (0.2 % in a), and the edge itself is found to
a fraction of a cell (Δ/a ≈ 3 %); 1 % allows a third of a cell (measured ≤ 0.3 %).
"""

import math

import pytest

from roughcontact import bem
from roughcontact import surfaces

E_STAR = 1.0
LENGTH = 1.0
A = 0.12


def cone(a):
    """Cone of slope 1: force and depth at contact radius ``a``."""
    return math.pi * E_STAR * a**2 / 2, math.pi * a / 2


def quartic(a, radius=0.5):
    """z = r⁴/(4R³): force and depth at contact radius ``a``."""
    return 16 * E_STAR * a**5 / (15 * radius**3), 2 * a**4 / (3 * radius**3)


BODIES = {1: (1.0, cone), 4: (0.5, quartic)}


@pytest.fixture(scope="module", params=[(1, 256), (1, 257), (4, 256), (4, 257)],
                ids=lambda p: f"m{p[0]}-n{p[1]}")
def indentation(request):
    exponent, n = request.param
    radius, closed_form = BODIES[exponent]
    force, depth = closed_form(A)
    z = surfaces.body_of_revolution(n, radius=radius, exponent=exponent, length=LENGTH)
    state = bem.solve(z, force=force, length=LENGTH, e_star=E_STAR, tol=1e-8)
    return state, force, depth


def test_converged(indentation):
    assert indentation[0].converged, "solve did not converge"


def test_depth(indentation):
    state, _, depth = indentation
    assert state.depth == pytest.approx(depth, rel=5e-3), "depth d(F) differs from eq. 7"


def test_contact_radius(indentation):
    state = indentation[0]
    measured = math.sqrt(state.contact_area / math.pi)
    assert measured == pytest.approx(A, rel=1e-2), "contact radius sqrt(A/pi)"


def test_stiffness(indentation):
    state = indentation[0]
    assert bem.stiffness(state) == pytest.approx(2 * E_STAR * A, rel=1e-2), "k = 2 E* a"
