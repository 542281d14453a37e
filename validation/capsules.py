r"""The section "A capsule between two plates": the closed capsule's solves (the theory's section 12).

The suite's capsules (``CASES``): every law's example rubber (``pocket.core.materials.LAWS``, stresses in units of
mu_0) at Phat_I = ``PRESSURE``, filled with a liquid and with a gas (``GAS``), and the Mooney-Rivlin rubber at a
lower and a higher Phat_I for the force-deformation figure. ``solve`` presses one between two plates: the shooting
solver at the plan's forces (``Plan.capsules``), the FE model (P2, its default mesh) at the plan's FE forces
(``Plan.capsule_fem``, compared where both solve); ``sequence`` is the FE model's mesh convergence on ``STUDY`` at
Fhat = ``FORCE``. The checks are ``capsulechecks``'s, the figure and the report's text ``capsulereport``'s.

The closed form (``sphere_pressure``). The inflated capsule is a sphere of uniform stretch lambda; with
w(lambda) = W(lambda, lambda), the energy per unit reference volume under equibiaxial stretch, the virtual work
P dV = 4 pi R^2 T w'(lambda) d lambda with dV = 4 pi R^3 lambda^2 d lambda gives

    Phat = w'(lambda) / (E lambda^2),        E = 3 mu_0,

and w' by law (I_1 = 2 lambda^2 + lambda^-4, dI_1/d lambda = 4 (lambda - lambda^-5); I_2 = 2 lambda^-2 +
lambda^4, dI_2/d lambda = 4 lambda^2 (lambda - lambda^-5)):

    Mooney-Rivlin  w' = 4 (lambda - lambda^-5) (C1 + C2 lambda^2)
    neo-Hookean    w' = 2 mu (lambda - lambda^-5)
    Yeoh           w' = 4 (lambda - lambda^-5) (C10 + 2 C20 x + 3 C30 x^2),     x = I_1 - 3
    Gent           w' = 2 mu (lambda - lambda^-5) / (1 - x / J_m)
    Ogden          w' = sum_p 2 mu_p (lambda^(alpha_p - 1) - lambda^(-2 alpha_p - 1))

(for Mooney-Rivlin, Phat = 2 (1 - lambda^-6)(1 + alpha lambda^2) / (3 (1 + alpha) lambda), the theory's
eq-capsule-mooney-rivlin), written here from the strain energies of ``pocket.core.materials`` and not from the
solvers' tension kernels: an independent answer for the inflated capsule of every law.
"""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from pocket.core.fluids import LIQUID, Fluid, gas
from pocket.core.materials import LAWS, Material, check
from pocket.core.states import CompressedState

from .convergence import Sequence
from .failures import located

__all__ = [
    "CASES",
    "FORCE",
    "GAS",
    "PRESSURE",
    "STUDY",
    "Capsule",
    "Curve",
    "capsule_value",
    "compression",
    "sequence",
    "solve",
    "sphere_pressure",
]

#: Phat_I of every law's capsules
PRESSURE = 0.2
#: the gas: Phat_atm = 2, ten times PRESSURE (air at 1 atm in a capsule inflated to a tenth of it above), compressed
#: slowly (isothermal)
GAS = gas(2.0, 1.0)
#: the force of the convergence study, about a third of the way along the curves (1 - H/lambda_I ~ 0.4)
FORCE = 1.0


@dataclasses.dataclass(frozen=True)
class Capsule:
    """A capsule of the suite: ``name`` (unique), ``label`` (the legends'), the rubber in units of mu_0, Phat_I,
    the fluid, and whether the FE model is compared on it (``fem``)."""

    name: str
    label: str
    material: Material
    pressure: float
    fluid: Fluid = LIQUID
    fem: bool = True

    def options(self) -> dict:
        """The solvers' keyword arguments for this capsule."""
        return {"fluid": self.fluid, "geometry": "capsule"}


def _rubber(law: str) -> Material:
    """The law's example rubber, its stresses in units of mu_0."""
    return check(law, dict(LAWS[law].example)).scaled()


def _cases() -> tuple[Capsule, ...]:
    out = []
    for law in LAWS:
        rubber = _rubber(law)
        for fluid, what in ((LIQUID, "liquid"), (GAS, "gas")):
            out.append(Capsule(f"capsule-{law}-{what}", f"{law}, {what}", rubber, PRESSURE, fluid))
    for phat in (0.1, 0.4):
        out.append(Capsule(f"capsule-mooney-rivlin-{phat:g}", f"mooney-rivlin, Phat_I = {phat:g}",
                           _rubber("mooney-rivlin"), phat, LIQUID, fem=False))
    return tuple(out)


#: the suite's capsules (module docstring); Mooney-Rivlin's example is the paper's silicone (alpha = 47 / 160)
CASES = _cases()
#: the capsule of the convergence study
STUDY = CASES[0]


@dataclasses.dataclass(frozen=True)
class Curve:
    """One capsule pressed by the plates: the shooting states at ``forces`` (Fhat; 0 is the inflated capsule),
    the FE states at ``fem_forces`` (none if the plan runs no FE column on it), and the solves' ``seconds``."""

    capsule: Capsule
    forces: tuple[float, ...]
    shooting: tuple[CompressedState, ...]
    fem_forces: tuple[float, ...]
    fem: tuple[CompressedState, ...]
    seconds: float

    def shooting_at(self, force: float) -> CompressedState:
        """The shooting state at the force ``force`` (one of ``forces``)."""
        return self.shooting[self.forces.index(force)]


