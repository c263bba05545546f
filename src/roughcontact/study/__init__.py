"""The Snakemake parameter study: configuration, runs, the indent job, merge, fits, claims, figures.

By role, bottom up:

* configuration: :mod:`.axes` (the registry of sweep axes), :mod:`.schema` and :mod:`.config`
  (the validated configuration; :mod:`.limits` the estimates it is checked against),
  :mod:`.runs` (the sweep's runs and their names) and :mod:`.settings` (``JobSettings``, the
  typed settings of one job);
* files: :mod:`.provenance`, :mod:`.logs`, :mod:`.runfile` (the run file's data model) and
  :mod:`.io` (reading and writing);
* the job: :mod:`.indent` (one indent core for every surface);
* ensembles and fits: :mod:`.merge`, :mod:`.ensemble` (statistics over seeds and the one
  ``resolved()`` rule), :mod:`.statistics` (bootstrap and verdict rules), :mod:`.zeta`
  (ζ(H) and its law), :mod:`.verdicts` (eq. 16 fits, crossover), :mod:`.exponents`,
  :mod:`.convergence`, :mod:`.calibration`;
* results: :mod:`.claims` (the claim registry and the claims table), :mod:`.scorecard` (every
  model of :mod:`roughcontact.models.scorecard` against the ensembles), :mod:`.figures`,
  :mod:`.plotting` and :mod:`.tables`;
* :mod:`.measured`: scans and spectra pressed in physical units.

Nothing here is imported by ``import roughcontact``; the modules import xarray, pandas, netCDF4
and matplotlib (the ``pipeline`` extra) where they use them. The workflow owns its paths: run,
log and figure patterns live in ``workflow/rules``.
"""
