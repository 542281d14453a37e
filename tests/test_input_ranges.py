"""Inputs outside the model's documented ranges are one line on stderr and exit 2, before any solving.

The ranges: a prestretch in [1, PRESTRETCH_LIMIT], Gent's Jm in JM_RANGE, an Ogden exponent's |alpha_p| in
EXPONENT_RANGE (``pocket.core.materials``), a sphere's K = R_s/R in SPHERE_RADII (``pocket.core.indenters``), a
volume V/R^3 up to VOLUME_LIMIT (``pocket.core.inputs``), and a file or folder name that is not empty. Each
regression below is an input that once ran for minutes, failed with exit 1 or was silently ignored; the
hypothesis tests draw values outside each range. The solvers are replaced by a function that fails the test, so
a refusal that came from a solve (rather than before it) fails too.
"""

import math
import re
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pocket.apps.cases import parse
from pocket.cli import main, solve
from pocket.core.errors import STRETCH_LIMIT, InputError
from pocket.core.indenters import SPHERE_RADII, Sphere
from pocket.core.inputs import VOLUME_LIMIT, check_volume
from pocket.core.materials import EXPONENT_RANGE, JM_RANGE, PRESTRETCH_LIMIT, Material

INFLATE = ["inflate", "--pressure", "0.3"]
COMPRESS = ["compress", "--pressure", "0.3", "--force", "1", "--alpha", "0.3"]
SPHERE = [*COMPRESS, "--indenter", "sphere", "--indenter-radius"]


def _no_solving(*args, **kwargs):
    raise AssertionError("a solver was called before the input was refused")


@pytest.fixture
def unsolved(monkeypatch):
    """The command line's solvers replaced by ``_no_solving``."""
    monkeypatch.setattr(solve, "entry", lambda *args, **kwargs: _no_solving)


def _refused(capsys, argv) -> str:
    """The one line of stderr of ``pocket argv``, which must exit 2 and print nothing."""
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    assert "Traceback" not in err
    return err


@pytest.mark.parametrize("solver", ["shooting", "fem"])
@pytest.mark.parametrize(("argv", "message"), [
    ([*INFLATE, "--alpha", "0.3", "--prestretch", "3000"],
     f"--prestretch = 3000.0, but a prestretch of the clamped sheet must be at most {PRESTRETCH_LIMIT:g}"),
    ([*SPHERE, "1e-300"], f"--indenter-radius = 1e-300, but a sphere's radius K = R_s/R must lie in "
                          f"[{SPHERE_RADII[0]:g}, {SPHERE_RADII[1]:g}]"),
    ([*SPHERE, "1e-6"], "--indenter-radius = 1e-06, but a sphere's radius K = R_s/R must lie in"),
    ([*INFLATE, "--law", "gent", "--mu", "1", "--jm", "1e-12"],
     f"--jm = 1e-12, but it must lie in [{JM_RANGE[0]:g}, {JM_RANGE[1]:g}]"),
    (["inflate", "--alpha", "0.3", "--volume", "1e6"],
     f"--volume = 1000000.0, but a state of the model encloses at most V/R^3 = {VOLUME_LIMIT:.3g}"),
    ([*INFLATE, "--alpha", "0.3", "--vtk", ""], "argument --vtk: '' is empty, but it must name a file or folder"),
])
def test_absurd_input_is_one_line_exit_2_before_solving(capsys, unsolved, solver, argv, message):
    """Each of these once hung (prestretch 3000), failed with exit 1 (a sphere of K = 1e-300 or 1e-6, Jm = 1e-12,
    V/R^3 = 1e6) or was ignored (--vtk ''): now the one line quoting the input and its range, for either solver."""
    assert message in _refused(capsys, [*argv, "--solver", solver])


