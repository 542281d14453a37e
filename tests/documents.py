"""The documentation a user reads, as text: the README and the site's Markdown pages (``docs/``), not what a
build generates there (the gallery's pages, the API's stubs, the built site)."""

import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[1]
#: folders of docs/ that a build writes
GENERATED = {"_build", "auto_examples", "generated"}


def pages() -> list[pathlib.Path]:
    """README.md, then every Markdown page of docs/ but the generated ones, in path order."""
    docs = sorted(p for p in (ROOT / "docs").rglob("*.md") if not GENERATED & set(p.relative_to(ROOT).parts))
    return [ROOT / "README.md", *docs]


def text() -> str:
    """Every page of ``pages()``, joined."""
    return "\n".join(page.read_text() for page in pages())
