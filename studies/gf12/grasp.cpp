// Studies of GF chapter 12, §12.5–12.6, in the scalar asked for (--scalar): force closure by the rank
// test, the surfaces that cannot be gripped without friction, positive (push-only) grasps with seven
// fingers, form closure as the dual linear program, second-order contact and the curved feasible
// regions (erratum E12.3), friction cones (E12.4), two fingers never suffice, convex-cone duality and
// the dual friction cone (E12.2), the planar two-finger criterion and the polyhedral approximation.
// In float128 and mpfr (software arithmetic) the long LP searches use smaller samples, counted in the
// check names.
#include "gf12/common.hpp"

#include "soma/geometry/statics/grasp.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <functional>
#include <random>

namespace soma::studies::gf12::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::atan;
using std::atan2;
using std::cos;
using std::sin;
using std::sqrt;

template <class S> S tol(int ulps = 64) { return Tolerance<S>::identity(ulps); }
/// A surface parameter scale: 3.14159 (not π: the samples stay off the seam), exactly as S rounds it.
template <class S> S nearPi() { return frac<S>(314159, 100000); }

/// A surface as (u, v) ∈ [−1, 1]² ↦ (point, inward normal, not necessarily unit).
template <class S> using Surface = std::function<std::pair<Vec3<S>, Vec3<S>>(const S&, const S&)>;
template <class S> Surface<S> ellipsoid(const S& a, const S& b, const S& cc) {
  return [=](const S& u, const S& v) {
    const S th = nearPi<S>() * u, ph = frac<S>(29, 20) * v;
    const Vec3<S> x(a * cos(ph) * cos(th), b * cos(ph) * sin(th), cc * sin(ph));
    return std::pair<Vec3<S>, Vec3<S>>{x, Vec3<S>(-x.x() / (a * a), -x.y() / (b * b), -x.z() / (cc * cc))};
  };
}
template <class S> Surface<S> torusSurface() {
  return [](const S& u, const S& v) {
    const S th = nearPi<S>() * u, ph = nearPi<S>() * v;
    const Vec3<S> d(cos(ph) * cos(th), cos(ph) * sin(th), sin(ph));
    return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(Vec3<S>(2 * cos(th), 2 * sin(th), 0) + d / S(2)), Vec3<S>(-d)};
  };
}
template <class S>
WrenchSet<S> sample(const Surface<S>& s, int n, std::mt19937_64& g, std::vector<Vec3<S>>* pts = nullptr,
                    std::vector<Vec3<S>>* nrm = nullptr) {
  std::vector<Vec3<S>> p, nn;
  for (int i = 0; i < n; ++i) {
    const S u = uni<S>(g), v = uni<S>(g);
    const auto [x, m] = s(u, v);
    p.push_back(x);
    nn.push_back(m.normalized());
  }
  if (pts) *pts = p;
  if (nrm) *nrm = nn;
  return contactNormalWrenches<S>(p, nn);
}

// ---- §12.5 --------------------------------------------------------------------------------------
template <class S> void forceClosure(Context& c) {
  auto g = std::mt19937_64(1251);
  const Surface<S> ell = ellipsoid<S>(frac<S>(3, 2), S(1), frac<S>(7, 10));
  int rank6 = 0, rank5 = 0;
  for (int i = 0; i < 200; ++i) {
    rank6 += wrenchSpan<S>(sample(ell, 6, g)).rank == 6;
    rank5 += wrenchSpan<S>(sample(ell, 5, g)).rank == 5;
  }
  c.checkEqual("6 random bilateral contacts on an ellipsoid (1.5, 1, 0.7) span se*(3) (of 200)", 200, rank6);
  c.checkEqual("5 contacts never span: rank 5 (of 200)", 200, rank5);
  // six normal lines of a torus lie in a linear complex: a dependence Σ w_i 𝒩_i = 0
  const WrenchSet<S> N = sample(torusSurface<S>(), 6, g);
  const auto span = wrenchSpan<S>(WrenchSet<S>(N.transpose()));  // null vector of N = the weights
  c.checkEqual("six contacts on a torus: rank of [𝒩₁ … 𝒩₆]", 5, wrenchSpan<S>(N).rank);
  c.checkResidual("the dependence Σ w_i 𝒩_i = 0 (w from the SVD, |w| = 1)", S((N * span.annihilatedScrews.at(0)).norm()), tol<S>(1024));
  c.note("The rank test uses the one-sided Jacobi SVD (small_linalg) with Tolerance::rank() = 1024 ε relative to σ₁.");
}