def test_an_empty_vtk_folder_is_refused_not_ignored_when_it_would_be_solved(capsys, tmp_path, monkeypatch):
    """``--vtk ''`` was skipped by a truth test and the command succeeded without writing a series: it is refused
    (exit 2), and nothing is written in the current folder (which '' would name as a path)."""
    monkeypatch.chdir(tmp_path)
    _refused(capsys, [*COMPRESS, "--vtk", ""])
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv", [
    ["run", "--sample", "1", "--out", ""], ["run", "--sample", "1", "--out", "x", "--vtk", " "], ["run", ""],
    ["sweep", "--alpha", "0.3", "--pressure", "0.3", "--force", "0.1", "--out", ""],
    ["sense", "--sample", "1", "--pressure", "6 kPa", "--table", ""], ["validate", "--out", ""],
    ["validate", "--cases", ""], [*COMPRESS, "--indenter", "profile", "--indenter-file", ""],
    [*COMPRESS, "--solver", "fem", "--mesh", ""],
])
def test_an_empty_file_or_folder_name_is_refused(capsys, tmp_path, monkeypatch, argv):
    """An empty or blank name names no file or folder (``run --out ''`` wrote its results into the current folder):
    one line naming the option, exit 2, nothing written."""
    monkeypatch.chdir(tmp_path)
    assert "is empty, but it must name a file or folder" in _refused(capsys, argv)
    assert list(tmp_path.iterdir()) == []


_CASE = """
[sheet]
thickness = "0.25 mm"
{sheet}
[clamp]
radius = "20 mm"
[initial]
{initial}
[loads]
forces = ["0.2 N"]
{indenter}
"""


@pytest.mark.parametrize(("sheet", "initial", "indenter", "message"), [
    ('modulus = "1 MPa"\nalpha = 0.3\nprestretch = 3000', 'pressure = "4 kPa"', "",
     "sheet.prestretch = 3000, but a prestretch of the clamped sheet must be at most"),
    ('material = "gent"\nmu = "0.3 MPa"\njm = 1e-12', 'pressure = "4 kPa"', "", "sheet.jm = 1e-12, but it must lie in"),
    ('material = "ogden"\nmu = ["1 MPa"]\nexponents = [60.0]', 'pressure = "4 kPa"', "",
     "sheet.exponents[0] = 60.0, but |alpha_p| must lie in"),
    ('modulus = "1 MPa"\nalpha = 0.3', 'pressure = "4 kPa"', '[indenter]\nshape = "sphere"\nradius = "0.01 mm"',
     "indenter.radius = '0.01 mm' (K = R_s/R = 0.0005), but a sphere's radius K = R_s/R must lie in"),
    ('modulus = "1 MPa"\nalpha = 0.3', 'volume = "100 m^3"', "",
     "initial.volume = '100 m^3' (V/R^3 = 1.25e+07), but a state of the model encloses at most"),
])
def test_a_case_file_outside_the_ranges_is_refused_when_read(sheet, initial, indenter, message):
    """A case file gets the same ranges as the command line, when it is read (no solver runs in ``parse``), the
    message naming its key with the value as written and, for a length or volume, its dimensionless form:
    0.01 mm on a 20 mm clamp is K = 5e-4; 100 m^3 over it is V/R^3 = 100 / 0.02^3 = 1.25e7."""
    with pytest.raises(InputError, match="^" + re.escape(message)):
        parse(tomllib.loads(_CASE.format(sheet=sheet, initial=initial, indenter=indenter)))


def test_the_volume_limit_is_the_isoperimetric_bound_of_the_stretch_limit():
    """VOLUME_LIMIT = (pi / 6) (1 + J)^(3/2) R^3 with J = STRETCH_LIMIT^2: a closed surface of area A encloses at most
    A^(3/2) / (6 sqrt(pi)), here the sheet (area at most J pi R^2) and the clamp's disc (pi R^2)."""
    area = (1.0 + STRETCH_LIMIT**2) * math.pi
    assert pytest.approx(area**1.5 / (6.0 * math.sqrt(math.pi)), rel=1e-14) == VOLUME_LIMIT
    assert check_volume("volume", VOLUME_LIMIT) == VOLUME_LIMIT
    with pytest.raises(InputError, match="encloses at most"):
        check_volume("volume", math.nextafter(VOLUME_LIMIT, math.inf))


