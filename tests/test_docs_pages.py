"""The documentation's validation page quotes the validation suite's own tolerances, so that it cannot
drift from the code that applies them."""

from documents import ROOT
from pocket.validation import convergence, findings, limits, verdicts

PAGE = (ROOT / "docs" / "validation.md").read_text()


def _rows() -> dict:
    """The page's table rows by their first cell's code name: `fem_p2` -> the row's text."""
    rows = {}
    for line in PAGE.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("| `") and cells[0].startswith("`"):
            rows[cells[0].strip("`")] = line
    return rows


def test_validation_page_quotes_every_tolerance_of_the_suite():
    """Exact answer: each tolerance of ``verdicts.TOLERANCES`` has a row on the page, named as in the code,
    holding its value to two significant digits (computed ones, like the sphere's h^2, included)."""
    rows = _rows()
    for name, (tolerance, _) in verdicts.TOLERANCES.items():
        assert name in rows, name
        assert f"{tolerance:.2g}" in rows[name], (name, tolerance, rows[name])


def test_validation_page_quotes_the_convergence_and_limit_constants():
    """Exact answer: the page names each constant beside its value: the finest error of P2 on fitted meshes,
    the Richardson factor, the models' 1 % limit, the paper's analytical range and the reading of its fig. 3b."""
    text = " ".join(PAGE.split())
    for name, value in (("FITTED_P2_FINEST", f"{convergence.FITTED_P2_FINEST:g}"),
                        ("RICHARDSON_FACTOR", f"within {convergence.RICHARDSON_FACTOR:g} of"),
                        ("LIMIT", f"Within {100 * limits.LIMIT:g} %"),
                        ("ANALYTICAL_RANGE", f"\\hat F \\le {verdicts.ANALYTICAL_RANGE:g}"),
                        ("HEIGHT_READING", f"{findings.HEIGHT_READING:g} off")):
        assert f"`{name}`" in text, name
        assert value in text, (name, value)
