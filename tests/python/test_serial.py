"""Robots from files, URDF, DH and POE tables; fk, Jacobians, ik by every method and scalar (each
posture's fk reproduces the pose), dynamics identities, bad input."""
import json
import math

import mpmath
import numpy as np
import pytest

import soma

DEG = math.pi / 180


def pose_error(g, target):
    """max(|R − R*|_F, |t − t*|): the distance of two poses, computed here (not by soma)."""
    G, T = np.asarray(g, dtype=float), np.asarray(target, dtype=float)
    return max(np.linalg.norm(G[:3, :3] - T[:3, :3]), np.linalg.norm(G[:3, 3] - T[:3, 3]))


def load_pose(path):
    d = json.loads(path.read_text())
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = d["rotation"], d["translation"]
    return m


def test_puma_all_methods_reproduce_the_pose(robots):
    puma = soma.Robot.from_file(robots / "puma560.json")
    assert puma.dof == 6 and puma.degrees and puma.convention == "dh" and puma.ik_class() == "pieper"
    target = load_pose(robots / "puma560_pose.json")
    r = soma.Robot.from_file(robots / "puma560_nolimits.json").ik(target)  # all 8 (the limits drop 6)
    assert r.count == 8 and r.certified and r.expected_count == 8 and r.method == "pieper"
    assert "IkResult(8 postures of 8 expected, method pieper" in repr(r)
    q0 = np.array([10, -60, 80, 20, 30, 40]) * DEG
    g0 = puma.fk(q0)
    for method in ("auto", "pieper", "general6r", "ceres", "nlopt"):
        for pose in (target, g0):
            r = puma.ik(pose, method=method)
            assert r.count >= 1, method
            assert r.postures.shape == (r.count, 6)
            for q in r.postures:
                assert pose_error(puma.fk(q).matrix, np.asarray(pose.matrix if isinstance(pose, soma.SE3) else pose)) <= 1e-8, method
        if method in ("auto", "pieper"):  # the closed form finds q0 among the postures of its pose
            assert min(np.abs(np.angle(np.exp(1j * (r.postures - q0)))).max(axis=1)) <= 1e-9


def test_manseur_doty_has_the_classical_sixteen(robots):
    arm = soma.Robot.from_file(robots / "manseur_doty.json")
    target = load_pose(robots / "manseur_doty_pose.json")
    r = arm.ik(target, method="general6r")
    assert r.count == 16 and r.expected_count == 16
    for q in r.postures:
        assert pose_error(arm.fk(q).matrix, target) <= 1e-8
    # sixteen different postures
    d = [np.abs(np.angle(np.exp(1j * (a - b)))).max() for i, a in enumerate(r.postures) for b in r.postures[i + 1:]]
    assert min(d) > 1e-4


def test_general_6r_in_mpfr_reproduces_the_pose_to_mpfr_precision(robots):
    arm = soma.Robot.from_file(robots / "general6r.json")
    target = load_pose(robots / "general6r_pose.json")
    rd = arm.ik(target, method="general6r")
    assert rd.count == 10 and rd.expected_count == 16
    # an exactly orthogonal rotation in decimals (Pythagorean triples): the pose is the same in every
    # scalar, so fk of each mpfr posture must reproduce it to mpfr's precision
    R = [["0.6", "-0.224", "0.768"], ["0.8", "0.168", "-0.576"], ["0", "0.96", "0.28"]]
    t = ["0.3", "-0.2", "0.4"]
    exact = {"rotation": R, "translation": t}
    r = arm.ik(exact, method="general6r", scalar="mpfr", bits=128)
    assert r.count >= 2 and r.count % 2 == 0 and r.scalar == "mpfr"
    assert r.postures.dtype == object and isinstance(r.postures[0, 0], mpmath.mpf)
    with mpmath.workprec(256):
        for q in r.postures:
            G = arm.fk(list(q), scalar="mpfr", bits=128)
            err = max([abs(G[i, j] - mpmath.mpf(R[i][j])) for i in range(3) for j in range(3)]
                      + [abs(G[i, 3] - mpmath.mpf(t[i])) for i in range(3)])
            assert err <= mpmath.mpf(2) ** -100
    assert arm.ik(exact, method="general6r").count == r.count
    for scalar in ("float", "long double", "float128"):
        rs = arm.ik(target, method="general6r", scalar=scalar)
        assert rs.count == 10, scalar
        for q in rs.postures:
            assert pose_error(arm.fk(np.array(q, dtype=float)).matrix, target) <= (1e-3 if scalar == "float" else 1e-9)


