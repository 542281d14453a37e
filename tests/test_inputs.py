"""The one input checker: magnitudes of dimensionless inputs, file inputs, and how messages quote values."""

import functools
import math

import pytest

from pocket.apps.solvers import record
from pocket.core.errors import InputError
from pocket.core.inputs import MAGNITUDES, check_alpha, check_file, check_force, check_positive, quote


def test_magnitude_bounds_are_inclusive():
    """Exact answer: the bounds of MAGNITUDES pass, the next doubles outside them do not."""
    low, high = MAGNITUDES
    check = functools.partial(check_positive, "pressure")
    assert check(low) == low
    assert check(high) == high
    for outside in (math.nextafter(low, 0.0), math.nextafter(high, math.inf), 1e300, 1e-300):
        with pytest.raises(InputError, match="is outside the magnitudes of the model's dimensionless inputs"):
            check(outside)


@pytest.mark.parametrize("check", [check_force, check_alpha])
def test_ratios_and_forces_are_bounded_above_only(check):
    """A force or an alpha may be as small as a double allows (the unloaded and the neo-Hookean limits);
    above the largest magnitude it is refused."""
    _low, high = MAGNITUDES
    assert check(1e-300) == 1e-300
    assert check(high) == high
    with pytest.raises(InputError, match="is outside the magnitudes of the model's dimensionless inputs"):
        check(math.nextafter(high, math.inf))


def test_zero_force_and_zero_alpha_are_inputs():
    """A plate that does not push (Fhat = 0) and a neo-Hookean rubber (alpha = 0) are not magnitudes."""
    assert check_force(0.0) == 0.0
    assert check_alpha(0.0) == 0.0


def test_quote_stays_short_and_never_recurses():
    """A list nested 100000 deep (repr would overflow the stack), a 10^6-item list and a long text
    are quoted in a few dozen characters, on one line."""
    deep = []
    for _ in range(100_000):
        deep = [deep]
    for value in (deep, list(range(1_000_000)), "x" * 10**6, {"a": {"b": {"c": 1}}}, 10**100):
        text = quote(value)
        assert len(text) <= 80, text
        assert "\n" not in text, text
        assert "..." in text, text
    assert quote(0.1) == "0.1"
    assert quote("20 mm") == "'20 mm'"
    assert quote(True) == "True"


def test_check_file(tmp_path):
    """A readable regular file of bounded size passes; a folder, a device, a missing file, a list
    and a file over the bound do not, each in one line naming it."""
    path = tmp_path / "mesh.vtu"
    path.write_text("x" * 100)
    assert check_file("mesh", str(path), max_bytes=100) == str(path)
    for value, message in ((str(tmp_path), "is not a regular file"), ("/dev/zero", "is not a regular file"),
                           (str(tmp_path / "no.vtu"), r"cannot read it \(No such file"),
                           ([0, 0.5, 1], "but it must be a file name")):
        with pytest.raises(InputError, match=message):
            check_file("mesh", value)
    with pytest.raises(InputError, match="has 100 bytes, but an input file has at most 99"):
        check_file("mesh", str(path), max_bytes=99)


def test_a_path_option_is_a_checked_file():
    """Exact answer: the FE record's mesh option (kind "path") refuses a device before any read."""
    with pytest.raises(InputError, match="--mesh = '/dev/zero' is not a regular file"):
        record("fem").checked({"mesh": "/dev/zero"}, "inflate", lambda name: f"--{name}")
