"""How well the solid places the contact edge: its contact radius and area under the plate against the mesh.

    python benchmarks/solid_contact_edge.py [--quick]

The headline rubber (Mooney-Rivlin alpha = 47/160) pressed by the plate, for sample 1 (T/R = 0.0125,
Phat_I = 0.322) and sample 4 (T/R = 0.08, Phat_I = 0.0503) at P_I = 5 kPa, at Fhat = 0.08, 0.16 and 0.32,
on the default mesh (64 elements along the radius, 4 layers), on 128 x 4 and on 256 x 8 (--quick: the
default and 128 x 4): the contact radius r_c (Lagrangian, R), the contact area A_c, the edge's own error
estimate (``extra["contact_radius_error"]``, ``pocket.solid.edgemesh``), P/P_I, and each mesh's differences
from the finest: the figures ``pocket.solid.edgemesh`` quotes. Then the same on the mesh as asked, without
the cluster that follows the edge (the extrapolation from the mesh's own nodes, as before it), for
comparison. The load average is printed: times on a busy machine are not idle times.
"""

from __future__ import annotations

import os
import sys
import time

from pocket.solid import edgemesh

from pocket import solid
from pocket.core.materials import mooney_rivlin

CASES = (("sample 1", 0.0125, 0.322), ("sample 4", 0.08, 0.0503222))
MESHES = ((64, 4), (128, 4), (256, 8))
FORCES = (0.08, 0.16, 0.32)


def curve(t, phat, elements, layers):
    tic = time.perf_counter()
    states = solid.compression_curve(mooney_rivlin(47 / 160), phat, FORCES, thickness_ratio=t, elements=elements,
                                     layers=layers)
    return states, time.perf_counter() - tic


def table(meshes):
    for name, t, phat in CASES:
        runs = {mesh: curve(t, phat, *mesh) for mesh in meshes}
        finest = runs[meshes[-1]][0]
        print(f"{name} (T/R = {t:g}, Phat_I = {phat:g}), load average {os.getloadavg()[0]:.1f}:")
        for (n, k), (states, seconds) in runs.items():
            print(f"  {n:3d} x {k} ({seconds:5.1f} s):")
            for s, f in zip(states, finest, strict=True):
                error = s.extra.get("contact_radius_error", float("nan"))
                print(f"    Fhat {s.force:.2f}: r_c {s.contact_radius:.5f} R (estimated error {error:.1e}, "
                      f"{s.contact_radius - f.contact_radius:+.1e} from the finest), A_c {s.contact_area:.5f} "
                      f"({s.contact_area / f.contact_area - 1:+.2%}), P/P_I {s.pressure_ratio:.6f} "
                      f"({s.pressure_ratio / f.pressure_ratio - 1:+.1e}), {s.extra['mesh_elements']} elements")


def main():
    meshes = MESHES[:2] if "--quick" in sys.argv else MESHES
    table(meshes)
    print("without the cluster (the mesh as asked, the edge extrapolated from its own nodes):")
    edgemesh_follow, edgemesh_ahead = edgemesh.follow, edgemesh.ahead
    edgemesh.follow = lambda model, y, control, tol: (model, y, control, 0)
    edgemesh.ahead = lambda model, y, control, force, before: (model, y, control)
    try:
        table(meshes)
    finally:
        edgemesh.follow, edgemesh.ahead = edgemesh_follow, edgemesh_ahead


if __name__ == "__main__":
    main()
