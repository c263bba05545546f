"""The results directory of one study run, read: the one study-directory reader.

A study run in a directory (``snakemake --directory DIR``, or the checkout itself) writes its
results under ``DIR/results/``. :class:`StudyDirectory` names every file that something outside
the workflow reads back (the grid-convergence and calibration tables, the grid error of two
studies, the docs' results pages), opens it, and fails in one line naming the file and the rule
that writes it. The paths are the workflow's rule outputs (``workflow/rules/*.smk``), written
here once for the readers; a test holds the two to each other.
"""
from __future__ import annotations

import json
from pathlib import Path

from ...errors import MergeError
from .io import read_groups

__all__ = ["StudyDirectory", "FILES", "RUN_DIRECTORIES"]

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
