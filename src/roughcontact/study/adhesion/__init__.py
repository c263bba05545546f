"""Adhesive runs of the study (``work_of_adhesion`` > 0): the job
(:mod:`roughcontact.study.adhesion.run`), the merged pull-off table and its figures.

Imports the core and numpy only; xarray and matplotlib where they are used.
"""
from .run import adhesive_run

__all__ = ["adhesive_run"]
