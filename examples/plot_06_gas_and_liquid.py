"""
Gas against liquid
==================

A pocket filled with water keeps its volume when pressed; one filled with air does not: the air is
compressed too, (P + P_atm) V^gamma = (P_I + P_atm) V_I^gamma, with P the gauge pressure and gamma = 1
for a slow (isothermal) press, 1.4 for a fast (adiabatic) one. This example presses the paper's sample 1
(0.25 mm silicone, R = 20 mm, at P_I = 4.81 kPa) filled with each, and shows how much softer the air
makes it.

Run it as a script: ``python examples/plot_06_gas_and_liquid.py``.
"""

# %%
# The model takes the ambient pressure in its own units, Phat_atm = P_atm R / (E T): for this sheet
# E T / R = 6 (C1 + C2) T / R = 15.5 kPa, so the atmosphere is Phat_atm = 6.53, about twenty times
# Phat_I. A gas is ``pocket.core.fluids.gas(ambient, gamma)``; None is the liquid.
import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.core.fluids import gas

C1, C2, THICKNESS, RADIUS = 160e3, 47e3, 0.25e-3, 0.020  # Pa, Pa, m, m: the paper's sample 1
PRESSURE_PA, AMBIENT_PA = 4812.75, 101325.0  # P_I and the atmosphere, Pa
FORCES = np.linspace(0.0, 2.0, 11)  # Fhat


def fluids() -> dict:
    """The three fillings: ``{name: fluid}`` (None: the liquid), the gas's ambient pressure as Phat_atm."""
    scale = 6 * (C1 + C2) * THICKNESS / RADIUS  # E T / R, Pa
    return {"liquid": None, "air, isothermal": gas(AMBIENT_PA / scale, 1.0),
            "air, adiabatic": gas(AMBIENT_PA / scale, 1.4)}


# %%
# Each state of a gas-filled pocket holds the gas law: the solver closes the volume with it instead of
# with V = V_I. The script checks it on every state: the gas law's residual is the largest relative
# departure of (P + P_atm) V^gamma from its value at rest, (P_I + P_atm) V_I^gamma, along the curve.
def main() -> dict:
    """Press the pocket filled with each fluid, print the comparison; returns ``{fluid: [state at each of
    FORCES]}``."""
    alpha, phat = C2 / C1, PRESSURE_PA / (6 * (C1 + C2) * THICKNESS / RADIUS)
    out = {name: shooting.compression_curve(alpha, phat, FORCES, fluid=fluid) for name, fluid in fluids().items()}
    print(f"sample 1 at P_I = {PRESSURE_PA / 1e3:g} kPa: Phat_I = {phat:.5f}, "
          f"Phat_atm = {fluids()['air, isothermal'].ambient:.4f}")
    print(f"{'fluid':<16} {'P/P_I at Fhat=2':>16} {'H/H0 at Fhat=2':>15} {'V/V_I at Fhat=2':>16} "
          f"{'gas law residual':>17}")
    for name, states in out.items():
        fluid, first, last = states[0].fluid, states[0], states[-1]
        law = "-"
        if fluid.is_gas:
            held = [(s.pressure + fluid.ambient) * s.volume**fluid.gamma for s in states]
            law = f"{max(abs(h / held[0] - 1) for h in held):.1e}"
        print(f"{name:<16} {last.pressure_ratio:>16.5f} {last.height_ratio:>15.5f} {last.volume / first.volume:>16.5f} "
              f"{law:>17}")
    return out


# %%
# The figure: the pressure rise, the height and the volume against the force. The liquid's pressure
# rises most; the air gives way, more so when it is compressed isothermally (gamma = 1) than
# adiabatically.
def draw(out: dict):
    """P/P_I, H/H0 and V/V_I against the force for each fluid."""
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.6), layout="constrained")
    for name, states in out.items():
        axes[0].plot(FORCES, [s.pressure_ratio for s in states], "o-", ms=3, label=name)
        axes[1].plot(FORCES, [s.height_ratio for s in states], "o-", ms=3, label=name)
        axes[2].plot(FORCES, [s.volume / states[0].volume for s in states], "o-", ms=3, label=name)
    for ax, label in zip(axes, ("$P/P_I$", "$H/H_0$", "$V/V_I$"), strict=True):
        ax.set_xlabel(r"$F/(P_I \pi R^2)$")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0].legend()
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
