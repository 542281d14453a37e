"""The page of every check (checks.html and checks.md beside the report): the verdicts per pocket, then every
check, failing first; the report itself keeps only the failing ones and links here."""

from __future__ import annotations

from .pockets import cell
from .verdicts import summary

__all__ = ["HEADER", "PAGE", "blocks", "failing_blocks"]

#: the page's files: HTML, Markdown
PAGE = ("checks.html", "checks.md")
#: the columns of a check's row
HEADER = ["case", "comparison", "step", "quantity", "where", "value", "reference", "error", "tolerance", "verdict"]
_ORDER = {"fail": 0, "pass": 1, "info": 2}


def _row(c) -> list:
    return [c.case, c.comparison, c.step, c.quantity, c.where, cell(c.value, 8), cell(c.reference, 8),
            cell(c.error, 3), cell(c.tolerance, 3), c.verdict]


def _summary_table(checks) -> tuple:
    rows = [[r["case"], r["comparison"], r["step"], r["checks"], r["worst"], cell(r["error"], 3),
             cell(r["tolerance"], 3), r["verdict"]] for r in summary(checks)]
    return ("table", ["case", "comparison", "step", "checks", "worst (quantity, where)", "error", "tolerance",
                      "verdict"], rows)


def failing_blocks(checks) -> list:
    """The report's section on the checks: the failing ones in full, and a link to the page of all."""
    failing = [_row(c) for c in checks if c.verdict == "fail"]
    out: list[tuple] = [("h", 2, "All checks"),
           ("p", f"{len(checks)} checks, {len(failing)} failing. Every one, with its value, reference, error, "
                 "tolerance and verdict, is in checks.csv and on a page of its own, with the verdicts per pocket, "
                 "comparison and step:"),
           ("link", *PAGE, f"every check ({PAGE[0]}, also {PAGE[1]})")]
    if failing:
        out += [("h", 3, "Failing checks"), ("table", HEADER, failing)]
    return out


def blocks(checks, title: str) -> list:
    """The page of every check of a report titled ``title``: the verdicts per pocket, comparison and step, then
    every check, failing first."""
    rows = [_row(c) for c in sorted(checks, key=lambda c: _ORDER[c.verdict])]
    n = {v: sum(c.verdict == v for c in checks) for v in _ORDER}
    return [("h", 1, f"{title}: every check"),
            ("p", f"{len(rows)} checks: {n['pass']} pass, {n['fail']} fail, {n['info']} informational (no "
                  "tolerance: a model's measured error, reported). Errors are relative (|value / reference - 1|) "
                  "unless the row says otherwise; the tolerances and their reasons are in the report. The same "
                  "rows are in checks.csv."),
            ("link", "index.html", "report.md", "back to the report (index.html, also report.md)"),
            ("toc",),
            ("h", 2, "Verdicts per pocket"),
            ("p", "One row per pocket, comparison and step: the verdict is 'fail' if any of its checks fails."),
            _summary_table(checks),
            ("h", 2, "Every check"),
            ("p", "Failing first, then passing, then informational."),
            ("table", HEADER, rows)]
