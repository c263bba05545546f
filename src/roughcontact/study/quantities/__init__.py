"""The per-load quantities of a run: the registry (:class:`Quantity`, :func:`register`,
:data:`QUANTITIES`) and one module of this package per family, each registering its quantities
when imported.

A quantity is one number a force-controlled run keeps at every load of its path: its name (the
run file's and the merged files' variable), NetCDF type, long name and units (the run file's
attributes), how it is computed from a solved :class:`roughcontact.bem.ContactState`
(:attr:`Quantity.compute`), which runs keep it (:attr:`Quantity.records`: every run, a run with a
hardness, a run with ``fields.patches``, ...) and the configuration key that turns it on
(:attr:`Quantity.option`, ``None`` where the run's kind decides). The load-path loop
(:func:`roughcontact.study.runs.indent.solve_load_path`), the run file's declaration
(:meth:`roughcontact.study.runs.jobs.JobSettings.file_spec`), the writer and the merge iterate over
:data:`QUANTITIES`; ``roughcontact list quantities`` prints them. Every module here is imported with
the package (:data:`_ORDER` first, then the others by name), so a new quantity is one new module.

Units are written as the run files write them: in the study's normalised units (``length``,
``e_star``; a measured run converts them).
"""
from __future__ import annotations

import dataclasses
from typing import Callable

from ..._registry import add, import_modules
from ..files.runfile import Variable

__all__ = ["OPT_IN", "Load", "Quantity", "QUANTITIES", "missing", "names", "opted_in", "optional", "recorded",
           "register", "variables"]

#: the configuration key that lists the opt-in quantities a study's runs keep
OPT_IN = "fields.quantities"


def _always(settings) -> bool:
    return True


@dataclasses.dataclass(frozen=True)
class Load:
    """What a quantity's :attr:`Quantity.compute` knows of the load besides its state.

    Attributes
    ----------
    settings : roughcontact.study.runs.indent.PathSettings
        How the path is solved (the run's name, its force key, the stiffness method, ...).
    index, total : int
        The load (0-based) and the path's loads.
    where : str
        The load in error messages: ``load step 3/19 (F/(E*L^2) = 1e-05``.
    cell : float
        The area of one grid cell (length²).
    cache : dict
        Intermediate results shared by the quantities of this load (e.g. its contact patches,
        counted once for two quantities), by a key of the module that computes them.
    """

    settings: object
    index: int
    total: int
    where: str
    cell: float
    cache: dict = dataclasses.field(default_factory=dict)


@dataclasses.dataclass(frozen=True)
class Quantity:
    """One per-load quantity of a run.

    Attributes
    ----------
    name : str
        Variable of the run file and of the merged files.
    dtype : str
        NetCDF type (``f8``, ``i8``, ``i1``).
    long_name, units : str
        The variable's attributes (CF ``units`` in the study's normalised units).
    compute : callable
        ``compute(state, load) -> value`` for a solved state and its :class:`Load`; raises an
        :class:`~roughcontact.errors.IndentError` naming the run, the load and what to change
        where the value cannot be used.
    records : callable
        ``records(settings) -> bool``: whether a run with these settings (anything with the
        attributes of :class:`~roughcontact.study.runs.indent.PathSettings` it reads, e.g.
        ``hardness``, ``patches``) keeps the quantity. Default: every run.
    option : str or None
        The configuration key that turns it on (``fields.patches``); ``None``: the run's kind.
    family : str
        The module that registered it (``normal``, ``plastic``, ``patches``, ...).
    needs : callable or None
        ``needs(cfg) -> str or None`` for an opt-in quantity that only some run kinds give: what the
        resolved configuration *cfg* lacks for any of its runs to keep it (``"a flat run (radius
        .inf)"``), ``None`` where one does. The configuration check refuses the quantity in one line
        naming its key ``fields.quantities[i]`` and what it needs (:func:`missing`). ``None``: every run
        of a generated elastic or plastic study gives it.
    """

    name: str
    dtype: str
    long_name: str
    units: str
    compute: Callable
    records: Callable = _always
    option: str | None = None
    family: str = ""
    needs: Callable | None = None

    @property
    def variable(self) -> Variable:
        """The run file's declaration of the variable."""
        return Variable(self.dtype, self.long_name, self.units)


#: every registered quantity, by name, in registration order
QUANTITIES: dict[str, Quantity] = {}


def register(quantity: Quantity) -> Quantity:
    """Add *quantity* to :data:`QUANTITIES`; ``ValueError`` for a name registered already."""
    return add(QUANTITIES, quantity.name, quantity, "quantity")


def opted_in(name: str) -> Callable:
    """The :attr:`Quantity.records` of an opt-in quantity *name*: a run keeps it where its settings'
    ``quantities`` (the configuration's :data:`OPT_IN`) name it."""
    def records(settings) -> bool:
        return name in (getattr(settings, "quantities", ()) or ())

    return records


def optional() -> tuple[str, ...]:
    """The names of the opt-in quantities (:data:`OPT_IN`), in the registry's order."""
    return tuple(q.name for q in QUANTITIES.values() if q.option == OPT_IN)


def missing(name: str, cfg) -> str | None:
    """What the resolved configuration *cfg* lacks for any of its runs to keep the quantity *name*
    (:attr:`Quantity.needs`); ``None`` where a run gives it."""
    needs = QUANTITIES[name].needs
    return None if needs is None else needs(cfg)


def names() -> tuple[str, ...]:
    """The registered quantities' names, in the registry's order."""
    return tuple(QUANTITIES)


def recorded(settings) -> tuple[str, ...]:
    """The names of the quantities a run with *settings* keeps (:attr:`Quantity.records`), in order."""
    return tuple(q.name for q in QUANTITIES.values() if q.records(settings))


def variables(selected) -> dict[str, Variable]:
    """``{name: Variable}`` of the registered quantities among *selected* (names), in the registry's
    order; other names (``force``, a tangential variable) are left out."""
    chosen = set(selected)
    return {q.name: q.variable for q in QUANTITIES.values() if q.name in chosen}


#: the families registered first, in this order (the run files' variable order)
_ORDER = ("normal", "plastic", "patches", "gap")


def _load() -> None:
    """Import every module of this package (:data:`_ORDER` first, then the others by name)."""
    import_modules(__name__, __path__, _ORDER)


_load()
