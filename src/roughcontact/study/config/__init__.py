"""The study's configuration: the sweep axes (:mod:`~roughcontact.study.config.axes`), the schema
and its package data, resolution and cross-key checks (:mod:`~roughcontact.study.config.resolve`,
whose public names this package re-exports), the typed settings of a study, units, limits and defaults.
"""
from .resolve import error_line, load_config, resolve_config, study_settings

__all__ = ["error_line", "load_config", "resolve_config", "study_settings"]