@given(st.floats(1e-6, 1e6))
def test_no_spherical_cap_over_the_clamp_encloses_more_than_the_bound_of_its_thinning(h):
    """The bound V <= (pi / 6) (1 + J)^(3/2) R^3, J the sheet's area over pi R^2, holds for every spherical cap of
    height h over the unit disc (area pi (1 + h^2), volume pi h (3 + h^2) / 6), and it is reached as h grows:
    h (3 + h^2) <= (2 + h^2)^(3/2), whose ratio tends to 1 (within 1e-6 of it past h = 1e3)."""
    thinning, volume = 1.0 + h * h, math.pi * h * (3.0 + h * h) / 6.0
    bound = math.pi / 6.0 * (1.0 + thinning) ** 1.5
    assert volume <= bound * (1.0 + 1e-15)
    if h > 1e3:
        assert volume > bound * (1.0 - 1e-6)


_BIG = 1e300


def _outside(low, high):
    """Positive floats below ``low`` or above ``high`` (up to 1e300)."""
    return st.one_of(st.floats(5e-324, low, exclude_max=True), st.floats(high, _BIG, exclude_min=True))


def _ogden(a):
    """The Ogden rubber of one term with exponent ``a`` and mu of its sign (stable), given as ``--flag=value``: argparse
    would read a separate ``-5e-324`` as an option."""
    return [*INFLATE, "--law", "ogden", f"--mu={math.copysign(1.0, a)!r}", f"--exponents={a!r}"]


#: (flag the message names, the command line with the drawn value) per range
_DRAWN = st.one_of(
    st.floats(PRESTRETCH_LIMIT, _BIG, exclude_min=True).map(
        lambda x: ("--prestretch", [*INFLATE, "--alpha", "0.3", "--prestretch", repr(x)])),
    _outside(*JM_RANGE).map(lambda x: ("--jm", [*INFLATE, "--law", "gent", "--mu", "1", "--jm", repr(x)])),
    st.tuples(_outside(*EXPONENT_RANGE), st.sampled_from([1.0, -1.0])).map(
        lambda xs: ("--exponents", _ogden(xs[0] * xs[1]))),
    _outside(*SPHERE_RADII).map(lambda x: ("--indenter-radius", [*SPHERE, repr(x)])),
    st.floats(VOLUME_LIMIT, _BIG, exclude_min=True).map(lambda x: ("--volume", ["inflate", "--alpha", "0.3",
                                                                               "--volume", repr(x)])),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(_DRAWN)
def test_a_value_outside_a_documented_range_is_refused_before_solving(capsys, monkeypatch, drawn):
    """Any value drawn outside a range (the prestretch above its limit, Jm, |alpha_p| or K below or above theirs,
    a volume above its limit) is one line naming the flag, exit 2, and no solver is called."""
    flag, argv = drawn
    monkeypatch.setattr(solve, "entry", lambda *args, **kwargs: _no_solving)  # each reading of stderr consumes it
    err = _refused(capsys, argv)
    assert err.startswith(f"pocket: error: {flag}")


@given(st.one_of(
    st.floats(PRESTRETCH_LIMIT, _BIG, exclude_min=True).map(
        lambda x: lambda: Material("neo-hookean", {"mu": 1.0}, prestretch=x)),
    _outside(*JM_RANGE).map(lambda x: lambda: Material("gent", {"mu": 1.0, "jm": x})),
    _outside(*EXPONENT_RANGE).map(lambda x: lambda: Material("ogden", {"mu": [1.0], "exponents": [x]})),
    _outside(*SPHERE_RADII).map(lambda x: lambda: Sphere(x)),
    st.floats(VOLUME_LIMIT, _BIG, exclude_min=True).map(lambda x: lambda: check_volume("volume", x)),
))
def test_the_python_api_refuses_the_same_values(build):
    """The ranges live where the rubber, the indenter and the volume are checked, so a Python caller who builds
    the same rubber or sphere gets the same InputError as the command line."""
    with pytest.raises(InputError):
        build()
