r"""The solid's convergence beside FElupe's on the paper's sample 4: two discretisations of one continuum.

    python benchmarks/felupe_convergence.py    # needs `pip install felupe tensortrax`; skips without them

The case: sample 4 of the paper (``pocket.validation.thickness.posed(4, 5.0)``): Mooney-Rivlin alpha = C2/C1 =
47/160, T/R = 0.08, inflated by a liquid to Phat_I = 0.0503222 (5 kPa), then pressed by the rigid flat plate at
the forces Fhat = F / (P_I pi R^2) of ``pocket.validation.solidstudy.FORCES`` (0.08, 0.16, 0.32) at fixed liquid
volume. Both models are the sheet's cross-section as an incompressible axisymmetric solid clamped through its
thickness at r = R, on the same mesh (``pocket.solid.mesh.section``: radial elements graded towards the clamp,
the clamp's corner elements ``corner`` T long, layers graded towards both surfaces):

- ``pocket.solid``: Taylor-Hood Q2/Q1 (continuous pressure), the liquid's pressure the multiplier of the cavity's
  volume, the plate's contact by Lagrange multipliers on an active set, and a cluster of short elements that
  follows the contact edge (``pocket.solid.edgemesh``); run twice: without the clamp's upper jaw
  (``clamp_radius=0``: the sheet held only at r >= R, as in FElupe) and as by default, with the rigid jaw whose
  edge is rounded to T/2 (the sheet's upper surface may not rise into it: a different boundary condition at the
  clamp, so its numbers differ from FElupe's by the model, not by the discretisation).
- FElupe (``felupe_pocket``): biquadratic displacement with a discontinuous linear pressure and volume ratio per
  element (u-p-J, nearly incompressible, bulk modulus 1e4 mu_0), the liquid's volume kept by a secant iteration on
  the pressure, the plate by a node-to-plane penalty, the force reached by a secant iteration on the plate's
  height; no upper jaw, and its mesh does not follow the contact edge.

Printed, for each model: the meshes refined by halving along each axis in turn, the others at pocket's defaults
(``pocket.validation.solidstudy.meshes``: 24 radial elements, 4 layers, corner T/4): the radial elements, the
layers through the thickness, and the clamp's corner elements' length. On each mesh V (the cavity's volume / R^3,
under the lower surface), H0 (the inflated upper surface's pole height / R, above the clamp plane), and at each
force P/P_I and the contact area A_c / (pi R^2) (the contact edge's deformed radius squared: pocket's
``contact_area``; FElupe's from its upper surface's nodes, ``felupe_pocket.contact_area``), with the run's wall
time. Under each axis the observed order p from its three finest meshes and Richardson's extrapolation q*
(``solidstudy.Study.estimate``; "-" where the differences do not shrink). Then one table: each model's estimate of
the converged value, q_default + sum over the axes of (q*_axis - q_default) (the axes' errors taken as additive; an
axis without q*, or whose order is below ``MIN_ORDER``, contributes its finest mesh), its uncertainty beside it
(``combined``: the sum over the axes of the larger of the last two changes, conservative where the values converge,
their scatter where they do not), and the relative differences of pocket's (without and with the jaw) from FElupe's.
F/P = Fhat / (P/P_I) there is the membrane's contact area (contact pressure = the fluid's): for this thick sheet it
is not the contact area, and its difference between the models is P/P_I's.

Cost, measured (load average 3.5 to 4 on 2 shared cores; each run one inflation and the three forces): FElupe 9 s
on 12 x 4, 12 s on 24 x 4, 17 s on 48 x 4, 27 s on 96 x 4, 45 s on 192 x 4, 8 s on 24 x 2, 17 s on 24 x 8, 10 to
11 s at corners T/2 and T/8; pocket 1.1 to 1.6 s on 12 to 24 x 4 at every corner, 2.3 to 2.8 s on 48 x 4, 14 to
16 s on 96 x 4, 62 to 66 s on 192 x 4, 0.6 to 0.8 s on 24 x 2,
4.7 to 5 s on 24 x 8. The whole script 339 to 343 s.
"""

from __future__ import annotations

import importlib.util
import os
import sys
import time

from pocket.validation import solidstudy
from pocket.validation.thickness import posed

SAMPLE = 4
#: per axis, the refined values (radial elements, layers, corner elements' length in T), coarse to fine
COUNTS = ((12, 24, 48, 96, 192), (2, 4, 8), (0.5, 0.25, 0.125))
#: the smallest observed order whose extrapolation the converged estimate uses: below it (the elements are
#: quadratic) the three finest meshes are not in the asymptotic range, and 1 / (2^p - 1) amplifies their scatter
MIN_ORDER = 1.0
#: the models: name -> the clamp's upper jaw's edge radius in T (None: FElupe, which has no jaw)
MODELS = {"FElupe": None, "pocket, no jaw": 0.0, "pocket, jaw T/2": 0.5}


