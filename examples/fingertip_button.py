"""A soft button for an 8 mm fingertip: the paper's section-6 button, pressed by a sphere instead of a plate.

The button of Bouremel et al., "Compression of pressurised elastic pockets" (section 6): a clamp radius
R = 20 mm, an inflated height H0 = 10 mm, the silicone of its Table 1 (E = 1 MPa, alpha = C2/C1 = 47/160),
filled with a liquid, to sit at H/H0 = 0.8 under a finger's 0.67 N. Here the finger is what it is, a
sphere of 8 mm radius, not a flat plate. The script designs the initial pressure P_I and the sheet's
thickness T by the full model, prints them beside the paper's rules, and writes the pocket pressed from
rest to the design force as a VTK series (profile, surface and the fingertip's surface per step) for
ParaView.

    python examples/fingertip_button.py [OUTPUT_FOLDER]      (default: fingertip-button)
"""

import math
import pathlib
import sys

import numpy as np

from pocket import shooting
from pocket.apps.design import design
from pocket.apps.vtk.files import write_series
from pocket.core.indenters import Sphere

RADIUS, HEIGHT, MODULUS, ALPHA = 0.020, 0.010, 1e6, 47 / 160  # m, m, Pa, C2/C1
FORCE, HEIGHT_RATIO, FINGERTIP = 0.67, 0.8, 0.008  # N, H/H0 at that force, m
STEPS = 11  # states of the VTK series, from rest to the design force


def main(out: pathlib.Path) -> dict:
    """Design the button, print it, write its VTK series into ``out``; returns what it printed, unrounded:
    ``{"design": the design (pocket.apps.design), "states": the pressed states, "vtk": the series' folder}``."""
    button = design(RADIUS, HEIGHT, MODULUS, ALPHA, FORCE, HEIGHT_RATIO,
                    indenter={"shape": "sphere", "radius": f"{FINGERTIP * 1e3:g} mm"})
    print(f"soft button for an {FINGERTIP * 1e3:g} mm fingertip: R = {RADIUS * 1e3:g} mm, H0 = {HEIGHT * 1e3:g} mm, "
          f"E = {MODULUS / 1e6:g} MPa, H/H0 = {HEIGHT_RATIO:g} at F = {FORCE:g} N")
    print(f"  initial pressure P_I = {button.pressure_initial_Pa / 1e3:.4g} kPa "
          f"(the paper's plate rule: {button.paper_pressure_initial_Pa / 1e3:.4g} kPa)")
    print(f"  sheet thickness  T   = {button.thickness_m * 1e3:.4g} mm "
          f"(the paper's plate rule: {button.paper_thickness_m * 1e3:.4g} mm)")
    print(f"  stiffness at F: {button.stiffness_N_per_m:.4g} N/m; travel at F: "
          f"{HEIGHT * (1.0 - HEIGHT_RATIO) * 1e3:.3g} mm")
    print(f"  dimensionless: Phat_I = {button.pressure_initial!r}, Fhat = {button.force!r}, "
          f"K = R_s/R = {FINGERTIP / RADIUS:g}")
    forces = np.linspace(0.0, button.force, STEPS)
    states = shooting.compression_curve(button.material, button.pressure_initial, forces,
                                        indenter=Sphere(FINGERTIP / RADIUS))
    folder = write_series(out / "vtk", states, times=forces * button.pressure_initial_Pa * math.pi * RADIUS**2)
    print(f"  VTK series ({STEPS} steps, time = the force in N, lengths in units of R): "
          f"{folder / 'surface.pvd'}, {folder / 'indenter.pvd'}")
    return {"design": button, "states": states, "vtk": folder}


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "fingertip-button"))
