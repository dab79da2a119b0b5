// Studies of GF §1.4 (manifolds): the inverse and implicit function theorems turned into Newton
// continuation on the planar 2R arm (checked against its closed-form inverse, and the derivative of
// the computed inverse against p_*⁻¹ by finite differences), and the immersion test (the
// Jacobian's rank) on curves and on the map ρ₁ of GF §5.2.3 for 3R arms. Every study honours --scalar.
#include "gf01/common.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <fmt/format.h>

#include <limits>

namespace soma::studies::gf01::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::atan2;

// ---- GF-1.4-inverse-implicit-function ---------------------------------------------------------
template <class S> using V2 = Eigen::Matrix<S, 2, 1>;
template <class S> using M2 = Eigen::Matrix<S, 2, 2>;

/// The planar 2R arm p(θ) = l₁(cos θ₁, sin θ₁) + l₂(cos(θ₁+θ₂), sin(θ₁+θ₂)) and its Jacobian p_*.
template <class S> struct Arm2R {
  S l1 = S(1), l2 = S(7) / S(10);
  V2<S> tip(const V2<S>& t) const {
    return V2<S>(l1 * cos(t(0)) + l2 * cos(t(0) + t(1)), l1 * sin(t(0)) + l2 * sin(t(0) + t(1)));
  }
  M2<S> jacobian(const V2<S>& t) const {
    const S s1 = sin(t(0)), c1 = cos(t(0)), s12 = sin(t(0) + t(1)), c12 = cos(t(0) + t(1));
    M2<S> J;
    J << -l1 * s1 - l2 * s12, -l2 * s12, l1 * c1 + l2 * c12, l2 * c12;
    return J;
  }
  /// Closed form (law of cosines, atan2): the elbow of the sign `elbow`.
  V2<S> inverse(const V2<S>& y, int elbow) const {
    const S c2 = (y.squaredNorm() - l1 * l1 - l2 * l2) / (S(2) * l1 * l2);
    const S s2 = S(elbow) * sqrt(S(1) - c2 * c2);
    const S t2 = atan2(s2, c2);
    return V2<S>(atan2(y(1), y(0)) - atan2(l2 * s2, l1 + l2 * c2), t2);
  }
};

/// Newton's method for p(θ) = y from θ; returns false when it does not reach `tol` in 50 steps or
/// p_* is numerically singular (pivot ratio ≤ the rank threshold, Tolerance::rank).
template <class S> bool newton(const Arm2R<S>& arm, const V2<S>& y, V2<S>& t, const S& tol, int* steps = nullptr) {
  for (int k = 0; k < 50; ++k) {
    V2<S> r = y - arm.tip(t);
    if (maxAbs(r) <= tol) {
      if (steps) *steps = k;
      return true;
    }
    if (!(detail::smallSolveInPlace<S, 2>(arm.jacobian(t), r) > Tolerance<S>::rank())) return false;
    t += r;
  }
  return false;
}
/// Continuation: the target moves from p(θ) to y in `n` steps, Newton at each.
template <class S> bool continuation(const Arm2R<S>& arm, const V2<S>& y, V2<S>& t, const S& tol, int n = 8) {
  const V2<S> b = arm.tip(t);
  for (int k = 1; k <= n; ++k)
    if (!newton(arm, V2<S>(b + (y - b) * (S(k) / S(n))), t, tol)) return false;
  return true;
}
template <class S> S angleDiff(const S& a, const S& b) { return abs(sin((a - b) / S(2))) * S(2); }

