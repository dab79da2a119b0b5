#pragma once
// Closed-form inverse kinematics: 3R wrists (GF §5.1), 3R arms (GF §5.2), Pieper robots (GF §10.3).
// Private implementation header: soma_instantiate (cmake/SomaInstantiate.cmake) instantiates it once per scalar (one TU
// each, so the five build in parallel; together they took ~3 min of CPU as one TU).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/geometry/serial/joint_limits.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/polynomial.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

namespace soma {

namespace {

using Clock = std::chrono::steady_clock;

template <class S> Mat3<S> rodrigues(const Vec3<S>& v, const S& th) {
  using std::cos;
  using std::sin;
  const Mat3<S> K = skew(v);
  return Mat3<S>::Identity() + sin(th) * K + (S(1) - cos(th)) * (K * K);
}

/// w rotated about the unit axis v by the angle with cosine c and sine s (Rodrigues' formula
/// c w + s v × w + (1 − c)(v·w) v, without forming the matrix).
template <class S> Vec3<S> rotateAbout(const Vec3<S>& v, const S& c, const S& s, const Vec3<S>& w) {
  return c * w + s * v.cross(w) + ((S(1) - c) * v.dot(w)) * v;
}

/// Signed angle of the rotation about unit v taking a to b (both taken relative to a point of
/// the axis and projected on the plane ⟂ v). `degenerate` when a lies on the axis.
// GF §5.2.1, GF-5.2.1-theta2-recovery (corrected, erratum E5.6: |v×(a−r)|² and b − r)
template <class S> S angleAbout(const Vec3<S>& v, const Vec3<S>& a, const Vec3<S>& b,
                               bool* degenerate, const S& scale2) {
  using std::atan2;
  const Vec3<S> ap = a - v * v.dot(a), bp = b - v * v.dot(b);
  // On the axis when |a′| ≤ √eps · scale: the accuracy of a point computed from a double root of
  // the positioning quartic (a pose on the singularity). (|a′|² ≤ 1024 eps · scale², i.e. 32√eps,
  // flagged genuine postures within 1 % of the axis in float; 1024 eps · scale missed the T³
  // singularity of GF-10.3-closing-remarks in double.)
  // A pose known to k ulps (forward kinematics composes six motions of ≤ 4 ulps each: k ≈ 16 is typical,
  // measured 2026-12-02 after the faster SE(3) compose of 3-4 ulps) splits a double root by √(k ε), so
  // the test is |a′|² ≤ 16 eps · scale² (√(16 eps) = 4√eps: 6e-8 in double, 0.14 % of the scale in float).
  if (degenerate) *degenerate = ap.squaredNorm() <= S(16) * Tolerance<S>::epsilon() * scale2;
  return atan2(v.dot(ap.cross(bp)), ap.dot(bp));
}

/// A point (or a plane) turning about a line: x(φ) = c0 + cc cos φ + cs sin φ.
template <class S> struct Circle {
  Vec3<S> c0, cc, cs;
  Vec3<S> at(const S& phi) const {
    using std::cos;
    using std::sin;
    return c0 + cc * cos(phi) + cs * sin(phi);
  }
};
/// x turned about the line (v, r) by σφ, σ = ±1. GF §5.2.1, GF-5.2.1-revolute-joint-exp
template <class S> Circle<S> circleOf(const Vec3<S>& v, const Vec3<S>& r, const Vec3<S>& x, int sigma) {
  const Vec3<S> u = x - r;
  const Vec3<S> vvu = v * v.dot(u);
  return {Vec3<S>(r + vvu), Vec3<S>(u - vvu), Vec3<S>(S(sigma) * v.cross(u))};
}

/// One side of the circle-pair problem: its two invariants under the middle rotation, as
/// coefficients of (1, cos φ, sin φ).
template <class S> using InvRows = Eigen::Matrix<S, 2, 3>;

/// Point x(φ) about middle axis (vm, rm): f1 = vm·x, f2 = |x − rm|² (the cos², sin² terms
/// combine to |cs|² because cc ⟂ cs and |cc| = |cs|). GF §5.2.1, GF-5.2.1-3r-ik-procedure
template <class S> InvRows<S> pointInvariants(const Circle<S>& c, const Vec3<S>& vm, const Vec3<S>& rm) {
  InvRows<S> f;
  const Vec3<S> d = c.c0 - rm;
  f << vm.dot(c.c0), vm.dot(c.cc), vm.dot(c.cs),  //
      d.squaredNorm() + c.cs.squaredNorm(), S(2) * d.dot(c.cc), S(2) * d.dot(c.cs);
  return f;
}

/// Plane {y : n·y = d} turned about the line (v, r) by σφ: n(φ) is the circle `nc` of the
/// normal (about the origin) and d(φ) − n(φ)·rm = d − n·r + n(φ)·(r − rm).
// GF §10.3.1 (parallel case: ℓ6 ∧ (a5* π a5), the plane of the three parallel axes), GF-10.3.2-T3-robot
template <class S> InvRows<S> planeInvariants(const Vec3<S>& v, const Vec3<S>& r, const Vec3<S>& n,
                                             const S& d, int sigma, const Vec3<S>& vm,
                                             const Vec3<S>& rm, Circle<S>* normal) {
  const Circle<S> nc = circleOf<S>(v, Vec3<S>::Zero(), n, sigma);
  if (normal) *normal = nc;
  const Vec3<S> w = r - rm;
  InvRows<S> f;
  f << vm.dot(nc.c0), vm.dot(nc.cc), vm.dot(nc.cs),  //
      d - n.dot(r) + nc.c0.dot(w), nc.cc.dot(w), nc.cs.dot(w);
  return f;
}

/// Real roots among the roots z of the polynomial t (ascending coefficients, degree ≥ 3), by
/// realRoots' rule (polynomial.cpp): |Im z| ≤ Tolerance::input()·max(1, |Re z|), Newton-polished
/// (steps kept while |p| falls), and accepted when |p(x)| ≤ 256 eps Σ|c_k x^k|; sorted.
template <class S> std::vector<S> realRootsOf(const std::vector<S>& t, const std::vector<std::complex<S>>& zs) {
  using std::abs;
  const int n = int(t.size()) - 1;
  auto eval = [&](const S& x) {
    S p = t[n];
    for (int k = n - 1; k >= 0; --k) p = p * x + t[k];
    return p;
  };
  std::vector<S> out;
  out.reserve(zs.size());
  for (const auto& z : zs) {
    const S scale = std::max<S>(S(1), abs(z.real()));
    if (abs(z.imag()) > Tolerance<S>::input() * scale) continue;
    S x = z.real(), px = eval(x);
    for (int it = 0; it < 16 && px != S(0); ++it) {
      S dp = S(0);
      for (int k = n; k >= 1; --k) dp = dp * x + S(k) * t[k];
      if (dp == S(0)) break;
      const S xn = x - px / dp, pn = eval(xn);
      if (!(abs(pn) < abs(px))) break;
      x = xn;
      px = pn;
    }
    S mag = S(0), xk = S(1);
    for (int k = 0; k <= n; ++k) {
      mag += abs(t[k]) * xk;
      xk *= abs(x);
    }
    if (abs(px) <= Tolerance<S>::identity(256) * mag) out.push_back(x);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <class S> struct PairRoots {
  std::vector<std::pair<S, S>> angles;  // (φA, φB)
  bool continuum = false;
  bool doubleRoot = false;
  std::vector<char> nearReal;  ///< per entry of angles: from a near-real complex pair (a candidate)
  std::vector<std::string> notes;
};

/// Smallest-singular left vector y of a 2×2 matrix (yᵀM ≈ 0 when M is singular).
template <class S> Vec2<S> leftNull(const Mat2<S>& M) {
  using std::sqrt;
  const Mat2<S> A = M * M.transpose();
  const S a = A(0, 0), b = A(0, 1), c = A(1, 1);
  const S h = (a - c) / S(2);
  const S lam = (a + c) / S(2) - sqrt(h * h + b * b);
  Vec2<S> y1(b, lam - a), y2(lam - c, b);
  Vec2<S> y = y1.squaredNorm() >= y2.squaredNorm() ? y1 : y2;
  if (y.squaredNorm() == S(0)) return Vec2<S>(S(1), S(0));
  return y.normalized();
}

/// FA·(1, cos φA, sin φA) = FB·(1, cos φB, sin φB): up to 4 real (φA, φB). The 2×2 block of the
/// better-conditioned side is inverted and c² + s² = 1 of the other side gives a quartic in
/// t = tan(ψ/2), φ = φ0 + ψ with φ0 chosen so that ψ = π is far from a root (the quartic's
/// leading coefficient is the conic's value there). When both blocks are singular the system
/// decouples into one equation per angle (the PUMA case: axes 1, 2 meet and 2 ∥ 3).
// GF §5.2.1, GF-5.2.1-3r-ik-procedure (pencil of conics → tan-half-angle quartic; singular 2×2
// system → eliminate the other angle)
template <class S> PairRoots<S> solveCirclePair(InvRows<S> FA, InvRows<S> FB) {
  using std::abs;
  using std::atan;
  using std::atan2;
  using std::cos;
  using std::sin;
  PairRoots<S> out;
  for (int i = 0; i < 2; ++i) {  // rows to unit scale (f1 is a length, f2 a squared length)
    const S s = std::max<S>(FA.row(i).cwiseAbs().maxCoeff(), FB.row(i).cwiseAbs().maxCoeff());
    if (s == S(0)) {
      out.continuum = true;
      out.notes.push_back("invariant equation " + std::to_string(i + 1) + " vanishes identically");
      return out;
    }
    FA.row(i) /= s;
    FB.row(i) /= s;
  }
  const Mat2<S> MA = FA.template rightCols<2>(), MB = FB.template rightCols<2>();
  const Vec2<S> k = FB.col(0) - FA.col(0);
  auto rel = [](const Mat2<S>& M) {
    const S n2 = M.squaredNorm();
    return n2 > S(0) ? S(abs(M.determinant()) / n2) : S(0);
  };
  const S condA = rel(MA), condB = rel(MB);
  if (std::max<S>(condA, condB) > Tolerance<S>::sqrtEpsilon()) {
    // u_free = (cos, sin) of the quartic's angle, u_dep = P u_free + m.
    const bool freeIsB = condA >= condB;
    Mat2<S> P;
    Vec2<S> m;
    if (freeIsB) {
      const Mat2<S> inv = MA.inverse();
      P = inv * MB;
      m = inv * k;
    } else {
      const Mat2<S> inv = MB.inverse();
      P = inv * MA;
      m = -(inv * k);
    }
    const Mat2<S> G = P.transpose() * P;
    const Vec2<S> h = P.transpose() * m;
    const S e = m.squaredNorm() - S(1);
    auto f = [&](const Vec2<S>& u) { return S(u.dot(G * u) + S(2) * h.dot(u) + e); };
    S phi0 = S(0), best = S(-1);
    for (int j = 0; j < 8; ++j) {
      const S ph = pi<S>() * S(j) / S(4);
      const S val = abs(f(Vec2<S>(-cos(ph), -sin(ph))));
      if (val > best) {
        best = val;
        phi0 = ph;
      }
    }
    Mat2<S> R0;
    R0 << cos(phi0), -sin(phi0), sin(phi0), cos(phi0);
    const Mat2<S> Gp = R0.transpose() * G * R0;
    const Vec2<S> hp = R0.transpose() * h;
    const std::array<S, 5> c = {Gp(0, 0) + S(2) * hp(0) + e, S(4) * Gp(0, 1) + S(4) * hp(1),
                                S(-2) * Gp(0, 0) + S(4) * Gp(1, 1) + S(2) * e,
                                S(-4) * Gp(0, 1) + S(4) * hp(1), Gp(0, 0) - S(2) * hp(0) + e};
    S cmax = S(0);
    for (const auto& ci : c) cmax = std::max<S>(cmax, abs(ci));
    const S cscale = S(1) + G.cwiseAbs().maxCoeff() + h.cwiseAbs().maxCoeff() + abs(e);
    std::vector<S> ts;
    std::size_t strict = 0;  // ts[0..strict) are roots to round-off, the rest near-real candidates
    if (cmax <= Tolerance<S>::rank() * cscale) {
      out.continuum = true;
      out.notes.push_back("the conic vanishes on the whole circle: one angle is free (0 returned)");
      ts.push_back(S(0));  // ψ = 0: φ = φ0
    } else {
      // The quartic's roots are computed once (Aberth) and split here as quarticRealRoots does
      // (polynomial.cpp: trimmed degree ≥ 3 → realRoots); degree ≤ 2 goes through it.
      int deg = 4;
      while (deg >= 0 && abs(c[deg]) <= Tolerance<S>::epsilon() * cmax) --deg;
      std::vector<std::complex<S>> zs;
      if (deg >= 3) {
        const std::vector<S> t(c.begin(), c.begin() + deg + 1);
        zs = polynomialRoots<S>(t);
        ts = realRootsOf<S>(t, zs);
      } else {
        ts = quarticRealRoots<S>(c);
      }
      strict = ts.size();
      // A double root (a pose on a singularity) splits under the rounding of the coefficients
      // into a pair x ± iy with |y| up to ~√(coefficient error): keep the real parts of such
      // near-real pairs as candidates too; finish() keeps a candidate only if Newton brings its
      // posture onto the pose (residual ≤ √eps), so a genuine complex pair is dropped there.
      if (ts.size() < 4) {
        if (deg < 3) zs = polynomialRoots<S>(std::vector<S>(c.begin(), c.end()));
        for (const auto& z : zs) {
          const S scale = std::max<S>(S(1), abs(z.real()));
          if (!(z.imag() > S(0)) || z.imag() > Tolerance<S>::input() * scale) continue;
          bool known = false;
          for (const S& t : ts) known = known || abs(t - z.real()) <= Tolerance<S>::input() * scale;
          if (!known) ts.push_back(z.real());
        }
      }
    }
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const S phiFree = phi0 + S(2) * atan(ts[i]);
      const Vec2<S> uf(cos(phiFree), sin(phiFree));
      const Vec2<S> ud = P * uf + m;
      const S phiDep = atan2(ud(1), ud(0));
      if (i > 0 && abs(ts[i] - ts[i - 1]) <= Tolerance<S>::input() * (S(1) + abs(ts[i])))
        out.doubleRoot = true;
      out.angles.emplace_back(freeIsB ? phiDep : phiFree, freeIsB ? phiFree : phiDep);
      out.nearReal.push_back(i >= strict && !out.continuum ? 1 : 0);
    }
    return out;
  }
  // Decoupled: yᵀ MA = 0 gives an equation in φB alone, zᵀ MB = 0 one in φA alone.
  const Vec2<S> y = leftNull(MA), z = leftNull(MB);
  const Vec2<S> wB = MB.transpose() * y, wA = MA.transpose() * z;
  const TrigRoots<S> rB = solveLinearTrig<S>(wB(0), wB(1), -y.dot(k));
  const TrigRoots<S> rA = solveLinearTrig<S>(wA(0), wA(1), z.dot(k));
  out.notes.push_back("the invariant equations decouple (each involves one angle)");
  std::vector<S> aA = rA.angles, aB = rB.angles;
  if (rA.free) {
    aA = {S(0)};
    out.continuum = true;
    out.notes.push_back("the first angle is free (0 returned)");
  }
  if (rB.free) {
    aB = {S(0)};
    out.continuum = true;
    out.notes.push_back("the second angle is free (0 returned)");
  }
  out.doubleRoot = rA.doubleRoot || rB.doubleRoot;
  for (const auto& a : aA)
    for (const auto& b : aB) {
      out.angles.emplace_back(a, b);
      out.nearReal.push_back(0);
    }
  return out;
}

enum class ResidualMode { Pose, Position, Rotation };

/// Forward kinematics with rotation matrices (no quaternions), for the residuals:
/// e^{(q1 + o1) ξ1} ··· e^{(qn + on) ξn} · M (SerialRobot::fk's product of exponentials, GF §4.5).
template <class S>
void fkMatrix(const SerialRobot<S>& robot, const JointVector<S>& q, const Mat3<S>& RM, const Vec3<S>& tM,
              Mat3<S>& R, Vec3<S>& t) {
  using std::cos;
  using std::sin;
  R.setIdentity();
  t.setZero();
  const auto& J = robot.joints();
  for (int i = 0; i < robot.dof(); ++i) {
    const Vec3<S>& v = J[i].axis;
    const S th = q(i) + J[i].offset;
    if (J[i].type == JointType::Prismatic) {
      t += R * (v * th);
      continue;
    }
    const S c = cos(th), s = sin(th), c1 = S(1) - c;
    Mat3<S> Ri;  // Rodrigues: c I + s [v]× + (1 − c) v vᵀ
    Ri << c + c1 * v.x() * v.x(), c1 * v.x() * v.y() - s * v.z(), c1 * v.x() * v.z() + s * v.y(),  //
        c1 * v.y() * v.x() + s * v.z(), c + c1 * v.y() * v.y(), c1 * v.y() * v.z() - s * v.x(),    //
        c1 * v.z() * v.x() - s * v.y(), c1 * v.z() * v.y() + s * v.x(), c + c1 * v.z() * v.z();
    const Vec3<S>& p = J[i].point;
    t += R * Vec3<S>(p - Ri * p);
    R = (R * Ri).eval();
  }
  t += R * tM;
  R = (R * RM).eval();
}

/// The target and home pose as matrices, computed once per solve.
template <class S> struct PoseMatrices {
  Mat3<S> RT, RM;
  Vec3<S> tT, tM;
  PoseMatrices(const SerialRobot<S>& robot, const SE3<S>& target)
      : RT(target.rotation()), RM(robot.home().rotation()), tT(target.translation()),
        tM(robot.home().translation()) {}
};

template <class S>
S residualOf(const SerialRobot<S>& robot, const JointVector<S>& q, const PoseMatrices<S>& pm, ResidualMode mode) {
  using std::sqrt;
  Mat3<S> R;
  Vec3<S> t;
  fkMatrix(robot, q, pm.RM, pm.tM, R, t);
  const S L = robot.lengthScale();
  switch (mode) {
    case ResidualMode::Position: return sqrt((t - pm.tT).squaredNorm()) / L;
    case ResidualMode::Rotation: return sqrt((R - pm.RT).squaredNorm());
    case ResidualMode::Pose: break;
  }
  // poseResidual (serial_robot.hpp): sqrt(max(|R − R*|², |t − t*|² / L²))
  return sqrt(std::max<S>((R - pm.RT).squaredNorm(), (t - pm.tT).squaredNorm() / (L * L)));
}

/// Revolute joints wrapped to (−π, π] (SerialRobot::wrap without its copy; in-range values kept).
template <class S> void wrapInPlace(const SerialRobot<S>& robot, JointVector<S>& q) {
  using std::atan2;
  using std::cos;
  using std::sin;
  for (int i = 0; i < robot.dof() && i < q.size(); ++i)
    if (robot.joints()[i].type == JointType::Revolute && !(q(i) > -pi<S>() && q(i) <= pi<S>()))
      q(i) = atan2(sin(q(i)), cos(q(i)));
}

/// Newton steps on the posture (full pose: body Jacobian and the SE(3) log; position: the tool
/// point's velocity columns; rotation: the angular rows), kept only while the residual falls.
template <class S>
void polish(const SerialRobot<S>& robot, JointVector<S>& q, const SE3<S>& target, const PoseMatrices<S>& pm,
            ResidualMode mode, S& res) {
  // Closed forms are exact up to rounding: Newton runs only when the residual is above 64 ulps.
  res = residualOf(robot, q, pm, mode);
  for (int it = 0; it < 4 && res > Tolerance<S>::identity(); ++it) {
    const JacobianMatrix<S> Js = robot.spatialJacobian(q);
    const SE3<S> t = robot.fk(q);
    JointVector<S> dq;
    if (mode == ResidualMode::Pose && robot.dof() == 6) {
      const Vec6<S> e = t.inverse().compose(target).log().coeffs();
      const Mat6<S> Jb = t.inverse().adjoint() * Js;
      dq = Jb.partialPivLu().solve(e);
    } else if (robot.dof() == 3) {
      Mat3<S> J;
      Vec3<S> e;
      if (mode == ResidualMode::Rotation) {
        J = Js.template topRows<3>();
        e = SO3<S>::fromMatrix(target.rotation() * t.rotation().transpose()).log().coeffs();
      } else {
        const Vec3<S> p = t.translation();
        for (int i = 0; i < 3; ++i)  // v + ω × p
          J.col(i) = Js.col(i).template tail<3>() + Js.col(i).template head<3>().cross(p);
        e = target.translation() - p;
      }
      dq = J.partialPivLu().solve(e);
    } else {
      return;
    }
    if (!allFinite(dq)) return;
    const JointVector<S> qn = q + dq;
    const S rn = residualOf(robot, qn, pm, mode);
    if (!(rn < res)) return;
    q = qn;
    res = rn;
  }
}

template <class S> JointVector<S> toJoints(const SerialRobot<S>& robot, const JointVector<S>& raw) {
  JointVector<S> q(raw.size());
  for (int i = 0; i < raw.size(); ++i) q(i) = raw(i) - robot.joints()[i].offset;
  wrapInPlace(robot, q);
  return q;
}

template <class S>
void finish(const SerialRobot<S>& robot, const SE3<S>& target, ResidualMode mode,
            const std::vector<JointVector<S>>& raws, Solution<S>& sol, Clock::time_point t0,
            const std::vector<char>& candidate = {}) {
  int outside = 0, missed = 0;
  const PoseMatrices<S> pm(robot, target);
  sol.postures.reserve(raws.size());
  sol.residuals.reserve(raws.size());
  for (std::size_t k = 0; k < raws.size(); ++k) {
    JointVector<S> q = toJoints(robot, raws[k]);
    S res;
    polish(robot, q, target, pm, mode, res);
    // A candidate (the real part of a complex pair near the real axis, see solveCirclePair) that
    // Newton cannot bring onto the pose is not a posture.
    if (k < candidate.size() && candidate[k] && !(res <= Tolerance<S>::sqrtEpsilon())) {
      ++missed;
      continue;
    }
    wrapInPlace(robot, q);
    const auto inside = shiftIntoLimits(robot, q);  // θ + 2πk where the limits lie off (−π, π]
    if (!inside) {
      ++outside;
      continue;
    }
    sol.postures.push_back(*inside);
    sol.residuals.push_back(res);
  }
  if (outside)
    sol.notes.push_back(std::to_string(outside) + " posture(s) outside the joint limits dropped");
  if (missed)
    sol.notes.push_back(std::to_string(missed) + " candidate(s) from near-real roots did not reach the pose and were dropped");
  sol.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
}

template <class S> void requireRevolute(const SerialRobot<S>& robot, int n, const char* method) {
  if (robot.dof() != n)
    throw InvalidInput(std::string("ik method ") + method + ": needs a robot with " + std::to_string(n) +
                       " joints, this one has " + std::to_string(robot.dof()));
  for (int i = 0; i < n; ++i)
    if (robot.joints()[i].type != JointType::Revolute)
      throw InvalidInput(std::string("ik method ") + method + ": joint " + std::to_string(i + 1) +
                         " is prismatic (closed forms here are for revolute joints)");
}

/// Common point of three lines (least squares) and the largest distance from it.
template <class S> bool concurrentPoint(const std::array<Vec3<S>, 3>& v, const std::array<Vec3<S>, 3>& r,
                                        const S& tol, Vec3<S>& c) {
  using std::abs;
  Mat3<S> A = Mat3<S>::Zero();
  Vec3<S> b = Vec3<S>::Zero();
  for (int i = 0; i < 3; ++i) {
    const Mat3<S> P = Mat3<S>::Identity() - v[i] * v[i].transpose();
    A += P;
    b += P * r[i];
  }
  const Eigen::PartialPivLU<Mat3<S>> lu(A);
  if (!(abs(lu.determinant()) > Tolerance<S>::input())) return false;  // parallel axes
  c = lu.solve(b);
  for (int i = 0; i < 3; ++i) {
    const Vec3<S> d = (c - r[i]) - v[i] * v[i].dot(c - r[i]);
    if (d.squaredNorm() > tol * tol) return false;
  }
  return true;
}

/// Planar 3R with parallel axes (joint indices j, j+1, j+2 of `robot`): E_j E_{j+1} E_{j+2} = X.
/// Up to 2 solutions (raw angles). GF §10.3.2 (the planar arm after the T³ reduction: cosine
/// rule for θ3, erratum E10.7; θ2 from X, Y, erratum E10.8)
template <class S> std::vector<Vec3<S>> planar3R(const SerialRobot<S>& robot, int j, const SE3<S>& X,
                                                 bool& doubleRoot, bool& degenerate) {
  const auto& J = robot.joints();
  const Vec3<S> u = J[j].axis;
  auto P = [&](const Vec3<S>& x) { return Vec3<S>(x - u * u.dot(x)); };
  const Vec3<S> r1 = J[j].point, r2 = J[j + 1].point, r3 = J[j + 2].point;
  const Vec3<S> w = X.act(r3);
  const Vec3<S> e = P(r2 - r1), f = P(r3 - r2);
  const S D2 = P(w - r1).squaredNorm();
  const Vec3<S> v2 = J[j + 1].axis;
  const TrigRoots<S> t2 = solveLinearTrig<S>(S(2) * e.dot(f), S(2) * e.dot(v2.cross(f)),
                                             D2 - e.squaredNorm() - f.squaredNorm());
  doubleRoot = t2.doubleRoot;
  std::vector<S> th2 = t2.angles;
  if (t2.free) {
    degenerate = true;
    th2 = {S(0)};
  }
  std::vector<Vec3<S>> out;
  const S L2 = robot.lengthScale() * robot.lengthScale();
  for (const S& a2 : th2) {
    const Vec3<S> a = J[j + 1].motion(a2).act(r3);
    bool deg = false;
    const S a1 = angleAbout<S>(J[j].axis, Vec3<S>(a - r1), Vec3<S>(w - r1), &deg, L2);
    if (deg) degenerate = true;
    const Mat3<S> R3 = rodrigues<S>(v2, a2).transpose() * rodrigues<S>(J[j].axis, a1).transpose() * X.rotation();
    const Vec3<S> v3 = J[j + 2].axis;
    Vec3<S> x = v3.cross(Vec3<S>::UnitX());
    if (x.squaredNorm() < S(1) / S(4)) x = v3.cross(Vec3<S>::UnitY());
    const S a3 = angleAbout<S>(v3, x, Vec3<S>(R3 * x), nullptr, S(1));
    out.emplace_back(a1, a2, a3);
  }
  return out;
}


}  // namespace

template <class S> TrigRoots<S> solveLinearTrig(const S& p, const S& q, const S& k) {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  TrigRoots<S> out;
  const S rho2 = p * p + q * q;
  const S scale = std::max<S>(sqrt(rho2), abs(k));
  if (rho2 <= Tolerance<S>::rank() * Tolerance<S>::rank() * scale * scale || scale == S(0)) {
    out.free = abs(k) <= Tolerance<S>::rank() * (scale > S(0) ? scale : S(1)) || scale == S(0);
    return out;  // p = q = 0: no solution unless k = 0 too
  }
  S disc = rho2 - k * k;
  if (disc < S(0)) {
    if (-disc > Tolerance<S>::rank() * rho2) return out;  // unreachable
    disc = S(0);
  }
  if (disc <= Tolerance<S>::rank() * rho2) out.doubleRoot = true;
  const S base = atan2(q, p), half = atan2(sqrt(disc), k);
  out.angles = {base - half, base + half};
  return out;
}

template <class S>
WristAngles<S> wrist3R(const Vec3<S>& v1, const Vec3<S>& v2, const Vec3<S>& v3, const Mat3<S>& R) {
  WristAngles<S> out;
  // v1ᵀ e^{θ2 v2} v3 = (v1·v2)(v2·v3) + cos θ2 [v1·v3 − (v1·v2)(v2·v3)] + sin θ2 v1·(v2×v3).
  const S c12 = v1.dot(v2) * v2.dot(v3);
  const TrigRoots<S> t2 =
      solveLinearTrig<S>(v1.dot(v3) - c12, v1.dot(v2.cross(v3)), S(v1.dot(R * v3)) - c12);
  out.doubleRoot = t2.doubleRoot;
  std::vector<S> th2 = t2.angles;
  if (t2.free) th2 = {S(0)};  // v1 = ±v3 and v2 ⟂ both or equal: degenerate wrist
  using std::cos;
  using std::sin;
  const Vec3<S> z = R * v3;
  Vec3<S> x = v3.cross(Vec3<S>::UnitX());
  if (x.squaredNorm() < S(1) / S(4)) x = v3.cross(Vec3<S>::UnitY());
  const Vec3<S> Rx = R * x;
  out.angles.reserve(th2.size());
  for (const S& a2 : th2) {
    const S c2 = cos(a2), s2 = sin(a2);
    const Vec3<S> y = rotateAbout<S>(v2, c2, s2, v3);  // the book's y = e^{θ2 ad v2} v3
    bool gimbal = false;
    const Vec3<S> yp = y - v1 * v1.dot(y);
    gimbal = yp.squaredNorm() <= Tolerance<S>::identity(64);
    // y'·z' = |y'|² cos θ1 and v1·(y'×z') = |y'|² sin θ1, i.e. −(y×v1)ᵀ R v3 (E5.1).
    const S a1 = gimbal ? S(0) : angleAbout<S>(v1, y, z, nullptr, S(1));
    if (gimbal) out.gimbal = true;
    // R3 x = e^{−θ2 v2} e^{−θ1 v1} R x
    const Vec3<S> R3x = rotateAbout<S>(v2, c2, S(-s2), rotateAbout<S>(v1, cos(a1), S(-sin(a1)), Rx));
    const S a3 = angleAbout<S>(v3, x, R3x, nullptr, S(1));
    out.angles.emplace_back(a1, a2, a3);
  }
  return out;
}

template <class S> PieperTriple<S> findPieperTriple(const SerialRobot<S>& robot) {
  PieperTriple<S> out;
  if (robot.dof() != 6 || !robot.allRevolute()) return out;
  const auto& J = robot.joints();
  const S tol = Tolerance<S>::input();
  for (int first : {3, 0, 1, 2}) {
    std::array<Vec3<S>, 3> v, r;
    for (int i = 0; i < 3; ++i) {
      v[i] = J[first + i].axis;
      r[i] = J[first + i].point;
    }
    const bool parallel = v[0].cross(v[1]).squaredNorm() <= tol * tol &&
                          v[0].cross(v[2]).squaredNorm() <= tol * tol;
    if (parallel) {
      out.first = first;
      out.concurrent = false;
      out.direction = v[0];
      return out;
    }
    Vec3<S> c;
    if (concurrentPoint<S>(v, r, tol * robot.lengthScale(), c)) {
      out.first = first;
      out.concurrent = true;
      out.point = c;
      return out;
    }
  }
  return out;
}

template <class S> bool isWrist(const SerialRobot<S>& robot) {
  if (robot.dof() != 3 || !robot.allRevolute()) return false;
  std::array<Vec3<S>, 3> v, r;
  for (int i = 0; i < 3; ++i) {
    v[i] = robot.joints()[i].axis;
    r[i] = robot.joints()[i].point;
  }
  Vec3<S> c;
  return concurrentPoint<S>(v, r, Tolerance<S>::input() * robot.lengthScale(), c);
}

template <class S> IkMethod classifyRobot(const SerialRobot<S>& robot) {
  if (!robot.allRevolute())
    throw InvalidInput("ik: the robot has a prismatic joint; the closed forms and the 6R solver "
                       "need revolute joints");
  if (robot.dof() == 3) return isWrist(robot) ? IkMethod::Wrist3R : IkMethod::Arm3R;
  if (robot.dof() == 6) return findPieperTriple(robot).first >= 0 ? IkMethod::Pieper : IkMethod::General6R;
  throw InvalidInput("ik: no method for a robot with " + std::to_string(robot.dof()) +
                     " joints (3R wrists and arms, 6R robots)");
}

template <class S> Solution<S> solveWrist3R(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 3, "wrist3r");
  if (!isWrist(robot)) throw InvalidInput("ik method wrist3r: the three axes do not meet in a point");
  Solution<S> sol;
  sol.method = "wrist3r";
  sol.expected_count = 2;
  const auto& J = robot.joints();
  const Mat3<S> R = target.rotation() * robot.home().rotation().transpose();
  const WristAngles<S> w = wrist3R<S>(J[0].axis, J[1].axis, J[2].axis, R);
  if (w.gimbal) {
    sol.continuum = true;
    sol.notes.push_back("gimbal singularity: θ1 and θ3 determined only in combination (θ1 = 0 returned)");
  }
  if (w.doubleRoot) sol.notes.push_back("double root: the two postures merge (boundary of the reachable set)");
  std::vector<JointVector<S>> raws;
  for (const auto& a : w.angles) raws.push_back(JointVector<S>(a));
  finish(robot, target, ResidualMode::Rotation, raws, sol, t0);
  return sol;
}

template <class S> Solution<S> solveArm3R(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 3, "arm3r");
  Solution<S> sol;
  sol.method = "arm3r";
  sol.expected_count = 4;
  const auto& J = robot.joints();
  const Vec3<S> p0 = robot.home().translation(), p = target.translation();
  // a = e^{θ3 S3} p0, b = e^{−θ1 S1} p; invariants of the rotation about axis 2.
  const Circle<S> ca = circleOf<S>(J[2].axis, J[2].point, p0, +1);
  const Circle<S> cb = circleOf<S>(J[0].axis, J[0].point, p, -1);
  const PairRoots<S> pr = solveCirclePair<S>(pointInvariants(ca, J[1].axis, J[1].point),
                                             pointInvariants(cb, J[1].axis, J[1].point));
  sol.notes = pr.notes;
  sol.continuum = pr.continuum;
  if (pr.doubleRoot) sol.notes.push_back("double root: two postures merge (on a bifurcation surface)");
  std::vector<JointVector<S>> raws;
  const S L2 = robot.lengthScale() * robot.lengthScale();
  std::vector<char> cand;
  for (std::size_t k = 0; k < pr.angles.size(); ++k) {
    const auto [a3, a1] = pr.angles[k];
    cand.push_back(pr.nearReal[k]);
    const Vec3<S> a = ca.at(a3), b = cb.at(a1);
    bool deg = false;
    const S a2 = angleAbout<S>(J[1].axis, Vec3<S>(a - J[1].point), Vec3<S>(b - J[1].point), &deg, L2);
    if (deg) {
      sol.continuum = true;
      sol.notes.push_back("the point lies on axis 2: θ2 is free (θ2 = 0 returned)");
    }
    raws.push_back(Vec3<S>(a1, deg ? S(0) : a2, a3));
  }
  finish(robot, target, ResidualMode::Position, raws, sol, t0, cand);
  return sol;
}

