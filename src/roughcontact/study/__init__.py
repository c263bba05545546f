"""The Snakemake parameter study: configuration, runs, the indent job, merge, fits, claims, figures.

By role, bottom up (modules of ``roughcontact.study``):

* configuration: ``axes`` (the registry of sweep axes), ``schema`` and ``config`` (the validated
  configuration; ``limits`` the estimates it is checked against), ``runs`` (the sweep's runs and
  their names) and ``settings`` (``JobSettings``, the typed settings of one job);
* files: ``provenance``, ``logs``, ``runfile`` (the run file's data model) and ``io`` (reading
  and writing);
* the job: ``indent`` (one indent core for every surface);
* ensembles and fits: ``merge``, ``ensemble`` (statistics over seeds and the one ``resolved()``
  rule), ``statistics`` (bootstrap and verdict rules), ``zeta`` (ζ(H) and its law),
  ``verdicts`` (eq. 16 fits, crossover), ``exponents``, ``convergence``, ``calibration``,
  ``grid_error`` (the grid error of an ensemble mean);
* results: ``claims`` (the claim registry and the claims table), ``scorecard`` (every model of
  :mod:`roughcontact.models.scorecard` against the ensembles; ``not_modelled`` the rows it does
  not score: a model off the paper value of an axis it does not declare), ``figures``, ``plotting`` and
  ``tables``;
* ``measured``: scans and spectra pressed in physical units.

Nothing here is imported by ``import roughcontact``; the modules import xarray, pandas, netCDF4
and matplotlib (the ``pipeline`` extra) where they use them. The workflow owns its paths: run,
log and figure patterns live in ``workflow/rules``.
"""
