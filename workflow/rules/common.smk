# Shared set-up: the package of this checkout, the validated and resolved config, the paths.
import os
import sys
from pathlib import Path

from snakemake.utils import validate

# Use the package of this checkout, also in the jobs (no install needed for the workflow itself).
SRC = str(Path(workflow.basedir) / "src")
sys.path.insert(0, SRC)
# (set, not required: the envvars directive does not apply)
os.environ.update(
    PYTHONPATH=os.pathsep.join(p for p in (SRC, os.environ.get("PYTHONPATH")) if p)
)

from roughcontact.errors import ConfigError  # noqa: E402  (numpy only)
from roughcontact.bem import (
    SOLVER_VERSION,
)  # noqa: E402  (a run reruns when it changes)
from roughcontact.study.config import resolve as rc_config, schema  # noqa: E402
from roughcontact.study.runs import (
    naming as study_runs,
    jobs as study_settings,
)  # noqa: E402
from roughcontact.study.config.settings import StudySettings  # noqa: E402
from roughcontact.study.config.companions import (
    coarse_config,
    fine_config,
)  # noqa: E402
from roughcontact.study.analysis import adhesion as study_adhesion  # noqa: E402
from roughcontact.study.config.stickiness import StickinessSettings  # noqa: E402
from roughcontact.study.config import measured as measured_inputs  # noqa: E402
from roughcontact.study.files import directory as study_directory  # noqa: E402

try:
    # one line naming the key and what is allowed, before any job starts; the paths of
    # topography and spectrum are relative to the last config file that names them
    C = rc_config.resolve_config(
        config, base_dir=measured_inputs.config_directory(workflow.configfiles)
    )
except ConfigError as err:
    raise SystemExit(rc_config.error_line(err))
# the same schema (package data) through Snakemake (passes once resolve_config did)
validate(C, schema.schema_file())
config.clear()
config.update(C)  # the report and the jobs see the resolved values
# the same, typed, for the input functions and params below (jobs get the mapping: it is the
# resolved configuration their files record)
STUDY = StudySettings.of(config)
# the companion study of the grid error (grid.coarse): the same sphere runs on the coarse grid
COARSE_CONFIG = (
    coarse_config(config)
    if STUDY.grid.coarse is not None and any(r != float("inf") for r in STUDY.radius)
    else None
)
COARSE = StudySettings.of(COARSE_CONFIG) if COARSE_CONFIG is not None else None
# the fine reference of the small loads (grid.fine): the sphere runs' loads up to grid.fine_to
FINE_CONFIG = fine_config(config) if STUDY.grid.fine is not None else None
FINE = StudySettings.of(FINE_CONFIG) if FINE_CONFIG is not None else None


# The workflow's paths: one run file, log and benchmark per (combination, seed).
RUN_PATTERN = "results/runs/{combo}/seed{seed}.nc"
LOG_PATTERN = "logs/indent/{combo}_seed{seed}.log"
# Snakemake's per-job benchmark (wall seconds, peak RSS max_rss in MB) of each run
BENCHMARK_PATTERN = "results/benchmarks/indent/{combo}_seed{seed}.tsv"
# ... and of the companion study on the coarse grid (grid.coarse)
COARSE_RUN_PATTERN = "results/indent_coarse/{combo}/seed{seed}.nc"
COARSE_LOG_PATTERN = "logs/indent_coarse/{combo}_seed{seed}.log"
COARSE_BENCHMARK_PATTERN = "results/benchmarks/indent_coarse/{combo}_seed{seed}.tsv"
# ... and of the fine reference (grid.fine)
FINE_RUN_PATTERN = "results/indent_fine/{combo}/seed{seed}.nc"
FINE_LOG_PATTERN = "logs/indent_fine/{combo}_seed{seed}.log"
FINE_BENCHMARK_PATTERN = "results/benchmarks/indent_fine/{combo}_seed{seed}.tsv"
# ... of an indent job of several runs (jobs.batch > 1): one benchmark per job, "{block}" its
# seeds (e.g. seeds0_5); the run files and logs stay one per run
BATCH_BENCHMARK_PATTERN = "results/benchmarks/indent/{combo}_{block}.tsv"
COARSE_BATCH_BENCHMARK_PATTERN = "results/benchmarks/indent_coarse/{combo}_{block}.tsv"
FINE_BATCH_BENCHMARK_PATTERN = "results/benchmarks/indent_fine/{combo}_{block}.tsv"
# The runs of a combination go to jobs in blocks of jobs.batch seeds (1: a job per run).
INDENT_BATCH = STUDY.jobs.batch
INDENT_BLOCKS = study_runs.seed_blocks(STUDY.seeds, INDENT_BATCH)
# The analysis (merge, zeta, crossover, exponents, figures; merge_coarse and grid_error) goes
# before every indent job still waiting: each of its jobs can start only once the runs it reads
# are done, and it is on the way to the report, while the runs left are not.
ANALYSIS_PRIORITY = 1 + max(
    (
        study_runs.indent_priority(STUDY, study_runs.combo_name(c), INDENT_BATCH)
        for c in study_runs.combinations(STUDY)
    ),
    default=0,
)
FIGURE_DIR = "results/figures"
CAPTION_DIR = "../report"  # relative to workflow/rules/

