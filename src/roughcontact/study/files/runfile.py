"""The run file's data model: every variable of a run and of the merged files, once.

Names, NetCDF types, long names and units of what one indentation run writes beyond its per-load
quantities (those: :mod:`roughcontact.study.quantities`)
(:mod:`roughcontact.study.runs.indent`) and what the merge reads back and stacks
(:mod:`roughcontact.study.analysis.merge`). Units are CF-style strings in the study's own units:
lengths in the unit of ``grid.length``, forces in ``e_star * length**2``.
"""
from __future__ import annotations

import dataclasses

import numpy as np


__all__ = ["Variable", "FIELD_VARIABLES",
           "TANGENTIAL_VARIABLES", "SLIP_VARIABLES", "SLIP_COORDS", "slip_fractions", "FIELD_GROUP", "RETRACT_VARIABLES",
           "PULL_OFF_VARIABLES", "HISTOGRAM_VARIABLES", "HISTOGRAM_COORDS", "HISTOGRAM_DIMS",
           "SCALARS", "FORCE_ATTRS", "RETRACT_ATTRS", "TITLE", "write_run",
           "STICKINESS_TITLE", "STICKINESS_VARIABLES", "STICKINESS_SCALARS", "APPROACH_ATTRS", "RunFileSpec"]

#: the ``title`` attribute that marks a run file (generated or measured)
TITLE = "roughcontact indentation run"


@dataclasses.dataclass(frozen=True)
class Variable:
    """One variable of a run file: per load (dimension ``force``) unless *dims* says otherwise."""

    dtype: str
    long_name: str
    units: str
    dims: tuple = ("force",)


#: The per-load quantities of a run (depth, stiffness, contact area, ...) are declared by the
#: quantity registry (:mod:`roughcontact.study.quantities`), which hands the writer their
#: :class:`Variable` (``write_run(variables=...)``) and the reader their names (the run file's
#: declaration, :class:`RunFileSpec`).
#: further per-load variables of a sphere run with a Poisson ratio (axis ``poisson``;
#: :mod:`roughcontact.study.runs.tangential`)
TANGENTIAL_VARIABLES = {
    "tangential_stiffness": Variable("f8", "full-stick tangential contact stiffness dQ/d(delta_x) (Cerruti kernel, "
                                           "normal-tangential coupling neglected)", "e_star * length"),
}
#: the partial-slip paths of a run with friction > 0 (axis ``friction``): per normal load of
#: ``tangential.at`` (dimension ``slip_load``, its values the 0-based load index) and tangential
#: load (dimension ``slip_step``, its values ``Q/(mu P)``)
SLIP_VARIABLES = {
    "slip_normal_force": Variable("f8", "normal force P of the partial-slip path", "e_star * length**2",
                                  ("slip_load",)),
    "slip_depth": Variable("f8", "indentation depth from first touch of the partial-slip path", "length",
                           ("slip_load",)),
    "gross_slip_displacement": Variable("f8", "largest micro-slip: tangential displacement at the onset of gross "
                                              "sliding, max of u_x[mu p] over the contact", "length", ("slip_load",)),
    "slip_force": Variable("f8", "tangential force Q", "e_star * length**2", ("slip_load", "slip_step")),
    "slip_displacement": Variable("f8", "tangential displacement delta_x of the indenter", "length",
                                  ("slip_load", "slip_step")),
    "slip_stiffness": Variable("f8", "tangential tangent stiffness dQ/d(delta_x): full stick of the stick zone",
                               "e_star * length", ("slip_load", "slip_step")),
    "stick_cells": Variable("i8", "number of contact cells that stick (|q| < mu p)", "1", ("slip_load", "slip_step")),
    "slip_iterations": Variable("i8", "influence products of the partial-slip solve (warm-started)", "1",
                                ("slip_load", "slip_step")),
}
def slip_fractions(steps: int) -> np.ndarray:
    """The ``slip_step`` coordinate of a partial-slip path of *steps* loads:
    ``Q/(μP) = 1/(steps+1) … steps/(steps+1)``."""
    return np.arange(1, int(steps) + 1) / (int(steps) + 1)


