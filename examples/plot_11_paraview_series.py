"""
A load path for ParaView
========================

Numbers are not the whole story: ParaView shows the pressed sheet in 3-D, coloured by its stretches
or tensions, and plays the load path as an animation. ``pocket.apps.vtk`` writes any list of states as
such a series: per step the profile (a line), the surface of revolution and the indenter's surface
(``.vtu`` files), and a ``.pvd`` collection of each whose time is the force. This example presses the
paper's pocket with an 8 mm fingertip (a sphere, R_s = 0.4 R) from rest to Fhat = 1, writes the series,
reads it back with pyvista and draws it.

Run it as a script: ``python examples/plot_11_paraview_series.py [OUTPUT_FOLDER]`` (without a folder,
the files go to a temporary one); in ParaView, open ``OUTPUT_FOLDER/vtk/surface.pvd`` and
``indenter.pvd`` and press play.
"""

# %%
# Every step of a series has the same points: each profile is resampled on one set of Lagrangian
# radii (with every step's contact edge among them), so a point is one material point throughout the
# series and ParaView can interpolate between steps. Lengths are in units of R.
import os
import pathlib
import sys
import tempfile

import matplotlib.pyplot as plt
import numpy as np
import pyvista

from pocket import shooting
from pocket.apps.vtk.files import write_series
from pocket.core.indenters import Sphere

ALPHA, PRESSURE, FINGERTIP = 47 / 160, 0.31, 0.4  # C2/C1, Phat_I, R_s/R
STEPS, FORCE = 6, 1.0  # states of the series, from rest to this Fhat
if not os.environ.get("DISPLAY"):  # no screen: VTK draws off screen, through EGL
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    pyvista.OFF_SCREEN = True


# %%
# ``write_series`` writes the folder whole or not at all, and refuses to replace a folder it did not
# write. pyvista's PVD reader then reads the collection back: its time values are the forces, and each
# file's field data holds the state's scalars (``force``, ``pressure``, ``height``, ...).
def main(out: pathlib.Path) -> dict:
    """Press the pocket, write its series into ``out / "vtk"``, read it back and print what it holds; returns
    ``{"states": the states, "vtk": the series' folder, "read": {"force": [...], "pressure": [...]} read back
    from the surface files' field data}``."""
    forces = np.linspace(0.0, FORCE, STEPS)
    states = shooting.compression_curve(ALPHA, PRESSURE, forces, indenter=Sphere(FINGERTIP))
    folder = write_series(out / "vtk", states, times=forces)
    reader = pyvista.get_reader(folder / "surface.pvd")
    read: dict = {"force": [], "pressure": []}
    for time in reader.time_values:
        reader.set_active_time_value(time)
        surface = reader.read()[0]
        for key in read:
            read[key].append(float(surface.field_data[key][0]))
    print(f"wrote vtk/ in the output folder: {len(list(folder.glob('*.vtu')))} .vtu files and "
          f"{', '.join(sorted(p.name for p in folder.glob('*.pvd')))}")
    print(f"each surface: {surface.n_points} points, {surface.n_cells} cells, point arrays "
          f"{', '.join(surface.point_data.keys())}")
    print(f"{'time (Fhat)':>12} {'force read back':>16} {'Phat read back':>15} {'Phat solved':>12}")
    for time, force, pressure, state in zip(reader.time_values, read["force"], read["pressure"], states, strict=True):
        print(f"{time:>12g} {force:>16.12g} {pressure:>15.12g} {state.pressure:>12.12g}")
    print(f"VTK series ({STEPS} steps, time = Fhat, lengths in units of R): vtk/surface.pvd, vtk/indenter.pvd")
    return {"states": states, "vtk": folder, "read": read}


# %%
# The pressed sheet in 3-D: the last step's surface coloured by the meridional stretch lambda_1, the
# fingertip above it, as ParaView would show them.
def scene(folder: pathlib.Path) -> pyvista.Plotter:
    """A plotter of the series' last step in ``folder``: the sheet coloured by lambda_1, and the indenter."""
    last = sorted(folder.glob("step_*_surface.vtu"))[-1]
    plotter = pyvista.Plotter(window_size=(900, 520))
    plotter.add_mesh(pyvista.read(last), scalars="lambda_1", cmap="viridis", smooth_shading=True,
                     scalar_bar_args={"title": ""})
    plotter.add_text(f"the sheet at Fhat = {FORCE:g}, coloured by its meridional stretch lambda_1", font_size=10)
    plotter.add_mesh(pyvista.read(str(last).replace("_surface", "_indenter")), color="wheat", opacity=0.5)
    plotter.camera_position = [(2.2, -2.2, 2.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]
    return plotter


# %%
# And the profiles of every step, read back from the profile files (x is rho, z is eta): the sheet
# wraps around the fingertip as the force grows.
def draw(numbers: dict):
    """The profile of every step of the series, read back from its files."""
    fig, ax = plt.subplots(figsize=(7, 3.2), layout="constrained")
    for path, force in zip(sorted(numbers["vtk"].glob("step_*_profile.vtu")), numbers["read"]["force"],
                           strict=True):
        points = pyvista.read(path).points
        ax.plot(points[:, 0], points[:, 2], label=f"Fhat = {force:g}")
    ax.set_xlabel(r"$\rho/R$")
    ax.set_ylabel(r"$\eta/R$")
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


# %%
# Run it: the files go to the folder given on the command line, or to a temporary one.
# sphinx_gallery_thumbnail_number = 2
if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(folder)
        numbers = main(out)
        draw(numbers)
        plotter = scene(numbers["vtk"])
        plotter.show()
    plt.show()
