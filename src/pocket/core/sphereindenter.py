r"""The sphere indenter (a fingertip) and the range of its radius (registered in ``pocket.core.indenters``).

Its lower cap is z = R_s - sqrt(R_s^2 - rho^2), R_s = K R: the surface exists for rho <= R_s only (its
equator, its ``reach``); there z is R_s and the slope infinite, and beyond it ``height``, ``slope`` and
``second`` are NaN: a sheet wrapping past the equator is outside the model, which a solver says in its own
words. The contact pressure exceeds P (p_c = P + (T_1 + T_2) / R_s), so F = P A_c is no identity.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

import numpy as np

from .errors import InputError
from .indenterbase import Indenter, Spell, key_name
from .inputs import check_finite, quote
from .sizes import length_warnings
from .units import positive

__all__ = ["SPHERE_RADII", "Sphere", "check_sphere_radius"]

#: K = R_s / R of a sphere. From 1e-3: a smaller sphere is finer than the finite-element mesh resolves at the
#: pole (with its default mesh the stretch at the contact is 0.4 % off the shooting solver's at K = 1e-3, 28 % at
#: 1e-4) and nears the start of the shooting solver's pole series (an expansion in r / K from r = 1e-5); and the
#: force it carries before the sheet wraps past its equator, about 4 K in Fhat (Phat_I = 0.3), is no finger's.
#: To 1e3: a larger sphere sags less than R / 2000 over the pocket, which is then the flat plate's (use it), and
#: its height R_s - sqrt(R_s^2 - rho^2) in doubles loses digits as K^2 grows
SPHERE_RADII = (1e-3, 1e3)


def check_sphere_radius(name: str, value, shown: str | None = None) -> float:
    """A sphere's radius K = R_s / R within ``SPHERE_RADII``; otherwise an InputError naming ``name`` and quoting
    the value (``shown`` instead if given: a length as written with its K)."""
    number = check_finite(name, value)
    shown = shown or f"{number:g}"
    if not number > 0.0:
        raise InputError(f"{name} = {shown}, but a sphere's radius must be > 0")
    low, high = SPHERE_RADII
    if not low <= number <= high:
        why = ("a smaller one is finer than the solvers resolve at the pole" if number < low else
               "a larger one sags less than R/2000 over the pocket: use the flat plate")
        raise InputError(f"{name} = {shown}, but a sphere's radius K = R_s/R must lie in "
                         f"[{low:g}, {high:g}] ({why})")
    return number


@dataclasses.dataclass(frozen=True)
class Sphere(Indenter):
    """A sphere of radius R_s (a fingertip), its lowest point on the axis: z(rho) = R_s - sqrt(R_s^2 - rho^2).

    Its surface exists out to its equator, rho <= R_s (NaN beyond).

    Parameters
    ----------
    radius : float
        K = R_s / R, in ``SPHERE_RADII`` (checked by ``check_sphere_radius``).

    Raises
    ------
    InputError
        For a radius outside ``SPHERE_RADII`` or not a number.

    Examples
    --------
    >>> import numpy as np
    >>> from pocket.core.indenters import Sphere
    >>> ball = Sphere(0.5)
    >>> print(ball.height(0.3), 0.5 - np.sqrt(0.5**2 - 0.3**2), ball.reach)
    0.09999999999999998 0.09999999999999998 0.5
    >>> print(np.round(ball.curvature([0.0, 0.2, 0.4]), 12))
    [2. 2. 2.]
    >>> Sphere(0.0)
    Traceback (most recent call last):
        ...
    pocket.core.errors.InputError: indenter.radius = 0, but a sphere's radius must be > 0
    """

    radius: float
    name = "sphere"
    summary = "a sphere of radius R_s (a fingertip), its lowest point on the axis"
    keys = ("radius",)

    def __post_init__(self):
        object.__setattr__(self, "radius", check_sphere_radius("indenter.radius", self.radius))

    def _root(self, rho) -> np.ndarray:
        """sqrt(R_s^2 - rho^2), NaN past the equator rho > R_s (no warning)."""
        inside = np.square(self.radius) - np.square(np.asarray(rho, dtype=float))
        with np.errstate(invalid="ignore"):
            return np.where(inside >= 0.0, np.sqrt(np.maximum(inside, 0.0)), np.nan)

    def height(self, rho) -> np.ndarray:
        """z = R_s - sqrt(R_s^2 - rho^2) (units R)."""
        return self.radius - self._root(rho)

    def slope(self, rho) -> np.ndarray:
        """dz/drho = rho / sqrt(R_s^2 - rho^2) (infinite at the equator)."""
        with np.errstate(divide="ignore"):
            return np.asarray(rho, dtype=float) / self._root(rho)

    def second(self, rho) -> np.ndarray:
        """d2z/drho2 = R_s^2 / (R_s^2 - rho^2)^(3/2), so that the curvature is 1/R_s (units 1/R)."""
        with np.errstate(divide="ignore"):
            return np.square(self.radius) / self._root(rho) ** 3

    @property
    def reach(self) -> float:
        """Its equator, rho = R_s (units R)."""
        return self.radius

    def describe(self) -> str:
        return f"a sphere of radius K = R_s/R = {self.radius:g}"

    def columns(self, clamp_radius: float) -> dict:
        return {"indenter": self.name, "indenter_radius_m": self.radius * clamp_radius}

    def journal(self) -> str:
        """``sphere K=...``, K written exactly."""
        return f"{self.name} K={self.radius!r}"

    @classmethod
    def from_model(cls, values: Mapping[str, object], spell: Spell = key_name) -> Sphere:
        """The sphere of ``values["radius"]`` = K (a number)."""
        return cls(check_sphere_radius(spell("radius"), values["radius"]))

    @classmethod
    def from_physical(cls, values: Mapping[str, object], clamp_radius: float, base=None, spell: Spell = key_name,
                      warnings: list | None = None) -> Sphere:
        """The sphere of radius ``values["radius"]``, a length of a pocket's sizes (``pocket.core.sizes``:
        outside them an InputError; a plain number above 1 m, millimetres meant?, a line appended to
        ``warnings``), K = R_s / R within ``SPHERE_RADII``."""
        written = values["radius"]
        radius = positive(spell("radius"), written, "length")
        found = length_warnings(spell("radius"), written, radius)
        if warnings is not None:
            warnings.extend(found)
        ratio = radius / clamp_radius
        return cls(check_sphere_radius(spell("radius"), ratio, f"{quote(written)} (K = R_s/R = {ratio:.3g})"))
