"""Units: strings with units and plain SI numbers give the same SI float; wrong ones are one-line errors."""

import pytest

from pocket.core.errors import InputError
from pocket.core.units import positive, quantity


@pytest.mark.parametrize(
    ("text", "kind", "si"),
    [
        ("0.25 mm", "length", 0.25e-3),
        ("20mm", "length", 0.02),
        ("4.8 kPa", "pressure", 4800.0),
        ("1.241 MPa", "pressure", 1.241e6),
        ("0.67 N", "force", 0.67),
        ("2 mL", "volume", 2e-6),
        ("0.5", "length", 0.5),  # a plain number is SI
        (0.5, "force", 0.5),
        (3, "pressure", 3.0),
    ],
)
def test_parsed_to_si(text, kind, si):
    """Exact: the SI value of each prefix, to rounding (mL is 1e-6 m^3 with one rounding)."""
    assert quantity("key", text, kind) == pytest.approx(si, rel=1e-15)


@pytest.mark.parametrize(
    ("value", "kind", "message"),
    [
        ("4 mm", "pressure", "key = '4 mm' has dimension [length], but a pressure (Pa) is needed"),
        ("1 kPa", "length", "but a length (m) is needed"),
        ("4 bananas", "force", "key = '4 bananas' is not a quantity with a known unit"),
        ("2 *", "force", "is not a quantity"),
        (True, "force", "key = True is not a force"),
        ([1], "force", "is not a force"),
        ("inf Pa", "pressure", "is not finite"),
    ],
)
def test_bad_values_name_the_key(value, kind, message):
    with pytest.raises(InputError) as err:
        quantity("key", value, kind)
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_positive():
    assert positive("sheet.thickness", "0.25 mm", "length") == pytest.approx(2.5e-4, rel=1e-15)
    with pytest.raises(InputError, match=r"sheet.thickness = '-0.25 mm', but it must be > 0"):
        positive("sheet.thickness", "-0.25 mm", "length")


@pytest.mark.parametrize(
    ("value", "given", "kind", "text"),
    [
        (0.0098787, "20 mm", "length", "9.8787 mm"),
        (0.01, "2 cm", "length", "1 cm"),
        (7e-6, "2 mL", "volume", "7 ml"),
        (4812.75, "4.8 kPa", "pressure", "4.81275 kPa"),
        (0.01, 0.02, "length", "0.01 m"),  # the user wrote plain SI
        (0.01, "4 bananas", "length", "0.01 m"),  # nothing to copy
    ],
)
def test_written_like(value, given, kind, text):
    """Exact: an SI value written in the unit the user wrote (prefixes are powers of ten)."""
    from pocket.core.units import written_like

    assert written_like(value, given, kind) == text
