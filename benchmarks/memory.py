"""Peak memory and time of surface generation: ``self_affine`` and ``rough_sphere`` per grid size.

Each (n, function) runs in a fresh interpreter, twice: once plain, for the wall time and the
growth of the peak resident set size over the RSS before the call (``ru_maxrss``; this includes
pocketfft's own line buffers, which tracemalloc does not see), and once under tracemalloc, for
the peak of the Python and numpy allocations during the call. Both peaks are given in bytes
per grid cell; the returned array itself is 8 B/cell.

Usage::

    python benchmarks/memory.py [--n 1025 2049] [--large]

``--large`` adds n = 4097 (about 5 s and 0.4 GB per call on 2 vCPUs).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import HURST, H_RMS, LENGTH, RADIUS, machine_lines  # noqa: E402

#: Run in a child interpreter; prints one JSON object.
CHILD = """
import json, resource, sys, time, tracemalloc
from roughcontact import surfaces
n, name = int(sys.argv[1]), sys.argv[2]
kwargs = dict(hurst={hurst}, h_rms={h_rms}, length={length}, seed=0)
if name == "rough_sphere":
    kwargs["radius"] = {radius}
func = getattr(surfaces, name)
func(64, **kwargs)


def rss_kib():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * resource.getpagesize() / 1024


before = rss_kib()
tick = time.perf_counter()
z = func(n, **kwargs)
seconds = time.perf_counter() - tick
rss_growth = (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) * 1024
del z
tracemalloc.start()
z = func(n, **kwargs)
peak = tracemalloc.get_traced_memory()[1]
tracemalloc.stop()
print(json.dumps(dict(seconds=seconds, rss_growth=rss_growth, traced_peak=peak)))
""".format(hurst=HURST, h_rms=H_RMS, length=LENGTH, radius=RADIUS)


def measure(n: int, name: str) -> dict:
    """Time and peaks of one call of ``surfaces.<name>`` on an ``n × n`` grid (fresh process)."""
    out = subprocess.run([sys.executable, "-c", CHILD, str(n), name], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[1025, 2049],
                        help="grid sizes (default 1025 2049)")
    parser.add_argument("--large", action="store_true", help="also n = 4097")
    args = parser.parse_args(argv)
    sizes = args.n + ([4097] if args.large and 4097 not in args.n else [])

    for line in machine_lines([]):
        print(line)
    print(f"{'n':>5}  {'function':<13}  {'traced peak B/cell':>18}  {'RSS growth B/cell':>17}"
          f"  {'seconds':>7}")
    for n in sizes:
        for name in ("self_affine", "rough_sphere"):
            m = measure(n, name)
            cells = n * n
            print(f"{n:>5}  {name:<13}  {m['traced_peak'] / cells:>18.1f}  "
                  f"{m['rss_growth'] / cells:>17.1f}  {m['seconds']:>7.2f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
