"""What the subcommands of the command line share: the flags named by a configuration error, and
the solver's and the output's options, the output's check."""
from __future__ import annotations

from ..errors import ConfigError
from ..study.config.axes import AXES

#: config keys (:attr:`ConfigError.key`) -> the command-line flag of ``indent``, beside each
#: sweep axis's own (``'hurst[0]'`` -> ``--hurst``: :func:`indent_flags`)
FLAGS = {
    "seeds[0]": "--seed",
    "grid.n": "--n", "grid.length": "--length", "e_star": "--e-star", "solver.tol": "--tol",
    "solver.stiffness": "--stiffness", "solver.rel_step": "--rel-step", "solver.maxiter": "--maxiter",
    "forces.sphere.from": "--force-from", "forces.flat.from": "--force-from",
    "forces.sphere.to": "--force-to", "forces.flat.to": "--force-to",
    "forces.sphere.count": "--force-count", "forces.flat.count": "--force-count",
    "forces.sphere": "--force-from/--force-to", "forces.flat": "--force-from/--force-to",
}


def indent_flags() -> dict:
    """:data:`FLAGS` and every sweep axis's key -> flag (the registry, read when called)."""
    return {**{f"{a.name}[0]": a.flag for a in AXES.values()}, **FLAGS}


def add_solver_options(parser, *, defaults: str) -> None:
    """The contact solver's options, shared by ``indent`` and ``measured`` (*defaults*: where an
    option not given comes from)."""
    parser.add_argument("--tol", type=float, default=None, help=f"solver tolerance (default: {defaults})")
    parser.add_argument("--stiffness", choices=["punch", "difference"], default=None, help="stiffness method")
    parser.add_argument("--rel-step", type=float, default=None, help="relative step of --stiffness difference")
    parser.add_argument("--maxiter", type=int, default=None, help="most solver iterations per load")


def add_output_options(parser) -> None:
    """The output file and the log file, shared by ``indent`` and ``measured``."""
    parser.add_argument("-o", "--output", required=True,
                        help="NetCDF file to write (atomically); a path, not - (standard output)")
    parser.add_argument("--log", default=None, help="also append progress lines to this file")


def flagged(err: ConfigError, flags: dict | None = None) -> str:
    """The one line of a config error in the command line's words: the key it is about
    (:attr:`ConfigError.key`) named by its flag, e.g. ``--hurst (hurst[0]) = 3 is not allowed``."""
    flags = indent_flags() if flags is None else flags
    message = str(err)
    flag = flags.get(err.key)
    if flag is None:
        return message
    return message.replace(f"config key '{err.key}'", f"{flag} ({err.key})", 1)


def output_error(output: str) -> str | None:
    """Why ``-o`` *output* cannot be written, in one line (``None``: it can). ``-`` is refused: a
    NetCDF file is binary and written by its path (atomically, by renaming a temporary file
    beside it), so standard output would be no use; without this, a file named ``-`` appeared."""
    if output == "-":
        return ("-o -: a NetCDF file cannot be written to standard output; "
                "give a file path, e.g. -o run.nc")
    return None
