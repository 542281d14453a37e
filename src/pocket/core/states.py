"""The vocabulary every solver returns: profiles, inflated and compressed states.

All quantities are dimensionless: lengths in units of the clamp radius R,
pressures as Phat = P R / (E T) (E = 3 mu_0 the small-strain Young's modulus of
the rubber, 6 (C1 + C2) for Mooney-Rivlin; T the sheet thickness), tensions
(membrane stress resultants) in units of E T, volumes in R^3, force as
Fhat = F / (P_I pi R^2).

A state echoes its inputs exactly: ``material``, ``pressure`` of an inflation,
``pressure_initial``, ``force``, ``fluid`` and ``indenter`` of a compression are
what the caller gave, never recomputed ones. Its ``alpha`` is derived from the
material: the C2/C1 a Mooney-Rivlin rubber was given by (``mooney_rivlin``,
exactly), None for a rubber given by its parameters (a Mooney-Rivlin one given
by C1, C2 reports those, not a recomputed C2/C1) and for every other law.

Every state also carries its smallest tensions ``tension_1_min`` and
``tension_2_min`` (units E T; by default the minima over its profile) and
``wrinkled``: membrane theory holds only while both tensions are positive, so
a state with a compressive tension anywhere is flagged and carries a warning
saying where, rather than passing for valid.
Solvers share these containers and nothing else, so that a bug in one cannot
hide from the cross-check with another.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping

import numpy as np

from .fluids import LIQUID, Fluid
from .geometries import DISC, Geometry
from .indenters import PLATE, Indenter
from .materials import Material
from .offset import check_thickness, volume_correction

__all__ = ["CHECKS", "UNINFLATED_UNDEFINED", "CompressedState", "InflatedState", "Profile"]

#: the membrane's own validity, reported by every state after its KEYS
CHECKS = ("tension_1_min", "tension_2_min", "wrinkled")
#: the keys a compressed state of an uninflated capsule (P_I = 0) leaves NaN and does not report: Fhat = F / (P_I pi
#: R^2) and P / P_I, undefined there (its force is ``force_ETR`` = F / (E T R))
UNINFLATED_UNDEFINED = ("force", "pressure_ratio")


@dataclasses.dataclass(frozen=True)
class Profile:
    """The meridian of the deformed sheet, sampled at Lagrangian radii.

    Every field is a float array of shape (n,), ordered by increasing ``r`` from the pole (r = 0) to the clamp
    (r = 1).

    Attributes
    ----------
    r : numpy.ndarray
        Lagrangian radius r / R of the flat sheet.
    rho, eta : numpy.ndarray
        Deformed radial position and height, in units of R.
    stretch_1, stretch_2 : numpy.ndarray
        Meridional and hoop stretches lambda_1, lambda_2.
    tension_1, tension_2 : numpy.ndarray
        Stress resultants T_1, T_2 in units of E T.
    contact : numpy.ndarray
        Bool, True where the sheet touches the indenter.

    Raises
    ------
    ValueError
        If the fields are not arrays of one common shape (n,).

    Examples
    --------
    >>> from pocket import shooting
    >>> profile = shooting.inflate(47 / 160, 0.31).profile
    >>> print(profile.r[0], profile.r[-1], bool(profile.contact.any()))
    0.0 1.0 False

    The rubber is incompressible, lambda_1 lambda_2 lambda_3 = 1:

    >>> import numpy as np
    >>> print(np.allclose(profile.stretch_1 * profile.stretch_2 * profile.stretch_3, 1.0))
    True
    """

    r: np.ndarray
    rho: np.ndarray
    eta: np.ndarray
    stretch_1: np.ndarray
    stretch_2: np.ndarray
    tension_1: np.ndarray
    tension_2: np.ndarray
    contact: np.ndarray

    def __post_init__(self):
        shapes = {f.name: np.shape(getattr(self, f.name)) for f in dataclasses.fields(self)}
        if len(set(shapes.values())) != 1 or len(shapes["r"]) != 1:
            raise ValueError(f"Profile fields must be arrays of one common shape (n,), got {shapes}")

    @property
    def stretch_3(self) -> np.ndarray:
        """Thickness ratio lambda_3 = 1 / (lambda_1 lambda_2), shape (n,)."""
        return 1.0 / (self.stretch_1 * self.stretch_2)


def _complete(state) -> None:
    """Fill the defaults of a new state: its smallest tensions from its profile, and a warning if one is
    not positive (frozen dataclass: object.__setattr__)."""
    profile = state.profile
    for k in (1, 2):
        name = f"tension_{k}_min"
        if math.isnan(getattr(state, name)) and profile is not None:
            object.__setattr__(state, name, float(np.min(getattr(profile, f"tension_{k}"))))
    low = min(state.tension_1_min, state.tension_2_min)
    if low <= 0.0:
        which = 1 if state.tension_1_min <= state.tension_2_min else 2
        where = ""
        if profile is not None:
            i = int(np.argmin(getattr(profile, f"tension_{which}")))
            where = f" at r = {profile.r[i]:.4g} R"
        if state.membrane:
            note = (f"compressive tension: T_{which} = {low:.4g} E T{where}; membrane theory needs T_1, T_2 > 0 "
                    "(the sheet would wrinkle there)")
        else:  # a solid carries compression; what it cannot show is a wrinkle out of its axisymmetric plane
            note = (f"compressive stress resultant: T_{which} = {low:.4g} E T{where}; the axisymmetric solid "
                    "carries it, but a real sheet may wrinkle or buckle out of axisymmetry there")
        if note not in state.warnings:
            object.__setattr__(state, "warnings", (*state.warnings, note))


def _scalars(state, keys, extra, described) -> dict:
    out = {key: float(getattr(state, key)) for key in keys if getattr(state, key) is not None}
    out.update({key: float(getattr(state, key)) for key in CHECKS[:2]})
    out["wrinkled"] = state.wrinkled
    out.update(described)
    out.update({k: (v if isinstance(v, (str, bool, int)) else float(v)) for k, v in extra.items()})
    out["solver"] = state.solver
    return out


class _Membrane:
    """What both states share: defaults filled in on creation, and the wrinkling flag."""

    # fields of both states (declared here for the type checker; each state's dataclass defines them)
    material: Material
    tension_1_min: float
    tension_2_min: float
    volume: float
    profile: Profile | None
    solver: str
    membrane: bool

    def __post_init__(self):
        _complete(self)

    @property
    def alpha(self) -> float | None:
        """The C2/C1 the rubber was given by (``Material.exact_alpha``); None for a rubber given by its
        parameters."""
        return self.material.exact_alpha

    @property
    def wrinkled(self) -> bool:
        """A tension is not positive somewhere: outside membrane theory."""
        return min(self.tension_1_min, self.tension_2_min) <= 0.0

    def volume_lower(self, thickness_ratio: float) -> float:
        """V_lower / R^3, the fluid's volume under the sheet's lower surface (``pocket.core.offset``) for a sheet
        of T/R = ``thickness_ratio`` (the unstretched rubber's, as ``pressure``'s T; a prestretched sheet is
        clamped T / lambda_p^2 thick), from the clamp's lower plane: ``volume`` + O((T/R)^2). For a membrane
        state; the solid's ``volume`` is already under its lower surface."""
        t = check_thickness("thickness_ratio", thickness_ratio)
        if self.profile is None:
            raise ValueError(f"a {self.solver} state without a profile has no lower surface")
        return self.volume + volume_correction(self.profile, t / self.material.prestretch**2)


