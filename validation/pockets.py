"""The report's table of pockets: each case in SI units and dimensionless, with the end of its range."""

from __future__ import annotations

import math

__all__ = ["case_table", "cell", "fluid_text", "rubber_text"]


def cell(x, digits=4) -> str:
    """A table cell: a number to ``digits`` significant digits, text as it is, "" for None or nan."""
    if x is None:
        return ""
    if isinstance(x, str):
        return x
    return "" if isinstance(x, float) and math.isnan(x) else f"{x:.{digits}g}"


def rubber_text(material) -> str:
    """A rubber in a table cell: its law and parameters, stresses in kPa ("yeoh: c10 85, c20 2, c30 0.1 kPa")."""
    parts = []
    stresses = material.definition.stresses
    for name, value in material.params:
        scale = 1e-3 if name in stresses else 1.0
        values = value if isinstance(value, tuple) else (value,)
        parts.append(f"{name} {' '.join(cell(v * scale) for v in values)}{' kPa' if scale != 1.0 else ''}")
    return f"{material.law}: {', '.join(parts)}"


def fluid_text(fluid) -> str:
    """A fluid in a table cell: "liquid", or "gas, 101.3 kPa, gamma 1.4" (ambient pressure in kPa)."""
    return fluid.kind if not fluid.is_gas else f"gas, {cell(fluid.ambient / 1e3)} kPa, gamma {cell(fluid.gamma)}"


def case_table(results):
    """(header, rows): each pocket in SI and dimensionless, with the end of its range."""
    header = ["case", "label", "T (mm)", "rubber", "fluid", "R (mm)", "P_I (kPa)", "alpha", "E (MPa)",
              "Phat_I", "Phat_atm", "lambda_0", "H0/R", "range end Fhat"]
    ends = {c.pocket: c for c in results.curves}
    rows = []
    for pocket in results.pockets:
        case, curves = pocket.case, ends.get(pocket)
        inflated = curves.reference[0].inflated if curves else None
        rows.append([case.name, case.label, cell(case.thickness * 1e3), rubber_text(case.material),
                     fluid_text(case.fluid), cell(case.radius * 1e3), cell(pocket.pressure_initial_Pa / 1e3, 6),
                     cell(case.alpha), cell(case.modulus / 1e6), cell(pocket.pressure_initial),
                     cell(pocket.fluid.ambient) if case.fluid.is_gas else "",
                     cell(inflated.stretch_pole, 6) if inflated else "", cell(inflated.height) if inflated else "",
                     cell(curves.force_end) if curves else ""])
    return header, rows
