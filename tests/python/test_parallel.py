"""Stewart platforms: the 40 complex solutions, each real posture's leg lengths equal to the
platform's, the numerical methods agreeing, bad input."""
import json

import numpy as np
import pytest

import soma


def test_general_platform_forty_solutions(platforms):
    P = soma.Platform.from_file(platforms / "general.json")
    r = P.solve()
    assert r.complex_count == 40 and r.expected_count == 40 and r.certified and r.count == 8
    for g in r.poses():
        assert np.abs(P.leg_lengths(g) - P.legs).max() <= 1e-9
        # leg lengths written out here: |R p_i + t − b_i|
        L = [np.linalg.norm(g.rotation @ p + g.translation - b) for p, b in zip(P.platform, P.base)]
        assert np.abs(np.array(L) - P.legs).max() <= 1e-9
    assert "StewartResult(8 real postures, 40 of 40 complex solutions" in repr(r)
    # the numerical search finds the same real postures
    c = P.solve(method="ceres")
    assert not c.certified and c.count == 8
    for g in c.poses():
        assert min(np.abs(g.matrix - h.matrix).max() for h in r.poses()) <= 1e-7


def test_platform_from_arrays_and_float128_leg_lengths(platforms):
    d = json.loads((platforms / "general.json").read_text())
    P = soma.Platform(d["base"], d["platform"], d["leg_lengths"])
    Q = soma.Platform.from_dict(d)
    assert np.array_equal(P.legs, Q.legs) and np.array_equal(P.base, Q.base)
    g = soma.SE3.exp(np.array([0.1, 0.2, -0.1, 0.05, 0.0, 1.0]))
    L = P.leg_lengths(g, scalar="float128")
    assert max(abs(float(L[i]) - P.leg_lengths(g)[i]) for i in range(6)) <= 1e-14


def test_bad_platforms(platforms):
    with pytest.raises(ValueError, match="malformed_five_legs"):
        soma.Platform.from_file(platforms / "malformed_five_legs.json")
    with pytest.raises(ValueError, match="leg length 3 is negative"):
        soma.Platform.from_file(platforms / "malformed_negative_leg.json").solve()
    with pytest.raises(ValueError, match='method "simplex" is not one of'):
        soma.Platform.from_file(platforms / "general.json").solve(method="simplex")
