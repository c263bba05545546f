"""The axes of the roughness spectrum beyond the paper's pure power law: a roll-off and a cutoff wavelength."""
from __future__ import annotations

from ....errors import ConfigError
from . import Axis, nullable, register

def _check_spectrum(cfg: dict, kinds: set) -> None:
    from ..limits import full_contact_slope

    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
    if None in cfg["rolloff"] and length in cfg["rolloff"]:
        raise ConfigError(f"config key 'rolloff' lists both null and grid.length = {length:g}, the same spectrum (a "
                          "roll-off at L is none); allowed: one of them", key="rolloff")
    rolloffs = [length if r is None else r for r in cfg["rolloff"]]
    cutoffs = [0.0 if c is None else c for c in cfg["cutoff"]]
    for i, rolloff in enumerate(cfg["rolloff"]):
        if rolloff is not None and rolloff > length:
            raise ConfigError(f"config key 'rolloff[{i}]' = {rolloff:g} is not allowed; allowed: null or a wavelength "
                              f"<= grid.length = {length:g} (the longest wavelength of the surface)",
                              key=f"rolloff[{i}]")
    for i, cutoff in enumerate(cfg["cutoff"]):
        if cutoff is not None and cutoff < 2 * length / n:
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: null or a wavelength "
                              f">= 2 cells = 2 grid.length/grid.n = {2 * length / n:.3g}", key=f"cutoff[{i}]")
        if cutoff is not None and cutoff >= min(rolloffs):
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: a wavelength below every "
                              f"roll-off ({min(rolloffs):g}), else no self-affine band is left", key=f"cutoff[{i}]")
    if max(cutoffs) > 0 and "flat" in kinds and cfg["forces"].get("flat"):
        slope = min(full_contact_slope(h, n, length, rolloff=r, cutoff=c or None)
                    for h in cfg["hurst"] for r in rolloffs for c in cutoffs) * min(cfg["h_rms"])
        if cfg["forces"]["flat"]["to"] >= 0.5 * slope:
            raise ConfigError(
                f"config key 'forces.flat.to' = {cfg['forces']['flat']['to']:g} would press the flat surfaces with "
                f"a cutoff close to full contact (rms slope ~ {slope:.3g}); allowed: to < {0.5 * slope:.3g}",
                key="forces.flat.to")


register(Axis(
    "rolloff", "rolloff", "roll-off wavelength of the spectrum (grid.length: none)", "length",
    "roll-off wavelengths of the roughness spectrum (length unit; C(q) is constant for q < 2 pi/rolloff); "
    "null = grid.length (no roll-off)",
    nullable(exclusiveMinimum=0), "roughness", paper_coordinate=float,
    flag_help="roll-off wavelength of the spectrum (default: L)", claim="j"))
register(Axis(
    "cutoff", "cutoff", "short-wavelength cutoff of the spectrum (0: none)", "length",
    "short-wavelength cutoffs of the roughness spectrum (length unit; C(q) = 0 for q > 2 pi/cutoff); "
    "null = none (every grid mode)",
    nullable(exclusiveMinimum=0), "roughness", paper_coordinate=lambda length: 0.0,
    flag_help="short-wavelength cutoff (default: none)", claim="i", check=_check_spectrum))
