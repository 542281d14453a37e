"""The membrane's reference surface (``pocket.core.geometries``): the flat clamped disc and the closed capsule, given
to every solver as a law and an indenter are, refused in one line by a solver that does not pose it, carried by the
states, and changing no reported number."""

import dataclasses
import importlib
import json
import math

import numpy as np
import pytest

from pocket import analytical, fem, shooting, solid
from pocket.apps.solvers import SOLVERS
from pocket.cli.main import main
from pocket.core.errors import InputError
from pocket.core.geometries import (
    CAPSULE,
    DISC,
    GEOMETRIES,
    Clamp,
    Geometry,
    Support,
    Symmetry,
    as_geometry,
    clamp_of,
    formulation,
    posed,
)
from pocket.core.states import CompressedState, InflatedState


class _Equator(Support):
    """A toy support: the meridian's end on the equatorial plane, free to move radially."""


class Hemisphere(Geometry):
    """A toy surface no solver poses: the upper half of the unit sphere, S in [0, pi/2]."""

    name = "toy-hemisphere"
    description = "the upper half of a sphere of radius R (a test's toy)"

    @property
    def length(self) -> float:
        return 0.5 * math.pi

    def radius(self, arc) -> np.ndarray:
        return np.sin(np.asarray(arc, dtype=float))

    def height(self, arc) -> np.ndarray:
        return np.cos(np.asarray(arc, dtype=float))

    @property
    def end(self) -> Support:
        return _Equator()

    @property
    def volume(self) -> float:
        return 2.0 * math.pi / 3.0


def test_the_disc_is_the_flat_sheet_clamped_at_its_rim():
    """Exact answers: on a flat disc the arc length from the pole is the radius, so r0(S) = S (the very array
    given, bit for bit) and z0 = 0 with the shape of S; its meridian is R long (1), ends at the clamp r = 1,
    z = 0, and encloses no volume; its word is ``pocket``."""
    arc = np.linspace(0.0, 1.0, 7)
    assert DISC.radius(arc) is arc
    assert DISC.radius([0.0, 0.25]).tolist() == [0.0, 0.25]
    assert DISC.height(arc.reshape(7, 1)).shape == (7, 1)
    assert not DISC.height(arc).any()
    assert (DISC.length, DISC.volume) == (1.0, 0.0)
    assert DISC.end == Clamp(radius=1.0, height=0.0)
    assert clamp_of(DISC) is DISC.end
    assert DISC.name == "pocket"
    assert GEOMETRIES == {"pocket": DISC, "capsule": CAPSULE}


def test_the_capsule_is_the_upper_half_of_the_unit_sphere_on_its_equators_symmetry():
    """Exact answers: the capsule's meridian is the quarter circle r0 = sin S, z0 = cos S (so r0^2 + z0^2 = 1 and
    its length is pi/2); it ends on the equatorial plane held by the mirror symmetry, not a clamp; the volume it
    encloses with that plane is that of the surface of revolution, integral of pi r0^2 dz (2 pi/3, by quadrature
    here: the half of the ball 4 pi/3)."""
    from scipy.integrate import quad

    arc = np.linspace(0.0, CAPSULE.length, 9)
    assert CAPSULE.length == 0.5 * math.pi
    np.testing.assert_allclose(CAPSULE.radius(arc) ** 2 + CAPSULE.height(arc) ** 2, 1.0, rtol=0, atol=1e-15)
    assert (CAPSULE.radius(0.0), CAPSULE.height(CAPSULE.length)) == (0.0, pytest.approx(0.0, abs=1e-16))
    volume = quad(lambda s: math.pi * math.sin(s) ** 2 * math.sin(s), 0.0, CAPSULE.length)[0]  # -dz0 = sin S dS
    assert CAPSULE.volume == pytest.approx(volume, rel=1e-14)
    assert CAPSULE.end == Symmetry(height=0.0)
    assert as_geometry("capsule") is CAPSULE
    with pytest.raises(ValueError, match=r"^the capsule geometry's meridian is not clamped at its end$"):
        clamp_of(CAPSULE)


def test_a_geometry_is_none_a_name_or_a_geometry():
    """Exact answers: None and the name ``pocket`` are the disc; a Geometry is returned as given; an unknown
    name or another object is a one-line InputError quoting it and naming the choices."""
    toy = Hemisphere()
    assert as_geometry(None) is DISC
    assert as_geometry("pocket") is DISC
    assert as_geometry(toy) is toy
    for value, shown in (("torus", "'torus'"), (1.0, "1.0")):
        with pytest.raises(InputError, match=rf"^geometry = {shown}, but it must be one of pocket, capsule or a "
                                             "Geometry"):
            as_geometry(value)


def test_a_surface_held_otherwise_has_no_clamp():
    """Exact answer: ``clamp_of`` a surface whose end is not clamped is a ValueError naming it (a solver that
    asks poses clamped surfaces only: a defect, not an input error)."""
    with pytest.raises(ValueError, match=r"^the toy-hemisphere geometry's meridian is not clamped at its end$"):
        clamp_of(Hemisphere())


def test_posed_gives_the_geometry_and_the_solvers_formulation():
    """Exact answers: None is the disc with the table's entry for it; a surface the table lacks is the one-line
    InputError naming the solver, the surface and those it poses."""
    assert posed({"pocket": "flat"}, "toy", None) == (DISC, "flat")
    assert formulation({"pocket": 1, "toy-hemisphere": 2}, "toy", Hemisphere()) == 2
    with pytest.raises(InputError, match=r"^solver toy does not implement the toy-hemisphere geometry "
                                         r"\(its geometries: pocket\)$"):
        posed({"pocket": 1}, "toy", Hemisphere())


