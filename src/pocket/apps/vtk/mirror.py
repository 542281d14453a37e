"""A meridian continued through its plane of mirror symmetry: the whole closed capsule from its upper half.

A surface whose meridian ends on a plane of mirror symmetry (``pocket.core.geometries.Symmetry``: a closed
capsule's equatorial plane z = h) is solved as its upper half, from the pole to the plane. Its whole meridian
runs on from the plane to the lower pole: the upper half's points in reverse order, the last (on the plane) not
repeated, each at the mirror height 2 h - eta. Point data go with their points; a vector field (the
displacement, shape (n, 3)) has its z component mirrored too. Revolved (``pocket.apps.vtk.revolve``) the whole
meridian, which starts and ends on the axis, is a closed surface.
"""

from __future__ import annotations

import numpy as np

__all__ = ["mirrored"]


def mirrored(rho, eta, data: dict, plane: float) -> tuple[np.ndarray, np.ndarray, dict]:
    """The meridian (``rho``, ``eta``), float arrays of shape (n,) from the pole to the plane z = ``plane``, and
    its point data ``data`` (name -> array of shape (n,) or (n, 3)), continued through the plane.

    Returns
    -------
    rho, eta : numpy.ndarray
        Shape (2 n - 1,): the given points, then their mirror images from the plane back to the lower pole.
    data : dict
        Each field at those points (a vector's z component mirrored).

    Examples
    --------
    >>> import numpy as np
    >>> from pocket.apps.vtk.mirror import mirrored
    >>> rho, eta, data = mirrored(np.array([0.0, 1.0]), np.array([1.0, 0.0]), {"s": np.array([2.0, 3.0])}, 0.0)
    >>> print(rho.tolist(), eta.tolist(), data["s"].tolist())
    [0.0, 1.0, 0.0] [1.0, 0.0, -1.0] [2.0, 3.0, 2.0]
    """
    rho, eta = np.asarray(rho, dtype=float), np.asarray(eta, dtype=float)
    below = slice(-2, None, -1)  # reversed, without the point on the plane
    out = {}
    for name, values in data.items():
        values = np.asarray(values)
        image = values[below].copy()
        if image.ndim == 2:
            image[:, 2] = -image[:, 2]
        out[name] = np.concatenate((values, image))
    return np.concatenate((rho, rho[below])), np.concatenate((eta, 2.0 * plane - eta[below])), out
