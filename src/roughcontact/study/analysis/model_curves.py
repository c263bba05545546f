"""The models' curves that need nothing the runs measure, computed once from the configuration
(rule ``model_curves``, before the runs end;
:func:`roughcontact.study.analysis.scorecard.precomputed_curves` computes them) for the two rules that draw on them: the scorecard's
predictions of every :attr:`~roughcontact.models.scorecard.Model.precomputable` model (Persson's,
Greenwood–Tripp's, MDR's, this package's) at the study's sphere loads, and Greenwood & Tripp's load
curve of Fig. 3 (J. Appl. Mech. 34, 153 (1967), doi:10.1115/1.3607616) at the paper's setting.

One NetCDF group per elastic sphere combination (its run name), holding ``k_<model>`` on the
dimension ``force`` (force units ``e_star * length²``; stiffness ``e_star * length``), and at the
paper's setting ``gt_force`` and ``gt_stiffness`` on ``gt_point`` with GT's ``gt_mu``. Each group
records the surface the models read (:func:`surface_key`) and the parameters of GT's curve
(:func:`gt_key`): a reader takes a curve only where they and the forces are the very same, and
else computes it itself (:func:`known`, :func:`gt_curve`), so the file can only save time, never
change a number. (This module imports no model: the figures' code fingerprint stays that of the
figures when a model is added.)
"""
from __future__ import annotations

import dataclasses
import logging

import numpy as np


__all__ = ["FigureCurve", "surface_key", "gt_key", "known", "gt_curve"]

log = logging.getLogger(__name__)

#: the group attribute that names a precomputed model with no prediction for the surface (None)
DECLINED = "declined_models"


@dataclasses.dataclass(frozen=True)
class FigureCurve:
    """Greenwood & Tripp's load curve of Fig. 3 (:func:`roughcontact.models.greenwood_tripp.self_affine_sphere_curve`).

    Attributes
    ----------
    force, stiffness : numpy.ndarray
        The curve's forces (``e_star * length²``) and stiffnesses (``e_star * length``).
    mu : float
        GT's ``μ`` of the surface and sphere.
    """

    force: np.ndarray
    stiffness: np.ndarray
    mu: float


def surface_key(surface) -> str:
    """The surface (:class:`roughcontact.models.scorecard.Surface`) a precomputed curve belongs to,
    as text: every field but ``zeta_fit`` (which a precomputable model does not read), exact
    (``repr`` of each float)."""
    return repr(dataclasses.replace(surface, zeta_fit=0.0))


def gt_key(*, hurst, h_rms, n, length, radius, e_star) -> str:
    """The parameters of Fig. 3's Greenwood–Tripp curve as text, exact."""
    return repr((float(hurst), float(h_rms), int(n), float(length), float(radius), float(e_star)))


def _matching(curves: dict | None, label: str, attribute: str, key: str):
    """The group of *label* if its *attribute* is *key*, else None."""
    if not curves or label not in curves:
        return None
    group = curves[label]
    return group if group.attrs.get(attribute) == key else None


def known(curves: dict | None, label: str, force, surface) -> dict:
    """``{model: k or None}`` of the precomputed models of *label* for the scorecard registry's
    ``predict(..., known)``: empty unless the group was computed for the same *surface* at the same
    *force* (exactly), so that a model is computed again rather than read for another surface."""
    group = _matching(curves, label, "surface", surface_key(surface))
    if group is None or not np.array_equal(group["force"].values, np.asarray(force, dtype=float)):
        if curves:
            log.info("model curves: none precomputed for %s; computing them", label)
        return {}
    declined = set(str(group.attrs.get(DECLINED, "")).split())
    return {name: None if name in declined else group[f"k_{name}"].values
            for name in str(group.attrs.get("models", "")).split()
            if name in declined or f"k_{name}" in group}


def gt_curve(curves: dict | None, label: str, *, hurst, h_rms, n, length, radius, e_star) -> FigureCurve:
    """Greenwood & Tripp's curve of Fig. 3 for *label*
    (:func:`roughcontact.models.greenwood_tripp.self_affine_sphere_curve` of these parameters):
    precomputed for the same parameters, else computed here."""
    parameters = dict(hurst=hurst, h_rms=h_rms, n=n, length=length, radius=radius, e_star=e_star)
    group = _matching(curves, label, "gt", gt_key(**parameters))
    if group is not None and "gt_force" in group:
        return FigureCurve(group["gt_force"].values, group["gt_stiffness"].values, float(group.attrs["gt_mu"]))
    from ...models.greenwood_tripp import self_affine_sphere_curve

    if curves:
        log.info("model curves: no Greenwood-Tripp curve precomputed for %s; computing it", label)
    gt = self_affine_sphere_curve(**parameters)
    return FigureCurve(gt.force, gt.stiffness, float(gt.mu))
