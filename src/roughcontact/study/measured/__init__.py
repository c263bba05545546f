"""The measured stage of the study: scans and spectra pressed as indenters, in physical units.

:mod:`roughcontact.study.measured.config` resolves the configuration's measured inputs (``topography``, ``spectrum``,
``units``) and converts units; :mod:`roughcontact.study.measured.jobs` prepares a scan, runs one load path of a tile or a
spectrum's seed (through the one indent core, :func:`roughcontact.study.indent.solve_load_path`);
:mod:`roughcontact.study.measured.merge` merges a surface's runs; :mod:`roughcontact.study.measured.spectrum` fits a scan's spectrum and predicts its k(F) with
every model of the registry (:mod:`roughcontact.study.measured.models`); :mod:`roughcontact.study.measured.figures` draws the report's figures. The
jobs' functions are the package's face here (``from roughcontact.study import measured``).
"""
from .jobs import MeasuredJob, job_of, prepare_surface, read_surface, run_job, run_order, sha256, tile_count
from .merge import merge_surface

__all__ = ["MeasuredJob", "job_of", "merge_surface", "prepare_surface", "read_surface", "run_job", "run_order",
           "sha256", "tile_count"]
