"""Rule ``stickiness_run``: one flat rough surface loaded into a Maugis–Dugdale half-space
(:func:`roughcontact.study.runs.stickiness.stickiness_run`) -> its run file."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(settings, *, output) -> dict:
    """Compute the stickiness run *settings* (a :class:`~roughcontact.study.config.stickiness.StickinessRun`,
    the rule's ``params``) and write it to *output* (NetCDF, atomic; its provenance records
    *settings*: ``config`` is :meth:`~roughcontact.study.config.stickiness.StickinessRun.record`,
    ``config_hash`` its hash; :func:`roughcontact.study.files.runfile.write_run`). Returns the run's
    variables."""
    from ..files import provenance, runfile
    from ..runs.stickiness import stickiness_run

    s = settings
    out = stickiness_run(s)
    runfile.write_run(output, out, kind="stickiness", attrs=provenance.provenance_attrs(
        config=s.record(), hurst=s.hurst, number=s.number, seed=s.seed, grid_n=s.n, grid_length=s.length,
        e_star=s.e_star, periodic=1, cutoff_cells=s.cutoff, area=s.area, solver_tol=s.tol,
        interaction="Maugis-Dugdale (roughcontact.bem.cohesive)",
        reference="L. Pastewka and M. O. Robbins, PNAS 111 (2014) 3298 (doi:10.1073/pnas.1320846111)"))
    log.info("wrote %s", output)
    return out
