"""Estimates a configuration is checked against before any job runs.

:func:`full_contact_slope`: the rms slope per rms height of the self-affine spectrum of a grid,
which bounds the load at which a nominally flat surface comes close to full contact
(:mod:`roughcontact.study.config.resolve` and the spectrum axes' checks in :mod:`roughcontact.study.config.axes`).
"""
from __future__ import annotations

import numpy as np

__all__ = ["full_contact_slope"]


def full_contact_slope(hurst: float, n: int, length: float, *, rolloff: float | None = None,
                       cutoff: float | None = None) -> float:
    """Estimated rms slope / h_rms of a self-affine surface with C(q) ~ q^(-2H-2)
    between q0 = 2 pi / L and the Nyquist wave number q1 = pi n / L (or the
    cutoff 2 pi/cutoff), constant below the roll-off 2 pi/rolloff."""
    with np.errstate(all="ignore"):  # extreme (but finite) L or H: the estimate is then inf or nan
        q_top = np.pi * n / length if cutoff is None else min(np.pi * n / length, 2 * np.pi / cutoff)
        q = np.geomspace(2 * np.pi / length, q_top, 4001)
        lnq = np.log(q)
        psd = np.maximum(q, 2 * np.pi / (length if rolloff is None else rolloff)) ** (-2 * hurst - 2)

        def trap(y):
            return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(lnq)))

        num = trap(q**4 * psd)  # int q^3 C(q) dq = int q^4 C dlnq
        den = trap(q**2 * psd)  # int q C(q) dq = int q^2 C dlnq
        return float(np.sqrt(num / den))
