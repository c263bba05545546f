# module: roughcontact.study.config.axes.plateau
"""A worn roughness: the summits of the generated surface cut flat at a plateau height.

A surface that has run in (plateau-honed cylinder liners, worn seals) keeps its valleys and loses
its summits. Heights are the indenter's shape measured from the half-space towards the indenter
(:mod:`roughcontact.bem.contact`), so the summits are the *lowest* heights: they touch first. The
axis ``plateau`` cuts the roughness flat at ``plateau · h_rms`` below its mean plane, on that
touching side, before the body is added; ``null``, the paper's setting, leaves it as generated. It
acts by a transform of the heights, so no surface generator needs a new keyword, and a run at the
paper's setting keeps its name, settings and hash.
"""
from __future__ import annotations

import math

import numpy as np

from . import Axis, nullable, register


def truncate(heights, plateau, run):
    """The roughness *heights* (mean 0, rms ``run.h_rms``; the lowest touch first) cut flat at
    ``−plateau · h_rms``: every height below it raised to it, the summits worn to a plateau."""
    return np.maximum(heights, -plateau * run.h_rms)


register(Axis(
    "plateau",                                   # config key, merged-file dimension, settings key
    "plateau",                                   # run-name tag: H0.7_R0.5_h0.009_plateau1.5
    "plateau depth of a worn roughness (inf: unworn)", "1",    # long_name and units of the coordinate
    "depth below the mean plane, in units of h_rms, at which the summits (the touching side) are cut "
    "flat (a worn, plateau-honed surface); null = unworn (the paper's surfaces)",   # the configuration reference
    nullable(exclusiveMinimum=0),                # JSON schema of one value: null or a number > 0
    "roughness",                                 # it acts on the roughness ...
    transform=truncate,                          # ... by cutting its heights, before the body is added
    paper_coordinate=lambda length: math.inf,    # null (the paper's setting) as a coordinate: inf
    flag_help="plateau depth in units of h_rms (default: unworn)",   # roughcontact indent --plateau
))
