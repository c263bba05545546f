"""The study's runs: their names, paths and resources (:mod:`~roughcontact.study.runs.naming`, whose
public names this package re-exports), the settings of one job and the jobs themselves (indent,
adhesive, stickiness, measured).
"""
from .naming import (AXES, DEFAULTS, axis_value, combinations, combo_name, force_grid, format_value, indent_resources,
                     kind_of, parse_combo, parse_run_path, parse_value, run_path, run_paths, runs, sphere_names)

__all__ = ["format_value", "parse_value", "runs", "run_path", "run_paths", "combinations", "axis_value",
           "indent_resources", "force_grid", "parse_run_path", "combo_name", "sphere_names", "parse_combo", "AXES",
           "DEFAULTS", "kind_of"]
