"""The content of the report, as ``document`` blocks and plain table rows.

Order, for a reader: the two verdicts and the models' limits (``limits``), one
line per comparison, then the figures, the pockets, the paper's statements, the
convergence study, the tolerances, the timings, the provenance, and last the
failing checks with a link to the page of every check (``checkpage``).
"""

from __future__ import annotations

from pocket.apps.provenance import environment

from . import capsulereport, checkpage, identification, limits, solidstudy, thickness
from .convergence import EXPECTED, FITTED_P2_FINEST, MESHES, RICHARDSON_FACTOR, richardson
from .convergence import FORCE as CONVERGENCE_FORCE
from .plotdata import pocket_label
from .pockets import case_table, cell
from .runner import WORKERS
from .suite import headline
from .verdicts import MEMBRANE, TOLERANCES

__all__ = ["blocks", "counts", "glance", "sequence_rows", "task_rows"]

#: the paper, cited where the report refers to it
PAPER = "Bouremel et al., \"Compression of pressurised elastic pockets\""


def _tolerance(tol) -> str:
    """A tolerance, or several by quantity ("height 0.1, volume 0.15")."""
    return ", ".join(f"{k} {v:g}" for k, v in tol.items()) if isinstance(tol, dict) else f"{tol:g}"


def counts(results) -> dict:
    """Number of checks per verdict."""
    return limits.tally(results.checks)


def glance(results) -> tuple[list, list]:
    """(header, rows): one row per comparison over all pockets, with its worst checked error."""
    groups: dict = {}
    for c in results.checks:
        groups.setdefault(c.comparison, []).append(c)
    rows = []
    for comparison, group in groups.items():
        n = {v: sum(c.verdict == v for c in group) for v in ("pass", "fail", "info")}
        scored = [c for c in group if c.tolerance]
        worst = max(scored, key=lambda c: c.error / c.tolerance) if scored else None
        where = (f"{worst.case}: {worst.quantity} ({worst.where})" if worst
                 else "no tolerance: a model's own error (the models' limits, above)" if n["info"] else "")
        rows.append([comparison, len({c.case for c in group}), len(group), n["pass"], n["fail"], n["info"],
                     cell(worst.error / worst.tolerance, 2) if worst else "", where,
                     "fail" if n["fail"] else "pass" if n["pass"] else "info"])
    header = ["comparison", "pockets", "checks", "pass", "fail", "info", "largest error / tolerance",
              "where", "verdict"]
    return header, rows


def sequence_rows(results):
    """(header, rows): every FE value of the convergence study with its error."""
    header = ["study", "order", "mesh", "elements", "h", "quantity", "fem", "shooting", "relative_error"]
    rows = []
    for seq in results.sequences:
        for quantity, values in seq.values.items():
            errors = seq.errors(quantity)
            for n, h, v, e in zip(seq.elements, seq.sizes, values, errors, strict=True):
                rows.append([seq.study, seq.order, seq.mesh, n, repr(float(h)), quantity, repr(float(v)),
                             repr(seq.reference[quantity]), repr(float(e))])
    return header, rows


def task_rows(results):
    """(header, rows): every solve task of the run with its wall time, longest first."""
    header = ["task", "case", "what", "seconds"]
    tasks = sorted(results.tasks, key=lambda t: -t.seconds)
    return header, [[t.kind, t.case, t.what, f"{t.seconds:.2f}"] for t in tasks]


