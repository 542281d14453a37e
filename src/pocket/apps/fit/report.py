"""A fit's result as users take it: a JSON-ready summary, a case file of the fitted sheet, a figure.

Units: stresses in Pa when the thickness T was given; without it the membrane model determines only
the products stress * T (it sees the rubber through its tension scale mu_0 T), reported in N/m.
The case file then writes the sheet with a nominal thickness ``NOMINAL_THICKNESS`` and the stresses
divided by it: the model solves the same sheet for any T with the same products. The figure
(matplotlib, imported here only) shows each test's data with the fitted curve and, below, the
residuals; ``write`` puts both in a folder written whole (``pocket.apps.folders.staged``).
"""

from __future__ import annotations

import math
import pathlib

import numpy as np

from pocket.core.errors import ConvergenceError, OutOfRangeError

from ..folders import staged
from .data import CONTROLS
from .leastsquares import Fit

__all__ = ["CASE", "FIGURE", "KIND", "NOMINAL_THICKNESS", "case_text", "summary", "write"]

#: the kind of folder ``write`` writes (its ownership marker)
KIND = "fit result"
#: thickness written in the case file of a fit without one (m)
NOMINAL_THICKNESS = 1e-3
FIGURE, CASE = "fit.png", "fitted.toml"
_CURVE = 60  # points of a fitted curve in the figure
_SI = {"pressure": ("kPa", 1e-3), "height": ("mm", 1e3), "volume": ("mL", 1e6), "force": ("N", 1.0)}
#: a capsule's test is micromanipulation: micronewtons and micrometres
_SI_CAPSULE = {"force": ("uN", 1e6), "gap": ("um", 1e6), "displacement": ("um", 1e6)}


def _unit(fit: Fit, key: str) -> str:
    unit = next(k.unit for k in fit.law_keys() if k.name == key)
    return ("Pa" if fit.setup.thickness else "N/m") if unit == "stress" else "Pa" if unit == "pressure" else "1"


def summary(fit: Fit) -> dict:
    r"""The fit as one JSON-ready dict.

    ``parameters`` maps each fitted key to its value, standard error, 95 % interval (an end the data do not
    bound is None: JSON's null), the method that made the interval (``pocket.apps.fit.intervals``) and unit
    (Pa for stresses, N/m for stress * T without a thickness, 1 for numbers); then ``mu0``, the sheet, the
    correlations, the residuals, the solver's calls and the warnings.

    Parameters
    ----------
    fit : Fit
        The fit's result (``pocket.apps.fit.leastsquares.fit``).

    Returns
    -------
    dict

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.fit.case import Request
    >>> from pocket.apps.fit.leastsquares import fit
    >>> from pocket.apps.fit.report import summary
    >>> from pocket.core.materials import Material
    >>> phats = [0.1, 0.2, 0.3, 0.4]
    >>> states = shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), phats)
    >>> rows = [f"{p * 3 * 0.4e6 * 1e-3 / 0.02},{s.height * 0.02}" for p, s in zip(phats, states)]
    >>> folder = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(folder.name) / "bulge.csv"
    >>> _ = path.write_text("pressure [Pa],height [m]\n" + "\n".join(rows) + "\n")
    >>> result = fit(Request((path,), "neo-hookean", 0.02, 1e-3).setup(), "neo-hookean")
    >>> mu = summary(result)["parameters"]["mu"]
    >>> low, high = mu["interval_95"]
    >>> print(round(mu["value"] / 1e6, 6), mu["unit"], low <= mu["value"] <= high)
    0.4 Pa True
    >>> folder.cleanup()
    """
    s = fit.statistics
    # a capsule's gaps: differences in units of its diameter (``pocket.apps.fit.capsulemodel``)
    plain = "in units of the diameter 2R" if any(t.kind == "capsule" for t in fit.setup.tests) else "relative"
    return {
        "law": fit.material.law,
        "parameters": {name: {"value": float(v), "standard_error": float(e),
                              "interval_95": [float(a) if math.isfinite(a) else None,
                                              float(b) if math.isfinite(b) else None],
                              "interval_method": method, "unit": _unit(fit, name)}
                       for name, v, e, (a, b), method in zip(s.names, s.values, s.standard_errors, s.intervals,
                                                             s.methods, strict=True)},
        "fixed": {name: {"value": float(v), "unit": _unit(fit, name)} for name, v in fit.fixed.items()},
        "mu0": {"value": s.mu0, "standard_error": s.mu0_error, "interval_95": [float(v) for v in s.mu0_interval],
                "unit": "Pa" if fit.setup.thickness else "N/m"},
        "thickness_m": fit.setup.thickness,
        "radius_m": fit.setup.radius,
        "tension_scale": "the membrane model sees the rubber only through mu_0 T" +
                         ("" if fit.setup.thickness else ": without a thickness, stresses are reported times T (N/m)"),
        "correlation": {"keys": list(s.names), "matrix": s.correlation.tolist()},
        "residuals": plain if not fit.setup.sigma else
                     f"in units of the stated uncertainty for {', '.join(fit.setup.sigma)}, {plain} otherwise",
        "residual_rms": s.rms,
        "data": int(fit.residuals.size),
        "degrees_of_freedom": s.dof,
        "solver": fit.setup.solver,
        "solver_calls": fit.calls,
        "seconds": fit.seconds,
        "starts": fit.starts,
        "trials_without_state": fit.penalised,
        "warnings": list(s.warnings),
        "files": [t.source for t in fit.setup.tests],
    }


