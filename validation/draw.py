"""Figures to PNG (matplotlib, imported here only) and to CSV (every plotted number).

Figures whose series name their pocket (``Series.group``) get two legends below
the panels, shared by all of them: colours are pockets, line styles and markers
are solvers. Other figures (the convergence study) keep a legend per panel.
Thin pocket lines carry dots of their colour, staggered by ``Series.layer``, so
that curves lying on each other all show.
Log axes carry plain tick labels (1, 2, 5, 10, ...), not only powers of ten.
"""

from __future__ import annotations

import csv
import math
import pathlib
import re
from typing import Any

from .plotdata import STYLES, Series

__all__ = ["PALETTE", "draw", "math_text", "write_csv"]

#: the colour cycle: matplotlib's ten, then three more, enough for one colour per pocket of the suite
PALETTE = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
           "#17becf", "navy", "darkgoldenrod", "teal", "maroon", "olive", "darkviolet", "saddlebrown", "deeppink",
           "slategray")
_WIDTH = 6.4  # inches per panel
_EMPHASIS = "0.15"  # the headline pocket's colour: near black
_BROAD = 3.4  # the headline pocket's line width
_FALLBACK = dict(linestyle="-", marker="o", markersize=4)
_DOTS = dict(marker="o", markersize=4.0)  # on a thin pocket line
_DOT_STEP = 0.07  # between dots, as a fraction of the axes' diagonal
_GOLDEN = 0.618034  # layer k's first dot at frac(k * _GOLDEN) of a step: no two layers alike


def _style(series, colors) -> dict:
    style = dict(STYLES.get(series.solver, _FALLBACK))
    line = style.get("linestyle") != "none"
    style["zorder"] = 3 if not line else 1.5 if series.emphasis else 2
    style["color"] = _EMPHASIS if series.emphasis else colors[series.color % len(colors)]
    if series.emphasis and line:
        style["linewidth"] = _BROAD
    elif series.group and style.get("linestyle") == "-":
        style.update(_DOTS, markevery=(_DOT_STEP * (series.layer * _GOLDEN % 1.0), _DOT_STEP))
    return style


def _tick(value: float, _=None) -> str:
    """A log axis' tick label: plain from 0.001 to 10000 (0.01, 2, 50), else a power of ten (10^-5, 2 x 10^-7)."""
    if 1e-3 <= value <= 1e4:
        return f"{value:g}"
    exponent = math.floor(math.log10(value) + 1e-9)
    mantissa = round(value / 10.0**exponent, 6)
    return f"$10^{{{exponent}}}$" if mantissa == 1 else f"${mantissa:g}\\times 10^{{{exponent}}}$"


