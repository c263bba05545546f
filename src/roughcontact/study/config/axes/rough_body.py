"""The axes of the rough body of Pohrt & Popov (2013): the Hurst exponent H, the radius R, the rms
height h_rms, and the body of revolution's exponent m beyond the paraboloid (the paper's Conclusions)."""
from __future__ import annotations

from ....errors import ConfigError
from . import Axis, number, register

register(Axis(
    "hurst", "H", "Hurst exponent H", "1",
    "Hurst exponents H of the generated surfaces (required, non-empty, unless topography or spectrum is given; "
    "then may be empty or missing)",
    number(exclusiveMinimum=0, exclusiveMaximum=2), "roughness", optional=False, may_be_empty=True,
    flag_help="Hurst exponent H, 0 < H < 2"))
register(Axis(
    "radius", "R", "sphere radius R", "length", "sphere radii R (.inf = nominally flat, periodic)",
    number(exclusiveMinimum=0, **{"x-allow-inf": True}), "body", kinds=("sphere",), optional=False,
    flag_help="sphere radius R; inf = nominally flat"))


def _check_exponent(cfg: dict, kinds: set) -> None:
    if "sphere" not in kinds:
        return
    for i, exponent in enumerate(cfg["exponent"]):
        if exponent in cfg["hurst"]:
            raise ConfigError(
                f"config key 'exponent[{i}]' = {exponent:g} equals a Hurst exponent: the body and the roughness "
                "then have parallel asymptotes and eqs. 16-17 no crossover; allowed: exponents other than every H",
                key=f"exponent[{i}]")


register(Axis(
    "exponent", "m", "exponent m of the body of revolution z = (R/m)(r/R)^m (2: paraboloid)", "1",
    "exponents m of the bodies of revolution z = (R/m)(r/R)^m pressed by the spheres (2 = the paper's "
    "paraboloid, 1 = a cone of slope 1); not used by flat surfaces",
    number(exclusiveMinimum=0, maximum=8), "body", kinds=("sphere",), paper=2.0,
    flag_help="body of revolution z = (R/m)(r/R)^m of the sphere (default 2: the paraboloid)", check=_check_exponent))
register(Axis(
    "h_rms", "h", "rms roughness height", "length",
    "rms roughness heights h of the generated surfaces (required, non-empty, unless topography or spectrum is "
    "given; then may be empty or missing)",
    number(exclusiveMinimum=0), "roughness", optional=False, may_be_empty=True,
    flag_help="rms roughness height"))
