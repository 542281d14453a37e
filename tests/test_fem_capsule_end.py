"""The end of the finite-element capsule's range: where the meridional tension at the contact edge vanishes.

At a low Phat_I the patch under the plate goes slack (valid states, flagged wrinkled) and, as the force rises, the
slack spreads to the contact edge: there T_1 falls to 0 and the free part would leave the plate with the unbounded
curvature P / T_1 (``pocket.core.errors.CAPSULE_EDGE``). The finite elements watch the edge's T_1, from the contact
zone's flux (``fem.post.edge_tension``, ``fem.steps.check_edge``): a step that lands where it is not positive is
outside the model, and the continuation bisects down to the end and quotes it. The capsule is the shooting solver's
own case (neo-Hookean, Phat_I = 0.01: ``tests/test_shooting_capsule.py``), whose ``range_end`` is the reference,
computed here. Deeper, the states resume on a second branch (``tests/test_fem_capsule_deep.py``): a force past
the end is refused only where it lies between the two, as ``PAST`` does.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from pocket.fem import capsule, fitted, model, post
from pocket.fem.api import default_mesh
from pocket.fem.newton import Tolerances
from pocket.shooting.capsule import _END_RTOL

from pocket import fem, shooting
from pocket.cli import main
from pocket.core.errors import CAPSULE_EDGE, OutOfRangeError, exit_status
from pocket.core.geometries import CAPSULE
from pocket.core.materials import as_material

RUBBER = as_material(0.0)  # neo-Hookean (Mooney-Rivlin alpha = 0)
PRESSURE = 0.01
PAST = 0.2  # a force past the end (the shooting solver's is near 0.15), short of the deep branch (about 1)
KEYS = ("pressure_ratio", "height", "volume", "contact_area", "contact_radius", "contact_radius_deformed",
        "stretch_contact")


def fem_end(force: float = PAST, **options) -> tuple[float, float]:
    """The bracket (lo, hi) of the end the finite elements quote on the way to ``force``: the last force they
    solved and the nearest beyond it they tried."""
    with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)) as refused:
        fem.compress(RUBBER, PRESSURE, force, geometry="capsule", **options)
    found = re.search(r"ends at force = (\S+) to (\S+) \(", str(refused.value))
    assert found, str(refused.value)
    lo, hi = (float(v) for v in found.groups())
    assert lo < hi < force
    return lo, hi


def _edge_tension(elements: int, rubber, pressure: float, force: float) -> float:
    """The finite elements' T_1 at the contact edge (``fem.post.edge_tension``) of the capsule pressed by ``force``
    on the default mesh of ``elements`` elements, a liquid inside."""
    m = model.discretize(rubber, default_mesh(elements), 2, 1e5, CAPSULE)
    tol = Tolerances(1e-10, 1e-10)
    y_i, _ = capsule.inflate(m, pressure, tol)
    fill = model.Control(volume=model.forms(m, y_i, model.FREE).volume)
    y, _ = fitted.first_contact(m, y_i, fill, fitted.A_FIRST, tol)
    y, _ = fitted.force_path(m, y, fill, force * np.pi * pressure, tol)
    return post.edge_tension(m, y)


def test_the_edge_tension_is_the_shooting_solvers():
    """The edge's T_1 the finite elements watch, the contact zone's flux over 2 pi rho(a), on a taut capsule (Mooney-
    Rivlin alpha = 0.2, Phat_I = 0.2, Fhat = 0.5) against the shooting state's T_1 at its last contact point: within
    the finite elements' error, estimated as the shift from the mesh of half as many elements (a flux converges at
    least at first order, the error of the finer mesh at most that shift)."""
    reference = shooting.compress(0.2, 0.2, 0.5, geometry="capsule")
    shot = reference.profile.tension_1[np.flatnonzero(reference.profile.contact)[-1]]
    coarse, fine = (_edge_tension(n, 0.2, 0.2, 0.5) for n in (64, 128))
    print(f"T_1 at the edge: shooting {shot!r}, finite elements {fine!r} (128 elements), {coarse!r} (64)")
    assert abs(fine / shot - 1) <= abs(fine / coarse - 1)


def test_a_force_past_the_end_is_refused_naming_the_slack_edge():
    """One message: the force lies between the capsule's two branches, the end of the one from the touch quoted as
    a bracket below it and the start of the deep one as a bracket above it, and the reason the shooting solver
    gives (the edge's tension vanishing)."""
    with pytest.raises(OutOfRangeError) as refused:
        fem.compress(RUBBER, PRESSURE, PAST, geometry="capsule")
    message = str(refused.value)
    found = re.fullmatch(rf"force = {PAST} lies between the capsule's two branches of states: the one pressed from "
                         r"the touch ends at force = (\S+) to (\S+) \(.*\), the one reached deeper starts at force = "
                         r"(\S+) to (\S+) \(.*\); between them " + re.escape(CAPSULE_EDGE), message)
    assert found, message
    end_lo, end_hi, start_hi, start_lo = (float(v) for v in found.groups())
    assert end_lo < end_hi < PAST < start_lo < start_hi


@pytest.mark.slow  # a minute: the shooting solver's march to its end at this low pressure
def test_the_end_brackets_the_shooting_solvers():
    """The end the finite elements quote on the default mesh, [lo, hi], holds the shooting solver's ``range_end``
    within the finite elements' own error of it. That error is estimated from the mesh of half as many elements:
    the end is the zero of the edge's tension, a flux, which converges at least at first order in h even where the
    corner at the edge is unresolved; for a sequence converging at order p >= 1 the finer mesh's error is at most
    |end_h - end_2h| / (2^p - 1) <= |end_h - end_2h|, each end taken as its bracket's middle and widened by its
    half-width. The shooting end is its march's to the relative step ``_END_RTOL``."""
    lo, hi = fem_end()
    elements = fem.inflate(RUBBER, PRESSURE, geometry="capsule").extra["elements"]
    coarse_lo, coarse_hi = fem_end(elements=elements // 2)
    mesh_error = abs(0.5 * (lo + hi) - 0.5 * (coarse_lo + coarse_hi)) + 0.5 * (coarse_hi - coarse_lo)
    end = shooting.range_end(RUBBER, PRESSURE, geometry="capsule")
    slack = mesh_error + _END_RTOL * end
    print(f"finite elements: end in [{lo:.10g}, {hi:.10g}] ({elements} elements), [{coarse_lo:.10g}, "
          f"{coarse_hi:.10g}] ({elements // 2}); shooting: {end:.10g}; allowed {slack:.3g} beyond the bracket")
    assert lo - slack <= end <= hi + slack


@pytest.mark.slow  # the shooting solver at this low pressure, seconds a force
def test_a_force_just_inside_the_end_solves_and_agrees_with_shooting():
    """Just inside the end (1e-3 below the shooting solver's end, as its own test takes it) the finite elements
    solve: the patch slack, flagged wrinkled. Every contract key agrees with the shooting solver's state within the
    finite elements' error there, which has two parts. The mesh's, estimated as the shift of the key from the mesh
    of half as many elements (first order at least, as for the end). And the corner's: the exact meridian leaves the
    plate with the curvature P / T_1(a), through a corner of radius r_c = T_1(a) / P (T_1(a) the shooting state's,
    here far below an element), which the elements, whose vertex sits at the edge, draw as a kink: the contact edge
    is then placed to about r_c, a relative error r_c / a_c in the contact radius and twice that in the contact area
    and in the pressure (F = P A_c); 2 r_c / a_c bounds every key's share. Refining does not shrink that share
    until the elements are shorter than r_c, so the mesh's shift alone would not bound the difference. The
    shooting's own error (rtol 1e-10; unchanged at 1e-11) is far below both."""
    end = shooting.range_end(RUBBER, PRESSURE, geometry="capsule")
    force = end * (1.0 - 1e-3)
    state = fem.compress(RUBBER, PRESSURE, force, geometry="capsule")
    elements = state.extra["elements"]
    coarse = fem.compress(RUBBER, PRESSURE, force, geometry="capsule", elements=elements // 2)
    reference = shooting.compress(RUBBER, PRESSURE, force, geometry="capsule")
    assert state.wrinkled
    assert state.extra["stretch_pole"] < 1.0
    assert any("compressive tension" in w for w in state.warnings)
    at_edge = np.flatnonzero(reference.profile.contact)[-1]
    tension = reference.profile.tension_1[at_edge]
    assert tension > 0.0
    corner = 2.0 * (tension / reference.pressure) / reference.contact_radius
    for key in KEYS:
        fe, shot, rough = getattr(state, key), getattr(reference, key), getattr(coarse, key)
        mesh = abs(fe / rough - 1)
        print(f"{key}: finite elements {fe!r}, shooting {shot!r}, differ by {abs(fe / shot - 1):.2e}; mesh "
              f"{mesh:.2e}, corner {corner:.2e}")
        assert abs(fe / shot - 1) <= mesh + corner, key


def test_the_command_line_refuses_a_force_past_the_end_in_one_line(capsys):
    """``pocket compress`` with the finite elements past the capsule's end: nothing on stdout, one line on stderr
    naming the end and its reason, the exit status of a state outside the model, no traceback."""
    status = main(["compress", "--geometry", "capsule", "--solver", "fem", "--law", "neo-hookean", "--mu", "1",
                   "--pressure", str(PRESSURE), "--force", "0.1", str(PAST)])
    out, err = capsys.readouterr()
    assert status == exit_status(OutOfRangeError("past the end"))
    assert out == ""
    assert err.count("\n") == 1
    assert "Traceback" not in err
    assert f"force = {PAST} lies between the capsule's two branches of states" in err
    assert CAPSULE_EDGE in err


@pytest.mark.slow  # four solves of the finite elements, a second or two
def test_height_control_ends_where_force_control_does():
    """The plate brought down past the end is refused naming the edge, its end quoted as a bracket of heights
    [h_beyond, h_reached]; a state inside one control's end is inside the other's (the force rises as the plate
    comes down, and the discrete end is one state): the force at h_reached is below the force bracket's upper
    end, and the height at the force bracket's lower end is above h_beyond."""
    lo, hi = fem_end()
    inside = fem.compress(RUBBER, PRESSURE, lo, geometry="capsule")
    with pytest.raises(OutOfRangeError, match=re.escape(CAPSULE_EDGE)) as refused:
        fem.compress_height(RUBBER, PRESSURE, inside.height - 0.005, geometry="capsule")
    found = re.search(r"ends at plate height h/R = (\S+) to (\S+) \(", str(refused.value))
    assert found, str(refused.value)
    reached, beyond = (float(v) for v in found.groups())
    assert beyond < reached
    assert fem.compress_height(RUBBER, PRESSURE, reached, geometry="capsule").force < hi
    assert inside.height > beyond
