"""
An uninflated capsule between two plates: where its states start
================================================================

A capsule filled with a liquid and not inflated (P_I = 0), the usual microcapsule test, has no membrane state
at a small compression: the patch under a plate is compressed towards its edge as it flattens, and nothing but an
inflation's tension would hold it. Its states start deep, where the free membrane's own stretching (the liquid
must be enclosed by more than the sphere's area) holds the contact edge taut: at a compression of about 21 %
for a neo-Hookean wall. A slightly inflated capsule (Phat_I = 0.01) has two branches: one pressed from the touch,
ending at a compression of 5.6 %, and one deeper, which tends to the uninflated capsule's.

At P_I = 0 Fhat = F / (P_I pi R^2) is undefined: the capsule is pressed by the plates' height (H R, half the gap)
or by a force given as F / (E T R), and its force is reported as ``force_ETR``. The shooting solver draws the
curves; the finite elements, solved independently, are the markers. A dashed line is where the pole's patch is
compressive (flagged ``wrinkled``: outside membrane theory there, a real wall wrinkles under the plate). The
force spans decades: a log scale.

Run it as a script: ``python examples/plot_14_uninflated_capsule.py``.
"""

# %%
# The uninflated capsule from where its range starts (a height above it is refused, quoting the start), by the
# shooting solver; the finite elements at three heights and under a force of 1 E T R.
import re

import matplotlib.pyplot as plt
import numpy as np

from pocket import fem, shooting
from pocket.core.errors import OutOfRangeError

NEO = 0.0  # a neo-Hookean wall (Mooney-Rivlin alpha = 0)
PHAT = 0.01  # the slightly inflated capsule's Phat_I


def quoted(solve, pattern: str) -> tuple[float, ...]:
    """The numbers ``pattern`` reads from the refusal of ``solve()``, printed."""
    try:
        solve()
    except OutOfRangeError as refused:
        print(refused)
        return tuple(float(v) for v in re.findall(pattern, str(refused)))
    raise AssertionError("a state where the range has none")


def main() -> dict:
    """The uninflated capsule (shooting, and the finite elements' markers) and the slightly inflated one's two
    branches (the finite elements), as lists of states; the uninflated range's start H* / R."""
    (start,) = quoted(lambda: shooting.compress_height(NEO, 0.0, 0.95, geometry="capsule"),
                      r"start deeper, at height = (\S+):")
    uninflated = [shooting.compress_height(NEO, 0.0, h, geometry="capsule") for h in np.linspace(start, 0.3, 20)]
    markers = [fem.compress_height(NEO, 0.0, h, geometry="capsule") for h in (0.7, 0.5, 0.3)]
    markers += fem.compression_curve(NEO, 0.0, [1.0], geometry="capsule", force_unit="ETR")
    # the slightly inflated capsule: its first branch by height up to the end it quotes, its second from the start
    first_end, second_start = quoted(lambda: fem.compress_height(NEO, PHAT, 0.9, geometry="capsule"),
                                     r"at plate height h/R = (\S+) to")
    top = fem.inflate(NEO, PHAT, geometry="capsule").height
    first = [fem.compress_height(NEO, PHAT, h, geometry="capsule") for h in np.linspace(top, first_end, 8)[1:]]
    second = [fem.compress_height(NEO, PHAT, h, geometry="capsule") for h in np.linspace(second_start, 0.3, 10)]
    return {"start": start, "uninflated": uninflated, "markers": markers, "first": first, "second": second}


# %%
# The figure: F / (E T R) against the compression 1 - H / lambda_I, dashed through every state and solid where
# the membrane is taut.
def _curve(axes, states, color, label, marker=None):
    x = np.array([1.0 - s.height / s.inflated.stretch_pole for s in states])
    y = np.array([s.extra["force_ETR"] for s in states])
    if marker:
        axes.plot(x, y, marker, color=color, label=label)
        return
    axes.plot(x, y, "--", color=color, lw=1.0)
    taut = np.array([not s.wrinkled for s in states])
    axes.plot(np.where(taut, x, np.nan), np.where(taut, y, np.nan), "-", color=color, label=label)


def draw(numbers: dict):
    """The uninflated capsule's force-compression curve beside the slightly inflated one's two branches."""
    fig, axes = plt.subplots(figsize=(7, 4.5), layout="constrained")
    _curve(axes, numbers["first"], "C1", f"Phat_I = {PHAT}: from the touch")
    _curve(axes, numbers["second"], "C2", f"Phat_I = {PHAT}: deeper")
    _curve(axes, numbers["uninflated"], "C0", "P_I = 0 (shooting)")
    _curve(axes, numbers["markers"], "C0", "P_I = 0 (finite elements)", "x")
    axes.axvline(1.0 - numbers["start"], color="0.6", lw=0.8)
    axes.set_yscale("log")
    axes.set_xlabel("compression 1 - H / lambda_I")
    axes.set_ylabel("F / (E T R)")
    axes.set_title(f"An uninflated capsule's states start at a compression of {100 * (1 - numbers['start']):.1f} %")
    axes.legend()
    axes.grid(alpha=0.3)
    return fig


# %%
# Run it.
if __name__ == "__main__":
    draw(main())
    plt.show()
