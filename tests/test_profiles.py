"""A user's indenter profile: a table (CSV with units) or functions, interpolated as a cubic spline in
rho^2 (``pocket.core.profiles``). Exact answers: a sphere given as a table reproduces the sphere's
height, slope and curvature at the spline's orders 4, 3, 2 and within its stated bounds; a flat table is
the plate; every table that is no profile is refused in one line naming the file and the row or column."""

import numpy as np
import pytest

from pocket.core import profiles
from pocket.core.errors import InputError
from pocket.core.indenters import PLATE, Profile, Sphere

RADIUS = 0.4  # a fingertip of 8 mm on a 20 mm clamp, units R
TOP = 0.3  # the table's last radius: 3/4 of the way to the equator, where g'''' is large but bounded


def _sphere_table(rows: int):
    rho = np.linspace(0.0, TOP, rows)
    return rho, Sphere(RADIUS).height(rho)


def _errors(rows: int) -> np.ndarray:
    """Largest |profile - sphere| of height, slope and curvature on a fine grid, for ``rows`` rows."""
    tip, ball = Profile(profiles.table(*_sphere_table(rows))), Sphere(RADIUS)
    x = np.linspace(0.0, TOP, 4001)
    return np.array([np.max(np.abs(getattr(tip, f)(x) - getattr(ball, f)(x))) for f in ("height", "slope",
                                                                                        "curvature")])


def test_a_sphere_given_as_a_table_reproduces_the_sphere_at_the_splines_orders():
    """Orders 4, 3, 2 for height, slope, curvature (the spline's, module docstring), fitted over 20-160 rows."""
    rows = np.array([20, 40, 80, 160])
    errors = np.array([_errors(n) for n in rows])
    spacing = np.array([np.max(np.diff(_sphere_table(n)[0] ** 2)) for n in rows])
    orders = [np.polyfit(np.log(spacing), np.log(errors[:, k]), 1)[0] for k in range(3)]
    # the asymptotic orders are 4, 3, 2; the not-a-knot ends reach them from below as h shrinks
    assert orders[0] > 3.5, f"observed orders {orders!r}"
    assert orders[1] > 2.5, f"observed orders {orders!r}"
    assert orders[2] > 1.5, f"observed orders {orders!r}"


def test_a_sphere_given_as_a_table_lies_within_the_stated_error():
    """Hall & Meyer's bounds with M = max g'''' = 15/16 (R_s^2 - rho_max^2)^(-7/2) of g(s) = R_s - sqrt(R_s^2 - s),
    the slope's scaled by 2 rho_max (z' = 2 rho g') and the curvature's by z'' = 2 g' + 4 s g'' (its
    denominator (1 + z'^2)^(3/2) >= 1 only shrinks it); the module states at most a few times (4) them."""
    rows = 40
    h = np.max(np.diff(_sphere_table(rows)[0] ** 2))
    fourth = 15.0 / 16.0 * (RADIUS**2 - TOP**2) ** -3.5
    bounds = np.array([5 / 384 * h**4, 2 * TOP / 24 * h**3, 2 / 24 * h**3 + 4 * TOP**2 * 3 / 8 * h**2]) * fourth
    errors = _errors(rows)
    assert np.all(errors <= 4.0 * bounds), f"errors {errors!r} against 4 x {bounds!r}"


def test_a_sphere_read_from_a_csv_file_in_millimetres_is_the_sphere(tmp_path):
    """The same sphere written in mm on a 20 mm clamp, read back: the table's error, not the units', shows."""
    rho, z = _sphere_table(40)
    path = tmp_path / "tip.csv"
    rows = "".join(f"{r * 20:.17g},{h * 20:.17g}\n" for r, h in zip(rho, z, strict=True))
    path.write_text("radius [mm],height [mm]\n" + rows)
    tip, x = Profile(profiles.read_csv(path, clamp_radius=0.020)), np.linspace(0.0, TOP, 101)
    direct = Profile(profiles.table(rho, z))
    for f in ("height", "slope", "curvature"):
        np.testing.assert_allclose(getattr(tip, f)(x), getattr(direct, f)(x), rtol=1e-12, atol=1e-14)


def test_a_flat_profile_is_the_plate():
    tip, x = Profile(profiles.table([0.0, 0.5, 1.0, 1.5], [0.0] * 4)), np.linspace(0.0, 1.5, 31)
    for f in ("height", "slope", "curvature"):
        np.testing.assert_array_equal(getattr(tip, f)(x), getattr(PLATE, f)(x))


def test_a_profile_is_not_defined_past_its_last_row():
    tip = Profile(profiles.table(*_sphere_table(10)))
    assert np.all(np.isnan([tip.height(TOP * 1.01), tip.slope(TOP * 1.01), tip.curvature(TOP * 1.01)]))