namespace {

/// Pieper robot with the special triple at joints 4-6 (first = 3) or 2-4 (first = 1).
template <class S>
std::vector<JointVector<S>> pieperCore(const SerialRobot<S>& robot, const PieperTriple<S>& tri,
                                       const SE3<S>& target, Solution<S>& sol, std::vector<char>& cand) {
  const auto& J = robot.joints();
  const SE3<S> A = target * robot.home().inverse();  // = E1 ··· E6
  const Mat3<S> RA = A.rotation();
  const S L2 = robot.lengthScale() * robot.lengthScale();
  std::vector<JointVector<S>> raws;
  raws.reserve(8);
  cand.reserve(8);
  // Sides of the circle pair: (joint, sign, transformed-by-A⁻¹?) and the middle joint.
  int ja, jb, jm, sa, sb, sm;
  if (tri.first == 3) {
    ja = 2, sa = +1, jb = 0, sb = -1, jm = 1, sm = +1;  // E2 E3 x = E1⁻¹ A x
  } else {
    ja = 4, sa = -1, jb = 0, sb = +1, jm = 5, sm = -1;  // E6⁻¹ E5⁻¹ x = A⁻¹ E1 x
  }
  // Line of joint jb as seen on the b side (through A⁻¹ when the triple is 2-4).
  const SE3<S> Bmap = tri.first == 3 ? SE3<S>() : A.inverse();
  const Vec3<S> vb = Bmap.so3().act(J[jb].axis), rb = Bmap.act(J[jb].point);
  const SE3<S> Xobj = tri.first == 3 ? A : A.inverse();  // the b-side object is Xobj applied
  const Vec3<S> vm = J[jm].axis, rm = J[jm].point;
  PairRoots<S> pr;
  Circle<S> ca, cb;
  if (tri.concurrent) {
    ca = circleOf<S>(J[ja].axis, J[ja].point, tri.point, sa);
    cb = circleOf<S>(vb, rb, Xobj.act(tri.point), sb);
    pr = solveCirclePair<S>(pointInvariants(ca, vm, rm), pointInvariants(cb, vm, rm));
  } else {
    const Vec3<S> n0 = tri.direction;
    const Vec3<S> nb = Xobj.so3().act(n0);
    const S db = nb.dot(Xobj.translation());  // plane n0·y = 0 moved by Xobj
    pr = solveCirclePair<S>(planeInvariants<S>(J[ja].axis, J[ja].point, n0, S(0), sa, vm, rm, &ca),
                            planeInvariants<S>(vb, rb, nb, db, sb, vm, rm, &cb));
  }
  for (const auto& n : pr.notes) sol.notes.push_back(n);
  if (pr.continuum) sol.continuum = true;
  if (pr.doubleRoot) sol.notes.push_back("double root in the positioning quartic (postures merge)");
  for (std::size_t k = 0; k < pr.angles.size(); ++k) {
    const auto [phA, phB] = pr.angles[k];
    const Vec3<S> a = ca.at(phA), b = cb.at(phB);
    bool deg = false;
    const S psi = tri.concurrent
                      ? angleAbout<S>(vm, Vec3<S>(a - rm), Vec3<S>(b - rm), &deg, L2)
                      : angleAbout<S>(vm, a, b, &deg, S(1));
    if (deg) {
      sol.continuum = true;
      sol.notes.push_back("wrist-type singularity: joint " + std::to_string(jm + 1) +
                          " is free (0 returned)");
    }
    // The circles already carry the sign of their joint (a = e^{σφ S} x with σφ = σθ), so θ = φ.
    const S thA = phA, thB = phB, thM = deg ? S(0) : S(sm) * psi;
    JointVector<S> th = JointVector<S>::Zero(6);
    th(ja) = thA;
    th(jb) = thB;
    th(jm) = thM;
    // The motion left for the triple.
    SE3<S> X;
    int j0;
    if (tri.concurrent) {  // the wrist needs only the rotation: matrices, no quaternions
      using std::cos;
      using std::sin;
      // first = 3: X = (E1 E2 E3)⁻¹ A; first = 1: X = E1⁻¹ A E6⁻¹ E5⁻¹ (rotation parts).
      Mat3<S> RX;
      j0 = tri.first;
      for (int col = 0; col < 3; ++col) {
        Vec3<S> w = RA.col(col);
        if (tri.first == 3) {
          for (int i = 0; i < 3; ++i) w = rotateAbout<S>(J[i].axis, cos(th(i)), S(-sin(th(i))), w);
        } else {
          w = rotateAbout<S>(J[0].axis, cos(th(0)), S(-sin(th(0))), w);
        }
        RX.col(col) = w;
      }
      if (tri.first == 1) {  // RX ← RX R6ᵀ R5ᵀ: rows rotated, i.e. (R5 R6 RXᵀ)ᵀ
        Mat3<S> T = RX.transpose();
        for (int col = 0; col < 3; ++col) {
          Vec3<S> w = T.col(col);
          w = rotateAbout<S>(J[5].axis, cos(th(5)), sin(th(5)), w);
          w = rotateAbout<S>(J[4].axis, cos(th(4)), sin(th(4)), w);
          T.col(col) = w;
        }
        RX = T.transpose();
      }
      const WristAngles<S> w = wrist3R<S>(J[j0].axis, J[j0 + 1].axis, J[j0 + 2].axis, RX);
      if (w.gimbal) {
        sol.continuum = true;
        sol.notes.push_back("wrist gimbal singularity: joints " + std::to_string(j0 + 1) + " and " +
                            std::to_string(j0 + 3) + " determined only in combination");
      }
      if (w.doubleRoot) sol.notes.push_back("wrist double root (postures merge)");
      for (const auto& t : w.angles) {
        JointVector<S> full = th;
        full.segment(j0, 3) = t;
        raws.push_back(std::move(full));
        cand.push_back(pr.nearReal[k]);
      }
      continue;
    }
    if (tri.first == 3) {
      X = (J[0].motion(th(0)) * J[1].motion(th(1)) * J[2].motion(th(2))).inverse() * A;
      j0 = 3;
    } else {
      X = J[0].motion(th(0)).inverse() * A * J[5].motion(th(5)).inverse() * J[4].motion(th(4)).inverse();
      j0 = 1;
    }
    std::vector<Vec3<S>> tr;
    if (tri.concurrent) {
      const WristAngles<S> w = wrist3R<S>(J[j0].axis, J[j0 + 1].axis, J[j0 + 2].axis, X.rotation());
      if (w.gimbal) {
        sol.continuum = true;
        sol.notes.push_back("wrist gimbal singularity: joints " + std::to_string(j0 + 1) + " and " +
                            std::to_string(j0 + 3) + " determined only in combination");
      }
      if (w.doubleRoot) sol.notes.push_back("wrist double root (postures merge)");
      tr = w.angles;
    } else {
      bool dbl = false, dg = false;
      tr = planar3R<S>(robot, j0, X, dbl, dg);
      if (dbl) sol.notes.push_back("planar arm double root (elbow straight: postures merge)");
      if (dg) {
        sol.continuum = true;
        sol.notes.push_back("planar arm degenerate (a point on an axis)");
      }
    }
    for (const auto& t : tr) {
      JointVector<S> full = th;
      full.segment(j0, 3) = t;
      raws.push_back(full);
      cand.push_back(pr.nearReal[k]);
    }
  }
  return raws;
}

}  // namespace

