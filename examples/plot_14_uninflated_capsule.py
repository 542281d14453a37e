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
and its force is reported as F / (E T R). The shooting solver draws the curves; the finite elements, solved
independently, are the markers. A dashed line is where the pole's patch is compressive (flagged ``wrinkled``:
outside membrane theory there, a real wall wrinkles under the plate). The force spans decades: a log scale.

Run it as a script: ``python examples/plot_14_uninflated_capsule.py``.
"""

# %%
# The uninflated capsule from where its range starts: a height above it is refused, quoting the start.
import re

import matplotlib.pyplot as plt
import numpy as np

from pocket import fem, shooting
from pocket.core.errors import OutOfRangeError

NEO = 0.0  # a neo-Hookean wall (Mooney-Rivlin alpha = 0)

try:
    shooting.compress_height(NEO, 0.0, 0.95, geometry="capsule")
except OutOfRangeError as refused:
    print(refused)
    start = float(re.search(r"start deeper, at height = (\S+):", str(refused)).group(1))
uninflated = [shooting.compress_height(NEO, 0.0, h, geometry="capsule") for h in np.linspace(start, 0.3, 20)]
markers = [fem.compress_height(NEO, 0.0, h, geometry="capsule") for h in (0.7, 0.5, 0.3)]

# %%
# The slightly inflated capsule, by the finite elements: its first branch by force up to the end it quotes, then
# its second branch by height, from the start it quotes for a height in the gap.
PHAT = 0.01
try:
    fem.compress_height(NEO, PHAT, 0.9, geometry="capsule")
except OutOfRangeError as refused:
    print(refused)
    first_end, second_start = (float(v) for v in re.findall(r"at (?:force|plate height h/R) = (\S+) to", str(refused)))
top = fem.inflate(NEO, PHAT, geometry="capsule").height
first = [fem.compress_height(NEO, PHAT, h, geometry="capsule") for h in np.linspace(top, first_end, 8)[1:]]
second = [fem.compress_height(NEO, PHAT, h, geometry="capsule") for h in np.linspace(second_start, 0.3, 10)]


def draw(axes, states, color, label, marker=None):
    """F / (E T R) against the compression 1 - H / lambda_I: a dashed line through every state, solid where taut."""
    x = np.array([1.0 - s.height / s.inflated.stretch_pole for s in states])
    y = np.array([s.extra["force_ETR"] for s in states])
    if marker:
        axes.plot(x, y, marker, color=color, label=label)
        return
    axes.plot(x, y, "--", color=color, lw=1.0)
    taut = np.array([not s.wrinkled for s in states])
    axes.plot(np.where(taut, x, np.nan), np.where(taut, y, np.nan), "-", color=color, label=label)


fig, axes = plt.subplots(figsize=(7, 4.5))
draw(axes, first, "C1", f"Phat_I = {PHAT}: from the touch")
draw(axes, second, "C2", f"Phat_I = {PHAT}: deeper")
draw(axes, uninflated, "C0", "P_I = 0 (shooting)")
draw(axes, markers, "C0", "P_I = 0 (finite elements)", "x")
axes.axvline(1.0 - start, color="0.6", lw=0.8)
axes.set_yscale("log")
axes.set_xlabel("compression 1 - H / lambda_I")
axes.set_ylabel("F / (E T R)")
axes.set_title("An uninflated capsule's states start at a compression of "
               f"{100 * (1 - start):.1f} %")
axes.legend()
fig.tight_layout()
plt.show()
