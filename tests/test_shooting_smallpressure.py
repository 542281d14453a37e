"""Small pressures (Hencky's regime, Phat_I down to 1e-6): states exist and converge to the small-strain limit.

In that regime the strains scale as Phat^(2/3) and the shape as Phat^(1/3); every dimensionless
ratio of a compressed state (H/H0, P/P_I, a_c at a given Fhat) tends to a limit with a first
correction of relative order Phat^(2/3) (the next term of the expansion in the strain).
"""

import numpy as np
import pytest
from test_shooting_inflation import hencky_constant

from pocket import shooting

FORCES = [0.01, 0.1, 1.0, 10.0]
PRESSURES = [1e-4, 1e-5, 1e-6]


@pytest.fixture(scope="module")
def curves():
    return {p: shooting.compression_curve(0.3, p, FORCES) for p in PRESSURES}


def test_compressed_states_exist_far_below_the_range_end(curves):
    """Exact answer: the range end grows like 1/Phat_I (Fhat is F/(P_I pi R^2)), so these forces are
    far inside it; and each state keeps its volume and F = P A_c."""
    for p, states in curves.items():
        assert shooting.range_end(0.3, p) > 1e3 * max(FORCES)
        for s in states:
            assert s.volume == pytest.approx(s.inflated.volume, rel=1e-9)
            assert s.pressure_ratio * s.contact_area == pytest.approx(s.force, rel=1e-12)


@pytest.mark.parametrize("key", ["height_ratio", "pressure_ratio", "contact_radius"])
def test_ratios_approach_the_small_strain_limit_at_order_two_thirds(curves, key):
    """Exact answer: successive differences over Phat_I = 1e-4, 1e-5, 1e-6 shrink by 10^(2/3) = 4.64
    (first correction O(Phat^(2/3))), at every force."""
    for i in range(len(FORCES)):
        values = [getattr(curves[p][i], key) for p in PRESSURES]
        ratio = (values[0] - values[1]) / (values[1] - values[2])
        # the next term, O(Phat^(4/3)), changes the ratio by ~1e-3 relative; the solver error (~1e-10) far less
        assert ratio == pytest.approx(10 ** (2 / 3), rel=0.01), (key, FORCES[i], values)


def test_hencky_limit_at_one_in_a_million():
    """Exact answer: H0/R / Phat^(1/3) -> Hencky's constant; with Richardson extrapolation in Phat^(2/3)
    from Phat = 1e-5 and 1e-6 the next term, O(Phat^(4/3)), is ~1e-8."""
    k = [shooting.inflate(0.3, p).height / p ** (1 / 3) for p in (1e-5, 1e-6)]
    k0 = k[1] + (k[1] - k[0]) / (10 ** (2 / 3) - 1)
    assert k0 == pytest.approx(hencky_constant(), rel=1e-7), (k0, hencky_constant())


def test_tolerance_refinement_at_one_in_a_million():
    """Exact answer: rtol 1e-8 -> 1e-10 -> 1e-12 converges; from 1e-10 to 1e-12 no strain-like quantity
    (lambda_c - 1, H/H0, P/P_I - 1, a_c) moves by more than 1e-8 relative."""
    runs = {rtol: shooting.compression_curve(0.3, 1e-6, FORCES, rtol=rtol) for rtol in (1e-8, 1e-10, 1e-12)}

    def gaps(a, b):
        return max(abs(f(x) / f(y) - 1) for x, y in zip(a, b, strict=True)
                   for f in (lambda s: s.stretch_contact - 1, lambda s: s.height_ratio,
                             lambda s: s.pressure_ratio - 1, lambda s: s.contact_radius))

    coarse, fine = gaps(runs[1e-8], runs[1e-12]), gaps(runs[1e-10], runs[1e-12])
    assert fine < 1e-8, (coarse, fine)
    assert fine <= coarse, (coarse, fine)
    inflated = [shooting.inflate(0.3, 1e-6, rtol=rtol) for rtol in (1e-10, 1e-12)]
    assert np.isclose(inflated[0].stretch_pole - 1, inflated[1].stretch_pole - 1, rtol=1e-8, atol=0)
