"""Sphinx configuration of pocket's documentation: ``sphinx-build -W -b html docs docs/_build/html``."""

import os
import pathlib
import sys

import pyvista

from pocket.apps.provenance import version as pocket_version

HERE = pathlib.Path(__file__).parent
sys.path.insert(0, str(HERE / "_ext"))

project = "pocket"
author = "the pocket developers"
copyright = "2026, the pocket developers"
release = pocket_version()
version = ".".join(release.split(".")[:2])

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    # MathJax served from the site itself, not a CDN: the pages' math renders offline too
    "sphinx-mathjax-offline",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "pocket_guide",
    "validation_report",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "_ext", "_inventories", "auto_examples/*.ipynb", "auto_examples/*.py",
                    "auto_examples/*.zip", "auto_examples/*.md5", "auto_examples/*.json"]

# MyST: $...$ and $$...$$ math, labelled equations, heading anchors for links between pages
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

# the API reference: numpydoc renders the docstrings' sections; autosummary writes one page per object
autosummary_generate = True
autodoc_default_options = {"members": True, "member-order": "bysource"}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False

# CI has no network: the inventories of the objects these pages link to are local files, written by
# _inventories/write.py with each object's address in its project's published documentation
intersphinx_mapping = {
    name: (url, str(HERE / "_inventories" / f"{name}.inv"))
    for name, url in {
        "python": "https://docs.python.org/3/",
        "numpy": "https://numpy.org/doc/stable/",
        "scipy": "https://docs.scipy.org/doc/scipy/",
        "skfem": "https://scikit-fem.readthedocs.io/en/latest/",
        "pint": "https://pint.readthedocs.io/en/stable/",
    }.items()
}

# the gallery: every script in examples/ runs when the docs build, its figures and printed numbers shown; the
# pyvista scraper takes the 3-D pictures (drawn off screen) of the plotters an example shows
pyvista.BUILDING_GALLERY = pyvista.OFF_SCREEN = True
sphinx_gallery_conf = {
    "examples_dirs": str(HERE.parent / "examples"),
    "gallery_dirs": str(HERE / "auto_examples"),
    "filename_pattern": r".*\.py$",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib", pyvista.Scraper()),
}

html_theme = "pydata_sphinx_theme"
html_title = f"pocket {version}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
}
html_static_path: list = []
# pages without sections of their own: no left sidebar, their tables get the width
html_sidebars = {page: [] for page in ("index", "theory", "validation", "performance", "developers")}

# a gallery example's figures are drawn off screen
os.environ.setdefault("MPLBACKEND", "Agg")
