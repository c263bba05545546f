"""Per-process timeline of a workflow run (``python benchmarks/pipeline.py --timeline``).

Put on ``PYTHONPATH`` with ``RC_TIMELINE`` set to a file, every Python process that starts (Snakemake
and each job's script) appends one line there when it exits: its pid, the wall clock (s since the
epoch) at which the kernel started it, at which this module ran (after the interpreter's own
start-up), at which it exited, its CPU time (user + system, s) and its first arguments. Without
``RC_TIMELINE`` it does nothing."""
import os
import sys
import time

_FILE = os.environ.get("RC_TIMELINE")
if _FILE:
    import atexit

    def _started() -> float:
        """The process's start (wall clock): its start time in clock ticks after boot."""
        with open("/proc/self/stat") as f:
            ticks = int(f.read().rsplit(")", 1)[1].split()[19])
        with open("/proc/uptime") as f:
            uptime = float(f.read().split()[0])
        return time.time() - uptime + ticks / os.sysconf("SC_CLK_TCK")

    _START, _SITE = _started(), time.time()

    def _record() -> None:
        times = os.times()
        name = " ".join(os.path.basename(a) for a in sys.argv[:3])
        with open(_FILE, "a") as f:
            f.write(f"{os.getpid()}\t{_START:.3f}\t{_SITE:.3f}\t{time.time():.3f}\t"
                    f"{times.user + times.system:.3f}\t{name}\n")

    atexit.register(_record)
