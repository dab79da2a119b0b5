"""soma: the geometry of robot kinematics, from Python.

The C++ library's entry points (never its command line) with numpy arrays in and out:

* Lie groups: ``SO3``, ``SE3`` (exp, log, compose, act, inverse, adjoint, with manif's
  ``J_out_in`` right Jacobians on ``jacobian(s)=True``), ``so3_rjac`` ... ``se3_ljacinv``;
  ``DualQuaternion``, ``StudyParameters``; the same maps on the scalar ladder:
  ``se3_exp``, ``se3_log``, ``so3_exp``, ``so3_log``, ``dual_quaternion``, ``study_parameters``,
  ``pose_from_study`` with ``scalar=`` and ``bits=``.
* Lines and screws: ``PluckerLine``, ``LinearComplex``, ``identify_screw_system``.
* Serial robots: ``Robot.from_file`` (robot JSON or URDF), ``Robot.from_urdf``,
  ``Robot.from_dict`` (a robot JSON document as Python data), ``Robot.dh`` and ``Robot.poe``
  (a table); ``fk``, ``jacobian``, ``ik`` (every posture, every method, any scalar),
  ``dynamics``, ``cuspidality``, ``cusp_map``, ``workspace``.
* Parallel robots: ``Platform`` and ``Platform.solve`` (all 40 complex solutions by homotopy).
* Planar synthesis: ``burmester``.
* ``run_scene`` (a scene file or dict), ``studies`` and ``run_studies`` (the book's studies).

Scalars: ``scalar="double"`` (default), ``"float"``, ``"long double"``, ``"float128"``,
``"mpfr"`` (with ``bits=``, default 256). Results in double and float are floats / float64
arrays; in long double, float128 and mpfr they are ``mpmath.mpf`` numbers (object arrays) that
carry every digit of the scalar. Bad input raises ``ValueError`` with soma's message (which names
the input and the defect).
"""
import json as _json
import os as _os
from dataclasses import dataclass, field
from typing import List

import numpy as _np

from . import _soma
from ._soma import (SO3, SE3, DualQuaternion, StudyParameters, PluckerLine, LinearComplex, Dynamics,  # noqa: F401
                    identify_screw_system, burmester, so3_rjac, so3_ljac, so3_rjacinv, so3_ljacinv, hat3,
                    se3_rjac, se3_ljac, se3_rjacinv, se3_ljacinv, se3_ad, hat6, ik_methods, stewart_methods,
                    scalars, mpfr_bits)

__all__ = [
    "SO3", "SE3", "DualQuaternion", "StudyParameters", "PluckerLine", "LinearComplex", "Dynamics", "Robot",
    "Platform", "IkResult", "StewartResult", "identify_screw_system", "burmester", "so3_rjac", "so3_ljac",
    "so3_rjacinv", "so3_ljacinv", "hat3", "se3_rjac", "se3_ljac", "se3_rjacinv", "se3_ljacinv", "se3_ad", "hat6",
    "se3_exp", "se3_log", "so3_exp", "so3_log", "dual_quaternion", "study_parameters", "pose_from_study",
    "ik_methods", "stewart_methods", "scalars", "mpfr_bits", "run_scene", "studies", "run_studies", "LADDER",
]

#: The scalar ladder, cheapest first (the names ``scalar=`` takes).
LADDER = ("float", "double", "long double", "float128", "mpfr")


# ---------------------------------------------------------------- numbers and poses as JSON
def _num(x):
    """A number for a JSON document soma reads: floats and ints as JSON numbers, anything wider
    (mpmath.mpf, numpy longdouble, decimal str) as a decimal string (io's number reader reads it
    exactly in the working scalar)."""
    if isinstance(x, bool):
        return x  # soma's reader names the defect
    if isinstance(x, (int, _np.integer)):
        return int(x)
    if isinstance(x, (float, _np.float64, _np.float32)):
        return float(x)
    if isinstance(x, str):
        return x
    from ._numbers import text
    return text(x, "number")


def _nums(a):
    if isinstance(a, (list, tuple, _np.ndarray)):
        return [_nums(x) for x in a]
    return _num(a)


