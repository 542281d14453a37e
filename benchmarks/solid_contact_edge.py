"""How well the solid places the contact edge: its contact radius under the plate against the mesh.

    python benchmarks/solid_contact_edge.py

The headline rubber (Mooney-Rivlin alpha = 47/160) pressed by the plate at Fhat = 0.5, for sample 1
(T/R = 0.0125, Phat_I = 0.322) and sample 4 (T/R = 0.08, Phat_I = 0.0503) at P_I = 5 kPa, meshed by 32 to
256 elements along the radius (two layers): the contact radius (the edge extrapolated from the gaps beyond
the active set, ``pocket.solid.results``), its spread over the meshes, and P/P_I beside it. The spread is the
figure ``pocket.solid.results`` quotes.
"""

from __future__ import annotations

import numpy as np

from pocket import solid
from pocket.core.materials import mooney_rivlin

CASES = (("sample 1", 0.0125, 0.322), ("sample 4", 0.08, 0.0503))
MESHES = (32, 64, 128, 256)
FORCE = 0.5


def main():
    for name, t, phat in CASES:
        states = [solid.compress(mooney_rivlin(47 / 160), phat, FORCE, thickness_ratio=t, elements=n) for n in MESHES]
        radii = np.array([s.contact_radius for s in states])
        print(f"{name} (T/R = {t:g}, Phat_I = {phat:g}), Fhat = {FORCE:g}:")
        for n, s in zip(MESHES, states, strict=True):
            print(f"  {n:4d} elements: contact radius {s.contact_radius:.5f} R, A_c {s.contact_area:.5f}, "
                  f"P/P_I {s.pressure_ratio:.6f}")
        print(f"  spread of the contact radius: +-{0.5 * np.ptp(radii):.1e} R ({np.ptp(radii) / radii.mean():.1%} "
              f"relative, {2 * np.ptp(radii) / radii.mean():.1%} in A_c)")


if __name__ == "__main__":
    main()
