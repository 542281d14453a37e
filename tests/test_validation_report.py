"""``pocket validate --quick`` end to end, and the report's files parsed back."""

import csv
import html.parser
import pathlib

import meshio
import numpy as np
import pytest
from pocket.validation.convergence import observed_order, richardson

from pocket.cli import main


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("validate") / "report"
    status = main(["validate", "--quick", "--out", str(out)])
    return status, out


def test_quick_run_passes(report, capsys):
    """Exact answer: every verdict passes (exit status 0), and summary.csv agrees."""
    status, out = report
    assert status == 0
    with (out / "summary.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert rows and {r["verdict"] for r in rows} <= {"pass", "info"}
    assert {r["comparison"] for r in rows} >= {"FEM P1 vs shooting", "FEM P2 vs shooting", "analytical vs shooting"}


def test_every_check_has_a_verdict_that_matches_its_numbers(report):
    """Exact answer: pass iff error <= tolerance; info iff no tolerance."""
    _, out = report
    with (out / "checks.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) > 50
    for r in rows:
        if r["tolerance"] in ("", "None"):
            assert r["verdict"] == "info", r
        else:
            assert (float(r["error"]) <= float(r["tolerance"])) == (r["verdict"] == "pass"), r


def test_figure_csvs_hold_the_plotted_numbers(report):
    """Exact answer: each PNG has its CSV, with finite numbers; fig2's shooting profile ends at the clamp (1, 0)."""
    _, out = report
    for name in ("fig2", "fig3a", "fig3b", "fig4", "fig5", "convergence"):
        png = out / f"{name}.png"
        assert png.stat().st_size > 10_000 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        with (out / f"{name}.csv").open() as handle:
            rows = list(csv.DictReader(handle))
        assert rows and all(np.isfinite([float(r["x"]), float(r["y"])]).all() for r in rows)
    with (out / "fig2.csv").open() as handle:
        clamp = [r for r in csv.DictReader(handle) if r["series"] == "shooting"][-1]
    assert float(clamp["x"]) == pytest.approx(1.0, abs=1e-9) and float(clamp["y"]) == pytest.approx(0.0, abs=1e-9)


def test_vtk_series_opens(report):
    """Exact answer: the .pvd lists every step; each surface reads back with meshio and carries the point data."""
    _, out = report
    pvd = (out / "vtk" / "surface.pvd").read_text()
    files = [line.split('file="')[1].split('"')[0] for line in pvd.splitlines() if "file=" in line]
    with (out / "states.csv").open() as handle:
        shooting = [r for r in csv.DictReader(handle) if r["case"] == "sample1-headline" and r["solver"] == "shooting"]
    assert len(files) == len(shooting) > 10
    for name in (files[0], files[-1]):
        mesh = meshio.read(out / "vtk" / name)
        assert {"lambda_1", "T_1", "contact"} <= set(mesh.point_data)
    assert mesh.point_data["contact"].any()  # the last step is compressed


class _Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.headings, self.depth = [], [], 0

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.images.append(dict(attrs)["src"])

    def handle_data(self, data):
        if self.lasttag in ("h1", "h2", "h3"):
            self.headings.append(data)


def test_html_and_markdown_are_complete(report):
    """Exact answer: the HTML parses, its images are files beside it (relative paths: no server), and the
    Markdown has the same sections, including the paper's disagreements."""
    _, out = report
    parser = _Links()
    parser.feed((out / "index.html").read_text())
    assert parser.images and all((out / src).is_file() and not pathlib.Path(src).is_absolute()
                                 for src in parser.images)
    markdown = (out / "report.md").read_text()
    for heading in ("Summary", "Figures", "Mesh convergence", "Where the paper and the model disagree",
                    "Provenance"):
        assert heading in parser.headings and f"## {heading}" in markdown
    import numpy

    assert f"| numpy | {numpy.__version__} |" in markdown  # the versions that ran
    for topic in ("Eq (9)", "(1 + alpha)", "under-predicts A_c", "5.7 F"):
        assert topic in markdown
    assert not list(out.parent.glob(".*partial"))  # the temporary folder is gone


def test_refuses_a_folder_that_is_not_a_report(tmp_path, capsys):
    """Exact answer: exit 2 with one line, the folder untouched, nothing left behind."""
    (tmp_path / "mine.txt").write_text("keep")
    assert main(["validate", "--quick", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not empty" in err
    assert [p.name for p in tmp_path.iterdir()] == ["mine.txt"]


def test_richardson_and_order_are_exact_on_a_power_law():
    """Exact answer: f(h) = 2 + 3 h^2 extrapolates to 2 with observed order 2."""
    h = np.array([0.4, 0.2, 0.1])
    f = 2.0 + 3.0 * h**2
    value, estimate, order = richardson(h, f)
    assert value == pytest.approx(2.0, rel=1e-13) and order == pytest.approx(2.0, rel=1e-12)
    assert estimate == pytest.approx(3.0 * 0.1**2, rel=1e-12)
    assert observed_order(h, f - 2.0) == pytest.approx(2.0, rel=1e-12)
    assert richardson(h, 2.0 + np.array([1.0, -0.5, 0.25])) is None  # alternating: no extrapolation


def test_converge_prints_orders_and_richardson(tmp_path, capsys):
    """Exact answer: the theory's orders (2 for P1, 4 for P2 in inflation) pass, and the
    Richardson value is printed next to the shooting value."""
    assert main(["converge", "--quick", "--out", str(tmp_path / "conv")]) == 0
    out = capsys.readouterr().out
    assert "observed order" in out and "Richardson" in out and "shooting" in out
    with (tmp_path / "conv" / "checks.csv").open() as handle:
        orders = [r for r in csv.DictReader(handle) if r["step"] == "order" and r["where"].startswith("inflation")]
    assert {float(r["reference"]) for r in orders} == {2.0, 4.0} and all(r["verdict"] == "pass" for r in orders)