template <class S> Solution<S> solvePieper(const SerialRobot<S>& robot, const SE3<S>& target) {
  const auto t0 = Clock::now();
  requireRevolute(robot, 6, "pieper");
  const PieperTriple<S> tri = findPieperTriple(robot);
  if (tri.first < 0)
    throw InvalidInput("ik method pieper: no three consecutive axes meet in a point or are parallel");
  Solution<S> sol;
  sol.method = "pieper";
  sol.expected_count = 8;
  sol.notes.push_back(std::string("axes ") + std::to_string(tri.first + 1) + "-" +
                      std::to_string(tri.first + 3) + (tri.concurrent ? " meet in a point" : " are parallel"));
  std::vector<JointVector<S>> raws;
  std::vector<char> cand;
  if (tri.first == 3 || tri.first == 1) {
    raws = pieperCore(robot, tri, target, sol, cand);
  } else {  // 1-3 or 3-5: solve the reversed robot (T⁻¹ with joints 6..1), where they are 4-6 / 2-4
    const SerialRobot<S> rev = robot.reversed();
    PieperTriple<S> rt = tri;
    rt.first = 3 - tri.first;
    // the reversed robot's coordinates are the tool-home frame: point p ↦ M⁻¹ p
    rt.point = robot.home().inverse().act(tri.point);
    rt.direction = robot.home().inverse().so3().act(tri.direction);
    for (auto& r : pieperCore(rev, rt, SE3<S>(target.inverse()), sol, cand)) raws.push_back(r.reverse().eval());
  }
  finish(robot, target, ResidualMode::Pose, raws, sol, t0, cand);
  return sol;
}