def _log_ticks(axis, low: float, high: float) -> None:
    """Ticks at 1, 2, 5 times powers of ten over up to three decades (else at powers of ten), labelled by _tick."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    subs = (1.0, 2.0, 5.0) if math.log10(high / low) <= 3.0 else (1.0,)
    axis.set_major_locator(LogLocator(base=10.0, subs=subs))
    axis.set_major_formatter(FuncFormatter(_tick))
    axis.set_minor_formatter(NullFormatter())


def _legends(fig, figure, colors) -> None:
    """The two shared legends below the panels: pockets by colour, solvers by style."""
    from matplotlib.lines import Line2D

    groups: dict[str, Series] = {}
    solvers: dict[str, Series] = {}
    for panel in figure.panels:
        for s in panel.series:
            groups.setdefault(s.group, s)
            solvers.setdefault(s.solver, s)
    lines: dict[str, Any] = {"linestyle": "-", "marker": "", "linewidth": 1.4}
    pockets = [Line2D([], [], **{**lines, "color": _style(s, colors)["color"],
                                 **({"linewidth": _BROAD} if s.emphasis else _DOTS)}) for s in groups.values()]
    styles = [Line2D([], [], **{**STYLES.get(name, _FALLBACK), "color": "0.3"}) for name in solvers]
    first = fig.legend(pockets, [math_text(g) for g in groups], loc="upper left", bbox_to_anchor=(0.02, 0.0),
                       ncol=2 if len(groups) > 4 else 1, fontsize=8, title="pockets (colour)", title_fontsize=8,
                       frameon=False)
    fig.legend(styles, list(solvers), loc="upper right", bbox_to_anchor=(0.98, 0.0), fontsize=8,
               title="solvers (line, marker)", title_fontsize=8, frameon=False)
    fig.add_artist(first)


def draw(figure, directory) -> pathlib.Path:
    """Write ``{figure.name}.png`` into ``directory``; returns its path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = figure.panels
    fig, axes = plt.subplots(1, len(panels), figsize=(_WIDTH * len(panels), 4.8), squeeze=False)
    colors = PALETTE
    shared = any(s.group for panel in panels for s in panel.series)
    for ax, panel in zip(axes[0], panels, strict=True):
        for s in panel.series:
            ax.plot(s.x, s.y, label=math_text(s.label), **_style(s, colors))
        for x, y, text in panel.marks:
            if x is not None:
                ax.axvline(x, color="0.4", linewidth=0.8, linestyle=":")
            if y is not None:
                ax.axhline(y, color="0.4", linewidth=0.8, linestyle=":")
            if text:  # in the empty top-right corner, not over the curves
                ax.text(0.98, 0.97, math_text(text) + " (dotted)", transform=ax.transAxes, ha="right", va="top",
                        fontsize=8, color="0.3")
        if "x" in panel.log:
            ax.set_xscale("log")
        if "y" in panel.log:
            ax.set_yscale("log")
        if panel.equal:
            ax.set_aspect("equal", adjustable="box")
        if panel.limits:
            ax.set_xlim(*panel.limits[0])
            ax.set_ylim(*panel.limits[1])
        if "x" in panel.log:
            _log_ticks(ax.xaxis, *ax.get_xlim())
        if "y" in panel.log:
            _log_ticks(ax.yaxis, *ax.get_ylim())
        ax.set_xlabel(math_text(panel.xlabel))
        ax.set_ylabel(math_text(panel.ylabel))
        if panel.title:
            ax.set_title(math_text(panel.title), fontsize=10)
        ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
        if panel.legend and not shared:
            ax.legend(fontsize=7, loc="best", framealpha=0.85)
    fig.tight_layout()
    if shared:
        _legends(fig, figure, colors)
    path = pathlib.Path(directory) / f"{figure.name}.png"
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


_SYMBOLS = (("A_c / (pi R^2)", r"$A_c/(\pi R^2)$"), ("F / (P_I pi R^2)", r"$F/(P_I\pi R^2)$"),
            ("F/(P_I pi R^2)", r"$F/(P_I\pi R^2)$"), ("H / H_0", r"$H/H_0$"), ("H / R", r"$H/R$"),
            ("P / P_I", r"$P/P_I$"), ("rho / R", r"$\rho/R$"), ("eta / R", r"$\eta/R$"),
            ("H_0", r"$H_0$"), ("a_c", r"$a_c$"), ("Fhat", r"$\hat F$"), ("Phat_I", r"$\hat P_I$"),
            ("alpha", r"$\alpha$"), ("lambda_1", r"$\lambda_1$"), ("<=", r"$\leq$"),
            ("rho / rho_c", r"$\rho/\rho_c$"), ("p_c / P", r"$p_c/P$"), ("R_s", r"$R_s$"),
            ("F / (E T R)", r"$F/(ETR)$"), ("1 - H / lambda_I", r"$1 - H/\lambda_I$"))


_PATTERN = re.compile("|".join(re.escape(p) for p, _ in sorted(_SYMBOLS, key=lambda s: -len(s[0]))))


def math_text(text: str) -> str:
    """The paper's symbols in matplotlib mathtext (one pass: a replacement is not replaced again)."""
    return _PATTERN.sub(lambda m: dict(_SYMBOLS)[m.group(0)], text)


def write_csv(figure, directory) -> pathlib.Path:
    """Write ``{figure.name}.csv``: one row per plotted point (panel, series, solver, x, y)."""
    path = pathlib.Path(directory) / f"{figure.name}.csv"
    with path.open("w", newline="") as handle:
        out = csv.writer(handle)
        out.writerow(["panel", "series", "solver", "x", "y", "x_label", "y_label"])
        for k, panel in enumerate(figure.panels):
            for s in panel.series:
                for x, y in zip(s.x, s.y, strict=True):
                    out.writerow([panel.title or k, s.label, s.solver, repr(float(x)), repr(float(y)),
                                  panel.xlabel, panel.ylabel])
    return path