def _slope(material: Material, stretch: float) -> float:
    """w'(lambda) of ``material`` (module docstring), in its stress unit."""
    law = material.law
    p = {k: v for k, v in material.params if isinstance(v, float)}  # the scalar parameters (Ogden's are lists)
    base = stretch - stretch**-5  # dI_1/d lambda over 4
    x = 2.0 * stretch**2 + stretch**-4 - 3.0
    if law == "mooney-rivlin":
        return 4.0 * base * (p["c1"] + p["c2"] * stretch**2)
    if law == "neo-hookean":
        return 2.0 * p["mu"] * base
    if law == "yeoh":
        return 4.0 * base * (p["c10"] + 2.0 * p["c20"] * x + 3.0 * p["c30"] * x**2)
    if law == "gent":
        return 2.0 * p["mu"] * base / (1.0 - x / p["jm"])
    if law == "ogden":
        mus, exponents = (tuple(v) for k, v in material.params if k in ("mu", "exponents") and isinstance(v, tuple))
        return sum(2.0 * m * (stretch ** (a - 1.0) - stretch ** (-2.0 * a - 1.0))
                   for m, a in zip(mus, exponents, strict=True))
    raise ValueError(f"no closed form for the {law} law")


def sphere_pressure(material: Material, stretch: float) -> float:
    """Phat = w'(lambda) / (E lambda^2) of the capsule inflated to the uniform stretch lambda = ``stretch``
    (module docstring; a rubber without prestretch).

    Parameters
    ----------
    material : pocket.core.materials.Material
        The rubber, in any stress unit (E = 3 mu_0 in the same unit).
    stretch : float
        lambda, the sphere's radius over the reference radius R.

    Returns
    -------
    float
        P R / (E T).

    Examples
    --------
    Mooney-Rivlin with alpha = 0.3 at lambda = 1.2, against its closed form:

    >>> from pocket.core.materials import mooney_rivlin
    >>> phat = sphere_pressure(mooney_rivlin(0.3), 1.2)
    >>> print(round(phat, 12), round(2 * (1 - 1.2**-6) * (1 + 0.3 * 1.2**2) / (3 * 1.3 * 1.2), 12))
    0.58047707209 0.58047707209
    """
    if material.prestretch != 1.0:
        raise ValueError("the closed form here is a rubber's without prestretch")
    return _slope(material, stretch) / (3.0 * material.mu0 * stretch**2)


def capsule_value(state, key: str) -> float:
    """The reported ``key`` of a capsule's state: an attribute, or one of its ``extra`` keys."""
    return float(state.extra[key]) if key in state.extra and not hasattr(state, key) else float(getattr(state, key))


#: the FE model's mesh in the comparison with shooting: twice the default's 256 elements (its O(h^4) error 16-fold
#: smaller, below the 1e-9 the two solvers are held to: ``verdicts.TOLERANCES["capsule_fem"]``)
FEM_ELEMENTS = 512


def compression(capsule: Capsule, forces, solver: str = "shooting", **options) -> tuple[CompressedState, ...]:
    """``capsule`` pressed at ``forces`` (Fhat) by ``solver`` ("shooting" or "fem")."""
    from pocket import fem, shooting

    module = shooting if solver == "shooting" else fem
    mesh = "no mesh (shooting)" if solver == "shooting" else f"FE P2 {options.get('elements', 'default')} mesh"
    with located(capsule.name, f"capsule between two plates ({solver})", mesh,
                 f"{len(forces)} forces Fhat = {min(forces):.6g} to {max(forces):.6g}"):
        return tuple(module.compression_curve(capsule.material, capsule.pressure, [float(f) for f in forces],
                                              **capsule.options(), **options))


def solve(capsule: Capsule, forces, fem_forces) -> Curve:
    """``capsule`` pressed at ``forces`` by shooting, and at ``fem_forces`` by the FE model too (among the shooting
    forces; none: no FE column)."""
    start = time.perf_counter()
    fem_forces = tuple(float(f) for f in fem_forces) if capsule.fem else ()
    every = tuple(sorted({float(f) for f in forces} | set(fem_forces)))
    states = compression(capsule, every)
    fe = compression(capsule, fem_forces, "fem", elements=FEM_ELEMENTS) if fem_forces else ()
    return Curve(capsule, every, states, fem_forces, fe, time.perf_counter() - start)


#: the quantities of the convergence study
QUANTITIES = ("height", "pressure", "contact_area", "contact_radius", "stretch_pole", "radius_equator")


def sequence(counts) -> Sequence:
    """The FE model (P2, default meshes of ``counts`` elements, the contact edge fitted) on ``STUDY`` at Fhat =
    ``FORCE``, against shooting."""
    start = time.perf_counter()
    reference = compression(STUDY, [FORCE])[0]
    values: dict[str, list[float]] = {q: [] for q in QUANTITIES}
    sizes = []
    for n in counts:
        state = compression(STUDY, [FORCE], "fem", elements=n)[0]
        assert state.profile is not None  # the FE model's states carry their profile
        sizes.append(float(np.diff(state.profile.r[:: state.extra["order"]]).max()))  # the largest element
        for q in QUANTITIES:
            values[q].append(capsule_value(state, q))
    return Sequence(study="capsule compression", order=2, mesh="fitted", elements=tuple(counts),
                    sizes=np.array(sizes), values={k: np.array(v) for k, v in values.items()},
                    reference={q: capsule_value(reference, q) for q in QUANTITIES},
                    seconds=time.perf_counter() - start)
