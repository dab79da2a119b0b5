"""SO(3), SE(3), dual quaternions, Study parameters: identities over random inputs, independent
formulas (Rodrigues, matrix products, mpmath's expm), finite-difference Jacobians, the ladder."""
import math

import mpmath
import numpy as np
import pytest

import soma

RNG = np.random.default_rng(20261202)
EPS = np.finfo(float).eps


def rodrigues(w):
    """exp([w]x) by Rodrigues' formula, written out independently of soma."""
    th = np.linalg.norm(w)
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    if th == 0:
        return np.eye(3)
    return np.eye(3) + math.sin(th) / th * K + (1 - math.cos(th)) / th**2 * K @ K


def random_twist():
    w = RNG.normal(size=3)
    w *= RNG.uniform(0.01, 3.0) / np.linalg.norm(w)  # angle in (0, 3): log is the inverse of exp
    return np.concatenate([w, RNG.normal(size=3)])


def test_so3_exp_is_rodrigues_and_log_inverts_it():
    for _ in range(200):
        w = random_twist()[:3]
        R = soma.SO3.exp(w)
        assert np.abs(R.matrix - rodrigues(w)).max() <= 16 * EPS
        assert np.abs(R.log() - w).max() <= 64 * EPS * max(1, np.linalg.norm(w)) / (math.pi - np.linalg.norm(w))


def test_se3_exp_log_identity_over_random_inputs():
    for _ in range(200):
        xi = random_twist()
        g = soma.SE3.exp(xi)
        assert np.abs(g.log() - xi).max() <= 1e3 * EPS * np.abs(xi).max()
        h = soma.SE3.random(int(RNG.integers(1 << 62)))
        assert soma.SE3.exp(h.log()).is_approx(h, 64 * EPS * max(1, np.abs(h.translation).max()))


def test_se3_group_operations_are_matrix_operations():
    for _ in range(50):
        a, b = soma.SE3.exp(random_twist()), soma.SE3.exp(random_twist())
        p = RNG.normal(size=3)
        assert np.abs(a.compose(b).matrix - a.matrix @ b.matrix).max() <= 64 * EPS
        assert np.abs((a * b).matrix - a.matrix @ b.matrix).max() <= 64 * EPS
        assert np.abs(a.inverse().matrix - np.linalg.inv(a.matrix)).max() <= 1e3 * EPS
        assert np.abs(a.act(p) - (a.matrix[:3, :3] @ p + a.matrix[:3, 3])).max() <= 64 * EPS
        assert np.abs(a * p - a.act(p)).max() == 0


def test_adjoint_moves_twists():
    # Ad(g) ξ is the twist of g exp(ξ) g⁻¹ (the hat of Ad(g)ξ is g ξ^ g⁻¹)
    for _ in range(20):
        g, xi = soma.SE3.exp(random_twist()), random_twist()
        lhs = soma.hat6(g.adjoint() @ xi)
        rhs = g.matrix @ soma.hat6(xi) @ np.linalg.inv(g.matrix)
        assert np.abs(lhs - rhs).max() <= 1e3 * EPS * np.abs(rhs).max()


def numeric_right_jacobian(f, x, h=1e-6):
    """J with f(x + δ) ≈ f(x) ⊕ J δ on SE(3) (right perturbation), by central differences."""
    cols = []
    for i in range(6):
        d = np.zeros(6)
        d[i] = h
        cols.append((f(x - d).inverse() * f(x + d)).log() / (2 * h))
    return np.column_stack(cols)


def test_se3_jacobians_match_finite_differences():
    for _ in range(10):
        xi = random_twist()
        g, J = soma.SE3.exp(xi, jacobian=True)
        Jn = numeric_right_jacobian(soma.SE3.exp, xi)
        assert np.abs(J - Jn).max() <= 1e-7
        assert np.abs(J - soma.se3_rjac(xi)).max() == 0
        assert np.abs(soma.se3_rjac(xi) @ soma.se3_rjacinv(xi) - np.eye(6)).max() <= 1e-12
        assert np.abs(soma.se3_ljac(xi) @ soma.se3_ljacinv(xi) - np.eye(6)).max() <= 1e-12
        # act: J_q_p = R and J_q_g = R [I | -[p]x] in manif's (ω; v)-ordered convention? compare numerically
        p = RNG.normal(size=3)
        q, Jg, Jp = g.act(p, jacobians=True)
        assert np.abs(Jp - g.rotation).max() <= 16 * EPS
        Jgn = np.column_stack([(g.rplus(e * 1e-6).act(p) - g.rplus(-e * 1e-6).act(p)) / 2e-6 for e in np.eye(6)])
        assert np.abs(Jg - Jgn).max() <= 1e-7
        c, Ja, Jb = g.compose(soma.SE3.exp(random_twist()), jacobians=True)
        assert Ja.shape == (6, 6) and Jb.shape == (6, 6)
        assert np.abs(Jb - np.eye(6)).max() == 0  # J_c_b = I (right Jacobians)