def _convergence_blocks(results):
    expected = "; ".join(f"{s} P{o} {m}: {', '.join(f'{q} {p:g} +- {t:g}' for q, (p, t, _) in d.items())}"
                         for (s, o, m), d in EXPECTED.items() if all(t is not None for _, t, _ in d.values()))
    out = [("h", 2, "Mesh convergence"),
           ("p", "Error of the FE model against the shooting reference on sequences of meshes, for the headline "
                 f"case: inflation, and compression at Fhat = {CONVERGENCE_FORCE:g}. Two mesh families: "
                 + "; ".join(f"{name}: {what}" for name, what in MESHES.items()) + "."),
           ("p", "Expected orders, and why. Lagrange elements of order p converge at O(h^2p) in smooth "
                 "functionals (2 for P1, 4 for P2: the volume, the pressure, the heights, the contact area, and "
                 "the contact radius, fixed by a variationally consistent flux) wherever the solution is smooth "
                 "inside every element. The pole stretch is a derivative at the axis, where the axisymmetric "
                 "forms are singular: on uniform meshes it converges at O(h^2) for both orders, on meshes graded "
                 "towards the axis at O(h^2p). At the contact edge the meridian's curvature jumps from 0 to "
                 "P/T1: the edge-fitted mesh puts a vertex there and keeps the full order; on a fixed mesh the "
                 "edge falls inside an element, the solution is only H^(5/2) there: smooth functionals converge "
                 "at O(h^3) at best, and the errors scatter as the edge moves inside its element from mesh to "
                 "mesh (the penalty's contact set is resolved to a quadrature point): the orders fitted to these "
                 "uniform meshes in compression are reported beside the theory's bound, not checked. "
                 f"Checked (observed +- tolerance): {expected}. P2 fitted in compression: the finest error below "
                 f"{FITTED_P2_FINEST:g}.")]
    rows = []
    for seq in results.sequences:
        label = f"FEM P{seq.order} {seq.mesh} meshes"
        for quantity, values in seq.values.items():
            order = [c for c in results.checks if c.step == "order" and c.quantity == quantity
                     and c.comparison == label and c.where.startswith(seq.study)]
            theory = EXPECTED[(seq.study, seq.order, seq.mesh)][quantity][0]
            extrapolated = richardson(seq.sizes, values)
            value, estimate = (extrapolated[:2] if extrapolated else (None, None))
            rows.append([seq.study, f"P{seq.order}", seq.mesh, " ".join(map(str, seq.elements)), quantity,
                         cell(order[0].value, 3) if order else "", cell(theory),
                         cell(float(seq.errors(quantity)[-1]), 2),
                         cell(value, 12), cell(estimate, 2), cell(seq.reference[quantity], 12),
                         cell(abs(value - seq.reference[quantity]), 2) if value is not None else "not monotone"])
    out.append(("table", ["study", "element", "meshes", "elements", "quantity", "observed order", "theory",
                          "finest error", "Richardson", "its error estimate", "shooting", "|Richardson - shooting|"],
                rows))
    out.append(("p", f"Richardson extrapolation from the three finest meshes with their observed order; it is "
                     f"checked (shooting within {RICHARDSON_FACTOR:g} error estimates) for inflation and for the "
                     "fitted meshes in compression. On uniform meshes in contact the edge moves inside its element "
                     "from mesh to mesh, the error is not a smooth function of h, and the extrapolation is reported "
                     "only."))
    return out


def _findings_blocks(results):
    out = [("h", 2, "Where the paper and the model disagree"),
           ("p", f"Each statement of the paper ({PAPER}) checked against the full model here (the shooting "
                 "solver, cross-checked by the FE model); the numbers are computed in this run. Verdicts are "
                 "about the paper and do not fail the run."),
           ("table", ["statement of the paper", "verdict"], [[f.title, f.verdict] for f in results.findings])]
    for f in results.findings:
        out += [("h", 3, f"{f.title}: {f.verdict}"),
                ("list", [f"Paper: {f.paper}", f"Model: {f.model}", *[f"Evidence: {e}" for e in f.evidence]])]
    return out


def _figure_blocks(results, figs, picture: bool, why: str) -> list:
    out = [("h", 2, "Figures"),
           ("p", f"The paper's figures 2-5 ({PAPER}) recomputed for its rubber (Mooney-Rivlin) filled with a "
                 "liquid, then the figures beyond the paper: one pocket filled with a liquid and with a gas, and "
                 "other rubber laws. Colours are pockets (one colour per pocket in every figure), line styles and "
                 "markers are solvers; the headline pocket is the broad dark line, drawn beneath the others; the "
                 "other pockets' lines carry dots of their colour, staggered so that curves lying on each other "
                 "all show.")]
    for fig in figs:
        in_sections = ("convergence", "identification", "thickness", "solid_convergence", capsulereport.NAME)
        if fig.name not in in_sections:
            out.append(("image", f"{fig.name}.png", f"{fig.caption} Data: {fig.name}.csv."))
    out.append(("h", 2, "The pocket in 3-D"))
    if picture:
        out.append(("image", "pocket3d.png", f"{pocket_label(headline(results.pockets))}: the shooting solution "
                                             "revolved about the axis, coloured by the meridional stretch (one "
                                             "scale for both views), the plate shown in (b)."))
    else:
        out.append(("p", f"No picture: {why}."))
    return out