@dataclasses.dataclass(frozen=True)
class InflatedState(_Membrane):
    """Step 1: the sheet inflated at the pressure ``pressure`` (Phat), as every solver returns it.

    Attributes
    ----------
    material : Material
        The rubber as given (``mooney_rivlin(alpha)`` for an alpha).
    pressure : float
        Phat = P R / (E T), as given (pressure control) or found (volume control).
    stretch_pole : float
        lambda_0, the equibiaxial stretch at the pole.
    height : float
        H0 / R, the pole's height above the clamp plane.
    volume : float
        V / R^3, the volume between the sheet and the clamp plane.
    stretch_clamp : float
        lambda_1 at the clamp, r = R.
    profile : Profile or None
        The meridian.
    solver : str
        The solver's name.
    extra : Mapping
        Solver-specific diagnostics (mesh size, iterations, ...), reported after ``KEYS``.
    warnings : tuple of str
        One-line notes on a state that is returned but should not pass unremarked (an approximate model outside
        its range, a compressive tension); the command line prints them and JSON carries them.
    tension_1_min, tension_2_min : float
        The smallest tensions, units E T (default: from the profile).
    membrane : bool
        False for a model of the sheet's thickness (the solid), whose warnings speak of its stress resultants.
    geometry : Geometry
        The reference surface it was solved on (the flat clamped disc by default); not a reported key.

    Examples
    --------
    >>> from pocket import shooting
    >>> state = shooting.inflate(47 / 160, 0.31)
    >>> print(list(state.scalars())[:6])
    ['alpha', 'pressure', 'stretch_pole', 'height', 'volume', 'stretch_clamp']
    >>> print(state.alpha == 47 / 160, state.pressure, state.wrinkled)
    True 0.31 False
    """

    material: Material
    pressure: float
    stretch_pole: float
    height: float
    volume: float
    stretch_clamp: float
    profile: Profile | None
    solver: str
    extra: Mapping[str, float | str] = dataclasses.field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    tension_1_min: float = math.nan
    tension_2_min: float = math.nan
    membrane: bool = True
    geometry: Geometry = DISC

    KEYS = ("alpha", "pressure", "stretch_pole", "height", "volume", "stretch_clamp")

    def scalars(self) -> dict:
        """The reported quantities as a flat dict (JSON-ready): KEYS (``alpha`` only for a rubber given by it),
        CHECKS, the material's law and parameters, then ``extra`` and the solver."""
        return _scalars(self, self.KEYS, self.extra, self.material.describe())


