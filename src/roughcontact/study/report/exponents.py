"""The local exponents' figure (the ``exponents`` rule, :mod:`roughcontact.study.rules.exponents`): what
:func:`roughcontact.study.analysis.exponents.exponent_table` measures, drawn for the report."""
from __future__ import annotations

from .plotting import layout_with_legends, legend_below, pyplot, save_png

__all__ = ["curves", "exponents_figure"]


def curves(table, kind: str) -> list:
    """``(label, rows)`` of every combination of one surface kind in *table*, for the figure; the
    label names H and the axes that vary (a flat surface has no radius and no body exponent)."""
    sub = table[table["kind"] == kind].dropna(axis=1, how="all")
    keys = [c for c in sub.columns if c not in ("kind", "force", "local_exponent", "ci_low", "ci_high")]
    return [(", ".join(f"{k} {v:g}" for k, v in zip(keys, values) if sub[k].nunique() > 1 or k == "hurst"), rows)
            for values, rows in sub.groupby(keys, sort=True)]


def exponents_figure(table, path) -> None:
    """Local exponents ``d ln k/d ln F`` with their 95 % bands, one panel per surface kind, against
    the fractal law's 1/(H+1) (dotted) and the linear law's 1 (dashed), every line in the legend
    under its panel."""
    plt = pyplot()
    kinds = sorted(set(table["kind"])) if len(table) else []
    fig, axes = plt.subplots(1, max(1, len(kinds)), figsize=(5.5 * max(1, len(kinds)), 4), squeeze=False)
    legends = []
    for ax, kind in zip(axes[0], kinds):
        for label, curve in curves(table, kind):
            line = ax.semilogx(curve["force"], curve["local_exponent"], "o-", ms=3, label=label)[0]
            ax.fill_between(curve["force"], curve["ci_low"], curve["ci_high"], color=line.get_color(), alpha=0.2)
        for hurst in sorted(set(table.loc[table["kind"] == kind, "hurst"])):
            ax.axhline(1 / (hurst + 1), ls=":", color="0.5", lw=0.8,
                       label=f"1/(H+1) = {1 / (hurst + 1):.3g}: fractal law, eq. 11 (H = {hurst:g})")
        ax.axhline(1.0, ls="--", color="0.3", lw=0.8, label="1: linear law K ∝ p (claim (l))")
        ax.set(xlabel="F / (E* L²)", ylabel="d ln k / d ln F", title=f"{kind}: local exponents (95 % band)")
        legends.append(legend_below(ax, gap=0.62, fontsize=6))
    if not kinds:
        axes[0][0].text(0.5, 0.5, "no resolved window", ha="center")
    layout_with_legends(fig, legends, left=0.7, right=0.45, bottom=0.62, top=0.38, wspace=0.9)
    save_png(fig, path)
