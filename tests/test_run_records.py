"""One job record for every kind of run (roughcontact.study.config.records): each kind is a
RunRecord, declares only its own fields, and its identity is its own record."""
import dataclasses
from pathlib import Path

import pytest

from roughcontact.study.config.records import ForcePathRecord, RunRecord
from roughcontact.study.config.stickiness import StickinessRun
from roughcontact.study.runs.jobs import JobSettings
from roughcontact.study.runs.measured import MeasuredJob

ROOT = Path(__file__).resolve().parents[1]

KINDS = {JobSettings: ForcePathRecord, MeasuredJob: ForcePathRecord, StickinessRun: RunRecord}


def _own_annotations(cls) -> set:
    return set(cls.__dict__.get("__annotations__", {}))


@pytest.mark.parametrize("kind", list(KINDS), ids=lambda c: c.__name__)
def test_every_kind_is_a_run_record(kind):
    assert issubclass(kind, KINDS[kind])


@pytest.mark.parametrize("kind", list(KINDS), ids=lambda c: c.__name__)
def test_no_kind_redeclares_a_shared_field(kind):
    shared = {f.name for f in dataclasses.fields(KINDS[kind])}
    assert _own_annotations(kind) & shared == set()


def test_the_record_itself_is_abstract():
    with pytest.raises(TypeError):
        RunRecord(n=8, length=1.0, e_star=1.0, tol=1e-8)


def test_stickiness_record_is_its_fields():
    run = StickinessRun(hurst=0.8, number=0.5, seed=1, n=64, length=1.0, e_star=1.0, rms_slope=0.1,
                        cutoff=4.0, range_ratio=0.5, area=0.1, steps=5, tol=1e-8)
    assert run.record() == {"n": 64, "length": 1.0, "e_star": 1.0, "tol": 1e-8, "hurst": 0.8, "number": 0.5,
                            "seed": 1, "rms_slope": 0.1, "cutoff": 4.0, "range_ratio": 0.5, "area": 0.1,
                            "steps": 5}


def test_measured_forces_are_the_force_grid():
    job = MeasuredJob(source="topography", name="s", index=0, radius=20.0, e_star=100.0, length_unit="um",
                      pressure_unit="GPa", n=None, length=None, force_from=1e-6, force_to=1e-2,
                      force_count=5, tol=1e-8, maxiter=100, stiffness_method="punch", rel_step=1e-3)
    assert job.forces_normalized()[2] == pytest.approx(1e-4, rel=1e-12)


def test_an_upgrade_reruns_no_run_of_an_earlier_study():
    """The indent rule's params are its runs' JobSettings, and Snakemake reruns a job whose params' repr
    changed. Seed 0 of presets/convergence-4097.yaml as recorded in .snakemake/metadata by the study run
    on 2026-11-29 (06:27 UTC, before fields.histograms existed): a field added later is left out of the
    repr at its default, so the repr is that same string and the run is not recomputed."""
    from roughcontact.study.config.resolve import load_config, study_settings
    from roughcontact.study.runs import jobs

    recorded = ("JobSettings(n=4097, length=1.0, e_star=1.0, tol=1e-08, force_from=1e-06, force_to=0.000562341325, "
                "force_count=23, stiffness_method='punch', rel_step=0.001, maxiter=10000, hurst=0.7, radius=0.5, "
                "h_rms=0.009, seed=0, options=(), realization_of=None, patches=False, quantities=(), field_loads=(), "
                "slip_loads=(), slip_steps=0)")
    study = study_settings(load_config(ROOT / "presets" / "convergence-4097.yaml"))
    job = jobs.job_settings(study, {"hurst": 0.7, "radius": 0.5, "h_rms": 9e-3, "seed": 0})
    assert repr(job) == recorded, "the params of an existing run changed: an upgrade would recompute it"
    with_histograms = dataclasses.replace(job, histogram_loads=(3,), histogram_bins=50)
    assert "histogram_loads=(3,)" in repr(with_histograms), "a run that keeps histograms says so in its params"
