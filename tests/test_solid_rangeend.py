"""The solid's own end of the compression range under a sphere, by the membrane solvers' rules
(``pocket.solid.rangeend``).

Exact answers: past the end the solid refuses (exit 2, one line naming the end) where it used to return states
with the sphere's lowest point and the sheet below the clamp plane; the end it names is the edge of what it
solves (a force there solves with the sheet above the plane, one a few bracket widths past it is refused); force
and height control name the same end. Limit: as T/R -> 0 the solid's end tends to the membrane's
(``pocket.shooting.range_end``), the difference first order in T/R.
"""

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pocket.solid.rangeend import END_RTOL

from pocket import shooting, solid
from pocket.cli import main
from pocket.core.errors import OutOfRangeError
from pocket.core.indenters import Sphere
from pocket.core.materials import mooney_rivlin

pytestmark = pytest.mark.slow  # the slow lane (pytest -m slow)

# the neo-Hookean pocket of the reproducer: Phat_I = 0.2 under a sphere of K = 0.5, whose membrane end (Fhat ~
# 1.46) is the sphere's lowest point reaching the clamp plane; a coarse solid (two layers, 32 elements) keeps
# each solve to seconds
K, PHAT, T = 0.5, 0.2, 0.02
COARSE = {"elements": 32, "layers": 2}
NEO_HOOKEAN = mooney_rivlin(0)


def _end(err: OutOfRangeError, key: str = "force") -> float:
    """The end's load quoted by the refusal ``err`` (``beyond_range``'s wording)."""
    return float(re.search(rf"which ends at {key} = ([-+0-9.e]+)", str(err)).group(1))


def _compress(force, thickness_ratio=T, **options):
    return solid.compress(NEO_HOOKEAN, PHAT, force, indenter=Sphere(K), thickness_ratio=thickness_ratio,
                          **{**COARSE, **options})


@pytest.fixture(scope="module")
def membrane_end():
    return shooting.range_end(NEO_HOOKEAN, PHAT, indenter=Sphere(K))


def test_solid_refuses_a_sphere_pressed_past_the_clamp_plane(capsys, membrane_end):
    """The reproducer: ``pocket compress --solver solid`` under a sphere at 1.5 times the membrane's end used to
    exit 0 with the sphere's lowest point and the mid-surface below the clamp plane (height < 0). Now: exit 2,
    nothing on stdout, one line on stderr in ``beyond_range``'s wording naming the force asked, the solid's end
    below it and what ends the range there."""
    force = 1.5 * membrane_end
    status = main(["compress", "--solver", "solid", "--alpha", "0", "--pressure", str(PHAT), "--indenter", "sphere",
                   "--indenter-radius", str(K), "--force", repr(force), "--thickness-ratio", str(T),
                   "--elements", "32", "--layers", "2"])
    out, err = capsys.readouterr()
    assert status == 2
    assert out == ""
    assert err.count("\n") == 1
    assert "Traceback" not in err
    assert err.startswith(f"pocket: error: force = {force:.10g} is beyond the model's range, which ends at force = ")
    assert 0.0 < _end(err) < force
    assert err.rstrip().endswith("there the sheet's mid-surface under the sphere reaches the clamp plane (the "
                                 "sphere's lowest point half the sheet's thickness above it)")


def test_the_named_end_is_the_edge_of_what_the_solid_solves(membrane_end, monkeypatch):
    """The end named is the last force solved inside the model, located to the bracket ``END_RTOL``: the state
    there has its mid-surface's pole (the sheet's lowest point under the sphere) and the sphere's lowest point
    above the clamp plane, the pole within the bracket's travel of it; a force 10 bracket widths past the end is
    refused, naming the same end to the bracket's width (each is located from its own path). On the mesh the end
    is located on, the mesh as asked: the state the solid returns there is solved again on a mesh clustered
    about its contact edge (``pocket.solid.edgemesh``), whose pole differs by that mesh's own difference (kept
    inside the model). Without the clamp's upper jaw: a state's active set is the same whichever path reached it
    only when no node grazes an obstacle, and on the jaw's rounded edge nodes graze it all along the sheet's
    wrapping (a free node joins the set once ``newton.SWEEP_TOL``, 1e-7 R, inside it), which moves the end from
    path to path by ~1e-8: with the jaw, ``test_with_the_jaw_the_end_is_located_to_the_path_s_own_noise``."""
    from pocket.solid import edgemesh

    monkeypatch.setattr(edgemesh, "follow", lambda model, y, control, tol: (model, y, control, 0))
    with pytest.raises(OutOfRangeError) as past:
        _compress(1.5 * membrane_end, clamp_radius=0)
    end = _end(past.value)
    at = _compress(end, clamp_radius=0)
    print(f"end Fhat = {end:.12g}: pole of the mid-surface at {at.extra['height_mid']:.3e} R, sphere's lowest point "
          f"at {at.height:.3e} R")
    assert 0.0 < at.extra["height_mid"] < at.height
    # the pole falls by dh/dFhat per unit force, ~0.13 R here (a travel of 0.13 R from Fhat 1.4 to 1.8 on the
    # default solid): over the bracket END_RTOL * Fhat it falls by ~2e-9 R; 1e-6 R bounds it with room for the
    # slope's change along this coarse solid
    assert at.extra["height_mid"] < 1e-6
    with pytest.raises(OutOfRangeError) as beyond:
        _compress(end * (1.0 + 10.0 * END_RTOL), clamp_radius=0)
    assert _end(beyond.value) == pytest.approx(end, rel=2.0 * END_RTOL)