def test_dh_table_as_python_data_is_the_file_robot(robots):
    doc = json.loads((robots / "puma560.json").read_text())
    rows = [(j["a"], j["alpha"], j["d"], j["theta"]) for j in doc["joints"]]
    arm = soma.Robot.dh(rows, angles="degrees", name="PUMA from rows", limits=[j["limits"] for j in doc["joints"]])
    ref = soma.Robot.from_file(robots / "puma560.json")
    q = np.array([0.1, -0.7, 0.4, 0.2, -0.3, 0.5])
    assert arm.fk(q).is_approx(ref.fk(q), 0.0)
    assert np.array_equal(arm.limits, ref.limits)
    assert soma.Robot.from_dict(doc).fk(q).is_approx(ref.fk(q), 0.0)
    assert "PUMA from rows" in repr(arm) and "6 joints RRRRRR" in repr(arm)


def test_poe_table_planar_3r_against_closed_form():
    home = np.eye(4)
    home[0, 3] = 3.0
    arm = soma.Robot.poe([((0, 0, 1), (0, 0, 0)), ((0, 0, 1), (1, 0, 0)), ((0, 0, 1), (2, 0, 0))], home)
    assert arm.convention == "poe" and arm.dof == 3
    rng = np.random.default_rng(3)
    for _ in range(20):
        q = rng.uniform(-3, 3, 3)
        a1, a2, a3 = q[0], q[0] + q[1], q[0] + q[1] + q[2]
        t = [math.cos(a1) + math.cos(a2) + math.cos(a3), math.sin(a1) + math.sin(a2) + math.sin(a3), 0]
        g = arm.fk(q)
        assert np.abs(g.translation - t).max() <= 1e-14
        assert abs(g.so3.log()[2] - math.atan2(math.sin(a3), math.cos(a3))) <= 1e-14


def test_urdf_robot(robots):
    arm = soma.Robot.from_file(robots / "puma560_nolimits.urdf")
    assert arm.dof == 6
    q0 = np.array([0.2, -0.9, 1.1, 0.3, 0.5, -0.4])
    target = arm.fk(q0)
    r = arm.ik(target)
    assert r.count == 8
    for q in r.postures:
        assert pose_error(arm.fk(q).matrix, target.matrix) <= 1e-8
    same = soma.Robot.from_urdf((robots / "puma560_nolimits.urdf").read_text())
    assert same.fk(q0).is_approx(target, 0.0)


def test_jacobian_is_the_derivative_of_fk(robots):
    arm = soma.Robot.from_file(robots / "general6r.json")
    q = np.array([0.3, -0.2, 0.5, 1.0, -0.7, 0.4])
    J = arm.jacobian(q)  # spatial: column i is the twist of joint i in the base frame
    h = 1e-6
    for i in range(6):
        e = np.zeros(6)
        e[i] = h
        col = (arm.fk(q + e) * arm.fk(q - e).inverse()).log() / (2 * h)
        assert np.abs(col - J[:, i]).max() <= 1e-8
    Jb = arm.jacobian(q, frame="body")
    assert np.abs(arm.fk(q).adjoint() @ Jb - J).max() <= 1e-12
    s = arm.singularity(q)
    # the measures of the spatial Jacobian with its linear rows divided by the length scale (numpy's SVD)
    sv = np.linalg.svd(np.vstack([J[:3], J[3:] / arm.length_scale]), compute_uv=False)
    assert abs(s["manipulability"] - sv.prod()) <= 1e-12 and abs(s["condition"] - sv[0] / sv[-1]) <= 1e-9
    assert len(arm.frames(q)) == 7  # F_0 .. F_6 (DH frames)


def test_dynamics_identities(robots):
    arm = soma.Robot.from_file(robots / "puma560_dynamics.json")
    dyn = arm.dynamics()
    rng = np.random.default_rng(11)
    th, thd, thdd = rng.uniform(-1, 1, 6), rng.uniform(-1, 1, 6), rng.uniform(-1, 1, 6)
    A = dyn.mass_matrix(th)
    assert np.abs(A - A.T).max() <= 1e-12 and np.linalg.eigvalsh(A).min() > 0
    tau = dyn.inverse_dynamics(th, thd, thdd)
    assert np.abs(tau - dyn.inverse_dynamics_closed_form(th, thd, thdd)).max() <= 1e-10  # two methods
    assert np.abs(dyn.forward_dynamics(th, thd, tau) - thdd).max() <= 1e-9
    assert abs(dyn.kinetic_energy(th, thd) - 0.5 * thd @ A @ thd) <= 1e-12
    # gravity torque = ∂E_P/∂θ (central differences)
    g = dyn.gravity_torque(th)
    for i in range(6):
        e = np.zeros(6)
        e[i] = 1e-6
        d = (dyn.potential_energy(th + e) - dyn.potential_energy(th - e)) / 2e-6
        assert abs(d - g[i]) <= 1e-6
    with pytest.raises(ValueError, match='no "links"'):
        soma.Robot.from_file(robots / "puma560.json").dynamics()


