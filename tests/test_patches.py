"""Contact patches (roughcontact.bem.patches) on contact sets whose patches are known by
construction, and on a smooth sphere (Hertz: one circular patch)."""
import numpy as np
import pytest

from roughcontact import bem, surfaces
from roughcontact.bem.patches import contact_patches, contact_window


def _disk(n, centre, radius):
    y, x = np.mgrid[:n, :n]
    return (y - centre[0]) ** 2 + (x - centre[1]) ** 2 <= radius**2


@pytest.mark.parametrize("n", [32, 33])
def test_two_separate_disks_are_two_patches(n):
    mask = _disk(n, (8, 8), 3) | _disk(n, (22, 22), 4)
    patches = contact_patches(mask)
    assert patches.count == 2


def test_largest_patch_is_the_larger_disk():
    small, large = _disk(40, (8, 8), 3), _disk(40, (25, 25), 6)
    assert contact_patches(small | large).largest == int(large.sum())


def test_corner_neighbours_are_two_patches():
    mask = np.zeros((8, 8), bool)
    mask[2, 2] = mask[3, 3] = True
    assert contact_patches(mask).count == 2


def test_periodic_wrap_joins_a_patch_across_the_edge():
    mask = np.zeros((16, 16), bool)
    mask[5:8, 0:2] = True
    mask[5:8, 14:16] = True
    assert (contact_patches(mask).count, contact_patches(mask, periodic=True).count) == (2, 1)


def test_periodic_corner_wrap_joins_four_pieces():
    mask = np.zeros((16, 16), bool)
    mask[:2, :2] = mask[:2, -2:] = mask[-2:, :2] = mask[-2:, -2:] = True
    patches = contact_patches(mask, periodic=True)
    assert (patches.count, patches.largest) == (1, 16)


def test_no_contact_has_no_patch():
    patches = contact_patches(np.zeros((9, 9), bool))
    assert (patches.count, patches.largest) == (0, 0)


def test_window_holds_every_contact_cell_with_its_margin():
    mask = _disk(40, (20, 12), 5)
    rows, cols = contact_window(mask, margin=2)
    assert (rows, cols) == (slice(13, 28), slice(5, 20))


def test_smooth_sphere_touches_in_one_patch():
    """Hertz: the contact of a smooth paraboloid is one disk, so one patch holding every contact cell."""
    n = 65
    z = surfaces.paraboloid(n, radius=0.5, length=1.0)
    state = bem.solve(z, force=1e-3, length=1.0, e_star=1.0)
    patches = contact_patches(state.contact)
    assert (patches.count, patches.largest) == (1, int(state.contact.sum()))
