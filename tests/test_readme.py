"""The README as the front door: short, the two commands of the quick start as they are, the docs' build
command, links that resolve, the front picture; and CITATION.cff, which names the paper pocket implements."""

import re

import yaml
from documents import ROOT

README = (ROOT / "README.md").read_text()
#: the quick start's commands, each to be pasted as it stands: the validation report, and the default test lane
COMMANDS = ("python3 -m venv .venv && .venv/bin/pip install '.[render]' && .venv/bin/pocket validate",
            "python3 -m venv .venv && .venv/bin/pip install '.[test]' && .venv/bin/pytest")
DOCS_BUILD = ".venv/bin/pip install '.[docs]' && .venv/bin/sphinx-build -W -b html docs docs/_build/html"
#: the paper, as the theory note cites it
PAPER = "Compression of pressurised elastic pockets"


def _sh_blocks(text: str) -> list[str]:
    return [block.strip() for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S)]


def test_readme_is_a_front_door_of_at_most_150_lines():
    """Exact answer: the README has at most 150 lines (the reference material lives in docs/)."""
    assert len(README.splitlines()) <= 150


def test_readme_quick_start_commands_paste_as_they_are():
    """Exact answer: each of the two commands is the whole of an sh block of its own, verbatim, so that a
    reader copies one block and gets exactly that command."""
    blocks = _sh_blocks(README)
    for command in COMMANDS:
        assert command in blocks, command


def test_readme_says_how_to_build_the_docs():
    """Exact answer: the docs' build command is an sh block of its own, and the README names the page it
    writes."""
    assert DOCS_BUILD in _sh_blocks(README)
    assert "docs/_build/html/index.html" in README


def test_readme_links_lead_somewhere():
    """Exact answer: every relative link and image of the README names a file or folder of the repository
    (they read on the forge as they are), and the front picture is the docs' own."""
    targets = re.findall(r"\]\(([^)\s]+)\)", README)
    local = [t.split("#")[0] for t in targets if not re.match(r"[a-z]+:", t)]
    assert "docs/_static/pocket.png" in local
    missing = [t for t in local if not (ROOT / t).exists()]
    assert not missing, missing
    assert "](_static/pocket.png)" in (ROOT / "docs" / "index.md").read_text()


def test_citation_names_the_paper_pocket_implements():
    """Exact answer: CITATION.cff is YAML with a cff-version, and among its references (or its preferred
    citation) an article titled as the theory note cites the paper, by Bouremel."""
    theory = (ROOT / "docs" / "theory.md").read_text()
    assert f"Bouremel et al., *{PAPER}*" in " ".join(theory.split())
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert str(cff["cff-version"]).startswith("1.")
    works = [*cff.get("references", []), *([cff["preferred-citation"]] if "preferred-citation" in cff else [])]
    papers = [w for w in works if w.get("title") == PAPER]
    assert papers, works
    assert any(a.get("family-names") == "Bouremel" for a in papers[0]["authors"])