def keys(forces) -> list:
    """The compared quantities: the inflated V and H0, then P/P_I and A_c at each force.

    Parameters
    ----------
    forces : sequence of float
        The forces Fhat = F / (P_I pi R^2).

    Returns
    -------
    list of tuple
        (quantity name, Fhat or None for the inflated sheet's).
    """
    return [("V", None), ("H0", None), *(("P/P_I", f) for f in forces), *(("A_c", f) for f in forces)]


def solve_felupe(mesh, forces) -> tuple[dict, float]:
    """FElupe's model of sample 4 inflated and pressed at ``forces``.

    Parameters
    ----------
    mesh : tuple of (int, int, float)
        The radial elements, the layers and the clamp's corner elements' length in thicknesses T.
    forces : sequence of float
        Fhat of each state, increasing.

    Returns
    -------
    values : dict
        (quantity, Fhat or None) -> value, as ``keys``: V / R^3, H0 / R, P/P_I, A_c / (pi R^2).
    seconds : float
        The run's wall time.
    """
    import felupe_pocket as fp

    material, phat, t = posed(SAMPLE, solidstudy.PRESSURE_KPA)
    start = time.perf_counter()
    m = fp.build(alpha=material.alpha, thickness=t, elements=mesh[0], layers=mesh[1], corner=mesh[2])
    inflated = fp.inflate(m, phat)
    curve = fp.compress(m, inflated, forces)
    out = {("V", None): inflated["volume"], ("H0", None): inflated["height"]}
    for row in curve:
        out["P/P_I", row["force"]] = row["pressure_ratio"]
        out["A_c", row["force"]] = row["contact_area"]
    return out, time.perf_counter() - start


def solve_pocket(mesh, forces, clamp_radius: float) -> tuple[dict, float]:
    """``pocket.solid``'s model of sample 4 inflated and pressed at ``forces``.

    Parameters
    ----------
    mesh : tuple of (int, int, float)
        The radial elements, the layers and the clamp's corner elements' length in thicknesses T.
    forces : sequence of float
        Fhat of each state, increasing.
    clamp_radius : float
        The clamp's upper jaw's edge radius in thicknesses T; 0: no jaw.

    Returns
    -------
    values : dict
        (quantity, Fhat or None) -> value, as ``keys``.
    seconds : float
        The run's wall time.
    """
    from pocket import solid

    material, phat, t = posed(SAMPLE, solidstudy.PRESSURE_KPA)
    start = time.perf_counter()
    states = solid.compression_curve(material, phat, forces, thickness_ratio=t, elements=mesh[0], layers=mesh[1],
                                     corner=mesh[2], clamp_radius=clamp_radius)
    out = {("V", None): states[0].inflated.volume, ("H0", None): states[0].inflated.height}
    for force, state in zip(forces, states, strict=True):
        out["P/P_I", force] = state.pressure_ratio
        out["A_c", force] = state.contact_area
    return out, time.perf_counter() - start


def study(name: str, forces) -> list[solidstudy.Study]:
    """The studies of one model along each axis, each mesh solved once.

    Parameters
    ----------
    name : str
        A key of ``MODELS``.
    forces : sequence of float
        Fhat of each state.

    Returns
    -------
    list of pocket.validation.solidstudy.Study
        One per axis of ``solidstudy.AXES``, its meshes those of ``COUNTS``.
    """
    from pocket import solid

    jaw = MODELS[name]
    default = (solid.DEFAULT_ELEMENTS, solid.DEFAULT_LAYERS, solid.DEFAULT_CORNER)
    t = posed(SAMPLE, solidstudy.PRESSURE_KPA)[2]
    done = {}
    out = []
    for axis, counts in zip(solidstudy.AXES, COUNTS, strict=True):
        grid = solidstudy.meshes(axis, counts)
        for mesh in grid:
            if mesh not in done:
                done[mesh] = solve_felupe(mesh, forces) if jaw is None else solve_pocket(mesh, forces, jaw)
        out.append(solidstudy.Study(SAMPLE, t, solidstudy.PRESSURE_KPA, tuple(forces), axis, grid,
                                    tuple(done[m][0] for m in grid), tuple(done[m][1] for m in grid), default))
    return out


