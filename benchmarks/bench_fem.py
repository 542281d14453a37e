"""Benchmark of the finite-element solver: cost per Newton iteration against N, Newton iterations per
state, a compression curve's time against the shooting solver's, and the default mesh's accuracy.

    python benchmarks/bench_fem.py [--quick]

1. One P2 Newton iteration at a pressed state on the edge-fitted mesh (Fhat 0.19, alpha 47/160,
   Phat_I 0.31; the state of a 256-element solve interpolated onto the mesh): the residual and
   tangent assembly, and the bordered solve (static condensation, banded LU, three border
   unknowns), for 1e2 .. 1e6 elements (--quick: to 1e4). Medians of repeats, the cost per element,
   and its ratio to the one at 1e3 (linear in N: about 1).
2. The 40-point compression curve at the default mesh (Fhat 0.02 .. 0.8, the same case): median time
   of repeats, Newton iterations per compressed state (and with the inflation), and the shooting
   solver's curve time with the ratio.
3. How the default mesh was chosen: the worst relative error against shooting (rtol 1e-12) in any
   reported scalar over the validation cases at Fhat = 0, 0.05, 0.19, 1 and 0.95 of each range end,
   for 64 .. 384 P2 elements of the default family (skipped with --quick).
4. Rubber laws and fluids: one assembly (residual and tangent) at 1e4 P2 elements for each law, and the
   40-point curve of section 2 for each law and for a gas, with their ratios to Mooney-Rivlin's (the
   law is a branch inside the compiled loop; Ogden's powers cost more than the invariants' products).
5. The inflation remembered (``pocket.fem.inflation.inflated_at``): a one-force compression at the
   default mesh after the inflation (as a case file does) and a button design by the FE
   (``pocket.apps.design``, whose inverse problems call the solver once per bracket step), each with
   every call solving its inflation (nothing remembered: as before) and with the inflation remembered,
   with the ratio and whether the answers are equal bit for bit (their pickles).
6. A fingertip: the 40-point curve of section 2 under spheres of radius R_s = 0.5 R and 2 R (edge-fitted,
   the contact zone wrapped on the sphere) against the plate's, with the Newton iterations per state.

The machine is shared: medians of repeats, with the least time beside them as the estimate of the
undisturbed cost.
"""

from __future__ import annotations

import pickle
import statistics
import sys
import time

import numpy as np
from pocket.fem import fitted, inflation, model
from pocket.fem.api import default_mesh
from pocket.fem.geometry import evaluate, node_radii, place
from pocket.fem.newton import Tolerances
from timing import median_time

from pocket import fem, shooting
from pocket.core.fluids import gas
from pocket.core.indenters import Sphere
from pocket.core.materials import check

ALPHA, PHAT, FHAT = 47 / 160, 0.31, 0.19
#: one rubber of each law for section 4 (the first is the paper's)
RUBBERS = {
    "mooney-rivlin": ALPHA,
    "neo-hookean": check("neo-hookean", {"mu": 1.0}),
    "yeoh": check("yeoh", {"c10": 0.5, "c20": -0.02, "c30": 0.003}),
    "gent": check("gent", {"mu": 1.0, "jm": 6.0}),
    "ogden (3 terms)": check("ogden", {"mu": [630e3, 1.2e3, -10e3], "exponents": [1.3, 5.0, -2.0]}),
}