template <class S> void inverseImplicit(Context& c) {
  std::mt19937_64 g(1401);
  const Arm2R<S> arm;
  const S tol = Tolerance<S>::identity(8);  // Newton's stopping rule on |p(θ) − y|
  S worstClosed(0), worstDeriv(0), worstImplicit(0);
  int solved = 0;
  const S h = fdStep<S>();
  for (int k = 0; k < 20; ++k) {
    // a = a regular configuration (0.8 ≤ |θ₂| ≤ 2.3), b = p(a); targets within 0.08 (inside the
    // annulus 0.3 ≤ |y| ≤ 1.7 of reachable points).
    V2<S> a(uniform<S>(g, -3, 3), uniform<S>(g, 0.8, 2.3) * (k % 2 == 0 ? S(1) : S(-1)));
    const V2<S> b = arm.tip(a);
    const V2<S> y = b + V2<S>(uniform<S>(g, -0.08, 0.08), uniform<S>(g, -0.08, 0.08));
    V2<S> t = a;
    if (!continuation(arm, y, t, tol)) continue;
    ++solved;
    const V2<S> closed = arm.inverse(y, a(1) > S(0) ? 1 : -1);
    worstClosed = maxOf(worstClosed, maxOf(angleDiff(t(0), closed(0)), angleDiff(t(1), closed(1))));
    // Derivative of the computed inverse (central differences of Newton solves) = p_*⁻¹ at θ.
    const M2<S> Jinv = arm.jacobian(t).inverse();
    for (int j = 0; j < 2; ++j) {
      auto inv = [&](const S& s) {
        V2<S> ts = t;
        newton(arm, V2<S>(y + V2<S>::Unit(j) * s), ts, tol);
        return ts;
      };
      worstDeriv = maxOf(worstDeriv, fdRatio<S>(inv, V2<S>(Jinv.col(j)), h));
    }
    // Implicit function: f(x, s) = p(x) − s u = b has the solution x = h(s) near (a, 0), with
    // h'(0) = −(∂f/∂x)⁻¹ ∂f/∂s = p_*⁻¹ u; h by Newton at s = ±h, ±h/2.
    const V2<S> u(uniform<S>(g), uniform<S>(g));
    auto hs = [&](const S& s) {
      V2<S> x = a;
      newton(arm, V2<S>(b + s * u), x, tol);
      return x;
    };
    worstImplicit = maxOf(worstImplicit, fdRatio<S>(hs, V2<S>(arm.jacobian(a).inverse() * u), h));
  }
  c.checkEqual("Newton continuation from (a, p(a)) reaches 20 nearby targets", 20, solved);
  // θ from Newton and from the closed form differ by the closed form's rounding: atan2 of
  // entries with error ε·cond(p_*) (|sin θ₂| ≥ 0.7 ⇒ cond ≤ 5).
  c.checkResidual("… the same posture as the closed-form inverse (law of cosines, atan2), tolerance 64ε",
                  worstClosed, Tolerance<S>::identity(64));
  c.checkResidual("derivative of the computed inverse (central differences of Newton solves, h = ε^{1/3}, h/2) = p_*⁻¹: "
                  "error over its bound (2× Richardson's estimate + rounding), 20 targets × 2 directions",
                  worstDeriv, S(1));
  c.checkResidual("implicit function h(s): h'(0) by central differences = −(∂f/∂x)⁻¹ ∂f/∂s: error over its bound",
                  worstImplicit, S(1));
  // Near the singularity (elbow straight, det p_* = l₁l₂ sin θ₂ → 0) the inverse's derivative
  // grows like 1/sin θ₂: at θ₂ = 0.01 the central differences of Newton solves (steps h·θ₂, inside
  // the shrinking neighbourhood) still give p_*⁻¹, whose norm is ~100× that at θ₂ = 1.
  {
    const V2<S> t0(S(1) / S(2), S(1) / S(100)), y = arm.tip(t0);
    const M2<S> Jinv = arm.jacobian(t0).inverse();
    S worstNear(0);
    for (int j = 0; j < 2; ++j) {
      auto inv = [&](const S& s) {
        V2<S> ts = t0;
        newton(arm, V2<S>(y + V2<S>::Unit(j) * s), ts, tol);
        return ts;
      };
      worstNear = maxOf(worstNear, fdRatio<S>(inv, V2<S>(Jinv.col(j)), S(h / S(100))));
    }
    c.checkResidual("θ₂ = 0.01: derivative of the computed inverse = p_*⁻¹ (error over its bound)", worstNear, S(1));
    const S growth = maxAbs(Jinv) / maxAbs(M2<S>(arm.jacobian(V2<S>(S(1) / S(2), S(1))).inverse()));
    c.recordIn("… ‖p_*⁻¹‖ at θ₂ = 0.01 over θ₂ = 1: grows like 1/sin θ₂ (sin 1 / sin 0.01 ≈ 84)", "> 50",
               io::numberText(growth), growth, S(50), growth > S(50));
  }
  // At the singularity itself p_* is singular: Newton cannot start (θ₂ = 0 exactly: det = 0).
  {
    V2<S> t(S(1) / S(2), S(0));
    const V2<S> y = arm.tip(t) + V2<S>(S(-1) / S(10), S(1) / S(20));
    c.checkEqual("start at the straight elbow θ₂ = 0: det p_* = 0 and the Newton step is undefined (solve refused)", 0,
                 newton(arm, y, t, tol) ? 1 : 0);
    // A target beyond reach (|y| = l₁ + l₂ + 0.05): no solution, Newton does not converge.
    V2<S> t2(S(1) / S(2), S(1) / S(10));
    const V2<S> far = V2<S>(cos(S(1) / S(2)), sin(S(1) / S(2))) * (arm.l1 + arm.l2 + S(1) / S(20));
    c.checkEqual("target outside the workspace (|y| = l₁ + l₂ + 0.05): Newton does not converge in 50 steps", 0,
                 newton(arm, far, t2, tol) ? 1 : 0);
  }
}

