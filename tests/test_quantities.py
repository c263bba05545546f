"""The per-load quantities' registry (:mod:`roughcontact.study.quantities`): the built-ins in order,
the opt-in quantities against Hertz's closed forms, and the key that turns them on.

Hertz (Johnson 1985, §3.9 and eq. 3.41): a rigid paraboloid ``z = r²/2R`` pressed by ``F`` into a
half-space of modulus ``E*`` touches on a circle of radius ``a = (3FR/4E*)^(1/3)`` under the peak
pressure ``p₀ = 2aE*/(πR)``, at the depth ``d = a²/R``; out of contact the surface sinks by
``u(r) = p₀/(2aE*) [(2a² − r²) asin(a/r) + a √(r² − a²)]``, so the gap is ``g = r²/2R − d + u``.
"""
from __future__ import annotations

import math
import types

import numpy as np
import pytest

from roughcontact import bem
from roughcontact.errors import ConfigError
from roughcontact.study import quantities
from roughcontact.study.config import resolve_config
from roughcontact.study.registries import listing

N, LENGTH, RADIUS, E_STAR = 257, 1.0, 0.5, 1.0
#: a = 0.1 L: 25.7 cells across the contact's radius
FORCE = 4 * E_STAR * 0.1**3 / (3 * RADIUS)


def _hertz_state():
    x = (np.arange(N) - N // 2) * (LENGTH / N)
    r2 = x[:, None] ** 2 + x[None, :] ** 2
    return bem.solve(r2 / (2 * RADIUS), force=FORCE, length=LENGTH, e_star=E_STAR), np.sqrt(r2)


def _values(state, *names):
    settings = types.SimpleNamespace(periodic=False)   # the free half-space (the patches read it)
    load = quantities.Load(settings=settings, index=0, total=1, where="load step 1/1 (", cell=(LENGTH / N) ** 2)
    return [quantities.QUANTITIES[name].compute(state, load) for name in names]


def _hertz_gap(r):
    a = (3 * FORCE * RADIUS / (4 * E_STAR)) ** (1 / 3)
    p0 = 2 * a * E_STAR / (math.pi * RADIUS)
    outside = np.maximum(r, a)
    u = p0 / (2 * a * E_STAR) * ((2 * a * a - outside**2) * np.arcsin(a / outside)
                                 + a * np.sqrt(outside**2 - a * a))
    return np.where(r > a, r * r / (2 * RADIUS) - a * a / RADIUS + u, 0.0)


def test_the_built_ins_are_registered_in_order():
    built_in = ("depth", "stiffness", "contact_area", "contact_cells", "iterations", "converged",
                "loading_stiffness", "plastic_cells", "contact_patches", "largest_patch_cells", "largest_patch_area",
                "mean_gap", "mean_free_gap", "mean_contact_pressure", "relative_contact_area")
    names = quantities.names()
    assert [n for n in names if n in built_in] == list(built_in)


def test_mean_contact_pressure_is_hertz_f_over_pi_a_squared():
    """F/(πa²) = (2/3) p₀; the contact's area on the grid errs by about one ring of cells, up to
    2Δ/a = 8 % (measured: −0.5 % on 257², 2026-11-29)."""
    state, _ = _hertz_state()
    a = (3 * FORCE * RADIUS / (4 * E_STAR)) ** (1 / 3)
    (pressure,) = _values(state, "mean_contact_pressure")
    assert pressure == pytest.approx(FORCE / (math.pi * a * a), rel=0.03)


def test_the_largest_patch_of_hertz_is_its_circle():
    """One patch, the contact circle πa²: its area on the grid errs by about one ring of cells, up
    to 2Δ/a = 8 % (measured: +0.5 % on 257², one patch, 2026-11-29)."""
    state, _ = _hertz_state()
    a = (3 * FORCE * RADIUS / (4 * E_STAR)) ** (1 / 3)
    (largest,) = _values(state, "largest_patch_area")
    assert largest == pytest.approx(math.pi * a * a, rel=2 * (LENGTH / N) / a)


def test_mean_free_gap_is_hertz_gap_out_of_contact():
    """The BEM gap averaged over the free cells against Hertz's closed form over the same cells: the
    far gap is the body's shape, the near one feels the discretised contact, whose error in u falls
    off with distance (tolerance 0.1 %; measured 1·10⁻⁵ on 257², 2026-11-29)."""
    state, r = _hertz_state()
    (free,) = _values(state, "mean_free_gap")
    assert free == pytest.approx(float(np.mean(_hertz_gap(r)[~state.contact])), rel=1e-3)


def test_mean_gap_counts_the_contact_as_zero():
    state, r = _hertz_state()
    (whole,) = _values(state, "mean_gap")
    assert whole == pytest.approx(float(np.mean(_hertz_gap(r))), rel=1e-3)


def _cfg(**fields):
    return {"grid": {"n": 65, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 1,
            "fields": fields}


def test_an_opt_in_quantity_changes_no_run_of_a_study_without_it():
    """A study that does not name it keeps every run's record (name, hash); one that does records it."""
    from roughcontact.study.runs import jobs, naming

    plain = resolve_config(_cfg())
    kept = resolve_config(_cfg(quantities=["mean_gap"]))
    run = naming.runs(plain)[0]
    assert "quantities" not in jobs.job_settings(plain, run).record()
    assert jobs.job_settings(kept, run).record()["quantities"] == ["mean_gap"]
    assert "mean_gap" in quantities.recorded(jobs.job_settings(kept, run))
    assert "mean_gap" not in quantities.recorded(jobs.job_settings(plain, run))


def test_an_unknown_quantity_is_refused_in_one_line():
    with pytest.raises(ConfigError, match="fields.quantities") as err:
        resolve_config(_cfg(quantities=["mean_gapp"]))
    assert "\n" not in str(err.value)


def test_a_quantity_an_adhesive_run_cannot_give_is_refused():
    with pytest.raises(ConfigError, match="'fields.quantities'"):
        resolve_config({**_cfg(quantities=["mean_gap"]), "work_of_adhesion": [1e-3]})


def test_the_listing_names_the_key_that_turns_each_on():
    rows = {row["name"]: row for row in listing("quantities")}
    assert rows["stiffness"]["option"] is None
    assert rows["contact_patches"]["option"] == "fields.patches"
    assert rows["mean_gap"]["option"] == quantities.OPT_IN