def test_so3_jacobians_and_constructors():
    w = np.array([0.3, -0.4, 1.2])
    R, J = soma.SO3.exp(w, jacobian=True)
    assert np.abs(J - soma.so3_rjac(w)).max() == 0
    assert np.abs(soma.so3_ljac(w) - soma.so3_rjac(-w)).max() <= 16 * EPS
    assert np.abs(soma.so3_rjac(w) @ soma.so3_rjacinv(w) - np.eye(3)).max() <= 1e-13
    q = R.quaternion
    assert soma.SO3.from_quaternion(*q).is_approx(R, 1e-15)
    axis = w / np.linalg.norm(w)
    assert soma.SO3.from_axis_angle(axis, np.linalg.norm(w)).is_approx(R, 1e-15)
    assert soma.SO3(R.matrix).is_approx(R, 1e-15)
    assert "SO3(rotation vector" in repr(R)


def test_dual_quaternion_and_study_parameters_agree_with_the_pose():
    for _ in range(20):
        g = soma.SE3.exp(random_twist())
        h = soma.DualQuaternion(g)
        assert h.is_unit()
        assert h.to_se3().is_approx(g, 1e-13)
        p = RNG.normal(size=3)
        assert np.abs(h.act(p) - g.act(p)).max() <= 1e-13
        s = soma.StudyParameters(g)
        assert abs(s.study_condition()) <= 1e-15
        assert s.to_se3().is_approx(g, 1e-13)
        # the Study parameters are the dual quaternion's coefficients (GF §9.3)
        assert np.abs(s.coeffs - h.coeffs).max() == 0
        assert np.abs(soma.pose_from_study(s.coeffs) - g.matrix).max() <= 1e-13
        g2 = soma.SE3.exp(random_twist())
        assert (h * soma.DualQuaternion(g2)).to_se3().is_approx(g * g2, 1e-12)


def test_ladder_exp_in_mpfr_against_mpmath_expm():
    xi = [0.3, -0.2, 0.9, 1.5, -0.7, 0.25]
    with mpmath.workprec(300):
        X = mpmath.matrix([[0, -xi[2], xi[1], xi[3]], [xi[2], 0, -xi[0], xi[4]], [-xi[1], xi[0], 0, xi[5]], [0, 0, 0, 0]])
        E = mpmath.expm(X)
    G = soma.se3_exp(xi, scalar="mpfr", bits=200)
    assert G.dtype == object and isinstance(G[0, 0], mpmath.mpf)
    err = max(abs(G[i, j] - E[i, j]) for i in range(4) for j in range(4))
    assert err <= mpmath.mpf(2) ** -190
    # each rung: the double answer agrees to its own precision, the wider ones to double's
    D = soma.se3_exp(xi)
    for scalar, tol in (("float", 1e-6), ("long double", 1e-18), ("float128", 1e-32)):
        M = soma.se3_exp(xi, scalar=scalar)
        with mpmath.workprec(300):  # mpf(x) rounds to the working precision
            e = max(abs(mpmath.mpf(M[i, j]) - E[i, j]) for i in range(4) for j in range(4))
        assert e <= tol, scalar
    assert np.abs(D - soma.SE3.exp(np.array(xi)).matrix).max() == 0


def test_ladder_log_and_study_in_mpfr():
    xi = ["0.3", "-0.2", "0.9", "1.5", "-0.7", "0.25"]  # exact decimals in mpfr
    G = soma.se3_exp(xi, scalar="mpfr", bits=256)
    back = soma.se3_log(G, scalar="mpfr", bits=256)
    s = soma.study_parameters(G, scalar="mpfr", bits=256)
    dq = soma.dual_quaternion(G, scalar="mpfr")
    w = soma.so3_log(soma.so3_exp(["0.1", "0.2", "0.3"], scalar="float128"), scalar="float128")
    with mpmath.workprec(300):  # mpf("0.3") and the sums at 300 bits, not mpmath's default 53
        assert max(abs(back[i] - mpmath.mpf(xi[i])) for i in range(6)) <= mpmath.mpf(10) ** -70
        a, c = s[:4], s[4:]
        assert abs(sum(a[i] * c[i] for i in range(4))) <= mpmath.mpf(10) ** -70  # on the Study quadric
        assert max(abs(dq[i] - s[i]) for i in range(8)) <= mpmath.mpf(10) ** -70
        assert max(abs(w[i] - mpmath.mpf(x)) for i, x in enumerate(["0.1", "0.2", "0.3"])) <= 1e-32


def test_bad_input_raises_value_error_with_soma_message():
    with pytest.raises(ValueError, match="not orthogonal"):
        soma.SE3(np.diag([1.0, 2.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="det = −1"):
        soma.SO3(np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ValueError, match="NaN or infinite"):
        soma.SE3.exp(np.array([np.nan, 0, 0, 0, 0, 0]))
    with pytest.raises(ValueError, match='scalar: "quad" is not one of'):
        soma.se3_exp([0] * 6, scalar="quad")
    with pytest.raises(ValueError, match="bits: 4 is outside"):
        soma.se3_exp([0] * 6, scalar="mpfr", bits=4)
    with pytest.raises(ValueError, match=r"xi\[2\].*not a decimal number"):
        soma.se3_exp([0, 0, "x1", 0, 0, 0], scalar="mpfr")
    with pytest.raises(ValueError, match="expected 6 numbers, got 5"):
        soma.se3_exp([0] * 5, scalar="float128")
    with pytest.raises(ValueError):
        soma.pose_from_study([0, 0, 0, 0, 1, 0, 0, 0])