// ---- GF-1.4-immersion-test --------------------------------------------------------------------
/// The 3 × 3 Jacobian of the tool point (columns vᵢ × (p − rᵢ) = the linear part of the spatial
/// Jacobian's columns moved to p).
template <class S> Mat3<S> pointJacobian(const SerialRobot<S>& robot, const JointVector<S>& q) {
  const JacobianMatrix<S> Js = robot.spatialJacobian(q);
  const Vec3<S> p = robot.fk(q).translation();
  Mat3<S> J;
  for (int i = 0; i < 3; ++i) J.col(i) = Vec3<S>(Js.template block<3, 1>(3, i)) + Vec3<S>(Js.template block<3, 1>(0, i)).cross(p);
  return J;
}
/// J₁ of GF §5.2.3: ρ₁(θ) = (cos θ₃, sin θ₃, p(θ)) ∈ R⁵.
template <class S> MatX<S> rho1Jacobian(const SerialRobot<S>& robot, const JointVector<S>& q) {
  MatX<S> J1 = MatX<S>::Zero(5, 3);
  J1(0, 2) = -sin(q(2));
  J1(1, 2) = cos(q(2));
  J1.block(2, 0, 3, 3) = pointJacobian(robot, q);
  return J1;
}
template <class S> Vec3<S> unit3(std::mt19937_64& g) {
  Vec3<S> v(uniform<S>(g), uniform<S>(g), uniform<S>(g));
  return v / sqrt(v.squaredNorm());
}

