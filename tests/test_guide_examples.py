"""The user guide's worked case files are valid cases: a reader who copies one gets no error."""

import pathlib
import re
import tomllib

import pytest

from pocket.apps.cases import parse

GUIDE = pathlib.Path(__file__).resolve().parents[1] / "docs" / "guide" / "case-files.md"
#: every TOML block of the page that is a whole case (it has a [sheet] table); the others are fragments
CASES = [block for block in re.findall(r"```toml\n(.*?)```", GUIDE.read_text(encoding="utf-8"), re.S)
         if "[sheet]" in block]


def test_the_guide_has_worked_cases():
    """Exact answer: the case-file page holds at least the three whole cases it promises (button, Yeoh and
    gas under a sphere, prestretched solid), so the test below cannot pass on an empty list."""
    assert len(CASES) >= 3


@pytest.mark.parametrize("text", CASES)
def test_a_worked_case_in_the_guide_is_a_valid_case(text):
    """The user's need: a worked example copied from the guide runs. Each whole case of the page parses and
    passes every check of the case reader (an InputError would fail the test), with the loads it lists."""
    data = tomllib.loads(text)
    case = parse(data, "guide example")
    assert len(case.loads) == len(next(iter(data["loads"].values())))