#: entry point -> its call with a small pocket (Mooney-Rivlin alpha 0.1, Phat 0.1) and the keyword ``geometry``
CALLS = {
    "inflate": lambda fn, g: fn(0.1, 0.1, geometry=g),
    "inflate_volume": lambda fn, g: fn(0.1, 0.3, geometry=g),
    "inflation_curve": lambda fn, g: fn(0.1, [0.1, 0.2], geometry=g),
    "compress": lambda fn, g: fn(0.1, 0.1, 0.5, geometry=g),
    "compression_curve": lambda fn, g: fn(0.1, 0.1, [0.5], geometry=g),
    "compress_height": lambda fn, g: fn(0.1, 0.1, 0.2, geometry=g),
    "range_end": lambda fn, g: fn(0.1, 0.1, geometry=g),
}
ENTRIES = [(s.name, name) for s in SOLVERS.values() for name in s.entry_points]


@pytest.fixture
def no_work(monkeypatch):
    """Every solver's first piece of work replaced by a failure: a refusal must come before any."""

    def work(*args, **kwargs):
        raise AssertionError("the solver started work before refusing the geometry")

    from pocket.fem import inflation as fem_inflation
    from pocket.shooting import inflation as shooting_inflation
    from pocket.solid import inflation as solid_inflation

    for module, name in ((shooting_inflation, "shot_pole"), (fem_inflation, "inflated_at"),
                         (fem_inflation, "to_volume"), (solid_inflation, "to_pressure"),
                         (solid_inflation, "to_volume")):
        monkeypatch.setattr(module, name, work)


@pytest.mark.parametrize(("solver", "name"), ENTRIES, ids=[f"{s}.{n}" for s, n in ENTRIES])
def test_every_entry_point_refuses_a_geometry_its_solver_does_not_pose(no_work, solver, name):
    """Exact answer: each entry point of each solver, given a surface no solver poses (a toy hemisphere), is the
    one-line InputError "solver <name> does not implement the toy-hemisphere geometry (its geometries: ...)" naming
    the surfaces of its table, raised before any solve."""
    fn = SOLVERS[solver].entry(name, "a test")
    with pytest.raises(InputError) as caught:
        CALLS[name](fn, Hemisphere())
    table = importlib.import_module(TABLES[solver]).GEOMETRIES
    assert "pocket" in table
    assert str(caught.value) == (f"solver {solver} does not implement the toy-hemisphere geometry "
                                 f"(its geometries: {', '.join(table)})")


#: solver -> the module holding its table of the surfaces it poses
TABLES = {"shooting": "pocket.shooting.inflation", "fem": "pocket.fem.api", "solid": "pocket.solid.api",
          "analytical": "pocket.analytical.model"}


#: solver -> (inflate, compress) with small meshes where a solver has one (the states' geometry is what is checked)
SMALL = {
    "shooting": (shooting.inflate, shooting.compress),
    "fem": (lambda *a, **k: fem.inflate(*a, elements=16, **k), lambda *a, **k: fem.compress(*a, elements=16, **k)),
    "solid": (lambda *a, **k: solid.inflate(*a, elements=16, layers=2, **k),
              lambda *a, **k: solid.compress(*a, elements=16, layers=2, **k)),
    "analytical": (analytical.inflate, analytical.compress),
}


@pytest.mark.parametrize("solver", SMALL)
def test_states_carry_the_geometry_they_were_solved_on(solver):
    """Exact answers: an inflated state, given no geometry or the name ``pocket``, carries the disc; a compressed
    state carries its inflated state's; neither reports it among its scalars (no reported key changes)."""
    inflate, compress = SMALL[solver]
    inflated = inflate(0.1, 0.1, geometry="pocket")
    pressed = compress(0.1, 0.1, 0.5)
    assert inflated.geometry is DISC
    assert pressed.inflated.geometry is DISC
    assert pressed.geometry is DISC
    assert "geometry" not in inflated.scalars()
    assert "geometry" not in pressed.scalars()


def test_a_compressed_state_reads_its_geometry_from_its_inflated_state():
    """Exact answer: the compressed state's ``geometry`` is its inflated state's, whatever that is (one fact,
    held once): a state whose inflated state is given the toy surface reports the toy surface."""
    pressed = analytical.compress(0.1, 0.1, 0.5)
    toy = Hemisphere()
    moved = dataclasses.replace(pressed, inflated=dataclasses.replace(pressed.inflated, geometry=toy))
    assert moved.geometry is toy
    assert "geometry" not in {f.name for f in dataclasses.fields(CompressedState)}
    assert next(f for f in dataclasses.fields(InflatedState) if f.name == "geometry").default is DISC


@pytest.mark.parametrize("argv", [["inflate", "--pressure", "0.1"],
                                  ["compress", "--pressure", "0.1", "--force", "0.5"]], ids=["inflate", "compress"])
def test_the_command_lines_json_is_the_states_on_the_disc(capsys, argv):
    """Exact answer: ``pocket inflate/compress --json`` (shooting) prints the scalars of the state the Python API
    solves with the disc given explicitly, every number equal to the last bit (float.hex), and no key
    naming the geometry: the reference surface changes no reported number or key."""
    assert main([*argv, "--alpha", "0.1", "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    state = (shooting.inflate(0.1, 0.1, geometry=DISC) if argv[0] == "inflate"
             else shooting.compress(0.1, 0.1, 0.5, geometry=DISC))
    expected = state.scalars()
    assert set(printed) - {"warnings"} == set(expected)
    assert "geometry" not in printed
    for key, value in expected.items():
        if isinstance(value, float):
            assert float(printed[key]).hex() == value.hex(), key
        else:
            assert printed[key] == value, key