# One directory, one study (roughcontact.study.files.directory): the config file(s) of this study,
# as its directory records them (results/configfile.txt, written when its first job starts); a
# directory holding another configuration's study is refused in one line naming both, before any
# job (a directory made before the record: refused where a run file of this study's paths was
# computed with other settings; the checkout's results/ is config.yaml's).
STUDY_NAMES = study_directory.config_names(workflow.configfiles, workflow.basedir)


def _expected_runs():
    """{run file: its job record} of this study's runs (the check of a directory without record)."""
    return {
        study_runs.run_path(run, RUN_PATTERN): study_settings.job_settings(
            STUDY, run
        ).record()
        for run in study_runs.runs(STUDY)
    }


if workflow.is_main_process:
    try:
        study_directory.check_study(
            Path.cwd(),
            STUDY_NAMES,
            checkout=workflow.basedir,
            # paths relative to the checkout where the command was typed there, else absolute
            shown_from=(
                workflow.basedir
                if workflow.overwrite_workdir is None
                and Path(workflow.workdir_init).resolve()
                == Path(workflow.basedir).resolve()
                else None
            ),
            runs=(
                None
                if not STUDY.generated
                or (
                    STUDY_NAMES == ["config.yaml"]
                    and Path.cwd().resolve() == Path(workflow.basedir).resolve()
                )
                else _expected_runs
            ),
        )
    except ConfigError as err:
        raise SystemExit(str(err))


onstart:
    study_directory.record_study(Path.cwd(), STUDY_NAMES)


def run_files(wildcards):
    """Every run file of the resolved config, in the order merge expects."""
    return study_runs.run_paths(STUDY, RUN_PATTERN)


def coarse_run_files(wildcards):
    """Every run file of the companion study on grid.coarse (its sphere runs: coarse_config),
    in the order merge expects."""
    if COARSE is None:
        raise ValueError("grid.coarse is not set: no coarse runs")
    return study_runs.run_paths(COARSE, COARSE_RUN_PATTERN)


def fine_run_files(wildcards):
    """Every run file of the fine reference on grid.fine (its sphere runs at the small loads:
    fine_config), in the order merge expects."""
    if FINE is None:
        raise ValueError("grid.fine is not set: no fine runs")
    return study_runs.run_paths(FINE, FINE_RUN_PATTERN)


def coarse_stiffness(wildcards):
    """The coarse companion's merged runs where grid.coarse is set (the fine reference's third grid)."""
    return rules.merge_coarse.output.stiffness if COARSE is not None else []


def fine_reference_table(wildcards):
    """The fine reference where grid.fine is set (the models rule's optional input)."""
    return rules.fine_reference.output.csv if FINE is not None else []


# The adhesive runs (work_of_adhesion > 0), in the order their merge expects; empty without.
ADHESIVE_RUNS = study_adhesion.adhesive_runs(STUDY)


def adhesive_run_files(wildcards):
    """The run files of the adhesive runs."""
    return [study_runs.run_path(run, RUN_PATTERN) for run in ADHESIVE_RUNS]


def claim_tables(wildcards):
    """The tables the registered claims read beyond the built-in inputs, each made by a rule of
    its own: their paths, in the order of roughcontact.study.claims.input_tables."""
    from roughcontact.study.claims import input_tables

    return [table.path for table in input_tables().values()]


def pull_off_table(wildcards):
    """The pull-off table where the study has adhesive runs (the claims rule's optional input)."""
    return rules.adhesion.output.csv if ADHESIVE_RUNS else []


# The stickiness sweep (the config's stickiness section; None without it) and its runs.
STICKINESS = StickinessSettings.of(config)
# (the stickiness_run rule's output: one run file per (H, N) combination and seed)
STICKINESS_PATTERN = "results/stickiness_run/{combination}/seed{seed}.nc"


def stickiness_run_files(wildcards):
    """The run files of the stickiness sweep, in the order its merge expects."""
    return [
        STICKINESS_PATTERN.format(combination=job.combination, seed=job.seed)
        for job in STICKINESS.jobs()
    ]


def stickiness_run_settings(wildcards):
    """The settings of the stickiness run of a job's wildcards, its identity (fails naming the
    sweep's runs for others)."""
    if STICKINESS is None:
        raise ValueError("the config has no stickiness section: no stickiness runs")
    return STICKINESS.job(wildcards.combination, wildcards.seed)


def stickiness_table(wildcards):
    """The stickiness table where the config has a stickiness section (the claims rule's optional input)."""
    return rules.stickiness.output.csv if STICKINESS is not None else []


# The tangential problem (axes poisson, friction; workflow/rules/tangential.smk): whether the
# sphere runs have a Poisson ratio (the full-stick stiffness) and a friction > 0 (partial slip).
TANGENTIAL = STUDY.generated and any(nu is not None for nu in STUDY.poisson)
PARTIAL_SLIP = TANGENTIAL and any(mu > 0 for mu in STUDY.friction)