def _pose_doc(pose):
    """{"rotation": 3x3, "translation": 3} from an SE3, a 4x4 array (any numbers) or such a dict."""
    if isinstance(pose, SE3):
        m = pose.matrix
        return {"rotation": m[:3, :3].tolist(), "translation": m[:3, 3].tolist()}
    if isinstance(pose, dict):
        return {k: _nums(v) if k in ("rotation", "translation") else v for k, v in pose.items()}
    a = _np.asarray(pose, dtype=object)
    if a.shape == (3, 3):
        return {"rotation": _nums(a.tolist()), "translation": [0, 0, 0]}
    if a.shape != (4, 4):
        raise ValueError(f"pose: expected an SE3, a 4x4 matrix or a dict with rotation and translation, got shape {a.shape}")
    return {"rotation": _nums(a[:3, :3].tolist()), "translation": _nums(a[:3, 3].tolist())}


def _pose_json(pose):
    return _json.dumps(_pose_doc(pose))


# ---------------------------------------------------------------- the ladder for the algebra
def se3_exp(xi, scalar="double", bits=256):
    """exp of the twist xi = (ω; v) as a 4x4 matrix in `scalar` (mpmath numbers beyond double)."""
    return _soma._se3_exp(xi, scalar, bits)


def se3_log(pose, scalar="double", bits=256):
    """The twist (ω; v) of a pose (SE3, 4x4 matrix, or dict; numbers may be str or mpf) in `scalar`."""
    return _soma._se3_log(_pose_json(pose), scalar, bits)


def so3_exp(w, scalar="double", bits=256):
    """exp of the rotation vector w as a 3x3 matrix in `scalar`."""
    return _soma._so3_exp(w, scalar, bits)


def so3_log(rotation, scalar="double", bits=256):
    """The rotation vector of a rotation (SO3, 3x3 or a pose) in `scalar`."""
    if isinstance(rotation, SO3):
        rotation = rotation.matrix
    return _soma._so3_log(_pose_json(rotation), scalar, bits)


def dual_quaternion(pose, scalar="double", bits=256):
    """The unit dual quaternion (a0..a3, c0..c3) of a pose, in `scalar` (GF §9.3)."""
    return _soma._dual_quaternion(_pose_json(pose), scalar, bits)


def study_parameters(pose, scalar="double", bits=256):
    """The Study parameters (a : ½ t a) of a pose, in `scalar` (GF §9.3)."""
    return _soma._study_parameters(_pose_json(pose), scalar, bits)


def pose_from_study(coordinates, scalar="double", bits=256):
    """The 4x4 matrix of a point of the Study quadric (checked: ValueError if not a rigid motion)."""
    return _soma._pose_from_study(coordinates, scalar, bits)


# ---------------------------------------------------------------- results
def _short(x):
    try:
        return f"{float(x):.3g}"
    except (TypeError, ValueError):
        return str(x)


@dataclass
class IkResult:
    """Every real posture for a pose (solveIk): each with its residual, and what the answer cost.

    ``postures`` is a (count, dof) array (float64; object array of mpmath.mpf beyond double),
    radians for revolute joints. ``certified`` is True when the method proves the list complete
    (the closed forms; the eigenproblem with 16 complex solutions)."""
    postures: object
    residuals: object
    seconds: float
    method: str
    scalar: str
    expected_count: int
    certified: bool
    continuum: bool
    complex_count: int
    solved_in: str
    notes: List[str] = field(default_factory=list)
    #: why there is no posture ("out of reach: …", "joint limits: …"); empty when there is one
    reason: str = ""
    #: a 6R whose joint screws span fewer than 6 dimensions everywhere: its self-motion's dimension
    #: (postures are then representatives, ``continuum`` is True, ``expected_count`` 0)
    self_motion_dimension: int = 0
    #: 6R robots: the generic Jacobian rank (6 unless degenerate); -1 otherwise
    generic_rank: int = -1
    #: general6r: the joint eliminated last ("theta3 last", …)
    elimination: str = ""

    @property
    def count(self):
        return len(self.residuals)

    def worst_residual(self):
        return max(self.residuals) if self.count else 0.0

    def __len__(self):
        return self.count

    def __repr__(self):
        cert = "certified" if self.certified else "not certified"
        s = (f"IkResult({self.count} postures of {self.expected_count} expected, method {self.method}, "
             f"scalar {self.scalar}" + (f" (solved in {self.solved_in})" if self.solved_in and self.solved_in != self.scalar.replace(' ', '-') else "")
             + f", {cert}, worst residual {_short(self.worst_residual())}, {self.seconds:.3g} s"
             + (", a continuum: representatives" if self.continuum else "") + ")")
        return s


