"""The results directory of one study run, read: the one study-directory reader.

A study run in a directory (``snakemake --directory DIR``, or the checkout itself) writes its
results under ``DIR/results/``. :class:`StudyDirectory` names every file that something outside
the workflow reads back (the grid-convergence and calibration tables, the grid error of two
studies, the docs' results pages), opens it, and fails in one line naming the file and the rule
that writes it. The paths are the workflow's rule outputs (``workflow/rules/*.smk``), written
here once for the readers; a test holds the two to each other.

One study, one directory: a study directory records the config file(s) its study was made from
(:data:`RECORD`, written when its first job starts); :func:`check_study` refuses, in one line
naming both, to run another configuration's study there, so a second study never overwrites the
first's run files and tables. :func:`default_directory` is where the workflow puts a study of a
``--configfile`` run in the checkout without ``--directory``: ``studies/<config file's stem>``.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

from ...errors import ConfigError, MergeError
from .io import read_groups

__all__ = ["StudyDirectory", "FILES", "RUN_DIRECTORIES", "RECORD", "STUDIES", "check_study", "config_names",
           "default_directory", "record_study"]

#: the study's result files read back: name -> (path under the study directory, the rule writing it)
FILES = {
    "stiffness": ("results/stiffness.nc", "merge"),
    "ensemble": ("results/ensemble.nc", "merge"),
    "coarse_stiffness": ("results/merge_coarse/stiffness.nc", "merge_coarse"),
    "zeta": ("results/zeta.csv", "crossover"),
    "zeta_fit": ("results/zeta.nc", "crossover"),
    "crossover": ("results/crossover.csv", "crossover"),
    "exponents": ("results/exponents.csv", "exponents"),
    "grid_error": ("results/grid_error.csv", "grid_error"),
    "fine_stiffness": ("results/merge_fine/stiffness.nc", "merge_fine"),
    "fine_reference": ("results/fine_reference.csv", "fine_reference"),
    "claims": ("results/claims.csv", "claims"),
    "models": ("results/models.csv", "models"),
    "models_fit": ("results/models.nc", "models"),
    "pull_off": ("results/adhesion/pull_off.csv", "adhesion"),
    "adhesion": ("results/adhesion/adhesion.nc", "adhesion"),
    "stickiness": ("results/stickiness/stickiness.csv", "stickiness"),
    "stickiness_fit": ("results/stickiness/stickiness.nc", "stickiness"),
    "summary": ("results/summary.html", "summary"),
    "tangential": ("results/tangential/tangential.csv", "tangential"),
    "tangential_fit": ("results/tangential/tangential.nc", "tangential"),
}

#: the run files of each run rule: rule -> directory under the study directory
RUN_DIRECTORIES = {
    "indent": "results/runs",
    "indent_coarse": "results/indent_coarse",
    "indent_fine": "results/indent_fine",
    "stickiness_run": "results/stickiness_run",
}


class StudyDirectory:
    """The results of the study run in *root* (module docstring).

    Parameters
    ----------
    root : str or os.PathLike
        The directory the study ran in (its ``results/`` below it).
    """

    def __init__(self, root):
        self.root = Path(root)

    def __repr__(self) -> str:
        return f"StudyDirectory({str(self.root)!r})"

    def path(self, name: str) -> Path:
        """The path of the result *name* (a key of :data:`FILES`); :class:`MergeError` naming the
        file and its rule where the study has not written it."""
        if name not in FILES:
            raise KeyError(f"no result file {name!r}; known: {', '.join(FILES)}")
        relative, rule = FILES[name]
        path = self.root / relative
        if not path.is_file():
            raise MergeError(f"{path}: missing; the rule {rule!r} writes it "
                             f"(snakemake --directory {self.root} ... {relative})")
        return path

    def has(self, name: str) -> bool:
        """Whether the study has written the result *name* (a key of :data:`FILES`)."""
        return (self.root / FILES[name][0]).is_file()

    def attrs(self, name: str = "stiffness") -> dict:
        """The global attributes of the NetCDF result *name* (its provenance)."""
        import xarray as xr

        with xr.open_datatree(self.path(name), engine="netcdf4") as tree:
            return dict(tree.attrs)

    def configuration(self) -> dict:
        """The resolved configuration the study's merged runs record (``stiffness.nc``)."""
        return json.loads(self.attrs("stiffness")["config"])

    def groups(self, name: str = "stiffness") -> dict:
        """``{kind: Dataset}`` of a merged file (:func:`roughcontact.study.files.io.read_groups`)."""
        return read_groups(self.path(name))

    def dataset(self, name: str):
        """The NetCDF result *name* as one Dataset, loaded in memory."""
        import xarray as xr

        with xr.open_dataset(self.path(name), engine="netcdf4") as ds:
            return ds.load()

    def table(self, name: str):
        """The CSV result *name* as a DataFrame."""
        import pandas as pd

        return pd.read_csv(self.path(name))

    def run_files(self, rule: str = "indent") -> list[Path]:
        """The run files the run rule *rule* (a key of :data:`RUN_DIRECTORIES`) wrote, sorted."""
        return sorted((self.root / RUN_DIRECTORIES[rule]).rglob("*.nc"))

    def benchmarks(self, rule: str = "indent") -> list[dict]:
        """Snakemake's benchmark rows (wall seconds ``s``, peak memory ``max_rss`` in MB, ...) of the
        jobs of *rule*, one per job, sorted by file name."""
        import pandas as pd

        files = sorted((self.root / "results" / "benchmarks" / rule).glob("*.tsv"))
        return [pd.read_csv(path, sep="\t").iloc[0].to_dict() for path in files]