def test_with_the_jaw_the_end_is_located_to_the_path_s_own_noise(membrane_end):
    """With the clamp's upper jaw (the default) the end named is the edge of what the solid solves to within
    ten bracket widths: a force ten widths below it solves with the sheet above the plane, one ten widths above
    it is refused naming the same end to ten widths (its nodes grazing the jaw's edge make the active set, and
    so the end, depend on the path by ~1e-8: ``test_the_named_end_is_the_edge_of_what_the_solid_solves``)."""
    with pytest.raises(OutOfRangeError) as past:
        _compress(1.5 * membrane_end)
    end = _end(past.value)
    at = _compress(end * (1.0 - 10.0 * END_RTOL))
    assert 0.0 < at.extra["height_mid"] < at.height
    with pytest.raises(OutOfRangeError) as beyond:
        _compress(end * (1.0 + 10.0 * END_RTOL))
    assert _end(beyond.value) == pytest.approx(end, rel=10.0 * END_RTOL)


def test_height_control_below_the_end_names_the_same_end(membrane_end):
    """``compress_height`` at H/R = 1e-4, below the end's height (where the mid-surface's pole, half the
    deformed thickness ~ T/4 below the sphere's lowest point, reaches the plane: ~5e-3 R here), is refused
    naming the end's height and its force; that force is force control's end: both are located to ``END_RTOL``
    on margins solved to Newton's 1e-10 R, so they agree to ~1e-8; 1e-6 bounds it."""
    with pytest.raises(OutOfRangeError) as past:
        _compress(1.5 * membrane_end)
    with pytest.raises(OutOfRangeError) as low:
        solid.compress_height(NEO_HOOKEAN, PHAT, 1e-4, indenter=Sphere(K), thickness_ratio=T, **COARSE)
    message = str(low.value)
    print(message)
    assert message.startswith("height = 0.0001 is beyond the model's range, which ends at height = ")
    assert _end(low.value, "height") > 1e-4
    force = float(re.search(r", force = ([-+0-9.e]+)", message).group(1))
    assert force == pytest.approx(_end(past.value), rel=1e-6)


def test_the_solids_end_tends_to_the_membranes_as_the_sheet_thins(membrane_end):
    """Limit: the membrane is the solid's first order in T/R, so the solid's end tends to the membrane's end,
    the difference O(T/R): at T/R = 0.01 and 0.02 it keeps its sign and falls with an order between 0.7 and 1.6
    (fitted; first order plus a second-order term and the mesh's share), and it is at most T relative (an O(T/R)
    error of coefficient one). Measured here (K = 0.5, Phat_I = 0.2, T/R 0.01 to 0.04, meshes 32 x 2 to 64 x
    4): (Fhat_solid - Fhat_end) / Fhat_end / T from -0.18 to -0.24, order 1.1 to 1.2; across K 0.4 to 0.7,
    Phat_I 0.15 to 0.3, alpha 0 to 0.3 (T/R = 0.02, 32 x 2) from -0.75 to +0.53 at its corners."""
    relative = {}
    for t in (0.01, 0.02):
        with pytest.raises(OutOfRangeError) as past:
            _compress(1.5 * membrane_end, thickness_ratio=t)
        relative[t] = (_end(past.value) - membrane_end) / membrane_end
    order = math.log2(relative[0.02] / relative[0.01]) if relative[0.02] * relative[0.01] > 0 else math.nan
    print(f"membrane end {membrane_end:.10g}; solid minus membrane, relative: {relative[0.01]:.3e} (T/R 0.01), "
          f"{relative[0.02]:.3e} (T/R 0.02), order {order:.2f}")
    assert 0.7 <= order <= 1.6
    assert all(abs(d) <= t for t, d in relative.items())


@settings(max_examples=5, deadline=None)
@given(radius=st.floats(0.4, 0.7), pressure=st.floats(0.15, 0.3), alpha=st.floats(0.0, 0.3),
       factor=st.floats(1.2, 2.0))
def test_past_the_end_the_solid_refuses(radius, pressure, alpha, factor):
    """Property, over spheres K in [0.4, 0.7], Phat_I in [0.15, 0.3] and Mooney-Rivlin alpha in [0, 0.3]: a force 1.2 to
    2 times the membrane's end (past the solid's too, which lies within T of it, 2 %, at T/R = 0.02:
    ``test_the_solids_end_tends_to_the_membranes_as_the_sheet_thins``) is refused, naming an end below it whose
    reason is one of the membrane's rules (the sheet reaching the clamp plane, or the sphere's equator)."""
    material = mooney_rivlin(alpha)
    force = factor * shooting.range_end(material, pressure, indenter=Sphere(radius))
    with pytest.raises(OutOfRangeError) as past:
        solid.compress(material, pressure, force, indenter=Sphere(radius), thickness_ratio=T, **COARSE)
    message = str(past.value)
    assert message.startswith(f"force = {force:.10g} is beyond the model's range")
    assert _end(past.value) < force
    assert re.search(r"there (the sheet's mid-surface under the sphere reaches the clamp plane|the free part of the "
                     r"sheet reaches the clamp plane|the sheet would wrap past the sphere's equator)", message)