#: the coordinates of the partial-slip paths
SLIP_COORDS = {"slip_load": ("i8", {"long_name": "index of the normal load of the partial-slip path", "units": "1"}),
               "slip_step": ("f8", {"long_name": "tangential load Q/(mu P)", "units": "1"})}

#: the contact fields a run keeps at chosen loads (``fields.at``), one group ``fields/loadI`` per load
#: (I the 0-based load index) over the contact's window (dimensions ``y``, ``x``), compressed
FIELD_VARIABLES = {
    "pressure": Variable("f8", "contact pressure p", "e_star"),
    "gap": Variable("f8", "gap between the indenter and the deformed half-space (0 in contact, to the solver's tolerance)", "length"),
    "contact": Variable("i1", "cell in contact (1) or not (0)", "1"),
}
#: the group of the fields kept at load *i* (0-based)
FIELD_GROUP = "fields/load{index}"

#: the histograms a run keeps at chosen loads (``fields.histograms``,
#: :mod:`roughcontact.study.quantities.histograms`): per load of the histograms (dimension
#: ``histogram_load``, its values the 0-based load index), the pressure over the contact cells and
#: the gap over the cells out of contact, each in equal bins from 0 to its largest value at that
#: load (dimensions ``pressure_bin``, ``gap_bin``; the bins' edges over ``pressure_edge``,
#: ``gap_edge``)
HISTOGRAM_VARIABLES = {
    "histogram_force": Variable("f8", "normal force F of the load of the histograms", "e_star * length**2",
                                ("histogram_load",)),
    "pressure_histogram": Variable("i8", "number of contact cells whose pressure lies in the bin", "1",
                                   ("histogram_load", "pressure_bin")),
    "pressure_bin_edges": Variable("f8", "edges of the pressure bins: equal bins from 0 to the largest pressure of "
                                         "the load", "e_star", ("histogram_load", "pressure_edge")),
    "gap_histogram": Variable("i8", "number of cells out of contact whose gap lies in the bin", "1",
                              ("histogram_load", "gap_bin")),
    "gap_bin_edges": Variable("f8", "edges of the gap bins: equal bins from 0 to the largest gap of the load",
                              "length", ("histogram_load", "gap_edge")),
}
#: the coordinate of the histograms' loads
HISTOGRAM_COORDS = {"histogram_load": ("i8", {"long_name": "index (0-based) of the load of the histograms",
                                              "units": "1"})}
#: the dimensions of a run file with histograms, beyond ``force``
HISTOGRAM_DIMS = ("histogram_load", "pressure_bin", "pressure_edge", "gap_bin", "gap_edge")

#: the force coordinate
FORCE_ATTRS = {"long_name": "normal force F", "units": "e_star * length**2"}

#: per-step variables of an adhesive run's retract path (dimension ``retract``,
#: :mod:`roughcontact.study.runs.adhesive`)
RETRACT_VARIABLES = {
    "retract_depth": Variable("f8", "approach from first touch along the retract path (displacement control)",
                              "length"),
    "retract_force": Variable("f8", "normal force along the retract path (negative: tensile)", "e_star * length**2"),
    "retract_contact_cells": Variable("i8", "number of grid cells in contact along the retract path", "1"),
}
#: the retract coordinate
RETRACT_ATTRS = {"long_name": "step of the retract path", "units": "1"}
#: the pull-off of an adhesive run (scalars)
PULL_OFF_VARIABLES = {
    "pull_off_force": Variable("f8", "pull-off force: the most tensile force of the retract path (load control)",
                               "e_star * length**2"),
    "pull_off_depth": Variable("f8", "approach at the pull-off force", "length"),
    "pull_off_contact_radius": Variable("f8", "contact radius sqrt(A/pi) at the pull-off force", "length"),
}