def _identification_blocks(results, figs) -> list:
    header, rows = identification.rows(results.fits)
    warned = [f"{f.label}: {w}" for f in results.fits for w in f.warnings]
    caption = next(f.caption for f in figs if f.name == "identification")
    return [("h", 2, "Identifying a rubber from its bulge test"),
            ("p", f"pocket fit's library fits a law's parameters to a user's tests by least squares on the full "
                  f"model. Here each law is fitted by the shooting model to {identification.POINTS} noise-free pole "
                  f"heights of a known rubber (the truth, stresses in Pa: {identification.describe(results.fits)}) "
                  f"computed by the P2 FE model at Phat = {identification.LOW:g} to {identification.HIGH:g}, "
                  f"R = {identification.RADIUS * 1e3:g} mm, T = {identification.THICKNESS * 1e3:g} mm. The exact "
                  f"answer is the truth; the tolerance is {TOLERANCES['fit'][0]:g}: {TOLERANCES['fit'][1]}. The "
                  "verdicts are also in the table 'Verdicts' (comparison 'fit to FE data vs the truth'); each fit's "
                  "seconds are in the timing table."),
            ("table", header, rows),
            ("p", "What the fits report the data do not determine (identifiability warnings): "
                  + ("; ".join(warned) if warned else "nothing") + "."),
            ("image", "identification.png", f"{caption} Data: identification.csv.")]


def _thickness_blocks(results, figs) -> list:
    comparisons = results.thicknesses
    header, rows = thickness.rows(comparisons)
    caption = next(f.caption for f in figs if f.name == "thickness")
    slopes = ", ".join(f"{q} {s:.2f}" for q, s in thickness.slopes(comparisons).items())
    seconds = sum(c.seconds for c in comparisons)
    return [("h", 2, "How thick is too thick: the membrane against the solid"),
            ("p", "Both solvers above, and the paper, treat the sheet as a membrane: a surface without thickness or "
                  "bending stiffness, solved here to 1e-10. Whether those are the right equations for a sheet of "
                  "thickness T is a question about the model, answered by a third one: pocket.solid solves the "
                  "sheet's cross-section as an incompressible hyperelastic solid (Taylor-Hood quadrilaterals, the "
                  "same strain energy, the clamp through the thickness, the fluid's pressure on the lower surface, "
                  "the plate on the upper one). The paper's four samples (Table 1: C1 = 160 kPa, C2 = 47 kPa, "
                  "R = 20 mm, a liquid) are solved by both at P_I = "
                  f"{', '.join(f'{p:g}' for p in sorted({c.pressure_kpa for c in comparisons}))} kPa; the error is "
                  "membrane / solid - 1, with the solid at its default mesh"
                  + (" and beside it the solid's own uncertainty, the error's change when the solid is solved again "
                     "on a mesh refined along all its axes at once (twice the elements along the radius and through "
                     "the thickness, the clamp's corner elements half as long)"
                     if any(c.refined for c in comparisons) else
                     " (this plan does not solve it on a refined mesh; the full report states the solid's own "
                     "uncertainty beside each error)")
                  + ". The solid's clamp holds the sheet between two plates, the upper one's edge rounded to half a "
                  "thickness (pocket.solid's default jaw); the membrane is hinged at r = R with nothing above it, "
                  "so part of each difference is the real clamp's, which a membrane cannot see. Heights of the "
                  "mid-surface compare the same surface; the upper surface "
                  "(what a plate meets) is lambda_3 T / 2 above it, which the rows 'upper surface' add to the "
                  "membrane's answer. The fluid's volume is under the solid's lower surface; the membrane's under "
                  "its mid-surface, which for an incompressible sheet is the same volume to first order in T/R "
                  "(the thinned sheet's offset, int lambda_3 T/2 dA, is exactly the T/2 by which the lower clamp "
                  "plane lies lower): the rows 'V (membrane's lower surface)' show that the membrane's volume under "
                  "its lower surface removes almost none of the difference, which comes from the clamp, where the "
                  "solid bends over a few thicknesses and the membrane's slope jumps. The checks are "
                  "informational: a model's error is a property of the model."),
            ("p", "Verdict, where the membrane is within 1 % of the solid:"),
            ("list", thickness.verdict(comparisons)),
            ("p", f"Slope of log(largest error) against log(T/R) over the four samples: {slopes} (each sample at "
                  "its own Phat_I, so these are not a clean order; the limit T/R -> 0 at one Phat_I is first order "
                  f"in the solid's tests). The solid's solves took {seconds:.1f} s in all."),
            ("table", header, rows),
            ("image", "thickness.png",
             f"{caption} Data: thickness.csv (plotted points), membrane_vs_solid.csv (every value).")]