@dataclass
class StewartResult:
    """Every real posture of a Stewart platform for its leg lengths (solveStewart).

    ``postures`` is a list of 4x4 matrices (float64, or object arrays of mpmath.mpf);
    ``poses()`` gives them as SE3 (double). ``complex_count`` is the number of complex solutions
    the homotopy found, counted with multiplicity (-1 for the numerical methods), and
    ``expected_count`` the count of the platform's class (``platform_class``, e.g. "6-6", "6-3";
    ``pattern`` its leg–joint incidence; ``tracker`` "fast" or "general", the homotopy's path
    tracker); ``multiplicities`` gives each real posture's (2 for a
    double root on the boundary of the assembly space). With ``solve(complex=True)``,
    ``complex_solutions`` lists every complex solution as a dict: ``translation`` (3 complex),
    ``rotation`` (the quaternion, 4 complex, a·a = 1), ``real`` and ``multiplicity`` (complex for
    float and double, mpmath.mpc for the other scalars)."""
    postures: list
    residuals: list
    seconds: float
    start_seconds: float
    method: str
    scalar: str
    expected_count: int
    complex_count: int
    certified: bool
    paths_tracked: int
    paths_failed: int
    notes: List[str] = field(default_factory=list)
    distinct_complex_count: int = -1
    multiplicities: list = field(default_factory=list)
    platform_class: str = ""
    pattern: str = ""
    tracker: str = ""
    complex_solutions: list = field(default_factory=list)

    @property
    def count(self):
        return len(self.residuals)

    def __len__(self):
        return self.count

    def poses(self):
        """The postures as SE3 (in double)."""
        return [SE3(_np.array(p, dtype=float)) for p in self.postures]

    def __repr__(self):
        worst = max(self.residuals) if self.residuals else 0.0
        cplx = f"{self.complex_count} of {self.expected_count} complex solutions, " if self.complex_count >= 0 else ""
        return (f"StewartResult({self.count} real postures, {cplx}method {self.method}, scalar {self.scalar}, "
                f"{'certified' if self.certified else 'not certified'}, worst residual {_short(worst)}, "
                f"{self.seconds:.3g} s)")


def _postures_array(postures):
    if not postures:
        return _np.zeros((0, 0))
    if isinstance(postures[0], _np.ndarray) and postures[0].dtype != object:
        return _np.vstack(postures)
    return _np.array([list(p) for p in postures], dtype=object)