#: the ``title`` attribute that marks a stickiness run file (:mod:`roughcontact.study.runs.stickiness`)
STICKINESS_TITLE = "roughcontact stickiness run"
#: per-approach variables of a stickiness run's loading path (dimension ``approach``)
STICKINESS_VARIABLES = {
    "depth": Variable("f8", "approach from first touch (displacement control; negative: apart)", "length"),
    "force": Variable("f8", "normal force, the cohesive zone's tension included (negative: tensile)",
                      "e_star * length**2"),
    "contact_cells": Variable("i8", "number of grid cells in contact (gap 0)", "1"),
    "zone_cells": Variable("i8", "number of grid cells in the cohesive zone (gap below the range, not in contact)",
                           "1"),
}
#: scalars of a stickiness run: its surface, its interaction and its loading slope
STICKINESS_SCALARS = {
    "rms_slope": Variable("f8", "rms gradient h' of the surface", "1"),
    "rms_curvature": Variable("f8", "rms of the mean curvature (Laplacian of h)/2 of the surface, h''", "1/length"),
    "interaction_range": Variable("f8", "range dr of the Maugis-Dugdale interaction", "length"),
    "work_of_adhesion": Variable("f8", "work of adhesion w", "e_star * length"),
    "pastewka_robbins_number": Variable("f8", "Pastewka & Robbins' number (h'E* dr/(2w)) (h'^2/(h'' dr))^(2/3)",
                                        "1"),
    "range_ratio": Variable("f8", "dr/g0, g0 = (16/3) h'^2/h''", "1"),
    "loading_slope": Variable("f8", "dF/dA of the loading with 0 < A <= stickiness.area L^2, in units of h'E* "
                                    "(negative: sticky)", "1"),
}
#: the approach coordinate of a stickiness run
APPROACH_ATTRS = {"long_name": "step of the loading path", "units": "1"}

@dataclasses.dataclass(frozen=True)
class RunFileSpec:
    """What the run file of one job must be (:func:`roughcontact.study.files.io.read_run` checks it):
    each job record gives its own (``JobSettings.file_spec``, ``StickinessRun.file_spec``,
    ``MeasuredJob.file_spec``).

    Attributes
    ----------
    title : str
        The ``title`` attribute (:data:`TITLE`, :data:`STICKINESS_TITLE`).
    variables : tuple of str
        Variables the file must hold.
    dims : tuple of str
        Its dimensions, exactly.
    config : dict
        The job's settings record: the file's ``config_hash`` must be its hash.
    scalars : dict
        ``{name: value}`` scalar variables the file must hold with these values (a generated
        run's H, R, h_rms and seed, named by its path).
    force_variable : str or None
        The variable holding the load path (``force``; a measured run: ``force_normalized``);
        ``None``: no load path to check (a stickiness run).
    forces : numpy.ndarray or None
        Its expected values (the file's units), equal to 1e-12 relative.
    """

    title: str
    variables: tuple
    dims: tuple
    config: dict
    scalars: dict = dataclasses.field(default_factory=dict)
    force_variable: str | None = None
    forces: np.ndarray | None = None


#: scalar variables of a run file: (NetCDF type, long name, units)
SCALARS = {
    "hurst": ("f8", "Hurst exponent H", "1"),
    "radius": ("f8", "sphere radius R (inf: nominally flat, periodic)", "length"),
    "h_rms": ("f8", "rms roughness height", "length"),
    "seed": ("i8", "random seed of the surface", "1"),
}

def _put(nc, name: str, dtype: str, dims: tuple, values, attrs: dict) -> None:
    """One variable *name* of the open NetCDF file *nc*: its type, dimensions, values and attributes."""
    var = nc.createVariable(name, dtype, dims)
    if dims:
        var[:] = values
    else:
        var.assignValue(values)
    var.setncatts(attrs)


def _meta(meta: Variable) -> dict:
    return {"long_name": meta.long_name, "units": meta.units}


