"""The Snakemake parameter study: configuration, runs, the indent job, merge, fits, verdicts, figures.

Layers, bottom up: :mod:`.schema` and :mod:`.config` (the validated configuration),
:mod:`.provenance` and :mod:`.logs`, :mod:`.runs` (run naming and job settings),
:mod:`.indent` (one job), :mod:`.merge` and :mod:`.zeta` (merged runs, ζ(H)),
:mod:`.verdicts`, :mod:`.effects` and :mod:`.claims` (intervals and the claims table),
:mod:`.figures`. Nothing here is imported by ``import roughcontact``; the modules import
xarray, pandas, netCDF4 and matplotlib (the ``pipeline`` extra) where they use them. The
workflow owns its paths: run, log and figure patterns live in ``workflow/rules``.
"""
