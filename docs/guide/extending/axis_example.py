# module: roughcontact.study.config.axes.plateau
"""A worn roughness: the asperities of the generated surface cut flat at a plateau height.

A surface that has run in (plateau-honed cylinder liners, worn seals) keeps its valleys and loses
its summits. The axis ``plateau`` cuts the roughness at ``plateau · h_rms`` above its mean plane
before the body is added; ``null``, the paper's setting, leaves it as generated. It acts by a
transform of the heights, so no surface generator needs a new keyword, and a run at the paper's
setting keeps its name, settings and hash.
"""
from __future__ import annotations

import math

import numpy as np

from . import Axis, nullable, register


def truncate(heights, plateau, run):
    """The roughness *heights* (mean 0, rms ``run.h_rms``) cut flat at ``plateau · h_rms``."""
    return np.minimum(heights, plateau * run.h_rms)


register(Axis(
    "plateau",                                   # config key, merged-file dimension, settings key
    "plateau",                                   # run-name tag: H0.7_R0.5_h0.009_plateau1.5
    "plateau height of a worn roughness (inf: unworn)", "1",   # long_name and units of the coordinate
    "heights, in units of h_rms above the mean plane, at which the roughness is cut flat (a worn, "
    "plateau-honed surface); null = unworn (the paper's surfaces)",   # the configuration reference
    nullable(exclusiveMinimum=0),                # JSON schema of one value: null or a number > 0
    "roughness",                                 # it acts on the roughness ...
    transform=truncate,                          # ... by cutting its heights, before the body is added
    paper_coordinate=lambda length: math.inf,    # null (the paper's setting) as a coordinate: inf
    flag_help="plateau height in units of h_rms (default: unworn)",   # roughcontact indent --plateau
))
