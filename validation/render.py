"""A 3-D picture of the pocket, inflated and compressed (pyvista offscreen, optional).

The surfaces are ``pocket.apps.vtkfiles.surface_mesh`` of the states (the meridian
revolved about the axis), coloured by the meridional stretch lambda_1; the
compressed pocket is shown with its plate. Returns None, with the reason, when
pyvista (the ``render`` extra) is not installed or cannot render here.
"""

from __future__ import annotations

import os
import pathlib

__all__ = ["render_pocket"]

_SIZE = (1400, 600)


def render_pocket(inflated, compressed, path) -> tuple[pathlib.Path | None, str]:
    """Write the picture to ``path``; returns (path, "") or (None, why not)."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    try:
        import pyvista
    except ImportError:
        return None, "pyvista is not installed (pip install 'pocket-mechanics[render]'): no 3-D picture"
    from pocket.apps.vtkfiles import surface_mesh

    pyvista.OFF_SCREEN = True
    try:
        plotter = pyvista.Plotter(shape=(1, 2), off_screen=True, window_size=_SIZE)
        limits = [min(s.profile.stretch_1.min() for s in (inflated, compressed)),
                  max(s.profile.stretch_1.max() for s in (inflated, compressed))]
        for column, (state, title) in enumerate(((inflated, "inflated, F = 0"),
                                                 (compressed, f"compressed, F/(P_I pi R^2) = {compressed.force:.3g}"))):
            plotter.subplot(0, column)
            surface = pyvista.from_meshio(surface_mesh(state, segments=96))
            plotter.add_mesh(surface, scalars="lambda_1", clim=limits, cmap="viridis", smooth_shading=True,
                             scalar_bar_args=dict(title="lambda_1 (meridional stretch)", fmt="%.3f"))
            plotter.add_mesh(pyvista.Disc(center=(0, 0, 0), inner=1.0, outer=1.25, c_res=96), color="gray")
            if getattr(state, "contact_radius", 0.0) > 0.0:
                plate = pyvista.Cylinder(center=(0, 0, state.height + 0.02), direction=(0, 0, 1), radius=0.8,
                                         height=0.04, resolution=96)
                plotter.add_mesh(plate, color="lightsteelblue", opacity=0.35)
            plotter.add_text(title, font_size=11)
            plotter.camera_position = [(3.3, -3.3, 2.4), (0.0, 0.0, 0.15), (0.0, 0.0, 1.0)]
        plotter.screenshot(str(path))
        plotter.close()
    except Exception as err:  # a missing GPU/EGL stack: say so, keep the rest of the report
        return None, f"pyvista could not render offscreen here ({type(err).__name__}: {err})"
    return pathlib.Path(path), ""