#: the study directory's record of the config file(s) its study was made from, one name a line
#: (:func:`config_names`); written when the study's first job starts (:func:`record_study`)
RECORD = "results/configfile.txt"

#: where the study of a ``--configfile`` run in the checkout without ``--directory`` goes:
#: ``studies/<stem>`` under the checkout (:func:`default_directory`)
STUDIES = "studies"


def _display(path, checkout) -> str:
    """*path* relative to the checkout where it lies in it (POSIX), else absolute."""
    path, checkout = Path(os.path.abspath(path)), Path(os.path.abspath(checkout))
    try:
        return path.relative_to(checkout).as_posix() or "."
    except ValueError:
        return str(path)


def config_names(configfiles, checkout) -> list[str]:
    """The names of the config files of a study (Snakemake's ``workflow.configfiles``, relative
    to the current directory or absolute): relative to the checkout where they lie in it
    (``config.yaml``, ``presets/tiny.yaml``), else their absolute paths. What :data:`RECORD`
    holds and :func:`check_study` compares."""
    return [_display(Path(f), checkout) for f in configfiles]


def default_directory(configfiles, checkout) -> str | None:
    """The study directory of a run in the checkout without ``--directory``:
    ``studies/<stem>`` (the stems of several config files joined by ``+``) for config files other
    than the checkout's own ``config.yaml``; ``None`` for that one (or none given): the checkout."""
    names = config_names(configfiles, checkout)
    if not names or names == ["config.yaml"]:
        return None
    return f"{STUDIES}/{'+'.join(Path(name).stem for name in names)}"


def _suggestion(names, root, checkout, shown_from) -> str:
    """A ``--directory`` for the study of *names* that is not *root*: ``studies/<stem>`` of the
    checkout (``studies/<parent>-<stem>`` where that is *root*), relative to *shown_from* where it
    lies there, else absolute."""
    target = Path(checkout) / STUDIES / "+".join(Path(name).stem for name in names)
    if target.resolve() == Path(root).resolve():   # two config files of one stem: add the parent's name
        target = Path(checkout) / STUDIES / "+".join(
            f"{Path(name).parent.name or 'checkout'}-{Path(name).stem}" for name in names)
    return _shown(target, shown_from)


def _shown(path, shown_from) -> str:
    """*path* as a message shows it: relative to *shown_from* where given and it lies there, else absolute."""
    return _display(path, shown_from) if shown_from is not None else os.path.abspath(path)


def _recorded(root) -> list[str] | None:
    path = Path(root) / RECORD
    if not path.is_file():
        return None
    return [line.strip() for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def check_study(root, names, *, checkout, shown_from=None, runs=None) -> None:
    """Refuse to run the study of the config files *names* (:func:`config_names`) in the study
    directory *root* where another study's files are: :class:`~roughcontact.errors.ConfigError`,
    one line naming both studies' config files, the ``--directory`` to use and how to replace.
    Its paths are shown relative to *shown_from* (the directory the command was typed in, where
    known: the checkout), else absolute; the config files by their names.

    *root* is that study's where its :data:`RECORD` names *names*, or where it has no record and no
    ``results/`` (a new study). A ``results/`` without a record (made before there were records)
    is taken for this study's unless one of its run files at the paths of this study was computed
    with other settings: *runs*, a callable giving ``{path under root: its job record}`` (the
    ``config`` attribute its run file must have: ``JobSettings.record()``)
    (``None``: no such check; the checkout's own ``config.yaml`` needs none, its ``results/``
    was always that study's).
    """
    if not names:
        return
    root = Path(root)
    here = _shown(root / "results", shown_from) + "/"
    recorded = _recorded(root)
    if recorded is not None:
        if recorded == list(names):
            return
        raise ConfigError(
            f"Not overwriting another study: {here} holds the study of {' + '.join(recorded)}, "
            f"this run's config is {' + '.join(names)}; run it in a directory of its own "
            f"(--directory {_suggestion(names, root, checkout, shown_from)}), or delete {here} to replace that study")
    if runs is None or not (root / "results").is_dir():
        return
    foreign = _foreign_run(root, runs())
    if foreign is not None:
        path, differences = foreign
        raise ConfigError(
            f"Not overwriting another study: {_shown(root / path, shown_from)} was computed with other settings"
            f"{f' ({differences})' if differences else ''} and {here} records no config file; run the study of "
            f"{' + '.join(names)} in a directory of its own (--directory {_suggestion(names, root, checkout, shown_from)}), "
            f"or, if {here} is that study's, write {' and '.join(names)} into {_shown(root / RECORD, shown_from)} "
            f"(one a line)")


def _foreign_run(root: Path, expected: dict):
    """The first existing run file under *root* of *expected* (``{path: job record}``) whose
    ``config_hash`` is not its record's, with the settings that differ; ``None`` where all agree."""
    present = {path: record for path, record in expected.items() if (root / path).is_file()}
    if not present:
        return None
    import netCDF4

    from .io import _differences
    from .provenance import config_hash

    for path, record in present.items():
        want = config_hash(record)
        try:
            with netCDF4.Dataset(root / path) as ds:
                got, recorded = getattr(ds, "config_hash", None), getattr(ds, "config", None)
        except OSError:
            continue   # unreadable: the merge names it
        if got != want:
            return path, _differences(recorded, record).removeprefix("; ")
    return None


def record_study(root, names) -> None:
    """Record in *root* (:data:`RECORD`) that its study is that of the config files *names*,
    where it has no record yet."""
    path = Path(root) / RECORD
    if names and not path.is_file():
        from .provenance import write_text

        write_text("".join(f"{name}\n" for name in names), path)
