"""The Snakemake parameter study: configuration, runs, the indent job, merge, fits, claims, figures.

By role, bottom up (subpackages of ``roughcontact.study``):

* ``config``: ``axes`` (the registry of sweep axes), ``schema`` (and ``config.schema.yaml``, package
  data), ``coerce``, ``resolve`` (the validated configuration; its public names re-exported by
  ``config``), ``settings`` (``StudySettings``), ``units``, ``limits`` (the estimates a configuration
  is checked against), ``defaults``, and the measured and stickiness sections (``measured``,
  ``stickiness``);
* ``runs``: ``naming`` (the sweep's runs, their names, paths and resources; re-exported by
  ``runs``), ``jobs`` (``JobSettings``, the typed settings of one job), ``path`` (the load-path
  loop), ``indent`` (one indent core for every surface) and the jobs of adhesive, stickiness and
  measured runs (``adhesive``, ``stickiness``, ``measured``);
* ``files``: ``runfile`` (the run file's data model), ``io`` (reading and writing), ``provenance``
  and ``logs``;
* ``analysis``: ``merge``, ``ensemble`` (statistics over seeds and the one ``resolved()`` rule),
  ``statistics`` (bootstrap and verdict rules), ``zeta`` (ζ(H) and its law), ``crossover`` (the
  crossover table: eq. 16 fits, F_tr, slopes, verdicts), ``exponents``, ``grid_error``, ``convergence``, ``calibration``, ``scorecard``
  (every model of :mod:`roughcontact.models.scorecard` against the ensembles; ``not_modelled`` the
  rows it does not score, ``decision`` its rule), the adhesive and stickiness tables
  (``adhesion``, ``stickiness``) and the measured surfaces' merge, spectrum, models and scorecard
  (``measured_*``);
* ``claims``: the claim registry and the claims table;
* ``report``: ``figures``, ``plotting``, ``tables``, ``summary`` (the landing page),
  ``which_model`` and the adhesive, stickiness and measured figures.

``registries`` lists what the registries hold and fingerprints the analysis code.

Nothing here is imported by ``import roughcontact``; the modules import xarray, pandas, netCDF4
and matplotlib (the ``pipeline`` extra) where they use them. The workflow owns its paths: run,
log and figure patterns live in ``workflow/rules``.
"""