def test_a_sphere_given_as_functions_is_the_sphere():
    ball = Sphere(RADIUS)
    tip = Profile(profiles.functions(ball.height, ball.slope, ball.curvature, extent=TOP))
    x = np.linspace(0.0, TOP, 51)
    for f in ("height", "slope", "curvature"):
        np.testing.assert_allclose(getattr(tip, f)(x), getattr(ball, f)(x), rtol=1e-14)


CSV_REFUSALS = [
    ("radius,height [mm]\n0,0\n1,0.1\n2,0.4\n3,0.9\n", r"column 1 \('radius'\) has no unit"),
    ("radius [mm],height []\n0,0\n1,0.1\n2,0.4\n3,0.9\n", r"column 2 \('height \[\]'\) has no unit"),
    ("radius [mm],height [kPa]\n0,0\n1,0.1\n2,0.4\n3,0.9\n", r"column 2 .* has dimension"),
    ("radius [mm],height [mm]\n0,0\n1,0.1\nabc,0.4\n3,0.9\n", r"row 3 is 'abc,0.4', but each row must be two"),
    ("radius [mm],height [mm]\n0,0\n1,0.1\n2\n3,0.9\n", r"row 3 is '2', but each row must be two numbers"),
    ("radius [mm],height [mm]\n0,0\n1,0.1\n2,0.4\n", r"3 rows, but a profile needs at least 4"),
    ("radius [mm],height [mm]\n0,0\n1,0.1\n2,0.4\n3,0.5\n", r"not convex at row 3 \('2,0.4'\)"),
    ("radius [mm],height [mm]\n0,0\n1,1\n2,2.1\n3,3.3\n", r"does not start flat on the axis"),
    ("radius [mm],height [mm]\n0,0.1\n1,0.2\n2,0.5\n3,1\n", r"row 1 \('0,0.1'\) has a height that is not 0"),
    ("radius [mm],height [mm]\n1,0\n2,0.1\n3,0.4\n4,0.9\n", r"row 1 \('1,0'\) has a radius that is not 0"),
    ("radius [mm],height [mm]\n0,0\n2,0.1\n1,0.4\n3,0.9\n", r"row 3 \('1,0.4'\): the radii must increase"),
    ("radius [mm]\n0\n1\n2\n3\n", r"the first line must name two columns with units"),
]


@pytest.mark.parametrize(("text", "match"), CSV_REFUSALS)
def test_a_bad_profile_file_is_one_line_naming_the_file(tmp_path, text, match):
    path = tmp_path / "tip.csv"
    path.write_text(text)
    with pytest.raises(InputError, match=match) as caught:
        profiles.read_csv(path, clamp_radius=0.020)
    assert str(caught.value).startswith(str(path))
    assert "\n" not in str(caught.value)


def test_a_profile_in_physical_units_needs_the_clamp_radius(tmp_path):
    path = tmp_path / "tip.csv"
    path.write_text("radius [mm],height [mm]\n0,0\n1,0.1\n2,0.4\n3,0.9\n")
    with pytest.raises(InputError, match=r"in mm, but a dimensionless command takes the profile in units of the "
                                         r"clamp radius: write the header like 'radius \[R\],height \[R\]'"):
        profiles.read_csv(path)
    path.write_text("radius [R],height [R]\n0,0\n0.1,0.01\n0.2,0.04\n0.3,0.09\n")
    np.testing.assert_allclose(Profile(profiles.read_csv(path)).height(0.25), 0.0625, rtol=1e-12)  # z = rho^2


def test_functions_that_are_no_profile_are_refused():
    with pytest.raises(InputError, match=r"z'\(0\) = 1, but a profile starts flat"):
        profiles.functions(lambda r: r, lambda r: np.ones_like(r), lambda r: np.zeros_like(r), extent=1.0)
    with pytest.raises(InputError, match=r"not convex near radius"):
        profiles.functions(lambda r: r**2 - r**4, lambda r: 2 * r - 4 * r**3, lambda r: 2 - 12 * r**2, extent=0.6)
    with pytest.raises(InputError, match=r"^indenter.shape = 1.0, but it must be a profile"):
        Profile(1.0)


def test_a_profile_table_survives_pickling():
    """A case holding a profile table can go to a worker process (the validation suite, sweeps): the copy is the
    same profile."""
    import pickle

    tip = Profile(profiles.table(*_sphere_table(12)))
    copy, x = pickle.loads(pickle.dumps(tip)), np.linspace(0.0, TOP, 17)
    for f in ("height", "slope", "curvature"):
        np.testing.assert_array_equal(getattr(copy, f)(x), getattr(tip, f)(x))
