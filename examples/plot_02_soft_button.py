"""
A soft button designed for a finger
===================================

Section 6 of Bouremel et al., "Compression of pressurised elastic pockets", designs a soft button: a
clamp radius R = 20 mm, an inflated height H0 = 10 mm, the silicone of its Table 1 (E = 1 MPa,
alpha = C2/C1 = 47/160), filled with a liquid, that a finger's 0.67 N presses to H/H0 = 0.8. The
unknowns are the initial pressure P_I and the sheet's thickness T. The paper gives rules of thumb for
them; ``pocket.apps.design`` solves the full model for them instead, once for the paper's flat plate
and once for what a finger is, a sphere of 8 mm radius. The figure is the button's feel: the force
against the travel, up to twice the design force.

Run it as a script: ``python examples/plot_02_soft_button.py``.
"""

# %%
# The inputs are physical (SI numbers, or strings with units): ``design`` turns them into the model's
# two dimensionless unknowns, Phat_I = P_I R / (E T) and Fhat = F / (P_I pi R^2). The inflated height
# depends on Phat_I alone, so it is found first (H0/R = h0(Phat_I)); then the force Fhat at which the
# button sits at H/H0 = 0.8; then P_I = F / (pi R^2 Fhat) and T = P_I R / (E Phat_I).
import matplotlib.pyplot as plt

from pocket.apps.design import design

RADIUS, HEIGHT, MODULUS, ALPHA = 0.020, 0.010, 1e6, 47 / 160  # m, m, Pa, C2/C1
FORCE, HEIGHT_RATIO, FINGERTIP = 0.67, 0.8, 0.008  # N, H/H0 at that force, m
POINTS = 10  # points of each force-travel curve
FINGERS = {"flat plate (the paper)": None,
           f"{FINGERTIP * 1e3:g} mm fingertip": {"shape": "sphere", "radius": f"{FINGERTIP * 1e3:g} mm"}}


# %%
# Each design also feeds the paper's (P_I, T) to the full model, which shows what the rules of thumb
# really give, and computes the force-travel curve with its stiffness dF/d(travel).
def main() -> dict:
    """Design the button for the plate and for the fingertip, print both; returns ``{finger: Design}``
    (``pocket.apps.design.Design``), keyed as ``FINGERS``."""
    print(f"soft button: R = {RADIUS * 1e3:g} mm, H0 = {HEIGHT * 1e3:g} mm, E = {MODULUS / 1e6:g} MPa, "
          f"alpha = {ALPHA:.5g}, H/H0 = {HEIGHT_RATIO:g} at F = {FORCE:g} N")
    designs = {}
    for finger, indenter in FINGERS.items():
        button = design(RADIUS, HEIGHT, MODULUS, ALPHA, FORCE, HEIGHT_RATIO, indenter=indenter, points=POINTS)
        designs[finger] = button
        print(f"pressed by the {finger}:")
        print(f"  initial pressure P_I = {button.pressure_initial_Pa / 1e3:.4g} kPa "
              f"(the paper's rule: {button.paper_pressure_initial_Pa / 1e3:.4g} kPa)")
        print(f"  sheet thickness  T   = {button.thickness_m * 1e3:.4g} mm "
              f"(the paper's rule: {button.paper_thickness_m * 1e3:.4g} mm)")
        print(f"  the paper's (P_I, T) in the full model: H0 = {button.paper_model_height_m * 1e3:.4g} mm, "
              f"H/H0 = {button.paper_model_height_ratio:.4g} at F")
        print(f"  stiffness at F: {button.stiffness_N_per_m:.4g} N/m; travel at F: "
              f"{HEIGHT * (1.0 - HEIGHT_RATIO) * 1e3:.3g} mm")
        print(f"  dimensionless: Phat_I = {button.pressure_initial!r}, Fhat = {button.force!r}")
    return designs


# %%
# The feel of each button: force against travel H0 - H. Both pass through the design point. The
# fingertip sinks into the dome, so its button needs a higher pressure and a thicker sheet to stop it
# at the same travel; it is stiffer at first and softer beyond the design point, where the plate's
# contact area grows fast.
def draw(designs: dict):
    """The force-travel curves, the design point marked."""
    fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
    for finger, button in designs.items():
        line, = ax.plot(button.curve_travel_m * 1e3, button.curve_force_N, marker=".", label=finger)
        ax.plot([HEIGHT * (1 - HEIGHT_RATIO) * 1e3], [FORCE], "o", mfc="none", ms=10, color=line.get_color())
    ax.set_xlabel("travel $H_0 - H$ (mm)")
    ax.set_ylabel("force $F$ (N)")
    ax.set_title(f"buttons designed for H/H0 = {HEIGHT_RATIO:g} at {FORCE:g} N (circled)")
    ax.grid(alpha=0.3)
    ax.legend()
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
