"""Write the intersphinx inventories of the external objects pocket's docs link to.

CI builds the docs with no network, so the docs cannot fetch numpy's, scipy's, scikit-fem's, pint's and
Python's own inventories at build time. This script writes, for each, a small inventory (Sphinx's version-2
``objects.inv`` format) of the objects pocket's docs name, each with its address in that project's published
documentation; ``docs/conf.py`` reads them as intersphinx's local inventories. Add an object here when a page
or a docstring links to one that is not listed, then run ``python docs/_inventories/write.py``.
"""

import pathlib
import zlib

HERE = pathlib.Path(__file__).parent

#: project -> (its documentation's name and version, [(object, domain:role, address relative to its docs)])
OBJECTS = {
    "python": ("Python", "3", [
        ("float", "py:class", "library/functions.html#float"),
        ("int", "py:class", "library/functions.html#int"),
        ("str", "py:class", "library/stdtypes.html#str"),
        ("bool", "py:class", "library/functions.html#bool"),
        ("dict", "py:class", "library/stdtypes.html#dict"),
        ("list", "py:class", "library/stdtypes.html#list"),
        ("tuple", "py:class", "library/stdtypes.html#tuple"),
        ("pathlib.Path", "py:class", "library/pathlib.html#pathlib.Path"),
        ("ValueError", "py:exception", "library/exceptions.html#ValueError"),
        ("RuntimeError", "py:exception", "library/exceptions.html#RuntimeError"),
    ]),
    "numpy": ("NumPy", "stable", [
        ("numpy.ndarray", "py:class", "reference/generated/numpy.ndarray.html#numpy.ndarray"),
        ("numpy.linspace", "py:function", "reference/generated/numpy.linspace.html#numpy.linspace"),
    ]),
    "scipy": ("SciPy", "stable", [
        ("scipy.optimize.least_squares", "py:function",
         "reference/generated/scipy.optimize.least_squares.html#scipy.optimize.least_squares"),
        ("scipy.optimize.brentq", "py:function",
         "reference/generated/scipy.optimize.brentq.html#scipy.optimize.brentq"),
        ("scipy.integrate.solve_ivp", "py:function",
         "reference/generated/scipy.integrate.solve_ivp.html#scipy.integrate.solve_ivp"),
    ]),
    "skfem": ("scikit-fem", "latest", [
        ("skfem.mesh.MeshLine1", "py:class", "api.html#skfem.mesh.MeshLine1"),
        ("skfem.mesh.MeshTri1", "py:class", "api.html#skfem.mesh.MeshTri1"),
        ("skfem.assembly.Basis", "py:class", "api.html#skfem.assembly.Basis"),
    ]),
    "pint": ("pint", "stable", [
        ("pint.Quantity", "py:class", "api/base.html#pint.Quantity"),
        ("pint.UnitRegistry", "py:class", "api/base.html#pint.UnitRegistry"),
    ]),
}


def inventory(project: str, version: str, objects: list) -> bytes:
    """The bytes of a version-2 Sphinx inventory of ``objects`` ((name, domain:role, address) triples)."""
    header = f"# Sphinx inventory version 2\n# Project: {project}\n# Version: {version}\n"
    header += "# The remainder of this file is compressed using zlib.\n"
    lines = "".join(f"{name} {role} 1 {address} -\n" for name, role, address in objects)
    return header.encode() + zlib.compress(lines.encode())


if __name__ == "__main__":
    for key, (project, version, objects) in OBJECTS.items():
        (HERE / f"{key}.inv").write_bytes(inventory(project, version, objects))