def write_run(path, out: dict, *, attrs: dict, variables: dict | None = None, stiffness_method: str | None = None,
              units: dict | None = None,
              scalars: dict | None = None, extra: dict | None = None, coordinates: tuple = (),
              kind: str = "indentation") -> None:
    """Write one run file (NetCDF4, atomic: :func:`roughcontact.study.files.provenance.write_netcdf`): the
    one run-file writer of generated, adhesive, measured and stickiness runs.

    Parameters
    ----------
    out : dict
        An indentation run: ``force`` and the per-load arrays of *variables* (``force`` in force
        units; an adhesive run's :data:`RETRACT_VARIABLES` and :data:`PULL_OFF_VARIABLES` too). A stickiness run: the arrays of :data:`STICKINESS_VARIABLES` (one per approach) and
        the scalars of :data:`STICKINESS_SCALARS`.
    variables : dict, optional
        ``{name: Variable}`` of the per-load quantities to write (an indentation run; in this order,
        :func:`roughcontact.study.quantities.variables`).
    attrs : dict
        Global attributes (provenance, settings); ``title`` is set to :data:`TITLE` (a stickiness
        run: :data:`STICKINESS_TITLE`).
    stiffness_method : str, optional
        How the stiffness was computed (named in its ``long_name``; indentation runs).
    units : dict, optional
        ``{name: (scale, units)}``: write ``out[name] * scale`` with these CF units instead of the
        study's normalised units (a measured run: ``force`` in N, ``stiffness`` in N/m, lengths
        in the scan's unit).
    scalars : dict, optional
        ``{name: value}`` of :data:`SCALARS` (a generated run's H, R, h_rms and seed).
    extra : dict, optional
        ``{name: (values, attrs)}`` further per-load variables (e.g. ``stiffness_normalized``).
    coordinates : tuple of str
        Names of *extra* per-load variables that are coordinates of the others (``force_normalized``).
    kind : str
        ``"indentation"`` (over ``force``) or ``"stickiness"`` (over ``approach``).
    """
    from . import provenance

    if kind == "stickiness":
        def fill(nc) -> None:
            """A stickiness run's attributes, its ``approach`` path and its scalars into *nc*."""
            nc.setncatts({**attrs, "title": STICKINESS_TITLE})
            count = len(out["force"])
            nc.createDimension("approach", count)
            _put(nc, "approach", "i8", ("approach",), np.arange(count), APPROACH_ATTRS)
            for name, meta in STICKINESS_VARIABLES.items():
                _put(nc, name, meta.dtype, ("approach",), np.asarray(out[name]).astype(meta.dtype), _meta(meta))
            for name, meta in STICKINESS_SCALARS.items():
                _put(nc, name, meta.dtype, (), np.asarray(out[name], dtype=meta.dtype), _meta(meta))

        provenance.write_netcdf(fill, path)
        return
    if kind != "indentation":
        raise ValueError(f"kind must be 'indentation' or 'stickiness', not {kind!r}")
    units = units or {}
    variables = variables or {}
    scalars = scalars or {}
    extra = extra or {}
    labels = " ".join((*scalars, *coordinates))

    def fill(nc) -> None:
        """The run file's attributes, dimensions and variables into the open file *nc*."""
        nc.setncatts({**attrs, "title": TITLE})
        nc.createDimension("force", len(out["force"]))
        scale, unit = units.get("force", (1.0, FORCE_ATTRS["units"]))
        _put(nc, "force", "f8", ("force",), out["force"] * scale, {**FORCE_ATTRS, "units": unit})
        for name, value in scalars.items():
            dtype, long, unit = SCALARS[name]
            _put(nc, name, dtype, (), value, {"long_name": long, "units": unit})
        for name, meta in variables.items():
            scale, unit = units.get(name, (1.0, meta.units))
            long = f"{meta.long_name} ({stiffness_method})" if name == "stiffness" else meta.long_name
            _put(nc, name, meta.dtype, ("force",), out[name] * scale if scale != 1.0 else out[name],
                 {"long_name": long, "units": unit, **({"coordinates": labels} if labels else {})})
        if "retract_force" in out:   # an adhesive run: its retract path and pull-off
            nc.createDimension("retract", len(out["retract_force"]))
            for name, meta in RETRACT_VARIABLES.items():
                _put(nc, name, meta.dtype, ("retract",), out[name], _meta(meta))
            for name, meta in PULL_OFF_VARIABLES.items():
                _put(nc, name, meta.dtype, (), out[name], _meta(meta))
        for name, (values, var_attrs) in extra.items():
            _put(nc, name, "f8", ("force",), values, var_attrs)
        for name, meta in TANGENTIAL_VARIABLES.items():   # axis poisson: per load
            if name in out:
                _put(nc, name, meta.dtype, ("force",), out[name], _meta(meta))
        if "slip_force" in out:   # axis friction: the partial-slip paths
            for dim, (dtype, dim_attrs) in SLIP_COORDS.items():
                nc.createDimension(dim, len(out[dim]))
                _put(nc, dim, dtype, (dim,), out[dim], dim_attrs)
            for name, meta in SLIP_VARIABLES.items():
                _put(nc, name, meta.dtype, meta.dims, out[name], _meta(meta))
        if out.get("histograms"):   # fields.histograms: per load of the histograms
            _put_histograms(nc, out["histograms"])
        for index, kept in sorted(out.get("fields", {}).items()):   # fields.at: one group per kept load
            _put_fields(nc, index, kept)

    provenance.write_netcdf(fill, path)


