"""Every solver has the same face: an ``api`` module offering exactly the entry points its record lists,
each with the arguments and result that ``pocket.core.solver`` declares for it, annotated; and the checks
every compression entry point makes (the forces, the indenter) are core's, the same in each solver."""

import importlib
import inspect
import typing

import numpy as np
import pytest

from pocket.apps.solvers import SOLVERS
from pocket.core import solver as faces
from pocket.core.errors import InputError
from pocket.core.indenters import PLATE, Plate, Profile, Sphere, posed
from pocket.core.inputs import check_forces
from pocket.core.profiles import table

#: entry point -> the Protocol of pocket.core.solver that declares its face
PROTOCOLS = {"inflate": faces.Inflate, "inflate_volume": faces.InflateVolume, "inflation_curve": faces.InflationCurve,
             "compress": faces.Compress, "compression_curve": faces.CompressionCurve,
             "compress_height": faces.CompressHeight, "range_end": faces.RangeEnd}


def _entry_points():
    return [(s, name) for s in SOLVERS.values() for name in s.entry_points]


def _positional(fn) -> list[str]:
    return [p.name for p in inspect.signature(fn).parameters.values()
            if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD and p.name != "self"]


def test_every_entry_point_has_a_protocol():
    """Exact answer: the Protocols of ``pocket.core.solver`` are one per name of ``ENTRY_POINTS``, no more."""
    assert set(PROTOCOLS) == set(faces.ENTRY_POINTS)


@pytest.mark.parametrize("record", SOLVERS.values(), ids=SOLVERS)
def test_each_solver_api_offers_exactly_its_records_entry_points(record):
    """Exact answer: the entry-point names in ``<solver>.api.__all__`` are the record's ``entry_points``, each
    a function of ``api``, and the package hands out that same object (its lazy ``__getattr__`` has one home,
    ``api``); the package's ``__all__`` lists them too."""
    package = importlib.import_module(record.module)
    api = importlib.import_module(f"{record.module}.api")
    assert {name for name in api.__all__ if name in faces.ENTRY_POINTS} == set(record.entry_points)
    for name in record.entry_points:
        assert inspect.isfunction(getattr(api, name)), name
        assert getattr(package, name) is getattr(api, name), name
        assert name in package.__all__, name


@pytest.mark.parametrize(("record", "name"), _entry_points(), ids=[f"{s.name}.{n}" for s, n in _entry_points()])
def test_each_entry_point_has_the_declared_face(record, name):
    """Exact answers: the entry point's positional arguments are the names its Protocol declares (material
    first), and its return annotation, resolved, is the Protocol's (``InflatedState``,
    ``list[CompressedState]``, ``float``...), so ``inspect.signature`` shows a return annotation for each."""
    fn = getattr(importlib.import_module(f"{record.module}.api"), name)
    protocol = PROTOCOLS[name].__call__
    assert _positional(fn) == _positional(protocol)
    assert inspect.signature(fn).return_annotation is not inspect.Signature.empty
    assert typing.get_type_hints(fn)["return"] == typing.get_type_hints(protocol)["return"]


def test_annotated_entry_points_annotate_every_argument():
    """Exact answer: every argument of an entry point defined in an ``api`` module, in ``pocket.analytical.model``,
    ``pocket.shooting.inflation`` or ``pocket.shooting.travel`` carries a type (the entry points of shooting's
    ``compression`` and ``rangeend`` get theirs from the Protocols they are declared with in its ``api``)."""
    homes = {"api", "model", "inflation", "travel"}
    checked = 0
    for record, name in _entry_points():
        fn = getattr(importlib.import_module(f"{record.module}.api"), name)
        if fn.__module__.rsplit(".", 1)[1] not in homes:
            continue
        checked += 1
        bare = [p.name for p in inspect.signature(fn).parameters.values() if p.annotation is inspect.Parameter.empty]
        assert not bare, (record.name, name, bare)
    assert checked >= len(_entry_points()) - 3  # all but shooting's compress, compression_curve and range_end


@pytest.mark.parametrize("record", [s for s in SOLVERS.values() if s.serves("compression_curve")], ids=lambda s: s.name)
def test_a_curve_without_forces_is_refused_the_same_way_by_every_solver(record):
    """Exact answer: a compression curve asked for no force is the one-line InputError "no force given" in every
    solver (``pocket.core.inputs.check_forces``), before any solve."""
    curve = record.entry("compression_curve", "a test")
    with pytest.raises(InputError, match=r"^no force given$"):
        curve(0.0, 0.1, [])


def test_check_forces_takes_one_force_or_several():
    """Exact answers: a number is one force, a sequence or an array keeps its order and becomes floats; a
    negative force is refused naming its value, as ``check_force`` does."""
    assert check_forces(0.5) == [0.5]
    assert check_forces([0.2, np.float64(0.1), 1]) == [0.2, 0.1, 1.0]
    assert check_forces(np.array([[0.3, 0.0]]).ravel()) == [0.3, 0.0]
    with pytest.raises(InputError, match=r"^force = -1\.0, but a plate can only push"):
        check_forces([0.1, -1.0])


def test_posed_gives_the_indenter_and_its_formulation():
    """Exact answers: None is the flat plate with the table's plate entry; a class missing from the table is the
    one-line InputError naming the solver, the indenter and the table's indenters; a non-indenter is refused by
    ``as_indenter``'s message."""
    assert posed({Plate: "plate"}, "toy", None) == (PLATE, "plate")
    ball = Sphere(0.5)
    assert posed({Plate: 1, Sphere: 2}, "toy", ball) == (ball, 2)
    refusal = r"^solver toy does not implement the sphere indenter \(its indenters: plate\)$"
    with pytest.raises(InputError, match=refusal):
        posed({Plate: 1}, "toy", ball)
    with pytest.raises(InputError, match=r"^indenter = 'sphere', but it must be an Indenter"):
        posed({Plate: 1}, "toy", "sphere")


def test_an_indenter_holds_its_own_parameters():
    """Exact answers: a profile indenter's ``shape`` is the very Shape it was made from, a sphere's radius the
    number it was given, and a profile's reach the shape's last radius."""
    shape = table([0.0, 0.25, 0.5, 1.0], [0.0, 0.03125, 0.125, 0.5])  # z = rho^2 / 2
    assert Profile(shape).shape is shape
    assert Profile(shape).reach == 1.0
    assert Sphere(0.5).radius == 0.5
    assert Sphere(1).radius == 1.0
    assert isinstance(Sphere(1).radius, float)
