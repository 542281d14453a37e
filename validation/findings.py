"""The section "Where the paper and the model disagree": one finding per statement, with evidence.

Each finding quotes the paper, states what the model here gives, and carries
the numbers (computed in this run) as its evidence. Verdicts: ``agrees`` or
``disagrees``, about the paper; they are reported, not failed (a disagreement
with the paper is a result, not a defect of the solvers).
"""

from __future__ import annotations

import dataclasses

from pocket.apps.design import PAPER_FORCE_FACTOR, PAPER_THICKNESS_FACTOR

__all__ = ["HEIGHT_READING", "Finding", "findings"]

#: how far from the paper's "H/H0 ~ 0.8" a value read off its fig. 3b may be
HEIGHT_READING = 0.05


@dataclasses.dataclass(frozen=True)
class Finding:
    title: str
    paper: str
    model: str
    evidence: tuple[str, ...]
    verdict: str  # "agrees" | "disagrees"


def _pct(x) -> str:
    return f"{100 * x:+.1f} %"


def _eq9(residuals) -> Finding:
    return Finding(
        "Eq (9): the pressure term",
        "the bracket of eq (9) ends with -(1/2) Phat (1 + alpha).",
        "normal equilibrium (eq (4a) with the curvatures of eq (5)) gives -3 (1 + alpha) Phat r~ "
        "(= p r~ with p = P R / (2 C1 T)); as printed there is no regular solution at the pole.",
        (f"eq (9) evaluated on the shooting solution (headline case), residual max|w' - rhs| / max|w'| for "
         f"0.05 <= r~ <= 0.95: printed term {residuals['printed']:.3g}, corrected term "
         f"{residuals['corrected']:.2g} (finite-difference error of the derivatives).",
         "the corrected form is also checked symbolically (sympy) in the project's tests."),
        "disagrees")


def _one_plus_alpha(ratios) -> Finding:
    lines = [f"alpha = {a:.4g}: T1(0) / (2 E T (lambda_0 - 1)) = {r:.4f} (eq (17a) as printed: {1 / (1 + a):.4f})"
             for a, r in ratios.items()]
    return Finding(
        "Eqs (17a) and (25): a missing factor (1 + alpha)",
        "T1 = 12 C1 T (lambda - 1), so eq (18) P_I = 24 C1 (T/R) sqrt(6) (lambda_0 - 1)^(3/2).",
        "linearising eq (6) gives T1 = 12 C1 (1 + alpha) T (lambda - 1) = 2 E T (lambda - 1): "
        "Phat_I = 4 sqrt(6) (lambda_0 - 1)^(3/2), independent of alpha.",
        ("pole tension of the full model at Phat = 1e-3 (lambda_0 - 1 ~ 2e-3), all alpha near 1, "
         "as the corrected form says:", *lines,
         "the linearisation is also checked symbolically (sympy) in the project's tests."),
        "disagrees")


def _contact_area(curves) -> Finding:
    rows, errors = [], {}
    for target in (0.1, 0.19, 0.5, 1.0):
        k = min(range(len(curves.forces)), key=lambda i: abs(curves.forces[i] - target))
        a, s = curves.approximate[k], curves.reference[k]
        if a is not None:
            errors[s.force] = a.contact_area / s.contact_area - 1
            rows.append(f"Fhat = {s.force:.3g}: A_c/(pi R^2) analytical {a.contact_area:.4f}, full model "
                        f"{s.contact_area:.4f} ({_pct(errors[s.force])}); P/P_I "
                        f"{a.pressure_ratio:.4f} vs {s.pressure_ratio:.4f}")
    pairs = [(a, s) for a, s in zip(curves.approximate[1:], curves.reference[1:], strict=True)
             if a is not None and s.force <= max(errors, default=0.0)]
    height = max((abs(a.height_ratio / s.height_ratio - 1) for a, s in pairs), default=0.0)
    over = all(e > 0 for e in errors.values())
    model = (f"the corrected analytical model {'over' if over else 'mis'}-predicts A_c (its pressure rises too "
             "slowly, and A_c = F/P), by " + ", ".join(f"{_pct(e)} at Fhat = {f:.3g}" for f, e in errors.items())
             + f"; its H/H0 stays within {100 * height:.1f} % up to Fhat = {max(errors, default=0.0):.3g}.")
    return Finding(
        "The analytical model at large force",
        "agreement is good for Fhat < 0.1; as the force increases the analytical model under-predicts A_c "
        "(section 5, fig. 3a).",
        model,
        (f"{curves.pocket.case.label} (Phat_I = {curves.pocket.pressure_initial:.3g}):", *rows,
         "see also the analytical rows of the verdict table."),
        "agrees" if errors and all(e < 0 for e in errors.values()) else "disagrees")