template <class S>
Solution<S> solveClosedForm(const SerialRobot<S>& robot, const SE3<S>& target, IkMethod method) {
  if (method == IkMethod::Auto) method = classifyRobot(robot);
  switch (method) {
    case IkMethod::Wrist3R: return solveWrist3R(robot, target);
    case IkMethod::Arm3R: return solveArm3R(robot, target);
    case IkMethod::Pieper: return solvePieper(robot, target);
    default: break;
  }
  if (method == IkMethod::General6R)
    throw InvalidInput("ik: method general6r is not a closed form (this robot has no three "
                       "consecutive axes meeting or parallel)");
  throw InvalidInput("ik: method " + std::string(ikMethodName(method)) + " is not a closed form (solveIk runs it)");
}

#define SOMA_INSTANTIATE_CLOSED_FORM_IK(S)                                                               \
  template TrigRoots<S> solveLinearTrig<S>(const S&, const S&, const S&);                     \
  template WristAngles<S> wrist3R<S>(const Vec3<S>&, const Vec3<S>&, const Vec3<S>&,           \
                                     const Mat3<S>&);                                          \
  template PieperTriple<S> findPieperTriple<S>(const SerialRobot<S>&);                         \
  template bool isWrist<S>(const SerialRobot<S>&);                                             \
  template IkMethod classifyRobot<S>(const SerialRobot<S>&);                                   \
  template Solution<S> solveWrist3R<S>(const SerialRobot<S>&, const SE3<S>&);                  \
  template Solution<S> solveArm3R<S>(const SerialRobot<S>&, const SE3<S>&);                    \
  template Solution<S> solvePieper<S>(const SerialRobot<S>&, const SE3<S>&);                   \
  template Solution<S> solveClosedForm<S>(const SerialRobot<S>&, const SE3<S>&, IkMethod);

}  // namespace soma
