"""End-to-end benchmark: a sweep through ``snakemake --cores 2`` in a fresh directory, against
the serial in-process solve of the same load paths, on the same machine in the same run.

First solves every run of the sweep one after another in one Python process with one BLAS and
OpenMP thread, as Snakemake runs an indent job (:func:`roughcontact.study.runs.indent.compute_run`:
surface, warm-started load path, stiffness at every load; no file written), then runs the whole workflow (all indent jobs, merge, fits,
figures, landing page) in a new directory, then the report. Prints a table of both wall times
and their ratio (the issue's target: workflow ≤ 0.6× the serial solve on 2 cores), when the last
run file was written, and the ``indent`` jobs from Snakemake's own per-job benchmark files
(``results/benchmarks/indent/*.tsv``: wall seconds and peak resident memory ``max_rss``; one file
per job, a job being ``jobs.batch`` runs), split by surface kind (sphere or flat).

Timings on a shared machine are only comparable within one run: the load average before and
after is printed, and the CPU time (user + system) of the serial solve and of the workflow with
all its jobs beside the wall times (on a loaded machine the workflow's several processes get a
larger share of the cores than the one serial process, so its wall-time ratio flatters it).

Usage::

    python benchmarks/pipeline.py [--configfile config.yaml] [--cores 2] [--keep DIR] [--no-serial] [--timeline]
"""

from __future__ import annotations

import argparse
import datetime
import math
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import machine_lines  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
#: the folder of the per-process tracer of ``--timeline``
TIMELINE = Path(__file__).resolve().parent / "timeline"


def snakemake(workdir: Path, configfile: Path, *args: str, timeline: Path | None = None) -> tuple[float, float]:
    """Run snakemake on the checkout's Snakefile in ``workdir``; return its wall time and the CPU
    time (user + system) of it and all its jobs (s). *timeline*: a file to which every Python
    process of the run appends its line (``benchmarks/timeline/sitecustomize.py``)."""
    command = [sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(workdir),
               "--configfile", str(configfile), *args]
    tracer = () if timeline is None else (str(TIMELINE),)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in (*tracer, str(REPO / "src"),
                                                                   os.environ.get("PYTHONPATH")) if p)}
    if timeline is not None:
        env["RC_TIMELINE"] = str(timeline)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    tick = time.perf_counter()
    result = subprocess.run(command, cwd=workdir, capture_output=True, text=True, env=env)
    seconds = time.perf_counter() - tick
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit(f"snakemake failed ({' '.join(args)}):\n{result.stderr[-3000:]}")
    return seconds, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


#: what Snakemake sets for a job of one thread (the indent jobs): one BLAS and OpenMP thread
ONE_THREAD = {name: "1" for name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                                     "VECLIB_MAXIMUM_THREADS", "NUMEXPR_NUM_THREADS")}