def _solid_study_blocks(results, figs) -> list:
    found = results.solid_studies
    header, rows = solidstudy.rows(found)
    targets = ", ".join(f"{q} {t:g}" + (" R" if q in solidstudy.ABSOLUTE else "")
                        for q, t in solidstudy.TARGETS.items())
    failing = [c for c in results.checks if c.comparison == solidstudy.COMPARISON and c.verdict == "fail"]
    caption = next(f.caption for f in figs if f.name == "solid_convergence")
    seconds = sum(sum(s.seconds) for s in found)
    return [("h", 2, "The solid's own error: its convergence with the mesh"),
            ("p", "The solid is the yardstick of the membrane's error above, so its own discretisation error must be "
                  "known and smaller. The paper's sample"
                  f"{'s' if len({s.sample for s in found}) > 1 else ''} "
                  f"{', '.join(sorted({str(s.sample) for s in found}))} at P_I = "
                  f"{found[0].pressure_kpa:g} kPa, pressed at F/(P_I pi R^2) = "
                  f"{', '.join(f'{f:g}' for f in found[0].forces)}, solved on meshes refined along the radius, "
                  "through the thickness and at the clamp's corner (the corner elements' length), one at a time, "
                  "each halving the element size. Observed order from the three finest meshes of an axis, and "
                  "Richardson's extrapolation q*; the default mesh's error is its distance from q*, or where the "
                  "differences do not yet shrink (no q*), its distance from the finest mesh plus the finest mesh's "
                  "own last change. "
                  "The clamp's upper jaw (its edge rounded to half a thickness, the solid's default) makes the "
                  "corner a boundary the mesh resolves: from corner elements as long as the edge's radius down, its "
                  "axis is a discretisation error like the others (without the jaw the corner is singular, and the "
                  "answer depends on its elements' length). "
                  f"Held to: {targets} (the contact area relative, the contact radius in units of R); "
                  "the other quantities are informational. "
                  + (f"{len(failing)} of these checks fail: " + "; ".join(
                      f"sample {c.case.split()[-1]} {c.quantity} ({c.where}): {c.error:.2e}" for c in failing[:6])
                     + ("; ..." if len(failing) > 6 else "") + "." if failing else "All of these checks pass.")
                  + f" The study's solves took {seconds:.1f} s in all."),
            ("table", header, rows),
            ("image", "solid_convergence.png", f"{caption} Data: solid_convergence.csv (every value).")]


def _pockets_blocks(results) -> list:
    header, rows = case_table(results)
    return [("h", 2, "Pockets"),
            ("p", "From the cases file (the suite's own cases.toml unless --cases names another), in SI units: "
                  "the rubber's law and parameters (stresses in kPa), E = 3 mu_0 its small-strain Young's modulus "
                  "(6 (1 + alpha) C1 for Mooney-Rivlin, alpha = C2/C1), Phat_I = P_I R / (E T), and for a gas "
                  "(ambient pressure P_atm, exponent gamma) Phat_atm = P_atm R / (E T). The range ends where the "
                  "free part of the sheet reaches the clamp plane (shooting, bisection)."),
            ("table", header, rows)]


