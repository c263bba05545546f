"""ζ(H), the prefactor of eq. 11: :mod:`roughcontact.study.analysis.zeta.fit` fits it on the merged runs with bootstrap-over-seeds
intervals (``zeta.csv``, ``zeta.nc``); :mod:`roughcontact.study.analysis.zeta.law` chooses a law ζ(H) over the swept Hurst
exponents from candidate forms (claim c′). The candidate forms and the calibrated law that
the models use are :mod:`roughcontact.models.zeta_law`."""
from .fit import fit_zeta, paper_setting
from .law import MIN_HURST, ZetaLaw, fit_law, fit_zeta_law

__all__ = ["fit_zeta", "paper_setting", "MIN_HURST", "ZetaLaw", "fit_law", "fit_zeta_law"]
