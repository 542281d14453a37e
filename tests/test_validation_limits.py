"""The headline's sentences on the models' limits, computed from data built here with known errors."""

from types import SimpleNamespace

from pocket.validation import limits
from pocket.validation.thickness import Comparison

_FORCES = (0.2, 0.5, 1.0)


def _sample(number, ratio, volume=0.0, area=(0.0, 0.0, 0.0), within=0.005):
    """A comparison whose membrane / solid - 1 is ``volume`` in V, ``area`` at the three forces in A_c, and
    ``within`` (inside 1 %) in every other quantity."""
    values = {("V", None): (1.0 + volume, 1.0), ("H0 (mid-surface)", None): (1.0 + within, 1.0)}
    for f, a in zip(_FORCES, area, strict=True):
        values["P/P_I", f] = (1.0 + within, 1.0)
        values["H/H0 (mid-surface)", f] = (1.0 - within, 1.0)
        values["A_c", f] = (1.0 + a, 1.0)
    return Comparison(number, ratio, 5.0, 0.05, _FORCES, values, 0.0)


def test_membrane_sentence_names_each_sample_and_its_errors():
    """Exact answer: samples 1 and 2 within 1 % everywhere are named together; sample 3 with one A_c value
    inside 1 % and one at 2 % is 'up to 2 %'; sample 4 (V 26 %, A_c 27.7 %, 34.6 %, 52.7 %) is 'off by 26 % in
    V and 28-53 % in A_c', within 1 % in the rest. The numbers are the ones built in, to two digits."""
    samples = [_sample(1, 0.0125), _sample(2, 0.025), _sample(3, 0.04, area=(0.005, 0.02, 0.003)),
               _sample(4, 0.08, volume=0.26, area=(0.527, 0.346, 0.277))]
    text = limits.sentence(*limits.membrane_vs_solid(samples))
    assert "P_I = 5 kPa, pressed to Fhat = 0.2, 0.5 and 1;" in text
    assert "): samples 1 and 2 within 1 % in every quantity; " in text
    assert "sample 3 (T/R = 0.04) within 1 % in V, H0, P/P_I and H/H0, off by up to 2 % in A_c; " in text
    assert text.endswith("sample 4 (T/R = 0.08) within 1 % in H0, P/P_I and H/H0, off by 26 % in V and "
                         "28-53 % in A_c.")


def _state(force, value, height=1.0, volume=1.0):
    inflated = SimpleNamespace(height=height, volume=volume)
    return SimpleNamespace(force=force, pressure_ratio=value, contact_area=value, height_ratio=value,
                           inflated=inflated)


def test_analytical_sentence_says_up_to_which_force_it_is_within():
    """Exact answer: a pocket whose analytical values are 0.5 %, 0.8 %, 3 % off the membrane's at Fhat = 0.005,
    0.05, 0.2 is within 1 % up to Fhat = 0.05, 3 % off over the curve; its inflated H0 10 % and V 20 % off. A
    pocket under a sphere (no analytical state) is not counted."""
    forces = (0.0, 0.005, 0.05, 0.2)
    errors = (0.0, 0.005, 0.008, 0.03)
    plate = SimpleNamespace(reference=[_state(f, 1.0) for f in forces],
                            approximate=[_state(f, 1.0 + e, height=1.1, volume=1.2)
                                         for f, e in zip(forces, errors, strict=True)])
    sphere = SimpleNamespace(reference=[_state(f, 1.0) for f in forces], approximate=[None] * len(forces))
    text = limits.sentence(*limits.analytical_vs_membrane([plate, sphere]))
    assert text.startswith("The analytical model against the membrane (shooting) on the 1 pocket pressed by the "
                           "plate: inflated, off by 10 % in H0 and 20 % in V; ")
    assert ("P/P_I within 1 % up to Fhat = 0.05 for 1 of 1 pockets (up to 0.5 % at Fhat = 0.005, up to 0.8 % for "
            "Fhat <= 0.1, up to 3 % over the curves)") in text