def _files_block(figs, tables, vtk) -> tuple:
    """The list of files; ``vtk`` is (steps written, states of the path), or None if no VTK was written."""
    items = [f"{', '.join(f'{f.name}.csv' for f in figs)}: every number of the figures, one row per point"]
    items += tables
    items.append(f"{checkpage.PAGE[0]} and {checkpage.PAGE[1]}: every check, and the verdicts per pocket")
    if vtk:
        written, count = vtk
        which = "at every force" if written == count else (f"at {written} of its {count} forces, spread along it "
                                                            "(pocket validate --vtk all writes every one)")
        items.append(f"vtk/: the headline case's compression path (shooting) {which}: one profile and one surface "
                     "per force on one fixed set of Lagrangian radii, with the state's scalars as field data, plus "
                     "surface.pvd and profile.pvd; open vtk/surface.pvd in ParaView and press play "
                     "(time = F/(P_I pi R^2)).")
    return ("list", items)


def blocks(results, figs, picture: bool, why: str, tables, vtk, title: str, wall: float) -> list:
    """All blocks of the report, under the heading ``title``; ``wall`` is the run's wall time in seconds,
    writing included."""
    header, rows = glance(results)
    out = [("h", 1, title), *limits.blocks(results),
           ("p", f"Plan '{results.plan.name}', {len(results.curves) or 'the headline'} pocket"
                 f"{'s' if len(results.curves) > 1 else ''}, {wall:.1f} s wall time in all, the report's "
                 f"writing included (the solves {results.seconds:.1f} s on {WORKERS} processes). The model and "
                 f"its solvers follow {PAPER}; dimensionless units throughout: lengths / R, Phat = P R / (E T), "
                 "Fhat = F / (P_I pi R^2)."),
           ("toc",),
           ("h", 2, "Verdicts"),
           ("p", "One line per comparison over all pockets: a comparison fails if any of its checks fails; "
                 "'info' checks have no tolerance that should hold (a model's own error against a more complete "
                 "one: the analytical model's, the membrane's against the solid; the orders reported, not checked). "
                 f"'{MEMBRANE}' is the wrinkling verdict: per pocket and solver it covers every state of the curve "
                 "(each state's smallest tensions and wrinkled flag are in states.csv), and fails if any state has "
                 "a tension <= 0 anywhere. "
                 "The largest error / tolerance is the closest call (1 is the limit). Per pocket, and every "
                 f"check: {checkpage.PAGE[0]} and checks.csv."),
           ("table", header, rows)]
    if results.curves:
        out += _figure_blocks(results, figs, picture, why) + _pockets_blocks(results)
    if results.findings:
        out += _findings_blocks(results)
    if results.fits:
        out += _identification_blocks(results, figs)
    if results.thicknesses:
        out += _thickness_blocks(results, figs)
    if results.solid_studies:
        out += _solid_study_blocks(results, figs)
    if results.capsules:
        caption = next(f.caption for f in figs if f.name == capsulereport.NAME)
        out += capsulereport.blocks(results.capsules, results.capsule_sequence, results.checks, caption,
                                    results.uninflated)
    if results.sequences:
        out += _convergence_blocks(results)
        out.append(("image", "convergence.png", "Error against element size (log-log), observed orders in the "
                                                "legend. Data: convergence.csv (plotted points), "
                                                "convergence_study.csv (every value)."))
    out += [("h", 2, "Tolerances"),
            ("list", [f"{name}: {_tolerance(tol)}: {why}" for name, (tol, why) in TOLERANCES.items()]),
            ("h", 2, "Timing"),
            ("p", f"Wall time of each solve task in its worker ({WORKERS} processes; the solves took "
                  f"{results.seconds:.1f} s, the whole run {wall:.1f} s, the report's writing included). The plan "
                  "(pocket.validation.plan) sets how much each task computes."),
            ("table", *task_rows(results)),
            ("h", 2, "Provenance"),
            ("p", "The software and machine of this run."),
            ("table", ["", "version"], [[k, v] for k, v in environment().items()]),
            ("h", 2, "Files"),
            _files_block(figs, tables, vtk)]
    return out + checkpage.failing_blocks(results.checks)