@dataclasses.dataclass(frozen=True)
class CompressedState(_Membrane):
    """Step 2: the inflated pocket pressed by ``indenter`` (the flat plate by default) at fixed fluid.

    Attributes
    ----------
    material : Material
        The rubber as given.
    pressure_initial : float
        Phat_I = P_I R / (E T), as given.
    force : float
        Fhat = F / (P_I pi R^2), as given (force control) or found (travel control); NaN, and not reported, for
        an uninflated capsule (P_I = 0), whose force is its ``extra["force_ETR"]`` = F / (E T R).
    pressure, pressure_ratio : float
        Phat = P R / (E T) and P / P_I (NaN, and not reported, where P_I = 0).
    contact_area : float
        The deformed area in contact, A_c / (pi R^2) (the curved area on a curved indenter;
        pi (lambda_c a_c)^2 / (pi R^2) on the plate).
    contact_radius : float
        The Lagrangian contact radius a_c / R.
    stretch_contact : float
        lambda_c, the stretch at the pole in contact.
    height, height_ratio : float
        H / R, the indenter's lowest point above the clamp plane (the dome's height under the plate), and H / H0.
    volume : float
        V / R^3.
    profile : Profile or None
        The meridian.
    inflated : InflatedState
        The step-1 state this one was compressed from.
    solver, extra, warnings, tension_1_min, tension_2_min, membrane
        As for ``InflatedState``.
    fluid : Fluid
        The fluid sealed in the pocket at Phat_I (a gas's ambient pressure as Phat_atm).
    indenter : Indenter
        What presses on it (``pocket.core.indenters``).
    contact_radius_deformed : float
        rho_c / R, where a solver gives it (NaN otherwise).
    contact_pressure_pole, contact_pressure_edge : float
        The contact pressure at the pole and at the contact edge, units E T / R, where a solver gives them.
    contact_pressure : numpy.ndarray or None
        That pressure at each point of the profile, shape (n,), NaN off the contact zone; None where a solver
        does not give it.

    Examples
    --------
    >>> from pocket import shooting
    >>> state = shooting.compress(47 / 160, 0.31, 0.19)
    >>> scalars = state.scalars()
    >>> print(scalars["force"], f"{scalars['pressure_ratio']:.4f}", scalars["solver"])
    0.19 1.2944 shooting

    The pressure ratio is the pressure over the inflated state's, and the fluid's volume is held:

    >>> print(abs(state.pressure_ratio - state.pressure / state.inflated.pressure) < 1e-12,
    ...       abs(state.volume - state.inflated.volume) < 1e-9)
    True True
    """

    material: Material
    pressure_initial: float
    force: float
    pressure: float
    pressure_ratio: float
    contact_area: float
    contact_radius: float
    stretch_contact: float
    height: float
    height_ratio: float
    volume: float
    profile: Profile | None
    inflated: InflatedState
    solver: str
    extra: Mapping[str, float | str] = dataclasses.field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    fluid: Fluid = LIQUID
    tension_1_min: float = math.nan
    tension_2_min: float = math.nan
    indenter: Indenter = PLATE
    contact_radius_deformed: float = math.nan
    contact_pressure_pole: float = math.nan
    contact_pressure_edge: float = math.nan
    contact_pressure: np.ndarray | None = None
    membrane: bool = True

    #: reported after KEYS where given (finite)
    CONTACT_KEYS = ("contact_radius_deformed", "contact_pressure_pole", "contact_pressure_edge")

    KEYS = (
        "alpha",
        "pressure_initial",
        "force",
        "pressure",
        "pressure_ratio",
        "contact_area",
        "contact_radius",
        "stretch_contact",
        "height",
        "height_ratio",
        "volume",
    )

    @property
    def geometry(self) -> Geometry:
        """The reference surface: that of the inflated state it was pressed from (one fact, held there)."""
        return self.inflated.geometry

    def scalars(self) -> dict:
        """The reported quantities as a flat dict (JSON-ready), as ``InflatedState.scalars`` with the
        ``CONTACT_KEYS`` a solver gave, and the fluid."""
        keys = tuple(k for k in self.KEYS if not (self.pressure_initial == 0.0 and k in UNINFLATED_UNDEFINED)) + \
            tuple(k for k in self.CONTACT_KEYS if math.isfinite(getattr(self, k)))
        return _scalars(self, keys, self.extra, {**self.material.describe(), **self.fluid.describe()})