def _quantity(value: float, unit: str) -> str:
    return f'"{value:.10g} {unit}"'


def case_text(fit: Fit) -> str:
    r"""A case file (TOML) of the fitted sheet, for ``pocket run``.

    The clamp, the fitted rubber, the initial pressure of the first compression test (else the middle
    pressure of the first inflation test) and forces (the compression test's, else a quarter, a half and one
    of P_I pi R^2).

    Parameters
    ----------
    fit : Fit
        The fit's result (``pocket.apps.fit.leastsquares.fit``).

    Returns
    -------
    str

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.fit.case import Request
    >>> from pocket.apps.fit.leastsquares import fit
    >>> from pocket.apps.fit.report import case_text
    >>> from pocket.core.materials import Material
    >>> phats = [0.1, 0.2, 0.3, 0.4]
    >>> states = shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), phats)
    >>> rows = [f"{p * 3 * 0.4e6 * 1e-3 / 0.02},{s.height * 0.02}" for p, s in zip(phats, states)]
    >>> folder = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(folder.name) / "bulge.csv"
    >>> _ = path.write_text("pressure [Pa],height [m]\n" + "\n".join(rows) + "\n")
    >>> result = fit(Request((path,), "neo-hookean", 0.02, 1e-3).setup(), "neo-hookean")
    >>> from pocket.apps.cases import parse
    >>> import tomllib
    >>> case = parse(tomllib.loads(case_text(result)))
    >>> print(case.material.law, round(case.material["mu"] / 1e6, 6), case.initial)
    neo-hookean 0.4 ('pressure', 18000.0)
    >>> folder.cleanup()
    """
    setup, material = fit.setup, fit.material
    thickness = setup.thickness or NOMINAL_THICKNESS
    factor = 1.0 if setup.thickness else 1.0 / NOMINAL_THICKNESS
    compression = [t for t in setup.tests if t.kind == "compression"]
    if compression:
        pressure = compression[0].initial_pressure
        assert pressure is not None  # a compression test has its P_I (``pocket.apps.fit.data.read``)
        forces = sorted(float(f) for f in compression[0].control if f > 0.0)
    else:
        first = setup.tests[0].control
        pressure = float(first[len(first) // 2])
        forces = [s * pressure * math.pi * setup.radius**2 for s in (0.25, 0.5, 1.0)]
    lines = [f"# the {material.law} sheet fitted by pocket fit to {', '.join(t.source for t in setup.tests)}"]
    if not setup.thickness:
        lines.append(f"# no thickness was given: the fit determines stress * T; written with T = "
                     f"{NOMINAL_THICKNESS * 1e3:g} mm (any T with the same products is the same sheet)")
    lines += ['name = "fitted"', "[sheet]", f"thickness = {_quantity(thickness, 'm')}",
              f'material = "{material.law}"']
    stresses = material.definition.stresses
    for name, value in material.params:
        if isinstance(value, tuple):
            cells = [_quantity(v * factor, "Pa") if name in stresses else f"{v:.10g}" for v in value]
            lines.append(f"{name} = [{', '.join(cells)}]")
        else:
            lines.append(f"{name} = {_quantity(value * factor, 'Pa') if name in stresses else f'{value:.10g}'}")
    if material.prestretch != 1.0:
        lines.append(f"prestretch = {material.prestretch:.10g}")
    lines += ["[clamp]", f"radius = {_quantity(setup.radius, 'm')}", "[initial]",
              f"pressure = {_quantity(pressure, 'Pa')}", "[loads]",
              f"forces = [{', '.join(_quantity(f, 'N') for f in forces)}]"]
    if setup.solver != "shooting":
        lines += ["[solver]", f'name = "{setup.solver}"']
    return "\n".join(lines) + "\n"


def _curve(fit: Fit, test):
    """The fitted model along a dense control range of ``test``: (controls, column -> values)."""
    import dataclasses

    top = float(np.max(test.control))
    low = 0.0 if test.kind == "compression" else top / _CURVE
    dense = dataclasses.replace(test, control=np.linspace(low, top, _CURVE),
                                responses={n: np.zeros(_CURVE) for n in test.responses})
    try:
        values = fit.predicted(dataclasses.replace(fit.setup, tests=(dense,)))
    except (OutOfRangeError, ConvergenceError):
        return dense.control, {}
    return dense.control, values[0]


def figure(fit: Fit, path: pathlib.Path) -> None:
    """Draw each test's data, fitted curve and residuals into the PNG ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    panels = [(t, name) for t in fit.setup.tests for name in t.responses]
    fig, axes = plt.subplots(2, len(panels), figsize=(4.8 * len(panels), 6.0), squeeze=False,
                             gridspec_kw={"height_ratios": [3, 1]}, sharex="col")
    start = 0
    for j, (test, name) in enumerate(panels):
        control = CONTROLS[test.kind]
        units = _SI_CAPSULE if test.kind == "capsule" else _SI
        cu, cf = units[control]
        ru, rf = units[name]
        data = test.responses[name]
        keep = np.isfinite(data)
        dense, curve = _curve(fit, test)
        top, bottom = axes[0, j], axes[1, j]
        top.plot(test.control[keep] * cf, data[keep] * rf, "o", ms=4, label="data")
        if name in curve:
            top.plot(dense * cf, curve[name] * rf, "-", label=f"fitted {fit.material.law}")
        top.set_ylabel(f"{name} [{ru}]")
        top.set_title(f"{pathlib.Path(test.source).name}: {test.kind}", fontsize=9)
        top.legend(fontsize=8)
        r = fit.residuals[start:start + int(np.count_nonzero(keep))]
        start += r.size
        bottom.axhline(0.0, color="0.6", lw=0.8)
        bottom.plot(test.control[keep] * cf, r, "o", ms=3)
        bottom.set_xlabel(f"{control} [{cu}]")
        bottom.set_ylabel("(model - data) / sigma" if name in fit.setup.sigma else "(model - data) / 2R"
                          if test.kind == "capsule" else "model / data - 1")
    fig.suptitle(f"{fit.material.law} fit: residual RMS {fit.statistics.rms:.3g}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


def write(fit: Fit, target: pathlib.Path) -> pathlib.Path:
    r"""Write the figure of a fit (``FIGURE``) and its fitted sheet's case file (``CASE``; not for a capsule's fit)
    into a folder.

    Whole or not at all; an existing folder is replaced only if pocket wrote it as a fit's result (``KIND``,
    ``pocket.apps.folders.check_replaceable``).

    Parameters
    ----------
    fit : Fit
        The fit's result (``pocket.apps.fit.leastsquares.fit``).
    target : pathlib.Path
        The folder, absolute.

    Returns
    -------
    pathlib.Path
        ``target``.

    Raises
    ------
    InputError
        For a folder pocket may not replace.
    OutputError
        If the files cannot be written.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from pocket import shooting
    >>> from pocket.apps.fit.case import Request
    >>> from pocket.apps.fit.leastsquares import fit
    >>> from pocket.apps.fit.report import write
    >>> from pocket.core.materials import Material
    >>> phats = [0.1, 0.2, 0.3, 0.4]
    >>> states = shooting.inflation_curve(Material("neo-hookean", {"mu": 1.0}), phats)
    >>> rows = [f"{p * 3 * 0.4e6 * 1e-3 / 0.02},{s.height * 0.02}" for p, s in zip(phats, states)]
    >>> folder = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(folder.name) / "bulge.csv"
    >>> _ = path.write_text("pressure [Pa],height [m]\n" + "\n".join(rows) + "\n")
    >>> result = fit(Request((path,), "neo-hookean", 0.02, 1e-3).setup(), "neo-hookean")
    >>> out = write(result, pathlib.Path(folder.name).resolve() / "fit")
    >>> print(sorted(p.name for p in out.iterdir() if not p.name.startswith(".")))
    ['fit.png', 'fitted.toml']
    >>> folder.cleanup()
    """
    with staged(target, KIND) as partial:
        figure(fit, partial / FIGURE)
        if all(t.kind != "capsule" for t in fit.setup.tests):  # a capsule's case file: not yet
            (partial / CASE).write_text(case_text(fit), encoding="utf-8")
    return target
