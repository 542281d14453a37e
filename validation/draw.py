"""Figures to PNG (matplotlib, imported here only) and to CSV (every plotted number)."""

from __future__ import annotations

import csv
import pathlib
import re

from .figures import STYLES

__all__ = ["draw", "write_csv"]

_WIDTH = 6.4  # inches per panel


def draw(figure, directory) -> pathlib.Path:
    """Write ``{figure.name}.png`` into ``directory``; returns its path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = figure.panels
    fig, axes = plt.subplots(1, len(panels), figsize=(_WIDTH * len(panels), 4.8), squeeze=False)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, panel in zip(axes[0], panels, strict=True):
        for s in panel.series:
            style = dict(STYLES.get(s.solver, dict(linestyle="-", marker="o", markersize=4)))
            ax.plot(s.x, s.y, label=s.label, color=colors[s.color % len(colors)], **style)
        for x, y, text in panel.marks:
            ax.axvline(x, color="0.4", linewidth=0.8, linestyle=":")
            ax.axhline(y, color="0.4", linewidth=0.8, linestyle=":")
            # in the empty top-right corner, not over the curves
            ax.text(0.98, 0.97, _math(text) + " (dotted)", transform=ax.transAxes, ha="right", va="top",
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
        ax.set_xlabel(_math(panel.xlabel))
        ax.set_ylabel(_math(panel.ylabel))
        if panel.title:
            ax.set_title(_math(panel.title), fontsize=10)
        ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
        if not panel.legend:
            pass
        elif len(panel.series) <= 8:
            ax.legend(fontsize=7, loc="best", framealpha=0.85)
        else:  # beside the axes, not over the curves (bbox_inches="tight" keeps it in the picture)
            ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    fig.tight_layout()
    path = pathlib.Path(directory) / f"{figure.name}.png"
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


_SYMBOLS = (("A_c / (pi R^2)", r"$A_c/\pi R^2$"), ("F / (P_I pi R^2)", r"$F/P_I\pi R^2$"),
            ("F/(P_I pi R^2)", r"$F/P_I\pi R^2$"), ("H / H_0", r"$H/H_0$"), ("H / R", r"$H/R$"),
            ("P / P_I", r"$P/P_I$"), ("rho / R", r"$\rho/R$"), ("eta / R", r"$\eta/R$"),
            ("H_0", r"$H_0$"), ("a_c", r"$a_c$"), ("Fhat", r"$\hat F$"))


_PATTERN = re.compile("|".join(re.escape(p) for p, _ in sorted(_SYMBOLS, key=lambda s: -len(s[0]))))


def _math(text: str) -> str:
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