def test_cuspidality_and_cusp_map(robots):
    wenger = soma.Robot.from_file(robots / "cusp3r_orthogonal_wenger.json")
    a = wenger.cuspidality(witness=False, aspect_grid=64)
    assert a["cuspidal"] and a["cusp_count"] == 4 and a["cusps"].shape == (4, 2)
    assert not soma.Robot.from_file(robots / "cusp3r_puma_arm.json").cuspidality(witness=False, aspect_grid=64)["cuspidal"]
    m = wenger.cusp_map("a3:0.5:2.5:5", "d2:0:1.5:4", threads=1)
    assert m["counts"].shape == (4, 5) and sum(m["histogram"]) == 20
    # the cell of the file's own arm (a3 = 1.5, d2 = 1) has its 4 cusps
    i, j = list(m["x"]).index(1.5), list(m["y"]).index(1.0)
    assert m["counts"][j, i] == 4


def test_workspace_map(robots):
    arm = soma.Robot.from_file(robots / "cusp3r_orthogonal_wenger.json")
    w = arm.workspace(samples=5000, grid=30)
    assert w["hits"].shape == (30, 30) and w["hits"].sum() == 5000
    assert 0 < w["reached_fraction"] <= 1
    d = w["dexterity"]
    assert ((d == -1) == (w["hits"] == 0)).all() and d.max() <= 1


def test_bad_robot_input(robots, tmp_path):
    doc = {"name": "bad", "angles": "radians", "convention": "dh",
           "joints": [{"type": "R", "a": "abc", "alpha": 0, "d": 0, "theta": 0}]}
    with pytest.raises(ValueError, match=r"<python dict>.*joints\[0\]\.a"):
        soma.Robot.from_dict(doc)
    with pytest.raises(ValueError, match="unknown key|not a known key|tip_link|colour"):
        soma.Robot.from_dict({**doc, "colour": "red", "joints": [{"type": "R", "a": 0, "alpha": 0, "d": 0, "theta": 0}]})
    with pytest.raises(ValueError, match="cannot read"):
        soma.Robot.from_file(tmp_path / "missing.json")
    puma = soma.Robot.from_file(robots / "puma560.json")
    with pytest.raises(ValueError, match='method "simplex" is not one of'):
        puma.ik(soma.SE3(), method="simplex")
    with pytest.raises(ValueError, match="5 joint values"):
        puma.fk(np.zeros(5))
    with pytest.raises(ValueError, match='scalar: "quad"'):
        puma.ik(soma.SE3(), scalar="quad")
    with pytest.raises(ValueError, match="not orthogonal"):
        puma.ik(np.diag([1.0, 2.0, 1.0, 1.0]))
    with pytest.raises(ValueError):
        soma.Robot.from_file(robots / "cusp_bad_4r.json").cuspidality()
    with pytest.raises(ValueError):
        soma.Robot.from_file(robots / "arm3r.json").ik(soma.SE3(), method="general6r")


def test_degenerate_robot_answers_its_self_motion_and_unreachable_says_why(robots):
    """Every axis through the origin: rank 3, a 3-dimensional self-motion at every reachable pose
    (each representative's fk checked here); a shifted pose is out of reach (issue 20 item 2)."""
    robot = soma.Robot.from_file(robots / "concurrent6r.json")
    home = np.eye(4)
    r = robot.ik(home, method="general6r")
    assert r.method == "self-motion" and r.continuum and r.self_motion_dimension == 3 and r.generic_rank == 3
    assert r.expected_count == 0 and r.count >= 1 and r.reason == ""
    for q in np.asarray(r.postures, dtype=float):
        assert pose_error(robot.fk(q).matrix, home) < 1e-12
    shifted = np.eye(4)
    shifted[:3, 3] = [0.5, 0, 0]
    u = robot.ik(shifted)
    assert u.count == 0 and not u.continuum and u.reason.startswith("out of reach")
    far = np.eye(4)
    far[:3, 3] = [10, 0, 0]
    p = soma.Robot.from_file(robots / "puma560.json").ik(far)
    assert p.count == 0 and p.reason.startswith("out of reach") and p.generic_rank == 6