def _put_histograms(nc, histograms: dict) -> None:
    """The histograms ``{load index: {"force": F, "pressure": Histogram, "gap": Histogram}}``
    (:class:`roughcontact.study.quantities.histograms.Histogram`) as :data:`HISTOGRAM_VARIABLES`."""
    loads = sorted(histograms)
    first = histograms[loads[0]]
    sizes = {"histogram_load": len(loads), "pressure_bin": len(first["pressure"].counts),
             "pressure_edge": len(first["pressure"].edges), "gap_bin": len(first["gap"].counts),
             "gap_edge": len(first["gap"].edges)}
    for dim in HISTOGRAM_DIMS:
        nc.createDimension(dim, sizes[dim])
    dtype, attrs = HISTOGRAM_COORDS["histogram_load"]
    _put(nc, "histogram_load", dtype, ("histogram_load",), np.asarray(loads), attrs)
    values = {"histogram_force": [histograms[i]["force"] for i in loads],
              "pressure_histogram": [histograms[i]["pressure"].counts for i in loads],
              "pressure_bin_edges": [histograms[i]["pressure"].edges for i in loads],
              "gap_histogram": [histograms[i]["gap"].counts for i in loads],
              "gap_bin_edges": [histograms[i]["gap"].edges for i in loads]}
    for name, meta in HISTOGRAM_VARIABLES.items():
        _put(nc, name, meta.dtype, meta.dims, np.asarray(values[name]).astype(meta.dtype), _meta(meta))


def _put_fields(nc, index: int, kept: dict) -> None:
    """The contact fields of load *index* (``kept``: the :data:`FIELD_VARIABLES` on the window, its
    ``row_start``, ``column_start``, ``cell_size`` and ``force``) as the group :data:`FIELD_GROUP`."""
    group = nc
    for part in FIELD_GROUP.format(index=index).split("/"):
        group = group.createGroup(part)
    rows, cols = np.shape(kept["pressure"])
    group.createDimension("y", rows)
    group.createDimension("x", cols)
    for name, meta in FIELD_VARIABLES.items():
        var = group.createVariable(name, meta.dtype, ("y", "x"), zlib=True, complevel=4, shuffle=True)
        var[:] = np.asarray(kept[name]).astype(meta.dtype)
        var.setncatts(_meta(meta))
    group.setncatts({"load_index": int(index), "force": float(kept["force"]), "row_start": int(kept["row_start"]),
                     "column_start": int(kept["column_start"]), "cell_size": float(kept["cell_size"]),
                     "comment": "the window of the grid holding every contact cell, 2 cells wider; "
                                "row_start/column_start: its first cell on the run's grid"})
