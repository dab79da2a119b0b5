"""Planar synthesis, scenes and the study runner."""
import math

import numpy as np
import pytest

import soma
from conftest import repo_file

POSITIONS = [(0, 0, 0), (1.0, 0.2, 10), (1.8, 0.7, 25), (2.3, 1.5, 45), (2.5, 2.4, 70)]


def test_burmester_pairs_keep_their_circles():
    pos = [(x, y, a * math.pi / 180) for x, y, a in POSITIONS]
    r = soma.burmester(pos)
    assert len(r["pairs"]) + r["complex_count"] == 4
    for p in r["pairs"]:
        m, z = p["centre"], p["circle"]
        for x, y, a in pos:  # |M_i z − m| = radius for every position, computed here
            c, s = math.cos(a), math.sin(a)
            w = np.array([c * z[0] - s * z[1] + x, s * z[0] + c * z[1] + y])
            assert abs(np.linalg.norm(w - m) - p["radius"]) <= 1e-9 * max(1, p["radius"])
    with pytest.raises(ValueError, match="need 2 to 5 positions, got 1"):
        soma.burmester([(0, 0, 0)])


def test_scene_file_and_dict():
    r = soma.run_scene(repo_file("examples/scenes/ur5_postures.json"), only=["postures"])
    assert r["ok"] and list(r["outputs"]) == ["postures"]
    out = r["outputs"]["postures"]
    assert out["count"] == 8
    assert any(t["id"].startswith("robot:ur5") for t in r["trace"])
    assert not any("figure" in t["id"] for t in r["trace"])  # only what the asked output needs
    scene = {"entities": {"p": {"kind": "pose", "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "translation": [0, 0, 0]}},
             "outputs": {"x": {"kind": "ik", "robot": "nobody", "pose": "p"}}}
    with pytest.raises(ValueError, match="nobody"):
        soma.run_scene(scene)


def test_studies_list_and_run():
    all_ = soma.studies()
    assert len(all_) > 100 and all(s["id"] for s in all_)
    sel = soma.studies(["GF-4.4.2*"])
    assert sel and all(s["id"].startswith("GF-4.4.2") for s in sel)
    res = soma.run_studies([sel[0]["id"]])
    assert len(res) == 1 and res[0]["passed"] and res[0]["checks"]
    assert all(c["error"] <= c["tolerance"] for c in res[0]["checks"])
    with pytest.raises(ValueError):
        soma.run_studies(["NO-SUCH-STUDY"])