def tangential_file(wildcards):
    """The merged tangential runs where the study has them (the claims rule's optional input)."""
    return rules.tangential.output.nc if TANGENTIAL else []


def grid_error_table(wildcards):
    """The grid error table where grid.coarse is set (the models rule's optional input)."""
    return rules.grid_error.output.csv if COARSE is not None else []


# A quiet console (profiles/default: --quiet rules) hides Snakemake's block of a failed job too:
# every failed job is one line instead. A local indent job's script prints its own (the run's
# error and its log), so Snakemake's block and its three lines on the script's exit status 1 are
# left out; any other failed job (another rule, a job the scheduler ended) is its rule, Snakemake's
# message and its logs on one line. Without --quiet rules nothing changes.
def _one_line_failures():
    from snakemake.logging import LogEvent, logger as snakemake_logger
    from snakemake.settings.enums import Quietness

    settings = getattr(workflow, "output_settings", None)
    if Quietness.RULES not in (getattr(settings, "quiet", None) or ()):
        return

    def one_line(record):
        text = str(record.msg)
        if (
            "CalledProcessError" in text
            and ".indent.py' returned non-zero exit status 1." in text
        ):
            return False
        if getattr(record, "event", None) != LogEvent.JOB_ERROR:
            return True
        name, message = getattr(record, "rule_name", "?"), getattr(
            record, "rule_msg", None
        )
        if str(name).startswith("indent") and message is None:
            return False
        logs = ", ".join(str(log) for log in getattr(record, "log", None) or ())
        where = " ".join(("Error in rule", str(name)))
        record.msg = f"{where}: {message or 'failed'}" + (
            f" (log: {logs})" if logs else ""
        )
        record.event = None  # a plain line, which --quiet rules lets through
        return True

    snakemake_logger.addFilter(one_line)


_one_line_failures()


# Scheduler resources of one indent job; both grow with the attempt: a job killed over a
# limit is retried with more.
def indent_mem_mb(wildcards, attempt):
    return study_runs.indent_resources(STUDY)["mem_mb"] * attempt


def indent_runtime(wildcards, attempt):
    return study_runs.indent_resources(STUDY)["runtime"] * attempt


def batch_runtime(runs):
    """The runtime of an indent job of *runs* runs (minutes), growing with the attempt."""
    return (
        lambda wildcards, attempt: study_runs.indent_resources(STUDY, runs)["runtime"]
        * attempt
    )


def indent_priority(study, runs):
    """The priority of an indent job of *runs* runs of *study*: its expected cost, so that two
    cores start the longest jobs first (study.runs.naming.indent_priority)."""
    return lambda wildcards: study_runs.indent_priority(study, wildcards.combo, runs)


def batch_settings(study, seeds):
    """The params of an indent job of *seeds*: the JobSettings of each of its runs, in order."""
    return lambda wildcards: tuple(
        study_settings.job_settings(
            study, {**study_runs.parse_combo(wildcards.combo), "seed": seed}
        )
        for seed in seeds
    )


# The measured inputs (workflow/rules/measured.smk): scans by name, spectra by name, radii.
from roughcontact.study.runs import (
    measured as study_measured,
)  # noqa: E402  (numpy only; xarray, SurfaceTopography inside the jobs)

# (the entries as the resolved configuration holds them: the measured_surface job gets its own)
TOPOGRAPHY = {e["name"]: e for e in config["topography"]}
SPECTRUM = {e["name"]: e for e in config["spectrum"]}
RADII = [study_runs.format_value(r) for r in STUDY.radius]


def tiles_of(wildcards):
    """The run files of one scan: known once its surface file gives the number of tiles."""
    surface = checkpoints.measured_surface.get(topo=wildcards.topo).output.nc
    count = study_measured.tile_count(surface)
    return expand(
        rules.measured_indent.output.run,
        topo=wildcards.topo,
        radius=RADII,
        tile=range(count),
    )


def measured_tables(rule):
    """The CSV tables of *rule* (measured_spectrum, measured_scorecard) of every scan, in the
    order of topography (the summary rule's inputs; empty without scans)."""
    return lambda wildcards: expand(
        getattr(rules, rule).output.csv, topo=list(TOPOGRAPHY)
    )


def spectrum_outputs(rule, name):
    """The output *name* of *rule* (spectrum_merge, spectrum_figures) of every measured spectrum, in
    the order of spectrum (the summary rule's inputs; empty without spectra)."""
    return lambda wildcards: expand(
        getattr(getattr(rules, rule).output, name), spec=list(SPECTRUM)
    )


def measured_targets():
    """Every merged file, scorecard and figure of the measured inputs (empty without them)."""
    return (
        expand(rules.measured_figures.output.kf, topo=list(TOPOGRAPHY))
        + expand(rules.measured_scorecard.output.html, topo=list(TOPOGRAPHY))
        + expand(rules.spectrum_figures.output.kf, spec=list(SPECTRUM))
    )
