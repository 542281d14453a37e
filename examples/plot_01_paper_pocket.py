"""
The paper's pocket pressed by a plate
=====================================

The headline pocket of Bouremel et al., "Compression of pressurised elastic pockets": a clamped silicone
sheet (Mooney-Rivlin, alpha = C2/C1 = 47/160) inflated by a liquid to Phat_I = P_I R / (E T) = 0.31, then
pressed by a rigid flat plate. This example solves its compression curve three ways: the shooting solver
(the reference), the finite elements (P2, at a few forces) and the paper's small-strain model, and draws
the plate's height, the fluid's pressure and the contact area against the force, the paper's figures 3
to 5 in one.

Run it as a script: ``python examples/plot_01_paper_pocket.py``.
"""

# %%
# Everything is in the model's own units: lengths in units of the clamp radius R, pressures as
# Phat = P R / (E T) and forces as Fhat = F / (P_I pi R^2). A number given as the rubber is the
# Mooney-Rivlin alpha.
import matplotlib.pyplot as plt
import numpy as np

from pocket import analytical, fem, shooting

ALPHA, PRESSURE = 47 / 160, 0.31  # C2/C1, Phat_I
FE_FORCES = (0.19, 0.5, 1.0, 2.0, 3.0)  # Fhat where the finite elements are solved
FORCES = np.union1d(np.linspace(0.0, 3.0, 25), FE_FORCES)  # Fhat along the curve (shooting, analytical)
KEYS = ("height_ratio", "pressure_ratio", "contact_area")


# %%
# Each solver's ``compression_curve`` inflates the pocket once and then raises the force step by step,
# each state starting from the one before. The liquid keeps its volume, so the pressure rises as the
# plate flattens the dome. The shooting solver integrates the membrane equations from the contact edge
# to the clamp and adjusts the unknowns (the contact radius, the stretch there and the pressure) until
# the sheet meets the clamp with the volume it started with. The finite elements minimise the sheet's
# energy on a mesh whose node follows the contact edge. The analytical model linearises the sheet
# about the flat state: good at small forces, off at large ones.
def main() -> dict:
    """Solve the curve with the three solvers and print it; returns ``{solver: [state, ...]}`` with the
    forces ``FORCES`` (shooting, analytical) and ``FE_FORCES`` (fem)."""
    states = {"shooting": shooting.compression_curve(ALPHA, PRESSURE, FORCES),
              "fem": fem.compression_curve(ALPHA, PRESSURE, FE_FORCES, elements=64),
              "analytical": analytical.compression_curve(ALPHA, PRESSURE, FORCES)}
    reference = {s.force: s for s in states["shooting"]}  # FORCES holds each of FE_FORCES exactly
    print(f"alpha = {ALPHA:.5g}, Phat_I = {PRESSURE}: H0/R = {states['shooting'][0].inflated.height:.6f}, "
          f"V/R^3 = {states['shooting'][0].volume:.6f}")
    print(f"{'Fhat':>5} {'H/H0 shooting':>14} {'H/H0 FE':>12} {'P/P_I shooting':>15} {'P/P_I FE':>12} "
          f"{'A_c/piR^2':>10} {'FE / shooting - 1 (P)':>22}")
    for f in states["fem"]:
        s = reference[f.force]
        print(f"{f.force:>5.2f} {s.height_ratio:>14.8f} {f.height_ratio:>12.8f} {s.pressure_ratio:>15.8f} "
              f"{f.pressure_ratio:>12.8f} {s.contact_area:>10.6f} {f.pressure / s.pressure - 1:>22.2e}")
    print("F = P A_c: the flat contact zone carries the fluid's pressure to the plate. The finite elements also")
    print("sum the plate's reaction from their nodes' contact forces, a second route to the force:")
    for f in states["fem"]:
        pressure_area = f.pressure * f.contact_area / f.pressure_initial  # P A_c in units of P_I pi R^2
        print(f"  Fhat = {f.force:<5g} reaction / (P A_c) - 1 = {f.extra['force_reaction'] / pressure_area - 1:+.1e}")
    return states


# %%
# The figure: the plate's height H/H0, the pressure rise P/P_I and the contact area A_c/(pi R^2)
# against the force. The small-strain model follows the full model at small forces and departs from
# it as the sheet's stretches grow.
def draw(states: dict):
    """The three panels of the curve, one line or marker set per solver."""
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.6), layout="constrained")
    styles = {"shooting": dict(color="k", lw=1.5), "fem": dict(ls="none", marker="o", color="tab:red"),
              "analytical": dict(ls="--", color="tab:blue")}
    labels = {"height_ratio": "$H/H_0$", "pressure_ratio": "$P/P_I$", "contact_area": r"$A_c/(\pi R^2)$"}
    for ax, key in zip(axes, KEYS, strict=True):
        for name, curve in states.items():
            ax.plot([s.force for s in curve], [getattr(s, key) for s in curve], label=name, **styles[name])
        ax.set_xlabel(r"$F/(P_I \pi R^2)$")
        ax.set_ylabel(labels[key])
        ax.grid(alpha=0.3)
    axes[0].legend()
    fig.suptitle(r"Mooney-Rivlin $\alpha$ = 47/160, $\hat P_I$ = 0.31, a liquid, the flat plate")
    return fig


# %%
# Run it: the table of the finite elements beside the shooting solver, then the figure.
if __name__ == "__main__":
    draw(main())
    plt.show()
