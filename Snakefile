# roughcontact parameter study (Pohrt & Popov 2013): `snakemake --cores 2`
# Sweep: config.yaml (or --configfile presets/*.yaml); output: results/ (a --configfile's study:
# studies/<its stem>/results/); report: `snakemake --report results/report.html`.  See README.md.
import sys
from pathlib import Path

from snakemake.utils import min_version

min_version("9.0")


sys.path.insert(0, str(Path(workflow.basedir) / "src"))
from roughcontact.study.files import directory as study_directory

# One study, one directory: a --configfile run in the checkout without --directory runs in
# studies/<the config file's stem>/ (snakemake --cores 2 --configfile presets/paper.yaml writes
# studies/paper/results/), beside the default study of config.yaml (results/), never over it; with
# --directory DIR, in DIR. A directory holds one study: common.smk refuses another's there.
STUDY_DIRECTORY = (
    study_directory.default_directory(workflow.overwrite_configfiles, workflow.basedir)
    if workflow.overwrite_workdir is None
    and Path.cwd().resolve() == Path(workflow.basedir).resolve()
    else None
)
if STUDY_DIRECTORY is not None:
    if workflow.is_main_process:
        print(
            f"This study runs in {STUDY_DIRECTORY}/ (its own directory; --directory DIR for another)",
            file=sys.stderr,
        )

    workdir: STUDY_DIRECTORY


# One YAML, one study: a file given with --configfile is the whole sweep (every key it does not
# name takes the schema's default, src/roughcontact/study/config/config.schema.yaml), wherever the
# study runs (--directory or not); config.yaml is the sweep only when no --configfile is given
# (then --config KEY=VALUE edits it).
# config.yaml is read by the package's loader first: an empty or broken file stops in one line naming
# the file (and the line of a YAML error), not in Snakemake's two naming neither. A file given with
# --configfile Snakemake reads itself, while parsing its command line, before this file runs
# (docs/guide/pipeline.md; `roughcontact check-config FILE` gives the line).
if not workflow.overwrite_configfiles:
    if Path("config.yaml").is_file():
        from roughcontact.errors import ConfigError
        from roughcontact.study.config.resolve import error_line, load_config

        try:
            # named as given in the checkout, by its whole path in another directory (--directory)
            load_config(
                "config.yaml"
                if Path.cwd() == Path(workflow.basedir)
                else Path("config.yaml").absolute()
            )
        except ConfigError as err:
            raise SystemExit(error_line(err))

    configfile: "config.yaml"


include: "workflow/rules/common.smk"


report: "workflow/report/workflow.rst"


include: "workflow/rules/indent.smk"
include: "workflow/rules/analysis.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/measured.smk"
include: "workflow/rules/adhesion.smk"
include: "workflow/rules/stickiness.smk"
include: "workflow/rules/tangential.smk"
include: "workflow/rules/histograms.smk"
include: "workflow/rules/area.smk"


# rules of your own: every file of workflow/rules/extra/, by name (docs/guide/package.md, "Adding a rule")
EXTRA_RULES = Path(workflow.basedir, "workflow", "rules", "extra")
for extra_rules in sorted(EXTRA_RULES.glob("*.smk")):

    include: extra_rules


# Snakemake (9.x) re-checks its job rate limit (--max-jobs-per-timespan, 100/1s by default) with a
# one-second threading.Timer after every scheduling step, and Python waits for the last one at exit:
# 1 s after the last job on every run (benchmarks/RESULTS.md, section 9). The workflow done, they
# have nothing left to wake.
onsuccess:
    import threading

    for timer in threading.enumerate():
        if isinstance(timer, threading.Timer):
            timer.cancel()


localrules:
    all,
    model_curves,
    merge,
    crossover,
    exponents,
    claims,
    models,
    area,
    figures,
    summary,
    merge_coarse,
    grid_error,
    merge_fine,
    fine_reference,
    adhesion,
    adhesion_figures,
    stickiness,
    stickiness_figures,
    tangential,
    tangential_figures,
    partial_slip_figures,
    histograms_figure,
    measured_surface,
    measured_merge,
    measured_spectrum,
    measured_scorecard,
    spectrum_merge,
    measured_figures,
    spectrum_figures,


rule all:
    default_target: True
    input:
        # the generated surfaces' study (none when hurst is empty: measured inputs only)
        (
            [
                rules.merge.output,
                rules.crossover.output,
                rules.exponents.output,
                rules.claims.output,
                rules.models.output,
                rules.area.output,
                rules.figures.output,
                rules.summary.output,
            ]
            + ([rules.fine_reference.output] if FINE is not None else [])
            if STUDY.generated
            else []
        ),
        # a sweep of measured scans or spectra only: its landing page too
        (
            [rules.summary.output]
            if not STUDY.generated and (TOPOGRAPHY or SPECTRUM)
            else []
        ),
        # the adhesive runs' pull-off and figures (none without work_of_adhesion > 0)
        (
            [rules.adhesion.output, rules.adhesion_figures.output]
            if ADHESIVE_RUNS
            else []
        ),
        # Pastewka & Robbins' stickiness (none without the config's stickiness section)
        (
            [rules.stickiness.output, rules.stickiness_figures.output]
            if STICKINESS is not None
            else []
        ),
        # the tangential problem (none without poisson; partial slip with friction > 0)
        (
            [rules.tangential.output, rules.tangential_figures.output]
            if TANGENTIAL
            else []
        ),
        ([rules.partial_slip_figures.output] if PARTIAL_SLIP else []),
        # the pressure and gap histograms of one load (none without fields.histograms.at)
        (
            [rules.histograms_figure.output]
            if STUDY.generated and STUDY.fields.histograms.at
            else []
        ),
        measured_targets(),
