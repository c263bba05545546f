"""Snakemake's directory locks left by a hard kill: found and removed, so that the same command again
resumes the study.

Snakemake locks the files of a run in ``.snakemake/locks/`` of its working directory and removes the
locks when it ends; a SIGKILL (or a lost terminal, a power loss) leaves them behind, and every later
run stops with ``LockException`` until ``snakemake --unlock``. The lock files name no process, so
:func:`stale_locks` asks the operating system instead: the locks are stale when no Snakemake
process other than the calling one has this directory as its working directory (Linux: ``/proc``).
Elsewhere, or where ``/proc`` cannot be read, every lock is kept (Snakemake's own message then says
what to do). A Snakemake process on another host sharing the directory over a network file system
cannot be seen: such a setup keeps its locks by ``ROUGHCONTACT_KEEP_LOCKS=1``.

The workflow calls :func:`clear_stale_locks` while Snakemake's main process reads the Snakefile
(``workflow/rules/indent.smk``; never in a job's Snakemake, which on a cluster runs on another
host), before Snakemake takes its own locks; with the default profile's ``rerun-incomplete: true`` the jobs
the kill interrupted are recomputed (their outputs are written atomically: nothing half-written is kept).
"""
from __future__ import annotations

import os
from pathlib import Path

__all__ = ["KEEP_LOCKS", "clear_stale_locks", "snakemake_processes", "stale_locks"]

#: environment variable: set to 1 to keep every lock (a directory shared by several hosts)
KEEP_LOCKS = "ROUGHCONTACT_KEEP_LOCKS"


def _is_snakemake(cmdline: list[str]) -> bool:
    """Whether a process's argument vector is a Snakemake process (``snakemake …`` or ``python -m snakemake …``)."""
    for i, arg in enumerate(cmdline[:3]):
        if os.path.basename(arg) == "snakemake" or (arg == "-m" and cmdline[i + 1:i + 2] == ["snakemake"]):
            return True
    return False


def snakemake_processes(directory) -> list[int] | None:
    """The ids of the Snakemake processes other than this one whose working directory is *directory*;
    ``None`` where that cannot be known (no ``/proc``)."""
    proc = Path("/proc")
    if not (proc / "self" / "cwd").exists():
        return None
    target = os.path.realpath(directory)
    me = os.getpid()
    found = []
    for entry in proc.iterdir():
        if not entry.name.isdigit() or int(entry.name) == me:
            continue
        try:
            cmdline = (entry / "cmdline").read_bytes().decode(errors="replace").split("\0")
        except OSError:   # ended meanwhile
            continue
        if not _is_snakemake(cmdline):
            continue
        try:
            cwd = os.readlink(entry / "cwd")
        except FileNotFoundError:   # ended meanwhile
            continue
        except OSError:   # another user's Snakemake, its directory unreadable: keep the locks
            return None
        if os.path.realpath(cwd) == target:
            found.append(int(entry.name))
    return found


def stale_locks(directory=".") -> list[Path]:
    """The lock files in ``.snakemake/locks`` of *directory* that no running Snakemake process holds
    (module docstring); empty when any may hold them, or when that cannot be known."""
    locks = sorted((Path(directory) / ".snakemake" / "locks").glob("*.lock"))
    if not locks or os.environ.get(KEEP_LOCKS, "") not in ("", "0"):
        return []
    others = snakemake_processes(directory)
    return locks if others == [] else []


def clear_stale_locks(directory=".") -> list[str]:
    """Remove :func:`stale_locks` of *directory*; the removed files' names."""
    removed = []
    for path in stale_locks(directory):
        try:
            path.unlink()
        except FileNotFoundError:
            continue
        removed.append(str(path))
    return removed