# ---------------------------------------------------------------- serial robots
class Robot:
    """A serial robot (GF ch. 4): from a robot JSON file or URDF, or a DH / POE table given as data.

    Joint values are in radians (metres for prismatic joints) whatever unit the file wrote its
    angles in (``degrees`` says which). The robot's file text is kept, so ``fk`` and ``ik`` in a
    wider scalar read it again in that scalar (decimal strings exact)."""

    def __init__(self, handle):
        self._h = handle

    # construction
    @classmethod
    def from_file(cls, path, tip=""):
        """A robot JSON file (DESIGN §6) or a URDF (``.urdf``; `tip` names the chain's tip link)."""
        path = _os.fspath(path)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise ValueError(f"{path}: cannot read ({e.strerror})") from None
        if path.endswith(".urdf") or text.lstrip().startswith("<"):
            return cls(_soma.Robot._from_urdf(text, path, tip))
        return cls(_soma.Robot._from_json(text, path))

    @classmethod
    def from_urdf(cls, xml, tip="", origin="<urdf string>"):
        """A serial chain of a URDF document (the XML text)."""
        return cls(_soma.Robot._from_urdf(xml, origin, tip))

    @classmethod
    def from_dict(cls, doc, origin="<python dict>"):
        """A robot JSON document as Python data: {"name", "angles", "convention", "joints", ...}."""
        if not isinstance(doc, dict):
            raise ValueError(f"{origin}: a robot document is a dict, got {type(doc).__name__}")
        return cls(_soma.Robot._from_json(_json.dumps(_nums_doc(doc)), origin))

    @classmethod
    def from_json(cls, text, origin="<json string>"):
        return cls(_soma.Robot._from_json(text, origin))

    @classmethod
    def dh(cls, rows, angles="radians", name="DH robot", modified=False, limits=None, **extra):
        """From a DH table: rows (a, alpha, d, theta) or dicts {"type", "a", "alpha", "d", "theta"}
        (standard DH, or modified with modified=True); `limits` a list of (lo, hi) per joint."""
        joints = []
        for i, r in enumerate(rows):
            if isinstance(r, dict):
                j = dict(r)
                j.setdefault("type", "R")
            else:
                r = list(r)
                if len(r) != 4:
                    raise ValueError(f"dh: row {i} needs (a, alpha, d, theta), got {len(r)} values")
                j = {"type": "R", "a": r[0], "alpha": r[1], "d": r[2], "theta": r[3]}
            if limits is not None:
                j["limits"] = list(limits[i])
            joints.append(j)
        doc = {"name": name, "angles": angles, "convention": "mdh" if modified else "dh", "joints": joints}
        doc.update(extra)
        return cls.from_dict(doc, origin=f"<{name}>")

    @classmethod
    def poe(cls, joints, home, angles="radians", name="POE robot", **extra):
        """From a product-of-exponentials table: joints [{"type", "axis", "point", ...}] or (axis, point)
        pairs (revolute), and the tool's home pose (SE3, 4x4 or dict)."""
        js = []
        for j in joints:
            if isinstance(j, dict):
                js.append(dict(j))
            else:
                axis, point = j
                js.append({"type": "R", "axis": list(axis), "point": list(point)})
        doc = {"name": name, "angles": angles, "convention": "poe", "joints": js, "home": _pose_doc(home)}
        doc.update(extra)
        return cls.from_dict(doc, origin=f"<{name}>")

    # properties
    name = property(lambda self: self._h.name)
    dof = property(lambda self: self._h.dof)
    convention = property(lambda self: self._h.convention)
    degrees = property(lambda self: self._h.degrees)
    limits = property(lambda self: self._h.limits, doc="dof x 2 (radians / metres; ±inf when unlimited)")
    joint_types = property(lambda self: self._h.joint_types)
    length_scale = property(lambda self: self._h.length_scale)
    origin = property(lambda self: self._h.origin)

    # kinematics
    def fk(self, q, scalar="double", bits=256):
        """The tool pose at joints q: an SE3 in double, a 4x4 matrix (mpmath numbers) in another scalar."""
        if scalar == "double":
            return self._h.fk(_np.asarray(q, dtype=float))
        return self._h._fk(q, scalar, bits)

    def frames(self, q):
        """Base, every link frame and the tool at q (SE3 each)."""
        return self._h.frames(_np.asarray(q, dtype=float))

    def jacobian(self, q, frame="spatial"):
        """The 6 x n Jacobian ("spatial" or "body"), columns the joint twists (ω; v)."""
        return self._h.jacobian(_np.asarray(q, dtype=float), frame)

    def singularity(self, q):
        """Manipulability, smallest and largest singular value, condition number at q."""
        return self._h.singularity(_np.asarray(q, dtype=float))

    def within_limits(self, q):
        return self._h.within_limits(_np.asarray(q, dtype=float))

    def ik_class(self):
        """The method ``method="auto"`` picks: wrist3r, arm3r, pieper or general6r."""
        return self._h.ik_class()

    def ik(self, pose, method="auto", scalar="double", bits=256, complete=True, starts=128):
        """Every real posture reaching `pose` (SE3, 4x4 matrix or dict; numbers may be decimal str or
        mpf), by `method` (``ik_methods()``) in `scalar`. general6r completes a possibly short answer
        with `starts` numerical starts unless complete=False."""
        d = self._h._ik(_pose_json(pose), method, scalar, bits, complete, starts)
        d["postures"] = _postures_array(d["postures"])
        return IkResult(**d)

    # dynamics and analyses
    def dynamics(self, gravity=9.81):
        """The dynamics model of GF ch. 13 from the file's "links" (mass, com, inertia): a Dynamics
        object in the dynamics variable θ = q + offset (``offsets``)."""
        return self._h._dynamics(gravity)

    @property
    def offsets(self):
        return self._h._offsets()

    def cuspidality(self, witness=True, aspect_grid=256, poses=4, seconds_per_pair=0.5):
        """Is the robot cuspidal (analyseCuspidality, GF §5.2.3)? 3R arms: the cusp points (ρ, z),
        the singular curves' images, aspects and a witness path; 6R: a witness search."""
        return _soma._cuspidality(self._h, witness, aspect_grid, poses, seconds_per_pair)

    def cusp_map(self, x, y, threads=0):
        """Cusp counts of the 3R arms obtained by varying two DH lengths, each axis "name:min:max:n"
        (e.g. "a3:0:3:40", "d2:0:2:40"); counts[j, i] is the arm at (x[i], y[j])."""
        return _soma._cusp_map(self._h, x, y, threads)

    def workspace(self, samples=200000, grid=120, start=None, goal=None, margin=0.05, seconds=2.0):
        """Workspace maps over (ρ, z): hits and the best dexterity σ_min/σ_max per cell (nZ x nRho,
        -1 where nothing fell), the boundary (3R), and a singularity-free plan when start and goal
        are given (analyseWorkspace)."""
        s = None if start is None else _np.asarray(start, dtype=float)
        g = None if goal is None else _np.asarray(goal, dtype=float)
        return _soma._workspace(self._h, samples, grid, s, g, margin, seconds)

    def __repr__(self):
        return repr(self._h)


