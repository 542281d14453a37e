"""The indenter classes: each owns its geometry (slope and second derivative those of its own height, its
reach where its surface ends), every solver poses the flat plate by default and its states carry it, and an
indenter a solver does not pose is refused in one line naming the solver and the indenter, before any work,
rather than solved as a flat plate."""

import dataclasses
import math

import numpy as np
import pytest
from pocket.analytical import model as analytical_model
from pocket.fem import api as fem_api
from pocket.fem import inflation as fem_inflation
from pocket.shooting import compression as shooting_compression
from pocket.shooting import inflation as shooting_inflation
from pocket.shooting import problem as shooting_problem

from pocket import analytical, fem, shooting
from pocket.core.errors import InputError
from pocket.core.indenters import INDENTERS, PLATE, Indenter, Profile, Sphere, as_indenter, register
from pocket.core.profiles import functions, table


@dataclasses.dataclass(frozen=True)
class Cone(Indenter):
    """A cone of slope ``slope`` (z = slope rho), a kind no solver poses: curved enough that F = P A_c is no
    identity on it."""

    steepness: float
    name = "toy-cone"
    summary = "a cone, defined by this test only"

    def height(self, rho):
        return self.steepness * np.asarray(rho, dtype=float)

    def slope(self, rho):
        return np.full_like(np.asarray(rho, dtype=float), self.steepness)

    def second(self, rho):
        return np.zeros_like(np.asarray(rho, dtype=float))

    @property
    def reach(self):
        return 1.0


#: each solver's table of the indenter classes it poses
TABLES = {"shooting": shooting_problem.CONTACTS, "fem": fem_api.CONTACTS, "analytical": analytical_model.CONTACTS}

