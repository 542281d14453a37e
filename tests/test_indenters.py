"""The indenter as a registered kind: every solver poses the flat plate by default, its states carry it,
and an indenter a solver does not pose is refused in one line naming the solver and the indenter,
before any work, rather than solved as a flat plate."""

import numpy as np
import pytest
from pocket.analytical import model as analytical_model
from pocket.fem import api as fem_api
from pocket.fem import inflation as fem_inflation
from pocket.shooting import compression as shooting_compression
from pocket.shooting import inflation as shooting_inflation

from pocket import analytical, fem, shooting
from pocket.core.errors import InputError
from pocket.core.indenters import FLAT, KINDS, Indenter, Kind, as_indenter, register

#: a cone of slope ``slope`` (z = slope rho): curved enough that F = P A_c is no identity on it
TOY = Kind("toy-cone", "a cone, registered by this test only", ("slope",),
           lambda params, rho: params["slope"] * rho, pressure_area=False)

REFUSALS = [
    ("shooting", lambda cone: shooting.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("shooting", lambda cone: shooting.compression_curve(0.1, 0.3, [0.0, 0.5], indenter=cone)),
    ("shooting", lambda cone: shooting.range_end(0.1, 0.3, indenter=cone)),
    ("fem", lambda cone: fem.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("fem", lambda cone: fem.compression_curve(0.1, 0.3, [0.0, 0.5], indenter=cone, contact="penalty")),
    ("fem", lambda cone: fem.compress_height(0.1, 0.3, 0.2, indenter=cone)),
    ("analytical", lambda cone: analytical.compress(0.1, 0.3, 0.5, indenter=cone)),
    ("analytical", lambda cone: analytical.range_end(0.1, 0.3, indenter=cone)),
]


@pytest.fixture
def cone(monkeypatch):
    """The toy kind registered for one test, and a cone of it; no inflation may start meanwhile."""
    monkeypatch.setitem(KINDS, TOY.name, TOY)

    def no_work(*args, **kwargs):
        raise AssertionError("the solver started work before refusing the indenter")

    for module, name in ((shooting_compression, "inflate"), (shooting_inflation, "inflate"),
                         (fem_inflation, "to_pressure"), (analytical_model, "inflate")):
        monkeypatch.setattr(module, name, no_work)
    return Indenter(TOY.name, {"slope": 0.5})


@pytest.mark.parametrize(("solver", "call"), REFUSALS)
def test_a_solver_refuses_an_indenter_it_does_not_pose(cone, solver, call):
    with pytest.raises(InputError) as caught:
        call(cone)
    message = str(caught.value)
    assert "\n" not in message
    assert f"solver {solver} does not implement the toy-cone indenter" in message


def test_the_fem_refuses_a_contact_method_that_does_not_pose_the_indenter(cone, monkeypatch):
    monkeypatch.setitem(fem_api.CONTACTS, TOY.name, ("fitted",))
    with pytest.raises(InputError, match=r"^contact = 'penalty' does not apply to the toy-cone indenter "
                                         r"\(its methods: fitted\)$"):
        fem.compress(0.1, 0.3, 0.5, indenter=cone, contact="penalty")


@pytest.mark.parametrize(("make", "match"), [
    (lambda: Indenter("cylinder"), r"^indenter = 'cylinder', but it must be one of flat, sphere"),
    (lambda: Indenter("sphere"), r"^indenter sphere takes the parameters \(radius\), not \(\)$"),
    (lambda: Indenter("flat", {"radius": 1.0}), r"^indenter flat takes the parameters \(\), not \(radius\)$"),
    (lambda: Indenter(TOY.name, {"slope": float("nan")}), r"^indenter.slope = nan is not finite"),
    (lambda: Indenter(TOY.name), r"takes the parameters \(slope\), not \(\)$"),
    (lambda: as_indenter("flat"), r"^indenter = 'flat', but it must be an Indenter"),
])
def test_a_bad_indenter_is_an_input_error(monkeypatch, make, match):
    monkeypatch.setitem(KINDS, TOY.name, TOY)
    with pytest.raises(InputError, match=match):
        make()


def test_a_kind_is_registered_once():
    with pytest.raises(ValueError, match="registered already"):
        register(KINDS["flat"])


def test_the_flat_plate_is_a_plane_on_which_the_force_is_pressure_times_area():
    rho = np.linspace(0.0, 1.0, 7).reshape(7, 1)
    assert np.array_equal(FLAT.height(rho), np.zeros((7, 1)))
    assert FLAT.pressure_area
    assert as_indenter(None) is FLAT


@pytest.mark.parametrize(("compression_curve", "options"), [
    (shooting.compression_curve, {}),
    (fem.compression_curve, {"elements": 32}),
    (fem.compression_curve, {"elements": 32, "contact": "penalty"}),
    (analytical.compression_curve, {}),
])
def test_states_carry_their_indenter_and_the_flat_plate_is_the_default(compression_curve, options):
    default = compression_curve(0.1, 0.3, [0.0, 0.5], **options)
    given = compression_curve(0.1, 0.3, [0.0, 0.5], indenter=FLAT, **options)
    assert [s.indenter for s in default + given] == [FLAT] * 4
    assert [s.scalars() for s in default] == [s.scalars() for s in given]


def test_the_sphere_is_its_cap_with_the_slope_and_curvature_of_its_profile():
    """Exact answers: the slope and the second derivative of z are those of finite differences of z
    (central, step 1e-5: error h^2 z'''/6, 1e-8 at rho = 0.35 where z''' ~ 600, relative 1e-7); the
    curvature of a sphere is 1/R_s everywhere on its cap; z(R_s) = R_s at the equator, NaN beyond."""
    from pocket.core.indenters import sphere

    tip = sphere(0.4)
    rho = np.linspace(0.0, 0.35, 8)
    h = 1e-5
    assert np.allclose(tip.slope(rho), (tip.height(rho + h) - tip.height(rho - h)) / (2 * h), rtol=1e-7, atol=1e-12)
    second = (tip.height(rho + h) - 2 * tip.height(rho) + tip.height(rho - h)) / h**2
    assert np.allclose(tip.curvature(rho) * (1 + tip.slope(rho) ** 2) ** 1.5, second, rtol=1e-4)
    assert np.allclose(tip.curvature(rho), 1 / 0.4, rtol=1e-12)
    assert tip.height(0.4) == 0.4
    assert np.isnan(tip.height(0.5))
    assert not tip.pressure_area


@pytest.mark.parametrize("radius", [0.0, -1.0, float("inf"), float("nan")])
def test_a_sphere_of_no_size_is_an_input_error(radius):
    from pocket.core.indenters import sphere

    with pytest.raises(InputError, match="radius"):
        sphere(radius)