def report(name: str, found: list[solidstudy.Study]) -> None:
    """Print one model's values on each mesh of each axis, with the observed orders and extrapolations.

    Parameters
    ----------
    name : str
        The model's name, printed.
    found : list of pocket.validation.solidstudy.Study
        Its studies (``study``).
    """
    columns = keys(found[0].forces)
    print(f"\n{name}: sample {SAMPLE}, T/R = {found[0].thickness_ratio:g}, P_I = {found[0].pressure_kpa:g} kPa")
    header = "".join(f"{q if f is None else f'{q} {f:g}':>13s}" for q, f in columns)
    for s in found:
        print(f"  refined {s.axis}")
        print(f"  {'mesh':>13s}{header}{'seconds':>9s}")
        for mesh, values, seconds in zip(s.meshes, s.values, s.seconds, strict=True):
            label = f"{mesh[0]}x{mesh[1]} {mesh[2]:g}T"
            print(f"  {label:>13s}" + "".join(f"{values[k]:13.8f}" for k in columns) + f"{seconds:9.1f}")
        found_k = [s.estimate(k) for k in columns]
        print(f"  {'order p':>13s}" + "".join(f"{e[2]:13.2f}" if e else f"{'-':>13s}" for e in found_k))
        print(f"  {'q*':>13s}" + "".join(f"{e[0]:13.8f}" if e else f"{'-':>13s}" for e in found_k))


def combined(found: list[solidstudy.Study], key) -> tuple[float, float]:
    """One model's estimate of the converged value of ``key`` and its uncertainty.

    The default mesh's value plus, along each axis, q* minus it (the axis' finest mesh's value where q* is missing
    or its observed order is below ``MIN_ORDER``); the uncertainty is the sum over the axes of the larger of the
    last two changes between the three finest meshes (a bound on |q* - q_h| where the order is 1 or more, and a
    measure of the scatter where the values do not converge smoothly, as the contact edge's within the elements).

    Parameters
    ----------
    found : list of pocket.validation.solidstudy.Study
        The model's studies, each holding the default mesh.
    key : tuple
        (quantity, Fhat or None), as ``keys``.

    Returns
    -------
    estimate, uncertainty : float
        In the quantity's units.
    """
    value = found[0].default_value(key)
    estimate, uncertainty = value, 0.0
    for s in found:
        found_k = s.estimate(key)
        q4, q2, q1 = s.series(key)[-3:]
        estimate += (found_k[0] if found_k and found_k[2] >= MIN_ORDER else q1) - value
        uncertainty += max(abs(q1 - q2), abs(q2 - q4))
    return estimate, uncertainty


def side_by_side(results: dict) -> None:
    """Print each model's converged estimates (``combined``) and their relative differences from the first's.

    Parameters
    ----------
    results : dict
        Model name -> its studies (``study``), FElupe's first.
    """
    forces = next(iter(results.values()))[0].forces
    names = list(results)
    print(f"\nconverged estimates (q_default + the axes' q* - q_default, the finest mesh's where p < {MIN_ORDER:g}; "
          f"+- the axes' largest last changes)\nand the relative differences from {names[0]}")
    print(f"  {'quantity':>12s}" + "".join(f"{n:>26s}" for n in names)
          + "".join(f"{f'{n} / {names[0]} - 1':>30s}" for n in names[1:]))
    rows = [(k, {n: combined(results[n], k) for n in names}) for k in keys(forces)]
    rows += [(("F/P", f), {n: (f / est, f * err / est**2) for n, (est, err) in
                           ((n, combined(results[n], ("P/P_I", f))) for n in names)}) for f in forces]
    for (q, f), by in rows:
        label = q if f is None else f"{q} {f:g}"
        print(f"  {label:>12s}" + "".join(f"{by[n][0]:15.8f} +- {by[n][1]:7.1e}" for n in names)
              + "".join(f"{by[n][0] / by[names[0]][0] - 1:30.2e}" for n in names[1:]))
    print("  V: volume / R^3 under the lower surface; H0: inflated upper pole / R; A_c: contact area / (pi R^2) from\n"
          "  the contact edge; F/P = Fhat / (P/P_I): the membrane's contact area (contact pressure = the fluid's).\n"
          "  pocket, no jaw is FElupe's model (the sheet held at r >= R only), discretised otherwise: its difference\n"
          "  is the two discretisations' residual error. pocket, jaw T/2 (pocket's default) adds the rigid upper jaw\n"
          "  with its edge rounded to T/2: another boundary condition at the clamp, its difference the jaw's effect.")

def main() -> int:
    """Run the study and print it; skipped when FElupe or tensortrax is not installed.

    Returns
    -------
    int
        The exit status, 0.
    """
    if importlib.util.find_spec("felupe") is None or importlib.util.find_spec("tensortrax") is None:
        print("felupe_convergence: felupe (and tensortrax) not installed; skipped")
        return 0
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    start = time.perf_counter()
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    results = {name: study(name, solidstudy.FORCES) for name in MODELS}
    for name, found in results.items():
        report(name, found)
    side_by_side(results)
    print(f"\ntotal {time.perf_counter() - start:.0f} s (load average now {os.getloadavg()[0]:.1f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