def _nums_doc(doc):
    """A JSON document with every number turned into what soma's reader takes (mpf → decimal str)."""
    if isinstance(doc, dict):
        return {k: _nums_doc(v) for k, v in doc.items()}
    if isinstance(doc, (list, tuple)):
        return [_nums_doc(v) for v in doc]
    if isinstance(doc, _np.ndarray):
        return [_nums_doc(v) for v in doc.tolist()]
    if doc is None or isinstance(doc, (str, bool)):
        return doc
    if isinstance(doc, SE3):
        return _pose_doc(doc)
    return _num(doc)


# ---------------------------------------------------------------- Stewart platforms
class Platform:
    """A Stewart–Gough platform (GF §11.5.4): six base joints (base frame), six platform joints
    (platform frame), six leg lengths."""

    def __init__(self, base=None, platform=None, legs=None, *, _handle=None, name="platform"):
        if _handle is None:
            doc = {"name": name, "base": _nums(_np.asarray(base, dtype=object).tolist()),
                   "platform": _nums(_np.asarray(platform, dtype=object).tolist()),
                   "leg_lengths": _nums(_np.asarray(legs, dtype=object).tolist())}
            _handle = _soma.Platform._from_json(_json.dumps(doc), f"<{name}>")
        self._h = _handle

    @classmethod
    def from_file(cls, path):
        path = _os.fspath(path)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise ValueError(f"{path}: cannot read ({e.strerror})") from None
        return cls(_handle=_soma.Platform._from_json(text, path))

    @classmethod
    def from_dict(cls, doc, origin="<python dict>"):
        return cls(_handle=_soma.Platform._from_json(_json.dumps(_nums_doc(doc)), origin))

    base = property(lambda self: self._h.base)
    platform = property(lambda self: self._h.platform)
    legs = property(lambda self: self._h.legs)

    def leg_lengths(self, pose, scalar="double", bits=256):
        """The six leg lengths of a pose of the platform (in `scalar`)."""
        if scalar == "double" and isinstance(pose, SE3):
            return self._h.leg_lengths_of(pose)
        return self._h._leg_lengths(_pose_json(pose), scalar, bits)

    def residual(self, pose):
        return self._h.residual(pose if isinstance(pose, SE3) else SE3(_np.asarray(pose, dtype=float)))

    def solve(self, method="homotopy", scalar="double", bits=256, starts=256, seed=1, complex=False):
        """Forward kinematics: every real posture for the leg lengths. homotopy tracks all 40
        complex solutions (certified count); ceres and nlopt are multi-start searches."""
        return StewartResult(**self._h._solve(method, scalar, bits, starts, seed, complex))

    def __repr__(self):
        return repr(self._h)


# ---------------------------------------------------------------- scenes and studies
def run_scene(scene, only=(), folder=None):
    """Evaluate a scene (a file path, or the scene document as a dict): {"ok", "outputs" (each
    output's JSON as Python data), "trace" (every node built, its time and why), "written"}.
    Relative files in a dict scene are resolved against `folder` (default: the working directory)."""
    if isinstance(scene, dict):
        return _soma._run_scene_text(_json.dumps(_nums_doc(scene)), "<python scene>",
                                     _os.fspath(folder) if folder else _os.getcwd(), list(only))
    return _soma._run_scene_file(_os.fspath(scene), list(only))


def studies(patterns=()):
    """The registered studies (ID, title, source, chapter, scalar_generic), all or by ID / glob."""
    return _soma._studies(list(patterns))


def run_studies(patterns, scalar="double", bits=256, out_dir="out/report", figures=False):
    """Run studies by ID or glob ("GF-4.*"); each result with its checks (expected, got, error,
    tolerance, passed)."""
    if isinstance(patterns, str):
        patterns = [patterns]
    return _soma._run_studies(list(patterns), scalar, bits, _os.fspath(out_dir), figures)
