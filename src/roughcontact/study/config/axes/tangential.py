"""The tangential axes: the Poisson ratio ``ν`` of the half-space and the Coulomb coefficient ``μ``
(issue: tangential stiffness of rough spheres; Johnson 1985, §7.2). Neither changes the normal
problem (:attr:`~roughcontact.study.config.axes.Axis.normal` is ``False``: the normal–tangential
coupling is neglected, :mod:`roughcontact.bem.cerruti`), so a study that leaves them out keeps
every run, name and output it had.

With ``ν`` given every load of a sphere run also gets its full-stick tangential stiffness
(:func:`roughcontact.bem.tangential_stiffness`); with ``μ > 0`` the loads of ``tangential.at``
also follow a Cattaneo–Mindlin partial-slip path ``Q = 0 … μP``
(:func:`roughcontact.bem.partial_slip`, ``tangential.steps`` loads)."""
from __future__ import annotations

from ....errors import ConfigError
from . import Axis, nullable, number, register


def _text(values) -> str:
    return "[" + ", ".join("null" if v is None else f"{v:g}" for v in values) + "]"


def _check_poisson(cfg: dict, kinds: set) -> None:
    given = [v for v in cfg["poisson"] if v is not None]
    if not given:
        return
    if len(given) != len(cfg["poisson"]):
        raise ConfigError(f"config key 'poisson' = {_text(cfg['poisson'])} mixes null with Poisson ratios; allowed: "
                          "[null] (no tangential problem) or Poisson ratios -1 < nu <= 0.5 only", key="poisson")
    if not cfg["hurst"]:
        raise ConfigError(f"config key 'poisson' = {_text(given)} acts on the generated rough spheres, and the study "
                          "has none (hurst is empty: measured inputs only); allowed: [null], or generated surfaces "
                          "(hurst, h_rms) with a finite radius", key="poisson")
    if "sphere" not in kinds:
        raise ConfigError(f"config key 'poisson' = {_text(given)} needs a sphere: the tangential problem is solved for "
                          "the rough spheres (finite radius) only; allowed: [null], or a finite radius", key="poisson")
    _elastic_only("poisson", given[0], cfg)


def _elastic_only(key: str, value: float, cfg: dict) -> None:
    """Tangential contact is built on elastic, non-adhesive normal states of generated spheres."""
    plastic = [h for h in cfg["hardness"] if h is not None]
    if plastic:
        raise ConfigError(f"config key '{key}' = {value:g} is not allowed with 'hardness' = {plastic[0]:g}; allowed: "
                          f"a tangential problem or a hardness (the tangential solve needs an elastic contact)", key=key)
    adhesive = [w for w in cfg["work_of_adhesion"] if w is not None and w > 0]
    if adhesive:
        raise ConfigError(f"config key '{key}' = {value:g} is not allowed with 'work_of_adhesion' = {adhesive[0]:g}; "
                          "allowed: a tangential problem or adhesion (not both)", key=key)


def _check_friction(cfg: dict, kinds: set) -> None:
    sliding = [m for m in cfg["friction"] if m > 0]
    if not sliding:
        return
    _elastic_only("friction", sliding[0], cfg)
    if not [v for v in cfg["poisson"] if v is not None]:
        raise ConfigError(f"config key 'friction' = {sliding[0]:g} needs 'poisson': the partial-slip path is solved "
                          "with the Cerruti kernel of a Poisson ratio; allowed: friction [0], or give poisson "
                          "(-1 < nu <= 0.5)", key="friction")
    at = (cfg.get("tangential") or {}).get("at")
    rng = cfg["forces"]["sphere"]
    for i, force in enumerate(at or ()):
        if not rng["from"] <= force <= rng["to"]:
            raise ConfigError(f"config key 'tangential.at[{i}]' = {force:g} is outside the spheres' load path; allowed: "
                              f"a force F/(E* L^2) within forces.sphere {rng['from']:g} ... {rng['to']:g}",
                              key=f"tangential.at[{i}]")


register(Axis(
    "poisson", "nu", "Poisson ratio of the half-space", "1",
    "Poisson ratios nu of the elastic half-space (the normal problem depends on E* only, the tangential one on "
    "nu too); null = no tangential problem (the paper's setting); given: every load of a sphere run also gets "
    "its full-stick tangential stiffness (Mindlin: k_t/k_n = 2(1-nu)/(2-nu)). -1 < nu <= 0.5",
    nullable(exclusiveMinimum=-1, maximum=0.5), "tangential", kinds=("sphere",),
    flag_help="Poisson ratio of the half-space: adds the full-stick tangential stiffness (default: none)",
    check=_check_poisson, normal=False))

register(Axis(
    "friction", "mu", "Coulomb friction coefficient", "1",
    "Coulomb friction coefficients mu of the interface; 0 = no tangential loading (the paper's setting); "
    "mu > 0 (needs poisson): the loads of tangential.at also follow a partial-slip path Q = 0 ... mu P at "
    "fixed normal load (Cattaneo-Mindlin; tangential.steps loads)",
    number(minimum=0), "tangential", kinds=("sphere",), paper=0.0,
    flag_help="Coulomb friction coefficient: adds the partial-slip path at the loads of tangential.at "
              "(default 0: none; needs --poisson)",
    check=_check_friction, normal=False))
