"""The Snakemake parameter study: configuration, runs, the indent job, merge, fits, claims, figures.

By role, bottom up:

* configuration: :mod:`roughcontact.study.axes` (the registry of sweep axes), :mod:`roughcontact.study.schema` and :mod:`roughcontact.study.config`
  (the validated configuration; :mod:`roughcontact.study.limits` the estimates it is checked against),
  :mod:`roughcontact.study.runs` (the sweep's runs and their names) and :mod:`roughcontact.study.settings` (``JobSettings``, the
  typed settings of one job);
* files: :mod:`roughcontact.study.provenance`, :mod:`roughcontact.study.logs`, :mod:`roughcontact.study.runfile` (the run file's data model) and
  :mod:`roughcontact.study.io` (reading and writing);
* the job: :mod:`roughcontact.study.indent` (one indent core for every surface);
* ensembles and fits: :mod:`roughcontact.study.merge`, :mod:`roughcontact.study.ensemble` (statistics over seeds and the one
  ``resolved()`` rule), :mod:`roughcontact.study.statistics` (bootstrap and verdict rules), :mod:`roughcontact.study.zeta`
  (ζ(H) and its law), :mod:`roughcontact.study.verdicts` (eq. 16 fits, crossover), :mod:`roughcontact.study.exponents`,
  :mod:`roughcontact.study.convergence`, :mod:`roughcontact.study.calibration`;
* results: :mod:`roughcontact.study.claims` (the claim registry and the claims table), :mod:`roughcontact.study.scorecard` (every
  model of :mod:`roughcontact.models.scorecard` against the ensembles), :mod:`roughcontact.study.figures`,
  :mod:`roughcontact.study.plotting` and :mod:`roughcontact.study.tables`;
* :mod:`roughcontact.study.measured`: scans and spectra pressed in physical units.

Nothing here is imported by ``import roughcontact``; the modules import xarray, pandas, netCDF4
and matplotlib (the ``pipeline`` extra) where they use them. The workflow owns its paths: run,
log and figure patterns live in ``workflow/rules``.
"""