def serial_solve(configfile: Path) -> tuple[float, float, dict]:
    """Wall and CPU seconds of solving every run of the sweep one after another in one new Python
    process with one thread, as an indent job has (imports done before the clock starts), and
    the study's size."""
    import json

    env = {**os.environ, **ONE_THREAD,
           "PYTHONPATH": os.pathsep.join(p for p in (str(REPO / "src"), os.environ.get("PYTHONPATH")) if p)}
    result = subprocess.run([sys.executable, __file__, "--serial-only", "--configfile", str(configfile)],
                            capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit(f"the serial solve failed:\n{result.stderr[-3000:]}")
    out = json.loads(result.stdout.strip().splitlines()[-1])
    return out["seconds"], out["cpu"], out["size"]


def _serial_solve_here(configfile: Path) -> dict:
    """The serial solve in this process (:func:`serial_solve`)."""
    sys.path.insert(0, str(REPO / "src"))
    from roughcontact.study.config.resolve import load_config, study_settings
    from roughcontact.study.runs import jobs, naming
    from roughcontact.study.runs.indent import compute_run

    study = study_settings(load_config(configfile), base_dir=configfile.parent)
    settings = [jobs.job_settings(study, run) for run in naming.runs(study)]
    if study.grid.coarse is not None and any(kind == "sphere" for kind in (s.kind for s in settings)):
        coarse = study.coarse_study()   # the grid error's companion runs (grid.coarse), as the workflow runs them
        settings += [jobs.job_settings(coarse, run) for run in naming.runs(coarse)]
    tick, cpu = time.perf_counter(), time.process_time()
    for job in settings:
        compute_run(job)
    seconds, cpu = time.perf_counter() - tick, time.process_time() - cpu
    size = {"runs": len(settings), "n": study.grid.n if study.grid.coarse is None
            else f"{study.grid.n}² and {study.grid.coarse}",
            "loads": "/".join(f"{kind} {study.forces[kind].count}" for kind in sorted({s.kind for s in settings})),
            "batch": study.jobs.batch}
    return {"seconds": seconds, "cpu": cpu, "size": size}


def job_table(workdir: Path) -> pd.DataFrame:
    """One row per indent job: kind (sphere/flat), wall seconds, peak RSS (MB)."""
    rows = []
    for path in sorted((workdir / "results/benchmarks/indent").glob("*.tsv")):
        record = pd.read_csv(path, sep="\t").iloc[0]
        radius = path.name.split("_R", 1)[1].split("_h", 1)[0]
        rows.append({"kind": "flat" if radius == "inf" else "sphere",
                     "seconds": float(record["s"]), "max_rss_mb": float(record["max_rss"])})
    if not rows:
        sys.exit(f"no per-job benchmark files under {workdir / 'results/benchmarks/indent'}")
    return pd.DataFrame(rows)


def companion_costs(workdir: Path) -> list[str]:
    """One line per companion of the study (``indent_coarse``: grid.coarse; ``indent_fine``: the fine
    reference of grid.fine): its jobs' summed wall and CPU seconds (Snakemake's benchmark files)
    against the study's own indent jobs', the same run."""
    def summed(rule):
        files = sorted((workdir / "results/benchmarks" / rule).glob("*.tsv"))
        records = [pd.read_csv(path, sep="\t").iloc[0] for path in files]
        return len(files), sum(float(r["s"]) for r in records), sum(float(r["cpu_time"]) for r in records)

    _, study_s, study_cpu = summed("indent")
    out = []
    for rule in ("indent_coarse", "indent_fine"):
        jobs, seconds, cpu = summed(rule)
        if jobs and study_s > 0 and study_cpu > 0:
            out.append(f"{rule}: {jobs} jobs, summed wall {seconds:.1f} s = {seconds / study_s:.2f} of the study's "
                       f"indent jobs ({study_s:.1f} s), CPU {cpu:.1f} s = {cpu / study_cpu:.2f} ({study_cpu:.1f} s)")
    return out


def timeline_table(path: Path, start: float, cores: int) -> list[str]:
    """The lines of ``--timeline``: when Snakemake started its first job, every job (its script,
    start and end after the workflow's start, CPU s), how long the cores idled during the runs,
    and Snakemake's own start-up, CPU and end."""
    rows = []
    for line in path.read_text().splitlines():
        pid, began, _site, ended, cpu, name = line.split("\t")
        script = name.split()[0] if name else ""
        rows.append({"script": script.rsplit(".", 2)[-2] if script.count(".") >= 2 else script.removesuffix(".py"),
                     "start": float(began) - start, "end": float(ended) - start, "cpu": float(cpu)})
    jobs = sorted((r for r in rows if r["script"] != "__main__"), key=lambda r: r["start"])
    main_rows = [r for r in rows if r["script"] == "__main__"]
    if not jobs or not main_rows:
        return [f"timeline: no jobs recorded in {path}"]
    smk = main_rows[0]
    indent = [r for r in jobs if r["script"] == "indent"]
    runs_end = max(r["end"] for r in indent)
    first = jobs[0]["start"]
    busy = sum(min(r["end"], runs_end) - max(r["start"], first) for r in jobs if r["start"] < runs_end)
    out = [f"timeline (s after snakemake started; {path}):",
           f"  snakemake start-up (parse, DAG) until its first job: {first:.2f}",
           f"  runs: {len(indent)} indent jobs, the last one ends at {runs_end:.2f}; the {cores} cores idle "
           f"{cores * (runs_end - first) - busy:.2f} core-s between the first job's start and then",
           f"  after the last job (snakemake ends): {smk['end'] - max(r['end'] for r in jobs):.2f}; "
           f"snakemake's own CPU {smk['cpu']:.2f}",
           f"  CPU of the jobs: indent {sum(r['cpu'] for r in indent):.1f} "
           f"(median job {sorted(r['cpu'] for r in indent)[len(indent) // 2]:.2f}), "
           f"the others {sum(r['cpu'] for r in jobs if r['script'] != 'indent'):.1f}",
           f"  {'job':>12} {'start':>7} {'end':>7} {'wall':>6} {'CPU':>6}"]
    out += [f"  {r['script']:>12} {r['start']:7.2f} {r['end']:7.2f} {r['end'] - r['start']:6.2f} {r['cpu']:6.2f}"
            for r in jobs]
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--configfile", type=Path, default=REPO / "config.yaml",
                        help="sweep to run (default config.yaml, the default run)")
    parser.add_argument("--cores", type=int, default=2, help="snakemake --cores (default 2)")
    parser.add_argument("--keep", type=Path, default=None,
                        help="run in this (new) directory and keep it; default: a temporary one")
    parser.add_argument("--no-serial", action="store_true", help="skip the serial in-process solve")
    parser.add_argument("--batch", type=int, default=None,
                        help="run the workflow with this jobs.batch (default: the config's; 1 = a job per run)")
    parser.add_argument("--timeline", action="store_true",
                        help="print every job's start, end and CPU time, Snakemake's start-up and the cores' idle "
                             "time (a tracer on PYTHONPATH: benchmarks/timeline/sitecustomize.py)")
    parser.add_argument("--serial-only", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    configfile = args.configfile.resolve()
    if args.serial_only:   # the child of serial_solve: one JSON line
        import json

        print(json.dumps(_serial_solve_here(configfile)))
        return 0

    for line in machine_lines([]):
        print(line)
    started = datetime.datetime.now(datetime.timezone.utc)
    load_before = os.getloadavg()
    serial, serial_cpu, size = (math.nan, math.nan, None) if args.no_serial else serial_solve(configfile)
    workdir = args.keep.resolve() if args.keep else Path(tempfile.mkdtemp(prefix="rc-pipeline-"))
    workdir.mkdir(parents=True, exist_ok=True)
    try:
        tick = time.time()
        batch = () if args.batch is None else ("--config", f"jobs={{batch: {args.batch}}}")
        trace = workdir / "timeline.tsv" if args.timeline else None
        run_seconds, run_cpu = snakemake(workdir, configfile, "--cores", str(args.cores), *batch, timeline=trace)
        timeline = [] if trace is None else timeline_table(trace, tick, args.cores)
        runs_done = max(p.stat().st_mtime for p in (workdir / "results/runs").rglob("*.nc")) - tick
        report_seconds, _ = snakemake(workdir, configfile, "--report", "results/report.html", *batch)
        jobs = job_table(workdir)
        coarse_jobs = len(list((workdir / "results/benchmarks/indent_coarse").glob("*.tsv")))
        companions = companion_costs(workdir)
    finally:
        if args.keep is None:
            shutil.rmtree(workdir, ignore_errors=True)
    load_after = os.getloadavg()

    name = configfile.relative_to(REPO) if configfile.is_relative_to(REPO) else configfile
    print(f"sweep: {name}, snakemake --cores {args.cores}"
          f"{'' if args.batch is None else f' --config jobs={{batch: {args.batch}}}'}, fresh directory; started {started:%Y-%m-%d %H:%M} UTC; "
          f"load average (1, 5, 15 min) before {', '.join(f'{x:.1f}' for x in load_before)}, "
          f"after {', '.join(f'{x:.1f}' for x in load_after)}")
    if size is not None:
        print(f"problem: {size['runs']} runs on {size['n']}² (loads: {size['loads']}), {len(jobs)} indent jobs"
              + (f" and {coarse_jobs} indent_coarse jobs (the grid error's companion runs)" if coarse_jobs else ""))
    header = f"{'':>38} {'wall s':>8} {'/ serial':>9} {'CPU s':>8} {'/ serial':>9}"
    print(header)
    print("-" * len(header))
    for label, seconds, cpu in (("serial in-process solve (1 core)", serial, serial_cpu),
                                (f"snakemake --cores {args.cores}: last run file", runs_done, math.nan),
                                (f"snakemake --cores {args.cores}: whole workflow", run_seconds, run_cpu)):
        print(f"{label:>38} {seconds:8.1f} {seconds / serial:9.2f} {cpu:8.1f} {cpu / serial_cpu:9.2f}")
    print(f"{'after the last run file (merge ... summary)':>38} {run_seconds - runs_done:8.1f} "
          f"{(run_seconds - runs_done) / serial:9.2f}")
    print("-" * len(header))
    print(f"(CPU: user + system of the process, or of snakemake and all its jobs; on {args.cores} idle cores the "
          f"workflow's wall time is at least its CPU time / {args.cores})")
    header = (f"{'kind':>7} {'jobs':>5} | {'job s median':>12} {'max':>7} {'sum':>8} | "
              f"{'peak RSS MB median':>18} {'max':>7}")
    print(header)
    print("-" * len(header))
    for kind, group in [*jobs.groupby("kind"), ("all", jobs)]:
        print(f"{kind:>7} {len(group):5d} | {group.seconds.median():12.2f} {group.seconds.max():7.2f} "
              f"{group.seconds.sum():8.1f} | {group.max_rss_mb.median():18.0f} {group.max_rss_mb.max():7.0f}")
    print("-" * len(header))
    for line in companions:
        print(line)
    for line in timeline:
        print(line)
    total = run_seconds + report_seconds
    print(f"wall time: workflow {run_seconds:.1f} s + report {report_seconds:.1f} s = {total:.1f} s "
          f"({math.floor(total / 60):.0f} min {total % 60:.0f} s); "
          f"sum of indent job times / workflow wall time = {jobs.seconds.sum() / run_seconds:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
