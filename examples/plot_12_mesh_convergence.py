"""
Mesh convergence of the finite elements
=======================================

The finite-element solver is checked against the shooting solver, which integrates the membrane
equations to 1e-10: its error on a sequence of meshes must fall at the rate the theory of the elements
predicts. For Lagrange elements of order p on meshes where the solution is smooth inside every
element, smooth outputs (the pressure, the heights, the volume) converge at O(h^2p): 2 for P1, 4 for
P2. The contact edge, where the meridian's curvature jumps, would break that smoothness if it fell
inside an element; pocket's mesh keeps a node on it. This example measures the error of the pressure
and the plate's height of the paper's pocket at Fhat = 0.19 (its figure 2b) on meshes of 8 to 64
elements, and fits the observed order.

Run it as a script: ``python examples/plot_12_mesh_convergence.py``.
"""

# %%
# ``fem.default_mesh(n, order)`` is the solver's mesh family, graded towards the axis, where the pole
# stretch needs it; the edge-fitted contact maps it onto the free part of the sheet. h is the largest
# element of the free part.
import matplotlib.pyplot as plt
import numpy as np

from pocket import fem, shooting

ALPHA, PRESSURE, FORCE = 47 / 160, 0.31, 0.19  # C2/C1, Phat_I, Fhat
ELEMENTS = (8, 16, 32, 64)  # mesh sizes
KEYS = ("pressure", "height")


def largest_element(state) -> float:
    """h: the largest element of the free part (the profile holds every node; P2's midside nodes skipped)."""
    vertices = state.profile.r[:: state.extra["order"]]
    return float(np.diff(vertices)[1:].max())  # the first element, in contact, holds the exact flat solution


# %%
# The observed order is the slope of log(error) against log(h), fitted by least squares
# (``np.polyfit``) over the meshes.
def main() -> dict:
    """Solve the state on each mesh with P1 and P2, print the errors and observed orders; returns
    ``{order: {"h": sizes, key: errors for key in KEYS, "orders": {key: observed order}}}``."""
    reference = shooting.compress(ALPHA, PRESSURE, FORCE)
    out = {}
    for order in (1, 2):
        states = [fem.compress(ALPHA, PRESSURE, FORCE, mesh=fem.default_mesh(n, order), order=order)
                  for n in ELEMENTS]
        result = {"h": np.array([largest_element(s) for s in states])}
        for key in KEYS:
            result[key] = np.array([abs(getattr(s, key) / getattr(reference, key) - 1) for s in states])
        result["orders"] = {key: float(np.polyfit(np.log(result["h"]), np.log(result[key]), 1)[0]) for key in KEYS}
        out[order] = result
        print(f"P{order}: {'elements':>8} {'h':>8} {'|P/P_shooting - 1|':>19} {'|H/H_shooting - 1|':>19}")
        for n, h, ep, eh in zip(ELEMENTS, result["h"], result["pressure"], result["height"], strict=True):
            print(f"    {n:>8} {h:>8.4f} {ep:>19.3e} {eh:>19.3e}")
        print(f"    observed order: pressure {result['orders']['pressure']:.2f}, height "
              f"{result['orders']['height']:.2f} (theory {2 * order})")
    return out


# %%
# The figure: the errors against h on logarithmic axes, with the theory's slopes for comparison.
def draw(out: dict):
    """Error against element size for both orders and both outputs."""
    fig, ax = plt.subplots(figsize=(6.5, 4.2), layout="constrained")
    for order, result in out.items():
        for key, marker in zip(KEYS, "os", strict=True):
            ax.loglog(result["h"], result[key], marker=marker, label=f"P{order} {key}, order "
                      f"{result['orders'][key]:.2f}")
        h = result["h"]
        ax.loglog(h, result["pressure"][-1] * (h / h[-1]) ** (2 * order), ":", color="0.4")
    ax.set_xlabel("h (largest element of the free part, units R)")
    ax.set_ylabel("|FE / shooting - 1|")
    ax.set_title("dotted: slopes 2 and 4", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
