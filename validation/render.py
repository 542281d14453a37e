"""A 3-D picture of the pocket, inflated and compressed (pyvista offscreen, optional).

The surfaces are ``pocket.apps.vtk.files.surface_mesh`` of the states (the meridian
revolved about the axis), coloured by the meridional stretch lambda_1 on one
colour scale; the compressed pocket is shown with its plate. pyvista renders
each view without text; matplotlib sets the two views side by side with their
titles and the colour bar, in the fonts and notation of the report's other
figures. Returns None, with the reason, when pyvista (the ``render`` extra) is
not installed or cannot render here.
"""

from __future__ import annotations

import os
import pathlib

from .draw import math_text

__all__ = ["render_pocket"]

_VIEW = (900, 620)  # pixels of each 3-D view
_CAMERA = [(3.3, -3.3, 2.4), (0.0, 0.0, 0.15), (0.0, 0.0, 1.0)]
_COLORMAP = "viridis"


def _view(pyvista, state, limits):
    """The image (array) of ``state``'s surface, clamp ring and plate."""
    from pocket.apps.vtk.files import surface_mesh

    plotter = pyvista.Plotter(off_screen=True, window_size=_VIEW)
    try:
        surface = pyvista.from_meshio(surface_mesh(state, segments=96))
        plotter.add_mesh(surface, scalars="lambda_1", clim=limits, cmap=_COLORMAP, smooth_shading=True,
                         show_scalar_bar=False)
        plotter.add_mesh(pyvista.Disc(center=(0, 0, 0), inner=1.0, outer=1.25, c_res=96), color="gray")
        if getattr(state, "contact_radius", 0.0) > 0.0:
            plate = pyvista.Cylinder(center=(0, 0, state.height + 0.02), direction=(0, 0, 1), radius=0.8,
                                     height=0.04, resolution=96)
            plotter.add_mesh(plate, color="lightsteelblue", opacity=0.35)
        plotter.camera_position = _CAMERA
        return plotter.screenshot(return_img=True)
    finally:
        plotter.close()


def _crop(images, margin: int = 12) -> list:
    """The images cut to one box around everything that is not background (the corner's colour)."""
    import numpy as np

    boxes = []
    for image in images:
        ink = np.any(np.abs(image.astype(int) - image[0, 0].astype(int)) > 8, axis=-1)
        rows, cols = np.flatnonzero(ink.any(axis=1)), np.flatnonzero(ink.any(axis=0))
        boxes.append((rows[0], rows[-1], cols[0], cols[-1]) if rows.size else (0, image.shape[0] - 1, 0,
                                                                               image.shape[1] - 1))
    top, bottom = max(min(b[0] for b in boxes) - margin, 0), max(b[1] for b in boxes) + margin
    left, right = max(min(b[2] for b in boxes) - margin, 0), max(b[3] for b in boxes) + margin
    return [image[top:bottom + 1, left:right + 1] for image in images]


def _compose(images, titles, limits, path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    fig, axes = plt.subplots(1, 2, figsize=(12.8, 4.6))
    for ax, image, title in zip(axes, _crop(images), titles, strict=True):
        ax.imshow(image)
        ax.set_axis_off()
        ax.set_title(math_text(title), fontsize=10)
    bar = fig.colorbar(ScalarMappable(Normalize(*limits), _COLORMAP), ax=axes, orientation="horizontal",
                       fraction=0.05, pad=0.02, aspect=50, format="%.3f")
    bar.set_label(math_text("lambda_1, the meridional stretch"), fontsize=10)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


def render_pocket(inflated, compressed, path) -> tuple[pathlib.Path | None, str]:
    """Write the picture to ``path``; returns (path, "") or (None, why not)."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    try:
        import pyvista
    except ImportError:
        return None, "pyvista is not installed (pip install 'pocket-mechanics[render]'): no 3-D picture"
    pyvista.OFF_SCREEN = True
    states = (inflated, compressed)
    limits = (min(s.profile.stretch_1.min() for s in states), max(s.profile.stretch_1.max() for s in states))
    try:
        images = [_view(pyvista, state, limits) for state in states]
    except Exception as err:  # a missing GPU/EGL stack: say so, keep the rest of the report
        return None, f"pyvista could not render offscreen here ({type(err).__name__}: {err})"
    titles = ("(a) inflated, F/(P_I pi R^2) = 0", f"(b) compressed, F/(P_I pi R^2) = {compressed.force:.3g}")
    _compose(images, titles, limits, path)
    return pathlib.Path(path), ""
