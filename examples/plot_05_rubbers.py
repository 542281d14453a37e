"""
Five rubbers at the same small-strain modulus
=============================================

pocket knows five strain-energy laws: Mooney-Rivlin, neo-Hookean, Yeoh, Gent and Ogden. This example
takes a typical rubber of each (the paper's silicone for Mooney-Rivlin, Ogden's fit of Treloar's rubber,
...), scales each to the same small-strain shear modulus mu_0, and inflates and presses the same pocket
with all five. At small strain they are one material; at large strain each law shows its own
character: the neo-Hookean sheet has a pressure maximum, the Gent sheet locks, the Yeoh sheet softens
and then stiffens.

Run it as a script: ``python examples/plot_05_rubbers.py``.
"""

# %%
# ``LAWS`` is the registry of the laws; each carries an example rubber in Pa. ``check`` builds the
# ``Material`` and ``scaled`` divides its stresses by mu_0: in the model's units E = 3 mu_0 = 3, and the
# pressure Phat = P R / (E T) means the same for every law.
import matplotlib.pyplot as plt
import numpy as np

from pocket import shooting
from pocket.core.materials import LAWS, check

VOLUMES = np.linspace(0.05, 3.0, 12)  # V/R^3 of the inflation curves
SMALL = 1e-4  # Phat of the small-strain comparison
PRESSURE, FORCES = 0.2, (0.1, 0.25, 0.5, 1.0, 1.5, 2.0)  # Phat_I and Fhat of the compression curves


def rubbers() -> dict:
    """Each law's example rubber in units of mu_0: ``{law: Material}``."""
    return {law: check(law, dict(definition.example)).scaled() for law, definition in LAWS.items()}


# %%
# The inflation is driven by the volume (``inflate_volume``), not the pressure, so that it passes the
# neo-Hookean pressure maximum, which pressure control cannot. The compression starts from Phat_I = 0.2,
# below that maximum, with a liquid.
def main() -> dict:
    """Inflate and press each rubber, print the comparison; returns ``{law: {"small": inflated state at
    SMALL, "inflation": [state at each of VOLUMES], "compression": [state at each of FORCES]}}``."""
    out = {}
    for law, rubber in rubbers().items():
        out[law] = {"small": shooting.inflate(rubber, SMALL),
                    "inflation": [shooting.inflate_volume(rubber, v) for v in VOLUMES],
                    "compression": shooting.compression_curve(rubber, PRESSURE, FORCES)}
    print(f"{'law':<14} {'parameters (units of mu_0)':<55} {'H0/R at Phat=1e-4':>18} {'Phat at V=3R^3':>15} "
          f"{'P/P_I at Fhat=2':>16}")
    for law, states in out.items():
        params = ", ".join(f"{k} = {', '.join(f'{x:.4g}' for x in np.atleast_1d(v))}"
                           for k, v in rubbers()[law].params)
        print(f"{law:<14} {params:<55} {states['small'].height:>18.8f} {states['inflation'][-1].pressure:>15.5f} "
              f"{states['compression'][-1].pressure_ratio:>16.5f}")
    heights = [states["small"].height for states in out.values()]
    print(f"at Phat = {SMALL:g} the five heights differ by {np.ptp(heights) / np.mean(heights):.1e} (relative), "
          f"the pole strain being {out['neo-hookean']['small'].stretch_pole - 1:.1e}")
    return out


# %%
# The figure: the pressure against the volume while inflating, and the pressure rise against the force
# under the plate.
def draw(out: dict):
    """Inflation and compression curves of the five rubbers."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.8), layout="constrained")
    for law, states in out.items():
        left.plot(VOLUMES, [s.pressure for s in states["inflation"]], "o-", ms=3, label=law)
        right.plot(FORCES, [s.pressure_ratio for s in states["compression"]], "o-", ms=3, label=law)
    left.set_xlabel("$V/R^3$")
    left.set_ylabel(r"$\hat P = P R/(E T)$")
    left.set_title("inflation", fontsize=10)
    right.set_xlabel(r"$F/(P_I \pi R^2)$")
    right.set_ylabel("$P/P_I$")
    right.set_title(rf"pressed by the plate from $\hat P_I$ = {PRESSURE:g}", fontsize=10)
    for ax in (left, right):
        ax.grid(alpha=0.3)
    left.legend()
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
