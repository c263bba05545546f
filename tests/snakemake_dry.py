"""Many real ``snakemake -n`` runs in little time, for the tests.

``python tests/snakemake_dry.py SNAKEFILE CONFIG_NAME DIR...`` imports
Snakemake (and what the workflow imports) once, then for every DIR forks a
child that changes into DIR and runs Snakemake's own command line,
``snakemake -s SNAKEFILE -n --configfile CONFIG_NAME``, exactly as
``python -m snakemake`` would, with its stdout and stderr in ``DIR/snakemake.out``
and its exit code in ``DIR/snakemake.rc``.  A fresh interpreter per run spends
most of its 3 s importing; a forked child starts with the imports done.

:func:`dry_run` is the test-side wrapper.
"""

from __future__ import annotations

import os
import subprocess
import sys
import traceback
from pathlib import Path

OUT, RC = "snakemake.out", "snakemake.rc"


def dry_run(snakefile: Path, config_name: str, dirs: list[Path], timeout: float = 300) -> list[tuple[int, str]]:
    """(exit code, stdout + stderr) of ``snakemake -n`` in each of *dirs*."""
    env = {**os.environ, "PYTHONPATH": str(Path(snakefile).parent / "src"), "OPENBLAS_NUM_THREADS": "1"}
    proc = subprocess.run([sys.executable, __file__, str(snakefile), config_name, *map(str, dirs)],
                          check=False, capture_output=True, text=True, timeout=timeout, env=env)
    if proc.returncode != 0:
        raise RuntimeError(f"snakemake_dry.py failed ({proc.returncode}):\n{proc.stdout}\n{proc.stderr}")
    return [(int((d / RC).read_text()), (d / OUT).read_text(errors="replace")) for d in map(Path, dirs)]


def _child(snakefile: str, config_name: str, directory: str) -> int:
    import snakemake.cli

    os.chdir(directory)
    fd = os.open(OUT, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    os.close(fd)
    try:
        snakemake.cli.main(["-s", snakefile, "-n", "--configfile", config_name])
    except SystemExit as exc:
        if exc.code is None or isinstance(exc.code, int):
            return exc.code or 0
        print(exc.code, file=sys.stderr)  # as the interpreter does for SystemExit("message")
        return 1
    except Exception:  # noqa: BLE001  (shown, as an uncaught exception would be)
        traceback.print_exc()
        return 1
    return 0


def main(argv: list[str]) -> int:
    snakefile, config_name, *dirs = argv
    import jsonschema  # noqa: F401  (imported once, before the children fork)
    import numpy  # noqa: F401
    import snakemake.api
    import snakemake.cli
    import snakemake.workflow  # noqa: F401
    import yaml  # noqa: F401

    import roughcontact.study.config.resolve  # noqa: F401
    import roughcontact.study.runs.naming  # noqa: F401
    import roughcontact.study.runs.jobs  # noqa: F401

    for directory in dirs:
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:
            code = 1
            try:
                code = _child(snakefile, config_name, directory)
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(code)
        _, status = os.waitpid(pid, 0)
        Path(directory, RC).write_text(str(os.waitstatus_to_exitcode(status)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
