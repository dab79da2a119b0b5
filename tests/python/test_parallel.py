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


def _rotation(a):
    """R(a) of a quaternion a = (w, x, y, z) with a·a = 1 (bilinear: also for complex a)."""
    w, x, y, z = a
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@pytest.mark.parametrize("name, cls, expected, real", [
    ("general", "6-6", 40, 8),      # GF §11.5.4: 40 complex
    ("dietmaier", "6-6", 40, 40),   # Dietmaier (ARK 1998): all 40 real
    ("six_three", "6-3", 16, 4),    # GF §11.5.2: a 6-3 platform has 16
])
def test_complex_solutions_satisfy_the_leg_equations(platforms, name, cls, expected, real):
    P = soma.Platform.from_file(platforms / f"{name}.json")
    r = P.solve(complex=True)
    assert r.platform_class == cls and r.expected_count == expected and r.certified
    # the fast double tracker for a general 6-6 platform, the general one for the others
    assert r.tracker == ("fast" if cls == "6-6" else "general")
    assert r.complex_count == expected == len(r.complex_solutions) == r.distinct_complex_count
    assert sum(s["real"] for s in r.complex_solutions) == r.count == real
    assert r.multiplicities == [1] * real
    eps = np.finfo(float).eps
    for s in r.complex_solutions:
        a, t = np.array(s["rotation"]), np.array(s["translation"])
        # a·a = 1 (bilinear) to rounding of the normalisation, relative to Σ|aᵢ|²
        assert abs(a @ a - 1) <= 4 * eps * np.sum(np.abs(a) ** 2)
        # every leg: (R qᵢ + t − pᵢ)·(R qᵢ + t − pᵢ) = Lᵢ² in complex arithmetic, written out here
        # (no conjugation); Newton-polished in the solve's frame, so rounding times the terms' size
        # (1 + |t|)², with the ~100 operations of the conversion: 1024 ε.
        for p, b, L in zip(P.platform, P.base, P.legs):
            u = _rotation(a) @ p + t - b
            assert abs(u @ u - L * L) <= 1024 * eps * (1 + np.abs(t).max()) ** 2
        if s["real"]:
            assert np.abs(t.imag).max() <= 1e-7 * (1 + np.abs(t).max())
    # the real complex solutions are the real postures
    for g in r.poses():
        assert min(np.abs(np.array(s["translation"]).real - g.translation).max()
                   for s in r.complex_solutions if s["real"]) <= 1e-9


def test_a_double_root_is_one_posture_of_multiplicity_two(platforms):
    # boundary.json: leg lengths of a posture on the boundary of the assembly space (two real
    # postures merged): 39 distinct complex solutions, one of multiplicity 2, 40 with it.
    r = soma.Platform.from_file(platforms / "boundary.json").solve(complex=True)
    assert r.complex_count == 40 and r.distinct_complex_count == 39 and r.certified
    assert sorted(r.multiplicities) == [1] * (r.count - 1) + [2]
    assert sum(s["multiplicity"] for s in r.complex_solutions) == 40


def test_complex_solutions_in_float128_carry_its_digits(platforms):
    r = soma.Platform.from_file(platforms / "six_three.json").solve(scalar="float128", complex=True)
    import mpmath
    z = r.complex_solutions[0]["translation"][0]
    # the parts keep float128's 113 bits (a double would have ≤ 53 in its mantissa)
    assert isinstance(z, mpmath.mpc) and mpmath.libmp.bitcount(z.real._mpf_[1]) > 53
    with pytest.raises(ValueError, match="only the homotopy finds the complex solutions"):
        soma.Platform.from_file(platforms / "general.json").solve(method="ceres", complex=True)