def _times(fun, repeat):
    """(median, least) wall time of ``fun()`` over ``repeat`` calls, in seconds."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fun()
        times.append(time.perf_counter() - t)
    return statistics.median(times), min(times)


def _pressed_state():
    """A converged pressed state on 256 P2 elements: (model, y, volume)."""
    m = model.discretize(ALPHA, default_mesh(256), 2, 1e5)
    tol = Tolerances()
    y_i, _ = inflation.to_pressure(m, PHAT, tol)
    volume = inflation.volume(m, y_i)
    y, _ = fitted.first_contact(m, y_i, model.Control(volume=volume), 0.05, tol)
    y, _ = fitted.force_path(m, y, model.Control(volume=volume), FHAT * np.pi * PHAT, tol)
    return m, y, volume


def _on(coarse, y, n):
    """The state y of the model ``coarse`` interpolated onto n elements: (model, y)."""
    m = model.discretize(ALPHA, default_mesh(n), 2, 1e5)
    a = float(y[coarse.dofs + 2])
    u = evaluate(place(coarse.xi, coarse.ref, a), coarse.ref, y[: coarse.dofs],
                 node_radii(place(m.xi, m.ref, a), m.ref)).ravel()
    return m, model.conform(m, np.concatenate([u, y[coarse.dofs:]]), model.FITTED)


def per_iteration(sizes):
    """Section 1."""
    coarse, y0, volume = _pressed_state()
    control = model.Control(volume=volume, force=FHAT * np.pi * PHAT, scale=FHAT * np.pi * PHAT)
    print("P2 elements | assembly [ms] (least) | solve [ms] (least) | iteration [ms] (least) |"
          " per element [us] | ratio to 1e3")
    base = None
    for n in sizes:
        m, y = _on(coarse, y0, n)
        repeat = 9 if n <= 10**4 else 5 if n <= 10**5 else 3
        model.linearize(m, y, model.FITTED, control)
        assembly = _times(lambda m=m, y=y: model.linearize(m, y, model.FITTED, control), repeat)

        def iteration(m=m, y=y):
            r, system = model.linearize(m, y, model.FITTED, control)
            system.solve(-r[: m.dofs], -r[m.dofs:])

        total = _times(iteration, repeat)
        solve = (total[0] - assembly[0], total[1] - assembly[1])
        per_element = 1e6 * total[0] / n
        if n == 1000:
            base = per_element
        ratio = f"{per_element / base:12.2f}" if base else " " * 12
        print(f"{n:11d} | {1e3 * assembly[0]:8.2f} ({1e3 * assembly[1]:8.2f}) | {1e3 * solve[0]:7.2f}"
              f" ({1e3 * solve[1]:7.2f}) | {1e3 * total[0]:9.2f} ({1e3 * total[1]:9.2f}) | {per_element:16.3f} |"
              f" {ratio}")


def curve(points, repeat):
    """Section 2."""
    forces = np.linspace(0.02, 0.8, points)
    fem.compression_curve(ALPHA, PHAT, forces[:2])  # compile and import once
    states = fem.compression_curve(ALPHA, PHAT, forces)
    fem_time = _times(lambda: fem.compression_curve(ALPHA, PHAT, forces), repeat)
    shooting.compression_curve(ALPHA, PHAT, forces[:2])
    shot_time = median_time(lambda: shooting.compression_curve(ALPHA, PHAT, forces), repeat)
    its = [s.extra["newton_iterations"] for s in states]
    inflation_its = states[0].inflated.extra["newton_iterations"]
    elements = states[0].extra["elements"]
    print(f"\n{points}-point compression curve, default mesh ({elements} P2 elements, Fhat 0.02..0.8):"
          f" {fem_time[0]:.3f} s (least {fem_time[1]:.3f} s); shooting {shot_time:.3f} s; ratio"
          f" {fem_time[0] / shot_time:.1f}")
    print(f"  Newton iterations per compressed state: mean {np.mean(its):.2f}, max {max(its)} (the first, with"
          f" the first contact: {its[0]}); with the inflation's {inflation_its}:"
          f" {(sum(its) + inflation_its) / points:.2f} per state")


def default_mesh_accuracy(sizes):
    """Section 3."""
    from pocket.validation.compute import range_end
    from pocket.validation.suite import load

    pockets, _ = load()
    worst = {n: (0.0, "") for n in sizes}
    for case in pockets:
        end = range_end(case)
        forces = sorted(f for f in (0.0, 0.05, 0.19, 1.0, 0.95 * end) if f <= 0.95 * end)
        fluid = case.fluid_options()
        refs = shooting.compression_curve(case.material, case.pressure_initial, forces, rtol=1e-12, **fluid)
        for n in sizes:
            states = fem.compression_curve(case.material, case.pressure_initial, forces, elements=n, **fluid)
            for state, ref in zip(states, refs, strict=True):
                a, b = (state.inflated, ref.inflated) if state.force == 0.0 else (state, ref)
                keys = ("stretch_pole", "height", "volume", "stretch_clamp") if state.force == 0.0 else a.KEYS[3:]
                for key in keys:
                    error = abs(getattr(a, key) / getattr(b, key) - 1.0)
                    if error > worst[n][0]:
                        worst[n] = (error, f"{case.case.name}, Fhat = {state.force:.4g}, {key}")
    print(f"\nDefault mesh family (P2), worst relative error against shooting over {len(pockets)} cases:")
    for n in sizes:
        mark = "  <- DEFAULT_ELEMENTS" if n == fem.DEFAULT_ELEMENTS else ""
        print(f"  {n:4d} elements: {worst[n][0]:.2e} ({worst[n][1]}){mark}")


def laws_and_fluids(repeat):
    """Section 4."""
    coarse, y0, volume = _pressed_state()
    control = model.Control(volume=volume, force=FHAT * np.pi * PHAT, scale=FHAT * np.pi * PHAT)
    forces = np.linspace(0.02, 0.8, 40)
    print("\nRubber laws, P2: one assembly at 1e4 elements and the 40-point curve (default mesh), median (least);"
          " ratios of the least times (the undisturbed cost) to Mooney-Rivlin's")
    print(f"{'law':16s} | assembly [ms] | ratio | curve [s]      | ratio")
    base = None
    for name, rubber in RUBBERS.items():
        m, y = _on(coarse, y0, 10**4)
        m = model.discretize(rubber, m.xi, 2, 1e5)
        model.linearize(m, y, model.FITTED, control)
        assembly = _times(lambda m=m, y=y: model.linearize(m, y, model.FITTED, control), 3 * repeat)
        fem.compression_curve(rubber, PHAT, forces[:2])
        curve_time = _times(lambda rubber=rubber: fem.compression_curve(rubber, PHAT, forces), repeat)
        base = base or (assembly[1], curve_time[1])
        print(f"{name:16s} | {1e3 * assembly[0]:5.2f} ({1e3 * assembly[1]:5.2f}) | {assembly[1] / base[0]:5.2f} |"
              f" {curve_time[0]:.3f} ({curve_time[1]:.3f}) | {curve_time[1] / base[1]:5.2f}")
    for fluid in (gas(0.5, 1.0), gas(0.5, 1.4)):
        fem.compression_curve(ALPHA, PHAT, forces[:2], fluid=fluid)
        curve_time = _times(lambda fluid=fluid: fem.compression_curve(ALPHA, PHAT, forces, fluid=fluid), repeat)
        label = f"MR, gas {fluid.gamma:g}"
        print(f"{label:16s} |               |       | {curve_time[0]:.3f} ({curve_time[1]:.3f}) |"
              f" {curve_time[1] / base[1]:5.2f}")


def remembered(repeat):
    """Section 5."""
    from pocket.apps.design import design

    def one_force():
        inflation.forget()  # a new chain: its inflation is not yet known
        return fem.inflate(ALPHA, PHAT), fem.compress(ALPHA, PHAT, FHAT)

    def button():
        inflation.forget()
        return design("20 mm", "8 mm", "1 MPa", ALPHA, "0.2 N", solver="fem", points=5).report()

    print("\nThe inflation remembered: median (least) wall time of a call chain, every inflation solved"
          " against each solved once")
    print(f"{'call chain':36s} | solved each time [s] | remembered [s]   | ratio | equal")
    for label, chain, times in (("inflate, then compress at one force", one_force, 3 * repeat),
                                ("button design, fem (5-point feel)", button, max(1, repeat // 3))):
        one_force()  # compile and import once
        kept = inflation.REMEMBERED
        try:
            inflation.REMEMBERED = 0
            before = chain()
            each = _times(chain, times)
        finally:
            inflation.REMEMBERED = kept
        after = chain()
        once = _times(chain, times)
        print(f"{label:36s} | {each[0]:8.3f} ({each[1]:8.3f}) | {once[0]:6.3f} ({once[1]:6.3f}) |"
              f" {each[1] / once[1]:5.2f} | {pickle.dumps(before) == pickle.dumps(after)}")


def fingertip(points, repeat):
    """Section 6."""
    forces = np.linspace(0.02, 0.8, points)
    print(f"\n{points}-point curve under a sphere against the plate's (default mesh, Fhat 0.02..0.8):")
    print(f"{'indenter':16s} | {'median s':>9s} ({'least':>6s}) | ratio to the plate | Newton its per state")
    plate = None
    for label, indenter in (("plate", None), ("sphere R_s = 2R", Sphere(2.0)), ("sphere R_s = R/2", Sphere(0.5))):
        fem.compression_curve(ALPHA, PHAT, forces[:2], indenter=indenter)
        states = fem.compression_curve(ALPHA, PHAT, forces, indenter=indenter)
        took = _times(lambda indenter=indenter: fem.compression_curve(ALPHA, PHAT, forces, indenter=indenter), repeat)
        plate = plate or took
        its = np.mean([s.extra["newton_iterations"] for s in states])
        print(f"{label:16s} | {took[0]:9.3f} ({took[1]:6.3f}) | {took[0] / plate[0]:18.2f} | {its:.2f}")


def main(argv=None):
    quick = "--quick" in (sys.argv[1:] if argv is None else argv)
    per_iteration([100, 1000, 10000] if quick else [100, 1000, 10000, 100000, 1000000])
    curve(40, 3 if quick else 7)
    if not quick:
        default_mesh_accuracy([64, 128, 192, 256, 384])
    laws_and_fluids(3 if quick else 7)
    remembered(3 if quick else 7)
    fingertip(40, 3 if quick else 7)


if __name__ == "__main__":
    main()