REFUSALS = [
    ("shooting", "toy-cone", lambda cone: shooting.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("shooting", "toy-cone", lambda cone: shooting.compression_curve(0.1, 0.3, [0.0, 0.5], indenter=cone)),
    ("shooting", "toy-cone", lambda cone: shooting.range_end(0.1, 0.3, indenter=cone)),
    ("fem", "toy-cone", lambda cone: fem.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("fem", "toy-cone", lambda cone: fem.compression_curve(0.1, 0.3, [0.0, 0.5], indenter=cone, contact="penalty")),
    ("fem", "toy-cone", lambda cone: fem.compress_height(0.1, 0.3, 0.2, indenter=cone)),
    ("analytical", "toy-cone", lambda cone: analytical.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("analytical", "toy-cone", lambda cone: analytical.range_end(0.1, 0.3, indenter=cone)),
    ("analytical", "sphere", lambda cone: analytical.compress(0.1, 0.3, 0.5, indenter=Sphere(0.5))),
]


@pytest.fixture
def cone(monkeypatch):
    """A cone of the toy kind; no inflation may start meanwhile."""

    def no_work(*args, **kwargs):
        raise AssertionError("the solver started work before refusing the indenter")

    for module, name in ((shooting_compression, "inflate"), (shooting_inflation, "inflate"),
                         (fem_inflation, "to_pressure"), (analytical_model, "inflate")):
        monkeypatch.setattr(module, name, no_work)
    return Cone(0.5)


@pytest.mark.parametrize(("solver", "name", "call"), REFUSALS)
def test_a_solver_refuses_an_indenter_it_does_not_pose(cone, solver, name, call):
    """One line: ``solver <name> does not implement the <indenter's name> indenter (its indenters: ...)``, the
    names those of the classes in the solver's ``CONTACTS``."""
    with pytest.raises(InputError) as caught:
        call(cone)
    poses = ", ".join(kind.name for kind in TABLES[solver])
    assert str(caught.value) == f"solver {solver} does not implement the {name} indenter (its indenters: {poses})"


def test_the_fem_refuses_a_contact_method_that_does_not_pose_the_indenter(cone, monkeypatch):
    monkeypatch.setitem(fem_api.CONTACTS, Cone, (("fitted",), True))
    with pytest.raises(InputError, match=r"^contact = 'penalty' does not apply to the toy-cone indenter "
                                         r"\(its methods: fitted\)$"):
        fem.compress(0.1, 0.3, 0.5, indenter=cone, contact="penalty")


@pytest.mark.parametrize(("make", "match"), [
    (lambda: Sphere(float("nan")), r"^indenter.radius = nan is not finite$"),
    (lambda: Sphere(0.0), r"^indenter.radius = 0, but a sphere's radius must be > 0$"),
    (lambda: Sphere(-1.0), r"^indenter.radius = -1, but a sphere's radius must be > 0$"),
    (lambda: Sphere(1e4), r"^indenter.radius = 10000, but a sphere's radius K = R_s/R must lie in \[0.001, 1000\] "),
    (lambda: Sphere("big"), r"^indenter.radius = 'big' is not a number$"),
    (lambda: Profile(1.0), r"^indenter.shape = 1.0, but it must be a profile \(pocket.core.profiles: "),
    (lambda: as_indenter("plate"), r"^indenter = 'plate', but it must be an Indenter \(pocket.core.indenters\)$"),
    (lambda: Cone(1.0).journal(), r"^a sweep records its indenter as text \(the plate, a sphere or a profile "
                                  r"table\), not a cone, defined by this test only$"),
    (lambda: Profile(_FUNCTIONS).journal(), r"^a sweep records its indenter .*, not a profile given as functions$"),
])
def test_a_bad_indenter_is_an_input_error_in_one_line(make, match):
    """A value that makes no indenter is refused by the class, in one line naming the field."""
    with pytest.raises(InputError, match=match) as caught:
        make()
    assert "\n" not in str(caught.value)


def test_each_name_is_registered_once_for_its_own_class():
    """The registry maps each name a user types to the class of that name, the plate first (the VTK files'
    indenter_code and the flags' choices follow its order), and refuses a second class under a taken name."""
    assert list(INDENTERS) == ["plate", "sphere", "profile"]
    assert all(kind.name == name for name, kind in INDENTERS.items())

    @dataclasses.dataclass(frozen=True)
    class Ball(Sphere):
        name = "sphere"

    for kind in (Sphere, Ball):
        with pytest.raises(ValueError, match=r"^indenter 'sphere' is registered already$"):
            register(kind)
    assert INDENTERS["sphere"] is Sphere


_RADII = np.linspace(0.0, 0.6, 13)
#: a profile table (a parabola with a quartic term, to rho = 0.6) and a profile given as functions (a paraboloid)
_TABLE = table(_RADII, 0.8 * _RADII**2 + 0.3 * _RADII**4, source="a test table")
_FUNCTIONS = functions(lambda r: r * r, lambda r: 2 * r, lambda r: 2 / (1 + 4 * r * r) ** 1.5, 0.5)

#: (indenter, radii inside its reach, its reach)
SURFACES = [(PLATE, np.linspace(0.0, 3.0, 7), math.inf), (Sphere(0.4), np.linspace(0.0, 0.35, 8), 0.4),
            (Profile(_TABLE), np.array([0.0, 0.02, 0.13, 0.27, 0.33, 0.48, 0.57]), 0.6),
            (Profile(_FUNCTIONS), np.linspace(0.0, 0.45, 6), 0.5)]


@pytest.mark.parametrize(("indenter", "rho", "reach"), SURFACES, ids=["plate", "sphere", "table", "functions"])
def test_steepnessand_curvature_are_those_of_the_height(indenter, rho, reach):
    """Exact answers to the finite differences' error: the slope is the central difference of z (step 1e-5:
    error h^2 z'''/6, below 1e-7 where z''' < 600 as on the sphere at rho = 0.35), the second derivative the
    central second difference of z (step 1e-4: error h^2 z''''/12 plus rounding eps z / h^2, both below 1e-6
    relative here; z is even, z(-rho) = z(rho)), the curvature z'' / (1 + z'^2)^(3/2); the surface ends at its
    reach (NaN beyond)."""
    h, h2 = 1e-5, 1e-4
    slope = (indenter.height(rho + h) - indenter.height(np.abs(rho - h))) / (2 * h)
    assert np.allclose(indenter.slope(rho), slope, rtol=1e-7, atol=1e-9)
    second = (indenter.height(rho + h2) - 2 * indenter.height(rho) + indenter.height(np.abs(rho - h2))) / h2**2
    assert np.allclose(indenter.second(rho), second, rtol=1e-5, atol=1e-6)
    assert np.array_equal(indenter.curvature(rho), indenter.second(rho) / (1 + indenter.slope(rho) ** 2) ** 1.5)
    assert indenter.reach == reach
    assert indenter.height(0.0) == 0.0
    if math.isfinite(reach):
        assert np.isfinite(indenter.height(reach))
        assert np.isnan(indenter.height(reach * 1.01))


def test_the_sphere_is_its_cap_of_curvature_one_over_its_radius():
    """Exact: z(R_s) = R_s at the equator; the curvature of a sphere is 1/R_s everywhere on its cap."""
    tip = Sphere(0.4)
    rho = np.linspace(0.0, 0.35, 8)
    assert np.allclose(tip.curvature(rho), 1 / 0.4, rtol=1e-12)
    assert tip.height(0.4) == 0.4
    assert not tip.pressure_area


def test_the_flat_plate_is_a_plane_on_which_the_force_is_pressure_times_area():
    rho = np.linspace(0.0, 1.0, 7).reshape(7, 1)
    assert np.array_equal(PLATE.height(rho), np.zeros((7, 1)))
    assert PLATE.pressure_area
    assert as_indenter(None) is PLATE
    assert INDENTERS["plate"]() == PLATE


def test_an_indenter_reports_itself_without_being_asked_its_kind():
    """The reported columns (a sphere's radius in metres: K times the clamp radius), the journal's cell (K
    written exactly), the numbers a VTK file carries and the meridian drawn (to the nearer of its reach and the
    one asked, its last radius exactly that)."""
    ball = Sphere(0.4)
    assert PLATE.columns(0.02) == {"indenter": "plate"}
    assert ball.columns(0.02) == {"indenter": "sphere", "indenter_radius_m": 0.4 * 0.02}
    assert Profile(_TABLE).columns(0.02) == {"indenter": "profile", "indenter_file": "a test table"}
    assert [PLATE.journal(), ball.journal()] == ["plate", "sphere K=0.4"]
    assert Profile(_TABLE).journal() == f"profile sha256={_TABLE.digest}"
    assert PLATE.numbers() == {}
    assert ball.numbers() == {"radius": 0.4}
    for indenter, reach, end in ((PLATE, 1.25, 1.25), (ball, 1.25, 0.4), (ball, 0.3, 0.3)):
        rho, z = indenter.meridian(reach, 5)
        assert rho[0] == 0.0
        assert rho[-1] == end
        assert np.all(np.diff(rho) > 0)
        assert np.array_equal(z, indenter.height(rho))


@pytest.mark.parametrize(("compression_curve", "options"), [
    (shooting.compression_curve, {}),
    (fem.compression_curve, {"elements": 32}),
    (fem.compression_curve, {"elements": 32, "contact": "penalty"}),
    (analytical.compression_curve, {}),
])
def test_states_carry_their_indenter_and_the_flat_plate_is_the_default(compression_curve, options):
    default = compression_curve(0.1, 0.3, [0.0, 0.5], **options)
    given = compression_curve(0.1, 0.3, [0.0, 0.5], indenter=PLATE, **options)
    assert [s.indenter for s in default + given] == [PLATE] * 4
    assert [s.scalars() for s in default] == [s.scalars() for s in given]