def _small_strain(small) -> Finding:
    return Finding(
        "Range of the analytical inflation",
        "the model is good when lambda_0 <= 1.1 (section 3).",
        f"at lambda_0 = 1.1 the model's H0 is {_pct(small['height'])} and its V {_pct(small['volume'])} off the "
        "full model's (the report's headline gives its error on every pocket).",
        (f"lambda_0 = 1.1 (Phat = {small['pressure_hat']:.4f}, alpha = 47/160): analytical / full - 1: "
         f"H0 {_pct(small['height'])}, V {_pct(small['volume'])}.",),
        "disagrees")


def _mm(x) -> str:
    return "none (outside the model's range)" if x is None else f"{x:.4f}"


def _design(button, evidence) -> list[Finding]:
    full, paper = evidence.buttons["full"], evidence.buttons["paper"]
    target, c, k = button.height_ratio, PAPER_FORCE_FACTOR, PAPER_THICKNESS_FACTOR
    pressure, thickness = button.paper
    agrees = abs(full["height_ratio"] - target) <= HEIGHT_READING
    tactile = Finding(
        f"Section 6: P_I ~ {c:g} F / (pi R^2) gives H/H0 ~ {target:g}",
        f"from fig. 3b, the tactile rule P_I ~ {c:g} F/(pi R^2) (Fhat = 1/{c:g} = {1 / c:.4f}) with H/H0 ~ {target:g}.",
        f"the full model gives H/H0 = {full['height_ratio']:.3f} at Fhat = 1/{c:g}, within +-{HEIGHT_READING} of "
        f"{target:g} (a reading off a figure); H/H0 = {target:g} exactly needs P_I = {full['coefficient']:.2f} "
        "F/(pi R^2).",
        (f"button R = {button.radius * 1e3:g} mm, H0 = {button.height * 1e3:g} mm, alpha = {button.alpha:.4g}, "
         f"sized by the full model (Phat_I = {full['pressure_hat']:.4f}): H/H0 = {full['height_ratio']:.4f} at "
         f"Fhat = {1 / c:.4f}; H/H0 = {target:g} at Fhat = {full['force_at_target']:.4f}.",
         f"sized by the paper's rules (Phat_I = {paper['pressure_hat']:.4f}): H/H0 = "
         f"{_mm(paper['height_ratio'])}; coefficient for H/H0 = {target:g}: {paper['coefficient']:.2f}."),
        "agrees" if agrees else "disagrees")
    thickness_full = pressure * button.radius / (button.modulus * full["pressure_hat"])
    paper_height = "none" if paper["height"] is None else f"{paper['height'] * button.radius * 1e3:.1f} mm"
    thickness_finding = Finding(
        f"Section 6: T = {k:g} P_I R^4 / (E H0^3)",
        f"the sheet thickness follows from H0, R, P_I and E through T = {k:g} P_I R^4 / (E H0^3) "
        "(the paper cites Bouremel et al., 2017, for it).",
        f"with E = 6 (C1 + C2) and the full model, H0 = {button.height * 1e3:g} mm at R = {button.radius * 1e3:g} mm "
        f"needs T = {evidence.thickness_coefficient:.3f} P_I R^4 / (E H0^3): the paper's T is "
        f"{k / evidence.thickness_coefficient:.2f} times that, and its button bulges to H0 = {paper_height}. "
        "(The small-strain limit of the coefficient is 0.1875 with the corrected eq (18), 0.1875 (1 + alpha) "
        "with eq (17a) as printed.)",
        (f"P_I = {c:g} F / (pi R^2) = {pressure:.0f} Pa, E = {button.modulus:.3g} Pa: paper's T = "
         f"{thickness * 1e3:.4f} mm (Phat_I = {paper['pressure_hat']:.4f}) gives H0/R = "
         f"{_mm(paper['height'])}; the full model's H0/R = {button.height / button.radius:g} needs Phat_I = "
         f"{full['pressure_hat']:.4f}, T = {thickness_full * 1e3:.4f} mm.",),
        "agrees" if abs(k / evidence.thickness_coefficient - 1) <= 0.1 else "disagrees")
    return [tactile, thickness_finding]


def findings(button, evidence, eq9, headline) -> list[Finding]:
    """All findings, in the order of the paper (``headline``: the headline pocket's ``compute.Curves``)."""
    return [_eq9(eq9), _one_plus_alpha(evidence.pole_ratio), _small_strain(evidence.small_strain),
            _contact_area(headline), *_design(button, evidence)]