template <class S> void ungrippable(Context& c) {
  using V3 = Vec3<S>;
  using P = std::pair<V3, V3>;
  auto g = std::mt19937_64(1252);
  struct Row {
    std::string name;
    Surface<S> s;
    int rank;
  };
  const S p = frac<S>(3, 10);
  const std::vector<Row> rows = {
      {"sphere", ellipsoid<S>(S(1), S(1), S(1)), 3},
      {"plane", [](const S& u, const S& v) { return P{V3(u, v, 0), V3(0, 0, 1)}; }, 3},
      {"circular cylinder", [](const S& u, const S& v) { return P{V3(cos(3 * u), sin(3 * u), v), V3(-cos(3 * u), -sin(3 * u), 0)}; }, 4},
      {"torus (surface of revolution)", torusSurface<S>(), 5},
      {"helicoid (u cos v, u sin v, 0.3 v)",
       [p](const S& u, const S& v) {
         const S r = S(1) / S(2) + u, t = 3 * v;
         return P{V3(r * cos(t), r * sin(t), p * t), V3(V3(cos(t), sin(t), 0).cross(V3(-r * sin(t), r * cos(t), p)))};
       }, 5},
      {"general cylinder over y = x³ − x", [](const S& u, const S& v) { return P{V3(u, u * u * u - u, v), V3(3 * u * u - 1, -1, 0)}; }, 5},
      {"ellipsoid (1.5, 1, 0.7)", ellipsoid<S>(frac<S>(3, 2), S(1), frac<S>(7, 10)), 6},
  };
  for (const auto& r : rows) {
    const auto sp = wrenchSpan<S>(sample(r.s, 60, g));
    c.checkEqual("rank of 60 sampled normal lines: " + r.name, r.rank, sp.rank);
    if (r.rank == 5) {
      const Eigen::Matrix<S, Eigen::Dynamic, 1> s = sp.annihilatedScrews.at(0);
      const S na = s.template head<3>().norm();
      const Vec6<S> t = Vec6<S>(s / (na > Tolerance<S>::sqrtEpsilon() ? na : S(s.template tail<3>().norm())));
      std::string txt;
      for (int k = 0; k < 6; ++k) txt += (k == 0 ? "" : k == 3 ? "; " : ", ") + toString(toDouble(t(k)), 3);
      c.note(r.name + ": annihilated screw (ω, v) = (" + txt + ")");
    }
  }
  // the symmetry screws: rotation about z, the helical screw of pitch 0.3, translation along z; the
  // SVD's null vector is accurate to ~ε σ₁/σ₅: 4096 ε (9.1e-13 in double; 1e-12 before).
  const auto heli = wrenchSpan<S>(sample(rows[4].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("helicoid: annihilated screw has pitch v_z/ω_z = 0.3 (its own helical motion; 4096 ε)", p, S(heli(5) / heli(2)), tol<S>(4096));
  const auto tor = wrenchSpan<S>(sample(rows[3].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("torus: annihilated screw is the rotation about z (|ω_z| = 1)", S(1), S(abs(tor(2))), tol<S>(4096));
  const auto ext = wrenchSpan<S>(sample(rows[5].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("general cylinder: annihilated screw is the translation along z (|v_z| = 1)", S(1), S(abs(ext(5))), tol<S>(4096));
  // nearly symmetric ellipsoid: σ₆/σ₁ ∝ a − b, from a − b = 1e-2 down to 1e-6 (four decades); in
  // float, where σ₆/σ₁ at 1e-6 is within a few ε of rounding, down to 1e-4 (two decades).
  const bool fourDecades = Tolerance<S>::epsilon() < S(1) / S(1000000000);
  const int last = fourDecades ? 1000000 : 10000;
  std::string tbl;
  S r1 = 0, r2 = 0;
  for (const int inv : {100, 10000, 1000000}) {
    if (inv > last) break;
    auto g2 = std::mt19937_64(99);
    const auto sp = wrenchSpan<S>(sample(ellipsoid<S>(S(1) + S(1) / S(inv), S(1), frac<S>(7, 10)), 60, g2));
    const S q = sp.singularValues[5] / sp.singularValues[0];
    tbl += "a − b = 1/" + std::to_string(inv) + ": σ₆/σ₁ = " + toString(toDouble(q), 3) + "; ";
    if (inv == 100) r1 = q;
    if (inv == last) r2 = q;
  }
  const S ratio = S(last / 100);
  c.record(std::string("σ₆/σ₁ scales like a − b (ratio over ") + (fourDecades ? "four decades ≈ 1e4)" : "two decades ≈ 1e2, float)"),
           toString(toDouble(ratio), 1) + " ± 10%", toString(toDouble(r1 / r2), 4), toDouble(abs(r1 / r2 / ratio - 1)), 0.1,
           abs(r1 / r2 / ratio - 1) <= S(1) / S(10));
  c.note("Nearly symmetric ellipsoid (1 + δ, 1, 0.7): " + tbl + "the sixth direction is the rotation about z, and is "
         "called independent only while σ₆/σ₁ > Tolerance::rank() = " + toString(toDouble(Tolerance<S>::rank()), 2) + ".");
}

template <class S> void positiveSeven(Context& c) {
  auto g = std::mt19937_64(1253);
  const Surface<S> ell = ellipsoid<S>(frac<S>(3, 2), S(1), frac<S>(7, 10));
  const int nSix = samples<S>(2000, 200), nSphere = samples<S>(200, 40);
  int six = 0, sevenFound = 0, sevenTries = 0;
  for (int i = 0; i < nSix; ++i) six += positiveSpan<S>(sample(ell, 6, g)).spans;
  std::vector<Vec3<S>> pts, nrm;
  S margin = 0;
  for (; sevenTries < 20000 && !sevenFound; ++sevenTries) {
    const WrenchSet<S> N = sample(ell, 7, g, &pts, &nrm);
    const auto ps = positiveSpan<S>(N);
    if (ps.spans) sevenFound = 1, margin = ps.margin;
  }
  c.checkEqual("6 push-only fingers never force-close (" + std::to_string(nSix) + " random grasps on the ellipsoid)", 0, six);
  c.checkEqual("a 7-finger positive force-closed grasp exists on the ellipsoid (random search)", 1, sevenFound);
  c.note("First 7-finger positively spanning grasp after " + std::to_string(sevenTries) + " random tries; margin max_w min_i w_i = " +
         toString(toDouble(margin), 3) + " (Σw = 1, unit columns). Six never work: six vectors that span R⁶ are independent, so no "
         "positive combination vanishes.");
  // on a Reuleaux surface no number of frictionless fingers helps
  int sphere = 0;
  for (int i = 0; i < nSphere; ++i) sphere += positiveSpan<S>(sample(ellipsoid<S>(S(1), S(1), S(1)), 12, g)).spans;
  c.checkEqual("12 push-only fingers on a sphere never force-close (" + std::to_string(nSphere) + " tries)", 0, sphere);
}

template <class S> void formClosureStudy(Context& c) {
  using V3 = Vec3<S>;
  auto g = std::mt19937_64(1254);
  // point contacts on the faces of the cube [−1, 1]³, inward normals
  const int per = samples<S>(60, 10);
  int agree = 0, closed = 0, total = 0;
  for (int m = 6; m <= 12; ++m)
    for (int t = 0; t < per; ++t) {
      std::vector<V3> p, n;
      for (int i = 0; i < m; ++i) {
        const int face = int(std::uniform_real_distribution<double>(0, 6)(g));
        V3 x = rv3<S>(g);
        x(face % 3) = face < 3 ? 1 : -1;
        V3 nn = V3::Zero();
        nn(face % 3) = face < 3 ? -1 : 1;
        p.push_back(x);
        n.push_back(nn);
      }
      const WrenchSet<S> N = contactNormalWrenches<S>(p, n);
      const bool force = positiveSpan<S>(N).spans;
      const auto form = formClosure<S>(N);
      agree += force == form.closed;
      closed += force;
      ++total;
      if (!form.closed) {  // the escape velocity keeps every contact (to the LP's rounding, 4096 ε)
        const S worst = (N.transpose() * form.escape).minCoeff();
        if (worst < -tol<S>(4096)) agree -= 1000;
      }
    }
  c.checkEqual("form closure (feasible velocities = {0}, dual LP) = force closure (primal LP), cube, " + std::to_string(total) +
               " grasps", total, agree);
  c.record("both outcomes occur", "some of each", std::to_string(closed) + " closed of " + std::to_string(total),
           0, 0, closed > total / 20 && closed < total - total / 20);
  c.note("Feasible object velocities for push-only point contacts: {s : 𝒩_i(s) ≥ 0}. The dual LP maximises Σ 𝒩_i(s) "
         "over |s_j| ≤ 1; a positive optimum is an escape velocity, checked to break no contact.");
}

/// Φ at the finger (fixed at the origin) after the OBJECT moves by e^{εs}: Φ(e^{−εs}·0).
template <class S> S objectMotionPhi(const S& kx, const S& ky, const Vec6<S>& s, const S& eps) {
  const Vec3<S> q = SE3Tangent<S>(Vec6<S>(-eps * s)).exp().translation();
  return kx * q.x() * q.x() + ky * q.y() * q.y() - 2 * q.z();
}

template <class S> void secondOrder(Context& c) {
  using V6 = Vec6<S>;
  using T = SE3Tangent<S>;
  auto g = std::mt19937_64(1255);
  S d1 = 0, d2 = 0;
  for (int i = 0; i < 100; ++i) {
    const S kx = uni<S>(g, -2, 2), ky = uni<S>(g, -2, 2);
    const V6 s = rv6<S>(g);
    // the book's f(t) for the FINGER moving: f(θ) = Φ(e^{θS}·0); exact derivatives of the 4×4 form
    Mat4<S> Sm = T(s).hat(), Q = Mat4<S>::Zero();
    Q(0, 0) = kx, Q(1, 1) = ky, Q(2, 3) = Q(3, 2) = -1;
    const Vec4<S> o(0, 0, 0, 1);
    const S f1 = o.dot((Sm.transpose() * Q + Q * Sm) * o);
    d1 = maxOf(d1, S(abs(f1 + 2 * s(5))));
    V6 s0 = s;
    s0(5) = 0;
    const Mat4<S> S0 = T(s0).hat();
    const S f20 = o.dot((S0.transpose() * S0.transpose() * Q + 2 * S0.transpose() * Q * S0 + Q * S0 * S0) * o);
    d2 = maxOf(d2, S(abs(f20 / 2 - secondOrderContactForm<S>(kx, ky, T(s0)))));
  }
  c.checkResidual("ḟ(0) = (0,1)(SᵀQ + QS)(0,1)ᵀ = −2 v_z: first-order contact ⟺ v_z = 0 (100 random)", d1, tol<S>());
  c.checkResidual("f̈(0)/2 at v_z = 0 = k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x (100 random)", d2, tol<S>(256));
  // and against the motion itself: Φ(e^{θs}·0) = −2 v_z θ + q θ² + O(θ³)
  const S kx = frac<S>(4, 5), ky = frac<S>(-2, 5);
  V6 s;
  s << frac<S>(3, 10), frac<S>(-7, 10), frac<S>(1, 5), frac<S>(1, 2), frac<S>(-3, 5), S(0);
  const S q = secondOrderContactForm<S>(kx, ky, T(s));
  const S t1 = S(1) / S(100), t2 = S(1) / S(1000);
  const S r1 = abs(objectMotionPhi<S>(kx, ky, V6(-s), t1) - q * t1 * t1), r2 = abs(objectMotionPhi<S>(kx, ky, V6(-s), t2) - q * t2 * t2);
  // The O(θ³) remainder at θ = 1e-3 (~1e-9) must stand 1000× above the rounding of Φ (64 ε θ); in
  // float it does not, and the ratio is not measurable.
  if (S(1000) * tol<S>(64) * t2 < r2) {
    c.record("remainder Φ(e^{θs}·0) − q θ² is O(θ³): ratio for θ = 1e-2 → 1e-3", "≈ 1000", toString(toDouble(r1 / r2), 4),
             toDouble(abs(r1 / r2 / 1000 - 1)), 0.05, abs(r1 / r2 / 1000 - 1) <= S(1) / S(20));
  } else {
    c.note("Skipped in this scalar: the O(θ³) remainder at θ = 1e-3 (" + toString(toDouble(r2), 3) +
           ") is not 1000× above the rounding of Φ (64 ε θ = " + toString(toDouble(tol<S>(64) * t2), 3) + ").");
  }
}

template <class S> void curvedRegions(Context& c) {
  using V3 = Vec3<S>;
  using V6 = Vec6<S>;
  using T = SE3Tangent<S>;
  auto g = std::mt19937_64(1256);
  // classify random object motions and compare with the simulated sign of Φ at the finger
  const S eps = S(1) / S(10000);
  int agree = 0, n = 0, printedWrong = 0, boundary = 0;
  for (int i = 0; i < 2000; ++i) {
    const S kx = uni<S>(g, -2, 2), ky = uni<S>(g, -2, 2);
    V6 s = rv6<S>(g);
    if (i % 2) s(5) = 0, ++boundary;  // half of them on the first-order boundary v_z = 0
    const auto cls = classifyObjectMotion<S>(kx, ky, T(s));
    if (cls == ContactMotion::ThirdOrder) continue;
    const S phi = objectMotionPhi<S>(kx, ky, s, eps);  // ≤ 0: finger outside, motion feasible
    const bool feasible = phi < 0;
    agree += feasible == (cls == ContactMotion::Separates);
    ++n;
    const S q = secondOrderContactForm<S>(kx, ky, T(s));
    const bool printed = s(5) < 0 && q <= 0;  // "v_z < 0" intersected with "q ≤ 0"
    printedWrong += printed != feasible;
  }
  c.checkEqual("corrected region (v_z < 0, or v_z = 0 and q < 0) = simulated Φ(e^{−εs}·0) < 0, ε = 1e-4", n, agree);
  c.checkPrintedFails("feasible set = {v_z < 0} ∩ {k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x ≤ 0} (misclassified of " +
                     std::to_string(n) + ")", "E12.3", S(printedWrong), S(0));
  // the extremes: flat contact (k = 0) reduces to the polyhedral case; a saddle separates along one slide
  const T slideY(V3::Zero(), V3(0, 1, 0)), slideX(V3::Zero(), V3(1, 0, 0));
  c.checkEqual("flat contact, pure slide: keeps contact to third order (polyhedral case)", "third order",
               classifyObjectMotion<S>(S(0), S(0), slideX) == ContactMotion::ThirdOrder ? "third order" : "decided");
  c.checkEqual("saddle k = (1, −0.5): slide along y separates", "separates",
               classifyObjectMotion<S>(S(1), frac<S>(-1, 2), slideY) == ContactMotion::Separates ? "separates" : "no");
  c.checkEqual("saddle k = (1, −0.5): slide along x penetrates (a dimple direction)", "penetrates",
               classifyObjectMotion<S>(S(1), frac<S>(-1, 2), slideX) == ContactMotion::Penetrates ? "penetrates" : "no");
  c.note("Object moves by e^{εs}, finger fixed at the contact: Φ(finger) = 2 v_z ε + q ε² + O(ε³), q = k_x v_x² + k_y v_y² − "
         "ω_x v_y + ω_y v_x. Feasible: v_z < 0, or v_z = 0 with q ≤ 0 (q = 0 needs third order). The printed rule intersects "
         "'v_z < 0' with 'q ≤ 0', which rejects feasible motions on both counts: v_z = 0 with q < 0 (the strict "
         "inequality) and v_z < 0 with q > 0 (first order already separates). " + std::to_string(boundary) +
         " of the 2000 samples lie on v_z = 0.");
}

// ---- §12.6 --------------------------------------------------------------------------------------
template <class S> void frictionCone(Context& c) {
  using V3 = Vec3<S>;
  using V6 = Vec6<S>;
  auto g = std::mt19937_64(1261);
  S mom = 0, ang = 0, alpha = 0;
  for (const S mu : {frac<S>(1, 5), frac<S>(3, 5), S(1), frac<S>(5, 2)}) {
    for (int i = 0; i < 20; ++i) {
      const V3 p = rv3<S>(g), n = rv3<S>(g).normalized();
      const WrenchSet<S> E = frictionConeEdges<S>(p, n, mu, 16);
      for (int j = 0; j < 16; ++j) {
        const Wrench<S> W{V6(E.col(j))};
        mom = maxOf(mom, S((W.moment() - p.cross(W.force())).norm()));
        ang = maxOf(ang, S(abs(atan2(S(W.force().cross(n).norm()), S(W.force().dot(n))) - atan(mu))));
        // a line through p lies in p's α-plane: it meets every line through p (reciprocal product 0)
        const Wrench<S> other = Wrench<S>::ofForce(p, rv3<S>(g));
        alpha = maxOf(alpha, S(abs(W.moment().dot(other.force()) + W.force().dot(other.moment()))));
      }
    }
  }
  c.checkResidual("edge wrenches have zero moment about the contact point (μ = 0.2, 0.6, 1, 2.5)", mom, tol<S>(256));
  c.checkResidual("semi-angle of the cone = atan μ", ang, tol<S>(256));
  c.checkResidual("cone lines lie in the α-plane of the contact (meet every line through it)", alpha, tol<S>(256));
  // standard form, F ≥ 0, 0 ≤ γ ≤ μ: zero moment
  c.checkResidual("standard form (0,0,0, γF cos θ, γF sin θ, F): zero moment",
                  S(standardFrictionWrench<S>(S(3), frac<S>(2, 5), frac<S>(11, 10)).moment().norm()), S(0));
  // μ = 2.5 (rubber on rubber, handbook value): the cone is built and its half-angle tangent, measured
  // from the edge forces, is 2.5 — outside the printed range [0, 1] by 1.5 (rounding bound 256 ε).
  S muMeasured = 0;
  {
    const V3 n = V3(frac<S>(3, 10), frac<S>(-1, 2), frac<S>(4, 5)).normalized();
    const WrenchSet<S> E = frictionConeEdges<S>(V3(frac<S>(1, 5), frac<S>(1, 10), frac<S>(-2, 5)), n, frac<S>(5, 2), 16);
    for (int j = 0; j < 16; ++j) {
      const V3 f = Wrench<S>{V6(E.col(j))}.force();
      muMeasured = maxOf(muMeasured, S(f.cross(n).norm() / f.dot(n)));
    }
  }
  c.checkNear("μ = 2.5 (rubber on rubber): edge forces at tan⁻¹ 2.5 from the normal (measured tangent)", frac<S>(5, 2), muMeasured, tol<S>(256));
  c.checkPrintedFails("'μ is a number between 0 and 1' — the measured tangent for rubber (μ ≈ 1–2.5) minus 1", "E12.4",
                      S(muMeasured - 1), tol<S>(256));
  c.checkEqual("μ = 0: the cone is a single line (rank of the edge wrenches)", 1,
               wrenchSpan<S>(frictionConeEdges<S>(V3(frac<S>(1, 10), frac<S>(1, 5), frac<S>(3, 10)), V3::UnitZ(), S(0), 8)).rank);
}

template <class S> void twoFingers(Context& c) {
  using V3 = Vec3<S>;
  using T = SE3Tangent<S>;
  auto g = std::mt19937_64(1262);
  S ann = 0;
  int rank5 = 0, spans2 = 0, spans3 = 0;
  const int nPairs = samples<S>(200, 40);
  for (int i = 0; i < nPairs; ++i) {
    const V3 p1 = rv3<S>(g), p2 = rv3<S>(g);
    const V3 n1 = rv3<S>(g).normalized(), n2 = rv3<S>(g).normalized();
    WrenchSet<S> E(6, 16);
    E << frictionConeEdges<S>(p1, n1, S(10), 8), frictionConeEdges<S>(p2, n2, S(10), 8);
    const V3 d = (p2 - p1).normalized();
    ann = maxOf(ann, S((E.transpose() * T(d, V3(p1.cross(d))).coeffs()).cwiseAbs().maxCoeff()));
    rank5 += wrenchSpan<S>(E).rank == 5;
    spans2 += positiveSpan<S>(E).spans;
  }
  const std::string of = " (of " + std::to_string(nPairs) + ")";
  c.checkResidual("every two-finger cone wrench pairs to 0 with the rotation about the joining line (μ = 10)" + of, ann, tol<S>(1024));
  c.checkEqual("two friction cones: rank 5" + of, nPairs, rank5);
  c.checkEqual("two friction cones never force-close" + of, 0, spans2);
  // three fingers: the equator of the unit sphere, normals to the centre
  for (const S mu : {frac<S>(1, 10), frac<S>(1, 2), S(1)}) {
    WrenchSet<S> E(6, 24);
    for (int i = 0; i < 3; ++i) {
      const S th = 2 * pi<S>() * i / 3;
      const V3 q(cos(th), sin(th), 0);
      E.middleCols(8 * i, 8) = frictionConeEdges<S>(q, V3(-q), mu, 8);
    }
    spans3 += positiveSpan<S>(E).spans;
  }
  c.checkEqual("three fingers at 120° on a sphere force-close for μ = 0.1, 0.5, 1", 3, spans3);
  c.note("Three contacts: 6 equations, 9 unknown force components — the grasp is statically indeterminate; the LP finds "
         "a strictly positive combination of the linearised cone edges.");
}

template <class S> void coneDuality(Context& c) {
  using V6 = Vec6<S>;
  using VX = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  // polyhedral cones in R⁶ (wrench space) given by generators; the dual is {f : f·g ≥ 0 ∀ generators}
  auto inDualLp = [](const WrenchSet<S>& gens, const V6& f) {  // min f·x over x ∈ cone, Σλ = 1: ≥ 0 iff f ∈ C*
    const Eigen::Index m = gens.cols();
    const MX A = MX::Ones(1, m);
    const VX b = VX::Ones(1), cc = gens.transpose() * f;
    return minimiseLinearProgram<S>(cc, A, b).value >= -tol<S>(4096);
  };
  // the inputs are drawn in double by Eigen's Random (the same on every rung) and cast to S
  auto rnd6 = [] { return castMatrix<S>(Eigen::Matrix<double, 6, 1>::Random().eval()); };
  auto cst6 = [](int n, int d) { return V6(V6::Constant(frac<S>(n, d))); };
  const int nTrials = samples<S>(300, 60);
  int deMorgan = 0, incl = 0, trials = 0;
  for (int t = 0; t < nTrials; ++t) {
    WrenchSet<S> C1(6, 4), C2(6, 5);
    for (int j = 0; j < 4; ++j) C1.col(j) = rnd6() + cst6(4, 5);
    for (int j = 0; j < 5; ++j) C2.col(j) = rnd6() + cst6(4, 5);
    WrenchSet<S> sum(6, 9);
    sum << C1, C2;
    // C₀ ⊆ C₂: positive combinations of C₂'s generators
    WrenchSet<S> C0(6, 3);
    for (int j = 0; j < 3; ++j) C0.col(j) = C2 * castMatrix<S>(Eigen::VectorXd::Random(5).cwiseAbs().eval());
    const V6 f = rnd6() + cst6(1, 2);
    deMorgan += inDualLp(sum, f) == (inDualLp(C1, f) && inDualLp(C2, f));
    incl += !inDualLp(C2, f) || inDualLp(C0, f);  // f ∈ C₂* ⇒ f ∈ C₀*
    ++trials;
  }
  c.checkEqual("(C₁ + C₂)* = C₁* ∩ C₂* (LP membership, " + std::to_string(trials) + " random cones and f)", trials, deMorgan);
  c.checkEqual("C₀ ⊆ C₂ ⇒ C₂* ⊆ C₀* (" + std::to_string(trials) + ")", trials, incl);
  // the grasp consequence: wrench closure ⟺ the dual cones meet only in 0 (three fingers on a sphere)
  WrenchSet<S> E(6, 24);
  for (int i = 0; i < 3; ++i) {
    const S th = 2 * pi<S>() * i / 3;
    const Vec3<S> q(cos(th), sin(th), 0);
    E.middleCols(8 * i, 8) = frictionConeEdges<S>(q, Vec3<S>(-q), frac<S>(1, 2), 8);
  }
  c.checkEqual("3 fingers: ∩ of dual cones = {0} (dual LP) and the cones positively span (primal LP)", "yes yes",
               yesNo(formClosure<S>(E).closed) + " " + yesNo(positiveSpan<S>(E).spans));
}

/// The dual friction cone as printed: the screws (0, 0, 0, λl cos φ, λl sin φ, l), l ≥ 0, 0 ≤ λ ≤ 1/μ,
/// i.e. ω = 0 and v_z ≥ μ|v_t|.
// GF §12.6 lines 7605–7607 as printed (erratum E12.2)
template <class S> bool inDualFrictionConeAsPrinted(const SE3Tangent<S>& s, const S& mu) {
  return s.ang().squaredNorm() == 0 && inDualFrictionCone<S>(s, mu);
}

template <class S> void dualFrictionCone(Context& c) {
  using V3 = Vec3<S>;
  using T = SE3Tangent<S>;
  auto g = std::mt19937_64(1264);
  const S mu = frac<S>(3, 5);
  int agree = 0, missed = 0, n = 0;
  for (int i = 0; i < 2000; ++i) {
    const V3 w = rv3<S>(g), v = rv3<S>(g);
    const T s(w, v);
    // exact dual test: min over the cone boundary of the pairing (closed form: F(v_z − μ|v_t|) at F = 1)
    const S exact = s.lin().z() - mu * s.lin().template head<2>().norm();
    const bool corr = inDualFrictionCone<S>(s, mu), printed = inDualFrictionConeAsPrinted(s, mu);
    agree += corr == (exact >= 0);
    missed += (exact >= 0) && !printed;
    ++n;
  }
  c.checkEqual("corrected dual {ω free, v_z ≥ μ|v_t|} = {s : 𝒲(s) ≥ 0 ∀ 𝒲 in the cone} (2000 random s)", n, agree);
  c.checkPrintedFails("dual = {(0, 0, 0, λl cos φ, λl sin φ, l)} only: members of the true dual it misses (of 2000)", "E12.2",
                      S(missed), S(0));
  // where it matters: two antipodal fingers on a sphere. Printed duals: translations only, and they meet in {0}
  // (v_x ≥ μ|v_t| and −v_x ≥ μ|v_t|), which would declare the grasp force closed.
  const V3 p1(-1, 0, 0), p2(1, 0, 0);
  WrenchSet<S> E(6, 16);
  E << frictionConeEdges<S>(p1, V3::UnitX(), mu, 8), frictionConeEdges<S>(p2, V3(-V3::UnitX()), mu, 8);
  const T roll(V3::UnitX(), V3::Zero());  // rotation about the joining line
  const bool inBothCorrected = (E.transpose() * roll.coeffs()).minCoeff() >= -tol<S>();
  c.checkEqual("antipodal pair: the roll about the joining line lies in both (corrected) dual cones", "yes", yesNo(inBothCorrected));
  const bool lpClosed = positiveSpan<S>(E).spans;
  c.checkEqual("antipodal pair is not force closed (LP)", "no", yesNo(lpClosed));
  // The printed claim computed: the printed dual at contact i is {ω = 0, v·nᵢ ≥ μ|v − (v·nᵢ)nᵢ|}; the
  // printed reasoning declares the grasp closed when the two printed duals meet only in 0. Count the
  // nonzero twists in both among 2000 random translations, ±x and the roll.
  const V3 n1 = V3::UnitX(), n2 = -V3::UnitX();
  auto inPrintedDual = [&](const T& s, const V3& nn) {
    const V3 v = s.lin();
    return s.ang().squaredNorm() == 0 && v.dot(nn) >= mu * (v - v.dot(nn) * nn).norm();
  };
  std::vector<T> probes = {T(V3::Zero(), V3::UnitX()), T(V3::Zero(), V3(-V3::UnitX())), roll};
  for (int i = 0; i < 2000; ++i) probes.emplace_back(V3::Zero(), rv3<S>(g));
  int common = 0;
  for (const T& s : probes) common += inPrintedDual(s, n1) && inPrintedDual(s, n2);
  const bool printedClosed = common == 0;
  c.checkEqual("antipodal pair: nonzero twists in both printed duals (of 2003 probes: 2000 translations, ±x, the roll)", 0, common);
  c.record("antipodal pair: printed duals meet only in 0 ⇒ 'any wrench can be balanced' [as printed]", "fails (erratum E12.2)",
           std::string("printed verdict: ") + (printedClosed ? "closed" : "not closed") +
               "; LP (positive span of the 16 edge wrenches): " + (lpClosed ? "closed" : "not closed"),
           1, 0, printedClosed && !lpClosed);
}

template <class S> void planarTwoFinger(Context& c) {
  using V2 = Vec2<S>;
  auto g = std::mt19937_64(1265);
  int agree = 0, closed = 0;
  const int n = samples<S>(3000, 600);
  for (int i = 0; i < n; ++i) {
    const S x1 = uni<S>(g), y1 = uni<S>(g), x2 = uni<S>(g), y2 = uni<S>(g);
    const V2 p1(x1, y1), p2(x2, y2);
    const S a1 = uni<S>(g, -3.2, 3.2), a2 = uni<S>(g, -3.2, 3.2), mu = uni<S>(g, 0.05, 1.5);
    const V2 n1(cos(a1), sin(a1)), n2(cos(a2), sin(a2));
    WrenchSet<S> W(3, 4);
    W << planarFrictionConeEdges<S>(p1, n1, mu), planarFrictionConeEdges<S>(p2, n2, mu);
    const bool lp = positiveSpan<S>(W).spans, geo = planarTwoFingerForceClosure<S>(p1, n1, p2, n2, mu);
    agree += lp == geo;
    closed += geo;
  }
  c.checkEqual("geometric criterion = LP (four cone edges positively span se*(2)), " + std::to_string(n) + " random grasps", n, agree);
  c.record("both outcomes occur", "some of each", std::to_string(closed) + " closed of " + std::to_string(n), 0, 0,
           closed > n / 60 && closed < n - n / 60);
  // the boundary: n₁ at atan μ ± δ from the joining line, δ = √ε (1.5e-8 in double; 1e-9 before, which
  // float cannot resolve): far above the tests' rank and LP thresholds (1024 ε), far below any real margin
  const S mu = S(1) / S(2), edge = atan(mu), delta = Tolerance<S>::sqrtEpsilon();
  bool ok = true;
  for (const S d : {S(-delta), delta}) {
    const V2 p1(0, 0), p2(1, 0), n1(cos(edge + d), sin(edge + d)), n2(-1, 0);
    WrenchSet<S> W(3, 4);
    W << planarFrictionConeEdges<S>(p1, n1, mu), planarFrictionConeEdges<S>(p2, n2, mu);
    const bool geo = planarTwoFingerForceClosure<S>(p1, n1, p2, n2, mu), lp = positiveSpan<S>(W).spans;
    ok = ok && geo == (d < 0) && lp == geo;
  }
  c.checkEqual("at the cone edge ± √ε rad both tests switch together", "yes", yesNo(ok));
}

template <class S> void polyhedral(Context& c) {
  using V3 = Vec3<S>;
  using VX = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  // two antipodal fingers squeeze the unit sphere (normal force ≤ 1 each); the largest load force
  // in the tangent plane, along a direction half-way between two cone edges. Exact (circular cones):
  // 2μ. Inscribed k-pyramid: 2μ cos(π/k).
  const S mu = S(1) / S(2);
  std::string tbl;
  S worstLp = 0, prevErr = 0, lastRatio = 0;
  for (const int k : {4, 8, 16, 32, 64}) {
    const V3 p1(1, 0, 0), p2(-1, 0, 0);
    WrenchSet<S> E(6, 2 * k);
    E << frictionConeEdges<S>(p1, V3(-V3::UnitX()), mu, k), frictionConeEdges<S>(p2, V3::UnitX(), mu, k);
    const S a = pi<S>() / k;
    const V3 u = -cos(a) * V3::UnitZ() - sin(a) * V3::UnitY();
    // variables [λ (2k), F, slack₁, slack₂]: E λ − F (0, u) = 0; Σ_finger λ + slack = 1; min −F
    const Eigen::Index nv = 2 * k + 3;
    MX A = MX::Zero(8, nv);
    VX b = VX::Zero(8), cc = VX::Zero(nv);
    A.block(0, 0, 6, 2 * k) = E;
    A.block(3, 2 * k, 3, 1) = -u;
    A.block(6, 0, 1, k).setOnes();
    A.block(7, k, 1, k).setOnes();
    A(6, 2 * k + 1) = A(7, 2 * k + 2) = 1;
    b(6) = b(7) = 1;
    cc(2 * k) = -1;
    const auto lp = minimiseLinearProgram<S>(cc, A, b);
    const S F = -lp.value, expect = 2 * mu * cos(a), err = 2 * mu - F;
    worstLp = maxOf(worstLp, S(abs(F - expect)));
    tbl += "k = " + std::to_string(k) + ": F = " + toString(toDouble(F), 12) + " (exact 2μ = 1, error " + toString(toDouble(err), 3) + "); ";
    if (prevErr > 0) lastRatio = prevErr / err;
    prevErr = err;
  }
  // a simplex solve of 8 equality rows with unit-scale data: 4096 ε (9.1e-13 in double; 1e-12 before)
  c.checkResidual("LP optimum = 2μ cos(π/k) for k = 4 … 64 (4096 ε)", worstLp, tol<S>(4096));
  c.checkNear("error to the exact cone shrinks 4× per doubling of k (1 − cos(π/k) ~ π²/2k²)", S(4), lastRatio, S(1) / S(100));
  c.note("Largest load (normal forces ≤ 1) two antipodal fingers hold on a sphere, μ = 0.5, load direction half-way "
         "between two cone edges: " + tbl + "the exact (second-order-cone) answer is 2μ = 1.");
}

}  // namespace

SOMA_STUDY_SCALAR("GF-12.5-force-closure-frictionless", "Force closure: the contact normals span se*(3) (rank 6, ≥ 6 fingers)", "GF §12.5", forceClosure);
SOMA_STUDY_SCALAR("GF-12.5-ungrippable-surfaces", "Reuleaux surfaces cannot be force-closed without friction (normals in a linear complex)",
     "GF §12.5", ungrippable);
SOMA_STUDY_SCALAR("GF-12.5-positive-grasp-seven", "Push-only frictionless grasps need seven fingers", "GF §12.5", positiveSeven);
SOMA_STUDY_SCALAR("GF-12.5-form-closure", "Form closure = force closure for point fingers on polyhedra (dual linear programs)", "GF §12.5",
     formClosureStudy);
SOMA_STUDY_SCALAR("GF-12.5-second-order-contact", "Second-order contact: v_z = 0 and k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x = 0", "GF §12.5",
     secondOrder);
SOMA_STUDY_SCALAR("GF-12.5-curved-feasible-regions", "Feasible object velocities at a curved contact (erratum E12.3)", "GF §12.5", curvedRegions);
SOMA_STUDY_SCALAR("GF-12.6-friction-cone", "The friction cone: semi-angle atan μ, lines in the α-plane (erratum E12.4)", "GF §12.6", frictionCone);
SOMA_STUDY_SCALAR("GF-12.6-two-fingers-insufficient", "Two friction cones never span se*(3); three fingers do", "GF §12.6", twoFingers);
SOMA_STUDY_SCALAR("GF-12.6-convex-cone-duality", "Dual cones: inclusion reverses, (C₁ + C₂)* = C₁* ∩ C₂*", "GF §12.6", coneDuality);
SOMA_STUDY_SCALAR("GF-12.6-dual-friction-cone", "The dual of the friction cone leaves ω free (erratum E12.2)", "GF §12.6", dualFrictionCone);
SOMA_STUDY_SCALAR("GF-12.6-planar-two-finger-grasp", "Planar two-finger grasps: each contact inside the other's cone", "GF §12.6", planarTwoFinger);
SOMA_STUDY_SCALAR("GF-12.6-polyhedral-approximation", "Linearised friction cones: the LP answer converges like 1/k²", "GF §12.6", polyhedral);

}  // namespace soma::studies::gf12::SOMA_UNITY_ID
