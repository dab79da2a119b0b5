"""Plücker lines, linear complexes and screw systems against independent formulas."""
import numpy as np
import pytest

import soma

RNG = np.random.default_rng(7)


def test_line_distance_and_angle_are_the_textbook_formulas():
    for _ in range(50):
        p1, q1, p2, q2 = (RNG.normal(size=3) for _ in range(4))
        a, b = soma.PluckerLine.through_points(p1, q1), soma.PluckerLine.through_points(p2, q2)
        d1, d2 = q1 - p1, q2 - p2
        n = np.cross(d1, d2)
        assert abs(a.distance(b) - abs(np.dot(p2 - p1, n)) / np.linalg.norm(n)) <= 1e-12
        cos = abs(np.dot(d1, d2)) / (np.linalg.norm(d1) * np.linalg.norm(d2))
        assert abs(abs(np.cos(a.angle(b))) - cos) <= 1e-12
        assert abs(np.dot(a.direction, a.moment)) <= 1e-12 * np.linalg.norm(a.direction) * np.linalg.norm(a.moment)
        assert np.linalg.norm(np.cross(a.foot - p1, d1)) <= 1e-12 * (1 + np.linalg.norm(p1)) * np.linalg.norm(d1)


def test_lines_of_a_complex_are_in_it():
    c = soma.LinearComplex(np.array([0.2, -0.5, 1.0, 0.3, 0.4, -0.1]))
    s = c.screw
    pitch = np.dot(s[:3], s[3:]) / np.dot(s[:3], s[:3])
    assert abs(c.pitch - pitch) <= 1e-15
    for t in np.linspace(0, 3, 7):
        line = c.line_through(RNG.normal(size=3), t)
        assert c.contains(line)
        # reciprocal product ω·b + v·α = 0
        assert abs(np.dot(line.direction, s[3:]) + np.dot(line.moment, s[:3])) <= 1e-12
    assert "LinearComplex(pitch" in repr(c)


def test_identify_screw_systems():
    line = np.array([[0, 0, 1, 0, 0, 0]], dtype=float).T           # a zero-pitch screw: a 1-system line
    r = soma.identify_screw_system(line)
    assert r["dimension"] == 1
    both = np.array([[0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 1]], dtype=float).T  # rotation + translation along z
    r2 = soma.identify_screw_system(both)
    assert r2["dimension"] == 2 and isinstance(r2["name"], str) and r2["name"]
    with pytest.raises(ValueError, match="6 x k"):
        soma.identify_screw_system(np.zeros((5, 2)))


def test_bad_lines():
    with pytest.raises(ValueError, match="coincide"):
        soma.PluckerLine.through_points(np.zeros(3), np.zeros(3))
    with pytest.raises(ValueError, match="PluckerLine"):
        soma.PluckerLine(np.array([1.0, 0, 0]), np.array([1.0, 0, 0]))