template <class S> void immersionTest(Context& c) {
  std::mt19937_64 g(1402);
  const S twoPi = S(2) * pi<S>();
  // A figure eight γ(t) = (sin 2t, sin t): |γ'| > 0 everywhere (an immersion of the circle), but
  // γ(0) = γ(π) (not injective: not an embedding).
  {
    S least = std::numeric_limits<S>::max(), worstFd(0);
    const S h = fdStep<S>();
    for (int k = 0; k < 720; ++k) {
      const S t = twoPi * S(k) / S(720);
      const V2<S> d(S(2) * cos(S(2) * t), cos(t));
      const V2<S> fd = (V2<S>(sin(S(2) * (t + h)), sin(t + h)) - V2<S>(sin(S(2) * (t - h)), sin(t - h))) / (S(2) * h);
      worstFd = maxOf(worstFd, maxAbs(V2<S>(fd - d)));
      const S n = sqrt(d.squaredNorm());
      least = n < least ? n : least;
    }
    c.checkResidual("figure eight (sin 2t, sin t): γ' by central differences = (2cos 2t, cos t) (720 t, 64 ε^{2/3})",
                    worstFd, fdBound<S>(64));
    // min |γ'|² = min over u = cos²t of 4(2u − 1)² + u, at u = 15/32: 31/64 (|γ'| = √31/8 ≈ 0.696).
    c.recordIn("… rank 1 everywhere: min |γ'| over 720 t ≥ √31/8 − grid error, so an immersion", "≥ 0.69",
               io::numberText(least), least, S(69) / S(100), least >= S(69) / S(100));
    const V2<S> a(sin(S(0)), sin(S(0))), b(sin(S(2) * pi<S>()), sin(pi<S>()));
    c.checkResidual("… but γ(0) = γ(π) = (0, 0): not injective, an immersion that is not an embedding",
                    maxAbs(V2<S>(a - b)), Tolerance<S>::identity(8));
  }
  // ρ₁ of GF §5.2.3 for random 3R arms: J₁ has rank 3 at every configuration (axes 1, 2 skew).
  int arms = 0;
  S leastSigma = std::numeric_limits<S>::max();
  for (int k = 0; k < 10; ++k) {
    std::vector<SerialJoint<S>> js(3);
    for (auto& j : js) {
      j.axis = unit3<S>(g);
      j.point = Vec3<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g));
    }
    SE3<S> home;
    home = SE3<S>(SO3<S>(), Vec3<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g)));
    const auto robot = SerialRobot<S>::fromPOE(js, home);
    ++arms;
    for (int m = 0; m < 20; ++m) {
      JointVector<S> q(3);
      q << uniform<S>(g, -3, 3), uniform<S>(g, -3, 3), uniform<S>(g, -3, 3);
      const std::vector<S> sig = detail::smallSingularValues<S>(rho1Jacobian(robot, q));
      const S r = sig[2] / sig[0];
      leastSigma = r < leastSigma ? r : leastSigma;
    }
  }
  c.recordIn(fmt::format("ρ₁ = (cos θ₃, sin θ₃, p) is an immersion for {} random 3R arms (skew axes 1, 2): smallest "
                         "σ₃/σ₁ of J₁ over 20 configurations each, far above the rank threshold",
                         arms),
             "> 1e-3", io::numberText(leastSigma), leastSigma, S(1) / S(1000), leastSigma > S(1) / S(1000));
  // Axes 1 and 2 meeting at r (coplanar): J₁ drops to rank 2 exactly where p lies in the plane of
  // axes 1, 2 (then v₁ × (p − r) ∥ v₂ × (p − r)). The configuration is found by bisection on
  // θ₃ ↦ (p − r)·(v₁ × v₂), and the rank read from the SVD (second method).
  {
    std::vector<SerialJoint<S>> js(3);
    const Vec3<S> r(uniform<S>(g), uniform<S>(g), uniform<S>(g));
    js[0].axis = unit3<S>(g);
    js[0].point = r;
    js[1].axis = unit3<S>(g);
    js[1].point = r;
    js[2].axis = unit3<S>(g);
    js[2].point = Vec3<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g));
    const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), Vec3<S>(uniform<S>(g), uniform<S>(g), uniform<S>(g))));
    const S t1 = S(3) / S(10);
    S t2(0);
    auto side = [&](const S& t3) {
      JointVector<S> q(3);
      q << t1, t2, t3;
      const JacobianMatrix<S> Js = robot.spatialJacobian(q);
      const Vec3<S> v1 = Js.template block<3, 1>(0, 0), v2 = Js.template block<3, 1>(0, 1);
      return (robot.fk(q).translation() - r).dot(v1.cross(v2));  // axes 1, 2 still meet at r (θ₁ fixes r)
    };
    // bracket a sign change of the plane-side function on a grid of (θ₂, θ₃), then bisect in θ₃
    S lo(0), hi(0);
    bool found = false;
    for (int m = 0; m < 16 && !found; ++m) {
      t2 = -pi<S>() + twoPi * S(m) / S(16);
      for (int k = 0; k < 64 && !found; ++k) {
        const S x0 = -pi<S>() + twoPi * S(k) / S(64), x1 = -pi<S>() + twoPi * S(k + 1) / S(64);
        if (side(x0) * side(x1) < S(0)) lo = x0, hi = x1, found = true;
      }
    }
    if (found)
      for (int it = 0; it < 400 && hi - lo > Tolerance<S>::epsilon() * S(4); ++it) {
        const S mid = (lo + hi) / S(2);
        (side(lo) * side(mid) <= S(0) ? hi : lo) = mid;
      }
    JointVector<S> q(3), q2(3);
    q << t1, t2, (lo + hi) / S(2);
    q2 << t1, t2, (lo + hi) / S(2) + S(1) / S(2);
    const std::vector<S> sig = detail::smallSingularValues<S>(rho1Jacobian(robot, q));
    const std::vector<S> sig2 = detail::smallSingularValues<S>(rho1Jacobian(robot, q2));
    c.checkEqual("axes 1, 2 meeting: a θ₃ with p in their plane exists (sign change found)", 1, found ? 1 : 0);
    // bisection to 4ε in θ₃, J₁ entries of unit scale: σ₃ of order ε · |∂J₁/∂θ₃|
    c.checkResidual("… there σ₃/σ₁ of J₁ vanishes (rank 2: ρ₁ is not an immersion), tolerance 1024ε", sig[2] / sig[0],
                    Tolerance<S>::rank());
    c.recordIn("… and 0.5 rad away it is rank 3 again", "> 1e-3", io::numberText(S(sig2[2] / sig2[0])), S(sig2[2] / sig2[0]),
               S(1) / S(1000), sig2[2] / sig2[0] > S(1) / S(1000));
  }
}

}  // namespace

SOMA_STUDY_SCALAR("GF-1.4-inverse-implicit-function", "Inverse and implicit function theorems as Newton continuation (planar 2R arm)",
                  "GF §1.4", inverseImplicit);
SOMA_STUDY_SCALAR("GF-1.4-immersion-test", "Immersion = injective Jacobian: figure eight and ρ₁ of §5.2.3 (rank of J₁)",
                  "GF §1.4", immersionTest);

}  // namespace soma::studies::gf01::SOMA_UNITY_ID
