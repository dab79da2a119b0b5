// Studies of GF chapter 12, §12.5–12.6 (double): force closure by the rank test, the surfaces that
// cannot be gripped without friction, positive (push-only) grasps with seven fingers, form closure
// as the dual linear program, second-order contact and the curved feasible regions (erratum
// E12.3), friction cones (E12.4), two fingers never suffice, convex-cone duality and the dual
// friction cone (E12.2), the planar two-finger criterion and the polyhedral approximation.
#include "soma/geometry/statics/grasp.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <functional>
#include <random>

namespace soma::studies::gf12::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 12 — Statics";
using V2 = Vec2<double>;
using V3 = Vec3<double>;
using V6 = Vec6<double>;
using VX = Eigen::VectorXd;
using WS = WrenchSet<double>;
using T = SE3Tangent<double>;
using std::abs;
using std::cos;
using std::sin;

const double kTol = Tolerance<double>::identity(64);
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
std::string yesNo(bool b) { return b ? "yes" : "no"; }

/// A surface as (u, v) ∈ [−1, 1]² ↦ (point, inward normal, not necessarily unit).
using Surface = std::function<std::pair<V3, V3>(double, double)>;
Surface ellipsoid(double a, double b, double cc) {
  return [=](double u, double v) {
    const double th = 3.14159 * u, ph = 1.45 * v;
    const V3 x(a * cos(ph) * cos(th), b * cos(ph) * sin(th), cc * sin(ph));
    return std::pair<V3, V3>{x, V3(-x.x() / (a * a), -x.y() / (b * b), -x.z() / (cc * cc))};
  };
}
WS sample(const Surface& s, int n, std::mt19937_64& g, std::vector<V3>* pts = nullptr, std::vector<V3>* nrm = nullptr) {
  std::vector<V3> p, nn;
  for (int i = 0; i < n; ++i) {
    const auto [x, m] = s(uni(g), uni(g));
    p.push_back(x);
    nn.push_back(m.normalized());
  }
  if (pts) *pts = p;
  if (nrm) *nrm = nn;
  return contactNormalWrenches<double>(p, nn);
}

// ---- §12.5 --------------------------------------------------------------------------------------
void forceClosure(Context& c) {
  auto g = std::mt19937_64(1251);
  const Surface ell = ellipsoid(1.5, 1.0, 0.7);
  int rank6 = 0, rank5 = 0;
  for (int i = 0; i < 200; ++i) {
    rank6 += wrenchSpan<double>(sample(ell, 6, g)).rank == 6;
    rank5 += wrenchSpan<double>(sample(ell, 5, g)).rank == 5;
  }
  c.checkEqual("6 random bilateral contacts on an ellipsoid (1.5, 1, 0.7) span se*(3) (of 200)", 200, rank6);
  c.checkEqual("5 contacts never span: rank 5 (of 200)", 200, rank5);
  // six normal lines of a torus lie in a linear complex: a dependence Σ w_i 𝒩_i = 0
  const Surface torus = [](double u, double v) {
    const double th = 3.14159 * u, ph = 3.14159 * v;
    const V3 d(cos(ph) * cos(th), cos(ph) * sin(th), sin(ph));
    return std::pair<V3, V3>{V3(V3(2 * cos(th), 2 * sin(th), 0) + 0.5 * d), V3(-d)};
  };
  const WS N = sample(torus, 6, g);
  const auto span = wrenchSpan<double>(WS(N.transpose()));  // null vector of N = the weights
  c.checkEqual("six contacts on a torus: rank of [𝒩₁ … 𝒩₆]", 5, wrenchSpan<double>(N).rank);
  c.checkResidual("the dependence Σ w_i 𝒩_i = 0 (w from the SVD, |w| = 1)", (N * span.annihilatedScrews.at(0)).norm(), kTol * 16);
  c.note("The rank test uses the one-sided Jacobi SVD (small_linalg) with Tolerance::rank() = 1024 ε relative to σ₁.");
}

void ungrippable(Context& c) {
  auto g = std::mt19937_64(1252);
  struct Row {
    std::string name;
    Surface s;
    int rank;
  };
  const double p = 0.3;
  const std::vector<Row> rows = {
      {"sphere", ellipsoid(1, 1, 1), 3},
      {"plane", [](double u, double v) { return std::pair<V3, V3>{V3(u, v, 0), V3(0, 0, 1)}; }, 3},
      {"circular cylinder",
       [](double u, double v) { return std::pair<V3, V3>{V3(cos(3 * u), sin(3 * u), v), V3(-cos(3 * u), -sin(3 * u), 0)}; }, 4},
      {"torus (surface of revolution)",
       [](double u, double v) {
         const double th = 3.14159 * u, ph = 3.14159 * v;
         const V3 d(cos(ph) * cos(th), cos(ph) * sin(th), sin(ph));
         return std::pair<V3, V3>{V3(V3(2 * cos(th), 2 * sin(th), 0) + 0.5 * d), V3(-d)};
       }, 5},
      {"helicoid (u cos v, u sin v, 0.3 v)",
       [p](double u, double v) {
         const double r = 0.5 + u, t = 3 * v;
         return std::pair<V3, V3>{V3(r * cos(t), r * sin(t), p * t), V3(V3(cos(t), sin(t), 0).cross(V3(-r * sin(t), r * cos(t), p)))};
       }, 5},
      {"general cylinder over y = x³ − x",
       [](double u, double v) { return std::pair<V3, V3>{V3(u, u * u * u - u, v), V3(3 * u * u - 1, -1, 0)}; }, 5},
      {"ellipsoid (1.5, 1, 0.7)", ellipsoid(1.5, 1, 0.7), 6},
  };
  for (const auto& r : rows) {
    const auto sp = wrenchSpan<double>(sample(r.s, 60, g));
    c.checkEqual("rank of 60 sampled normal lines: " + r.name, r.rank, sp.rank);
    if (r.rank == 5) {
      const VX s = sp.annihilatedScrews.at(0);
      const T t(V6(s / (s.head<3>().norm() > 1e-8 ? s.head<3>().norm() : s.tail<3>().norm())));
      c.note(r.name + ": annihilated screw (ω, v) = (" + toString(t.ang().x(), 3) + ", " + toString(t.ang().y(), 3) + ", " +
             toString(t.ang().z(), 3) + "; " + toString(t.lin().x(), 3) + ", " + toString(t.lin().y(), 3) + ", " +
             toString(t.lin().z(), 3) + ")");
    }
  }
  // the symmetry screws: rotation about z, the helical screw of pitch 0.3, translation along z
  const auto heli = wrenchSpan<double>(sample(rows[4].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("helicoid: annihilated screw has pitch v_z/ω_z = 0.3 (its own helical motion)", 0.3, heli(5) / heli(2), 1e-12);
  const auto tor = wrenchSpan<double>(sample(rows[3].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("torus: annihilated screw is the rotation about z (|ω_z| = 1)", 1.0, abs(tor(2)), 1e-12);
  const auto ext = wrenchSpan<double>(sample(rows[5].s, 60, g)).annihilatedScrews.at(0);
  c.checkNear("general cylinder: annihilated screw is the translation along z (|v_z| = 1)", 1.0, abs(ext(5)), 1e-12);
  // nearly symmetric ellipsoid: σ₆/σ₁ ∝ a − b
  std::string tbl;
  double r1 = 0, r2 = 0;
  for (const double d : {1e-2, 1e-4, 1e-6}) {
    auto g2 = std::mt19937_64(99);
    const auto sp = wrenchSpan<double>(sample(ellipsoid(1 + d, 1, 0.7), 60, g2));
    const double q = sp.singularValues[5] / sp.singularValues[0];
    tbl += "a − b = " + toString(d, 1) + ": σ₆/σ₁ = " + toString(q, 3) + "; ";
    (d == 1e-2 ? r1 : (d == 1e-6 ? r2 : r1)) = d == 1e-2 ? q : (d == 1e-6 ? q : r1);
  }
  c.record("σ₆/σ₁ scales like a − b (ratio over four decades ≈ 1e4)", "1e4 ± 10%", toString(r1 / r2, 4),
           abs(r1 / r2 / 1e4 - 1), 0.1, abs(r1 / r2 / 1e4 - 1) <= 0.1);
  c.note("Nearly symmetric ellipsoid (1 + δ, 1, 0.7): " + tbl + "the sixth direction is the rotation about z, and is "
         "called independent only while σ₆/σ₁ > Tolerance::rank() = 2.3e-13.");
}

void positiveSeven(Context& c) {
  auto g = std::mt19937_64(1253);
  const Surface ell = ellipsoid(1.5, 1.0, 0.7);
  int six = 0, sevenFound = 0, sevenTries = 0;
  for (int i = 0; i < 2000; ++i) six += positiveSpan<double>(sample(ell, 6, g)).spans;
  std::vector<V3> pts, nrm;
  double margin = 0;
  for (; sevenTries < 20000 && !sevenFound; ++sevenTries) {
    const WS N = sample(ell, 7, g, &pts, &nrm);
    const auto ps = positiveSpan<double>(N);
    if (ps.spans) sevenFound = 1, margin = ps.margin;
  }
  c.checkEqual("6 push-only fingers never force-close (2000 random grasps on the ellipsoid)", 0, six);
  c.checkEqual("a 7-finger positive force-closed grasp exists on the ellipsoid (random search)", 1, sevenFound);
  c.note("First 7-finger positively spanning grasp after " + std::to_string(sevenTries) + " random tries; margin max_w min_i w_i = " +
         toString(margin, 3) + " (Σw = 1, unit columns). Six never work: six vectors that span R⁶ are independent, so no "
         "positive combination vanishes.");
  // on a Reuleaux surface no number of frictionless fingers helps
  int sphere = 0;
  for (int i = 0; i < 200; ++i) sphere += positiveSpan<double>(sample(ellipsoid(1, 1, 1), 12, g)).spans;
  c.checkEqual("12 push-only fingers on a sphere never force-close (200 tries)", 0, sphere);
}

void formClosureStudy(Context& c) {
  auto g = std::mt19937_64(1254);
  // point contacts on the faces of the cube [−1, 1]³, inward normals
  int agree = 0, closed = 0, total = 0;
  for (int m = 6; m <= 12; ++m)
    for (int t = 0; t < 60; ++t) {
      std::vector<V3> p, n;
      for (int i = 0; i < m; ++i) {
        const int face = int(uni(g, 0, 6));
        V3 x(uni(g), uni(g), uni(g));
        x(face % 3) = face < 3 ? 1 : -1;
        V3 nn = V3::Zero();
        nn(face % 3) = face < 3 ? -1 : 1;
        p.push_back(x);
        n.push_back(nn);
      }
      const WS N = contactNormalWrenches<double>(p, n);
      const bool force = positiveSpan<double>(N).spans;
      const auto form = formClosure<double>(N);
      agree += force == form.closed;
      closed += force;
      ++total;
      if (!form.closed) {  // the escape velocity keeps every contact
        const double worst = (N.transpose() * form.escape).minCoeff();
        if (worst < -1e-12) agree -= 1000;
      }
    }
  c.checkEqual("form closure (feasible velocities = {0}, dual LP) = force closure (primal LP), cube, 420 grasps", total, agree);
  c.record("both outcomes occur", "some of each", std::to_string(closed) + " closed of " + std::to_string(total),
           0, 0, closed > 20 && closed < total - 20);
  c.note("Feasible object velocities for push-only point contacts: {s : 𝒩_i(s) ≥ 0}. The dual LP maximises Σ 𝒩_i(s) "
         "over |s_j| ≤ 1; a positive optimum is an escape velocity, checked to break no contact.");
}

/// Φ at the finger (fixed at the origin) after the OBJECT moves by e^{εs}: Φ(e^{−εs}·0).
double objectMotionPhi(double kx, double ky, const V6& s, double eps) {
  const V3 q = T(V6(-eps * s)).exp().translation();
  return kx * q.x() * q.x() + ky * q.y() * q.y() - 2 * q.z();
}

void secondOrder(Context& c) {
  auto g = std::mt19937_64(1255);
  double d1 = 0, d2 = 0;
  for (int i = 0; i < 100; ++i) {
    const double kx = uni(g, -2, 2), ky = uni(g, -2, 2);
    V6 s;
    for (int k = 0; k < 6; ++k) s(k) = uni(g);
    // the book's f(t) for the FINGER moving: f(θ) = Φ(e^{θS}·0); exact derivatives of the 4×4 form
    Mat4<double> S = T(s).hat(), Q = Mat4<double>::Zero();
    Q(0, 0) = kx, Q(1, 1) = ky, Q(2, 3) = Q(3, 2) = -1;
    const Vec4<double> o(0, 0, 0, 1);
    const double f1 = o.dot((S.transpose() * Q + Q * S) * o);
    const double f2 = o.dot((S.transpose() * S.transpose() * Q + 2 * S.transpose() * Q * S + Q * S * S) * o);
    d1 = std::max(d1, abs(f1 + 2 * s(5)));
    V6 s0 = s;
    s0(5) = 0;
    Mat4<double> S0 = T(s0).hat();
    const double f20 = o.dot((S0.transpose() * S0.transpose() * Q + 2 * S0.transpose() * Q * S0 + Q * S0 * S0) * o);
    d2 = std::max(d2, abs(f20 / 2 - secondOrderContactForm<double>(kx, ky, T(s0))));
    (void)f2;
  }
  c.checkResidual("ḟ(0) = (0,1)(SᵀQ + QS)(0,1)ᵀ = −2 v_z: first-order contact ⟺ v_z = 0 (100 random)", d1, kTol);
  c.checkResidual("f̈(0)/2 at v_z = 0 = k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x (100 random)", d2, kTol * 4);
  // and against the motion itself: Φ(e^{θs}·0) = −2 v_z θ + q θ² + O(θ³)
  const double kx = 0.8, ky = -0.4;
  V6 s;
  s << 0.3, -0.7, 0.2, 0.5, -0.6, 0.0;
  const double q = secondOrderContactForm<double>(kx, ky, T(s));
  const double r1 = abs(objectMotionPhi(kx, ky, V6(-s), 1e-2) - q * 1e-4), r2 = abs(objectMotionPhi(kx, ky, V6(-s), 1e-3) - q * 1e-6);
  c.record("remainder Φ(e^{θs}·0) − q θ² is O(θ³): ratio for θ = 1e-2 → 1e-3", "≈ 1000", toString(r1 / r2, 4),
           abs(r1 / r2 / 1000 - 1), 0.05, abs(r1 / r2 / 1000 - 1) <= 0.05);
}

void curvedRegions(Context& c) {
  auto g = std::mt19937_64(1256);
  // classify random object motions and compare with the simulated sign of Φ at the finger
  int agree = 0, n = 0, printedWrong = 0, boundary = 0;
  for (int i = 0; i < 2000; ++i) {
    const double kx = uni(g, -2, 2), ky = uni(g, -2, 2);
    V6 s;
    for (int k = 0; k < 6; ++k) s(k) = uni(g);
    if (i % 2) s(5) = 0, ++boundary;  // half of them on the first-order boundary v_z = 0
    const auto cls = classifyObjectMotion<double>(kx, ky, T(s));
    if (cls == ContactMotion::ThirdOrder) continue;
    const double phi = objectMotionPhi(kx, ky, s, 1e-4);  // ≤ 0: finger outside, motion feasible
    const bool feasible = phi < 0;
    agree += feasible == (cls == ContactMotion::Separates);
    ++n;
    const double q = secondOrderContactForm<double>(kx, ky, T(s));
    const bool printed = s(5) < 0 && q <= 0;  // "v_z < 0" intersected with "q ≤ 0"
    printedWrong += printed != feasible;
  }
  c.checkEqual("corrected region (v_z < 0, or v_z = 0 and q < 0) = simulated Φ(e^{−εs}·0) < 0, ε = 1e-4", n, agree);
  c.checkPrintedFails("feasible set = {v_z < 0} ∩ {k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x ≤ 0} (misclassified of " +
                     std::to_string(n) + ")", "E12.3", double(printedWrong), 0.0);
  // the extremes: flat contact (k = 0) reduces to the polyhedral case; a saddle separates along one slide
  const T slideY(V3::Zero(), V3(0, 1, 0)), slideX(V3::Zero(), V3(1, 0, 0));
  c.checkEqual("flat contact, pure slide: keeps contact to third order (polyhedral case)", "third order",
               classifyObjectMotion<double>(0, 0, slideX) == ContactMotion::ThirdOrder ? "third order" : "decided");
  c.checkEqual("saddle k = (1, −0.5): slide along y separates", "separates",
               classifyObjectMotion<double>(1, -0.5, slideY) == ContactMotion::Separates ? "separates" : "no");
  c.checkEqual("saddle k = (1, −0.5): slide along x penetrates (a dimple direction)", "penetrates",
               classifyObjectMotion<double>(1, -0.5, slideX) == ContactMotion::Penetrates ? "penetrates" : "no");
  c.note("Object moves by e^{εs}, finger fixed at the contact: Φ(finger) = 2 v_z ε + q ε² + O(ε³), q = k_x v_x² + k_y v_y² − "
         "ω_x v_y + ω_y v_x. Feasible: v_z < 0, or v_z = 0 with q ≤ 0 (q = 0 needs third order). The printed rule intersects "
         "'v_z < 0' with 'q ≤ 0', which rejects feasible motions on both counts: v_z = 0 with q < 0 (the strict "
         "inequality) and v_z < 0 with q > 0 (first order already separates). " + std::to_string(boundary) +
         " of the 2000 samples lie on v_z = 0.");
}

// ---- §12.6 --------------------------------------------------------------------------------------
void frictionCone(Context& c) {
  auto g = std::mt19937_64(1261);
  double mom = 0, ang = 0, alpha = 0;
  for (const double mu : {0.2, 0.6, 1.0, 2.5}) {
    for (int i = 0; i < 20; ++i) {
      const V3 p(uni(g), uni(g), uni(g)), n = V3(uni(g), uni(g), uni(g)).normalized();
      const WS E = frictionConeEdges<double>(p, n, mu, 16);
      for (int j = 0; j < 16; ++j) {
        const Wrench<double> W{V6(E.col(j))};
        mom = std::max(mom, (W.moment() - p.cross(W.force())).norm());
        ang = std::max(ang, abs(std::atan2(W.force().cross(n).norm(), W.force().dot(n)) - std::atan(mu)));
        // a line through p lies in p's α-plane: it meets every line through p (reciprocal product 0)
        const Wrench<double> other = Wrench<double>::ofForce(p, V3(uni(g), uni(g), uni(g)));
        alpha = std::max(alpha, abs(W.moment().dot(other.force()) + W.force().dot(other.moment())));
      }
    }
  }
  c.checkResidual("edge wrenches have zero moment about the contact point (μ = 0.2, 0.6, 1, 2.5)", mom, kTol * 4);
  c.checkResidual("semi-angle of the cone = atan μ", ang, kTol * 4);
  c.checkResidual("cone lines lie in the α-plane of the contact (meet every line through it)", alpha, kTol * 4);
  // standard form, F ≥ 0, 0 ≤ γ ≤ μ: zero moment
  c.checkResidual("standard form (0,0,0, γF cos θ, γF sin θ, F): zero moment",
                  standardFrictionWrench<double>(3, 0.4, 1.1).moment().norm(), 0.0);
  // μ = 2.5 (rubber on rubber, handbook value): the cone is built and its half-angle tangent, measured
  // from the edge forces, is 2.5 — outside the printed range [0, 1] by 1.5 (rounding bound kTol·4).
  double muMeasured = 0;
  {
    const V3 n = V3(0.3, -0.5, 0.8).normalized();
    const WS E = frictionConeEdges<double>(V3(0.2, 0.1, -0.4), n, 2.5, 16);
    for (int j = 0; j < 16; ++j) {
      const V3 f = Wrench<double>{V6(E.col(j))}.force();
      muMeasured = std::max(muMeasured, f.cross(n).norm() / f.dot(n));
    }
  }
  c.checkNear("μ = 2.5 (rubber on rubber): edge forces at tan⁻¹ 2.5 from the normal (measured tangent)", 2.5, muMeasured, kTol * 4);
  c.checkPrintedFails("'μ is a number between 0 and 1' — the measured tangent for rubber (μ ≈ 1–2.5) minus 1", "E12.4",
                      muMeasured - 1.0, kTol * 4);
  c.checkEqual("μ = 0: the cone is a single line (rank of the edge wrenches)", 1,
               wrenchSpan<double>(frictionConeEdges<double>(V3(0.1, 0.2, 0.3), V3::UnitZ(), 0.0, 8)).rank);
}

void twoFingers(Context& c) {
  auto g = std::mt19937_64(1262);
  double ann = 0;
  int rank5 = 0, spans2 = 0, spans3 = 0;
  for (int i = 0; i < 200; ++i) {
    const V3 p1(uni(g), uni(g), uni(g)), p2(uni(g), uni(g), uni(g));
    WS E(6, 16);
    E << frictionConeEdges<double>(p1, V3(uni(g), uni(g), uni(g)).normalized(), 10.0, 8),
        frictionConeEdges<double>(p2, V3(uni(g), uni(g), uni(g)).normalized(), 10.0, 8);
    const V3 d = (p2 - p1).normalized();
    ann = std::max(ann, (E.transpose() * T(d, V3(p1.cross(d))).coeffs()).cwiseAbs().maxCoeff());
    rank5 += wrenchSpan<double>(E).rank == 5;
    spans2 += positiveSpan<double>(E).spans;
  }
  c.checkResidual("every two-finger cone wrench pairs to 0 with the rotation about the joining line (200, μ = 10)", ann, kTol * 16);
  c.checkEqual("two friction cones: rank 5 (of 200)", 200, rank5);
  c.checkEqual("two friction cones never force-close (of 200)", 0, spans2);
  // three fingers: the equator of the unit sphere, normals to the centre
  for (const double mu : {0.1, 0.5, 1.0}) {
    WS E(6, 24);
    for (int i = 0; i < 3; ++i) {
      const double th = 2 * pi<double>() * i / 3;
      const V3 q(cos(th), sin(th), 0);
      E.middleCols(8 * i, 8) = frictionConeEdges<double>(q, V3(-q), mu, 8);
    }
    spans3 += positiveSpan<double>(E).spans;
  }
  c.checkEqual("three fingers at 120° on a sphere force-close for μ = 0.1, 0.5, 1", 3, spans3);
  c.note("Three contacts: 6 equations, 9 unknown force components — the grasp is statically indeterminate; the LP finds "
         "a strictly positive combination of the linearised cone edges.");
}

void coneDuality(Context& c) {
  auto g = std::mt19937_64(1263);
  // polyhedral cones in R⁶ (wrench space) given by generators; the dual is {f : f·g ≥ 0 ∀ generators}
  auto inDualLp = [](const WS& gens, const V6& f) {  // min f·x over x ∈ cone, Σλ = 1: ≥ 0 iff f ∈ C*
    const Eigen::Index m = gens.cols();
    Eigen::MatrixXd A = Eigen::MatrixXd::Ones(1, m);
    Eigen::VectorXd b = Eigen::VectorXd::Ones(1), cc = gens.transpose() * f;
    return minimiseLinearProgram<double>(cc, A, b).value >= -1e-12;
  };
  int deMorgan = 0, incl = 0, trials = 0;
  for (int t = 0; t < 300; ++t) {
    WS C1(6, 4), C2(6, 5);
    for (int j = 0; j < 4; ++j) C1.col(j) = V6::Random() + V6::Constant(0.8);
    for (int j = 0; j < 5; ++j) C2.col(j) = V6::Random() + V6::Constant(0.8);
    WS sum(6, 9);
    sum << C1, C2;
    // C₀ ⊆ C₂: positive combinations of C₂'s generators
    WS C0(6, 3);
    for (int j = 0; j < 3; ++j) C0.col(j) = C2 * Eigen::VectorXd::Random(5).cwiseAbs();
    V6 f = V6::Random() + V6::Constant(0.5);
    (void)g;
    deMorgan += inDualLp(sum, f) == (inDualLp(C1, f) && inDualLp(C2, f));
    incl += !inDualLp(C2, f) || inDualLp(C0, f);  // f ∈ C₂* ⇒ f ∈ C₀*
    ++trials;
  }
  c.checkEqual("(C₁ + C₂)* = C₁* ∩ C₂* (LP membership, 300 random cones and f)", trials, deMorgan);
  c.checkEqual("C₀ ⊆ C₂ ⇒ C₂* ⊆ C₀* (300)", trials, incl);
  // the grasp consequence: wrench closure ⟺ the dual cones meet only in 0 (three fingers on a sphere)
  WS E(6, 24);
  for (int i = 0; i < 3; ++i) {
    const double th = 2 * pi<double>() * i / 3;
    const V3 q(cos(th), sin(th), 0);
    E.middleCols(8 * i, 8) = frictionConeEdges<double>(q, V3(-q), 0.5, 8);
  }
  c.checkEqual("3 fingers: ∩ of dual cones = {0} (dual LP) and the cones positively span (primal LP)", "yes yes",
               yesNo(formClosure<double>(E).closed) + " " + yesNo(positiveSpan<double>(E).spans));
}

/// The dual friction cone as printed: the screws (0, 0, 0, λl cos φ, λl sin φ, l), l ≥ 0, 0 ≤ λ ≤ 1/μ,
/// i.e. ω = 0 and v_z ≥ μ|v_t|.
// GF §12.6 lines 7605–7607 as printed (erratum E12.2)
bool inDualFrictionConeAsPrinted(const T& s, double mu) { return s.ang().squaredNorm() == 0 && inDualFrictionCone<double>(s, mu); }

void dualFrictionCone(Context& c) {
  auto g = std::mt19937_64(1264);
  const double mu = 0.6;
  int agree = 0, missed = 0, n = 0;
  for (int i = 0; i < 2000; ++i) {
    const T s(V3(uni(g), uni(g), uni(g)), V3(uni(g), uni(g), uni(g)));
    // exact dual test: min over the cone boundary of the pairing (closed form: F(v_z − μ|v_t|) at F = 1)
    const double exact = s.lin().z() - mu * s.lin().head<2>().norm();
    const bool corr = inDualFrictionCone<double>(s, mu), printed = inDualFrictionConeAsPrinted(s, mu);
    agree += corr == (exact >= 0);
    missed += (exact >= 0) && !printed;
    ++n;
  }
  c.checkEqual("corrected dual {ω free, v_z ≥ μ|v_t|} = {s : 𝒲(s) ≥ 0 ∀ 𝒲 in the cone} (2000 random s)", n, agree);
  c.checkPrintedFails("dual = {(0, 0, 0, λl cos φ, λl sin φ, l)} only: members of the true dual it misses (of 2000)", "E12.2",
              double(missed), 0.0);
  // where it matters: two antipodal fingers on a sphere. Printed duals: translations only, and they meet in {0}
  // (v_x ≥ μ|v_t| and −v_x ≥ μ|v_t|), which would declare the grasp force closed.
  const V3 p1(-1, 0, 0), p2(1, 0, 0);
  WS E(6, 16);
  E << frictionConeEdges<double>(p1, V3::UnitX(), mu, 8), frictionConeEdges<double>(p2, V3(-V3::UnitX()), mu, 8);
  const T roll(V3::UnitX(), V3::Zero());  // rotation about the joining line
  const bool inBothCorrected = (E.transpose() * roll.coeffs()).minCoeff() >= -kTol;
  c.checkEqual("antipodal pair: the roll about the joining line lies in both (corrected) dual cones", "yes", yesNo(inBothCorrected));
  c.checkEqual("antipodal pair is not force closed (LP)", "no", yesNo(positiveSpan<double>(E).spans));
  // The printed claim computed: the printed dual at contact i is {ω = 0, v·nᵢ ≥ μ|v − (v·nᵢ)nᵢ|}; the
  // printed reasoning declares the grasp closed when the two printed duals meet only in 0. Count the
  // nonzero twists in both among 2000 random translations, ±x and the roll.
  const V3 n1 = V3::UnitX(), n2 = -V3::UnitX();
  auto inPrintedDual = [&](const T& s, const V3& n) {
    const V3 v = s.lin();
    return s.ang().squaredNorm() == 0 && v.dot(n) >= mu * (v - v.dot(n) * n).norm();
  };
  std::vector<T> probes = {T(V3::Zero(), V3::UnitX()), T(V3::Zero(), -V3::UnitX()), roll};
  for (int i = 0; i < 2000; ++i) probes.emplace_back(V3::Zero(), V3(uni(g), uni(g), uni(g)));
  int common = 0;
  for (const T& s : probes) common += inPrintedDual(s, n1) && inPrintedDual(s, n2);
  const bool printedClosed = common == 0;
  c.checkEqual("antipodal pair: nonzero twists in both printed duals (of 2003 probes: 2000 translations, ±x, the roll)", 0, common);
  c.record("antipodal pair: printed duals meet only in 0 ⇒ 'any wrench can be balanced' [as printed]", "fails (erratum E12.2)",
           std::string("printed verdict: ") + (printedClosed ? "closed" : "not closed") +
               "; LP (positive span of the 16 edge wrenches): " + (positiveSpan<double>(E).spans ? "closed" : "not closed"),
           1, 0, printedClosed && !positiveSpan<double>(E).spans);
}

void planarTwoFinger(Context& c) {
  auto g = std::mt19937_64(1265);
  int agree = 0, closed = 0;
  const int n = 3000;
  for (int i = 0; i < n; ++i) {
    const V2 p1(uni(g), uni(g)), p2(uni(g), uni(g));
    const double a1 = uni(g, -3.2, 3.2), a2 = uni(g, -3.2, 3.2), mu = uni(g, 0.05, 1.5);
    const V2 n1(cos(a1), sin(a1)), n2(cos(a2), sin(a2));
    WS W(3, 4);
    W << planarFrictionConeEdges<double>(p1, n1, mu), planarFrictionConeEdges<double>(p2, n2, mu);
    const bool lp = positiveSpan<double>(W).spans, geo = planarTwoFingerForceClosure<double>(p1, n1, p2, n2, mu);
    agree += lp == geo;
    closed += geo;
  }
  c.checkEqual("geometric criterion = LP (four cone edges positively span se*(2)), 3000 random grasps", n, agree);
  c.record("both outcomes occur", "some of each", std::to_string(closed) + " closed of " + std::to_string(n), 0, 0,
           closed > 50 && closed < n - 50);
  // the boundary: n₁ at atan μ ± δ from the joining line
  const double mu = 0.5, edge = std::atan(mu);
  std::string side;
  bool ok = true;
  for (const double d : {-1e-9, 1e-9}) {
    const V2 p1(0, 0), p2(1, 0), n1(cos(edge + d), sin(edge + d)), n2(-1, 0);
    WS W(3, 4);
    W << planarFrictionConeEdges<double>(p1, n1, mu), planarFrictionConeEdges<double>(p2, n2, mu);
    const bool geo = planarTwoFingerForceClosure<double>(p1, n1, p2, n2, mu), lp = positiveSpan<double>(W).spans;
    ok = ok && geo == (d < 0) && lp == geo;
  }
  c.checkEqual("at the cone edge ± 1e-9 rad both tests switch together", "yes", yesNo(ok));
}

void polyhedral(Context& c) {
  // two antipodal fingers squeeze the unit sphere (normal force ≤ 1 each); the largest load force
  // in the tangent plane, along a direction half-way between two cone edges. Exact (circular cones):
  // 2μ. Inscribed k-pyramid: 2μ cos(π/k).
  const double mu = 0.5;
  std::string tbl;
  bool all = true;
  double prevErr = 0, lastRatio = 0;
  for (const int k : {4, 8, 16, 32, 64}) {
    const V3 p1(1, 0, 0), p2(-1, 0, 0);
    WS E(6, 2 * k);
    E << frictionConeEdges<double>(p1, V3(-V3::UnitX()), mu, k), frictionConeEdges<double>(p2, V3::UnitX(), mu, k);
    const double a = pi<double>() / k;
    const V3 u = -cos(a) * V3::UnitZ() - sin(a) * V3::UnitY();
    // variables [λ (2k), F, slack₁, slack₂]: E λ − F (0, u) = 0; Σ_finger λ + slack = 1; min −F
    const Eigen::Index nv = 2 * k + 3;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(8, nv);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(8), cc = Eigen::VectorXd::Zero(nv);
    A.block(0, 0, 6, 2 * k) = E;
    A.block(3, 2 * k, 3, 1) = -u;
    A.block(6, 0, 1, k).setOnes();
    A.block(7, k, 1, k).setOnes();
    A(6, 2 * k + 1) = A(7, 2 * k + 2) = 1;
    b(6) = b(7) = 1;
    cc(2 * k) = -1;
    const auto lp = minimiseLinearProgram<double>(cc, A, b);
    const double F = -lp.value, expect = 2 * mu * cos(a), err = 2 * mu - F;
    all = all && abs(F - expect) <= 1e-12;
    tbl += "k = " + std::to_string(k) + ": F = " + toString(F, 12) + " (exact 2μ = 1, error " + toString(err, 3) + "); ";
    if (prevErr > 0) lastRatio = prevErr / err;
    prevErr = err;
  }
  c.checkEqual("LP optimum = 2μ cos(π/k) for k = 4 … 64 (to 1e-12)", "yes", yesNo(all));
  c.checkNear("error to the exact cone shrinks 4× per doubling of k (1 − cos(π/k) ~ π²/2k²)", 4.0, lastRatio, 0.01);
  c.note("Largest load (normal forces ≤ 1) two antipodal fingers hold on a sphere, μ = 0.5, load direction half-way "
         "between two cone edges: " + tbl + "the exact (second-order-cone) answer is 2μ = 1.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-12.5-force-closure-frictionless", "Force closure: the contact normals span se*(3) (rank 6, ≥ 6 fingers)", "GF §12.5", forceClosure);
SOMA_STUDY_DOUBLE("GF-12.5-ungrippable-surfaces", "Reuleaux surfaces cannot be force-closed without friction (normals in a linear complex)",
     "GF §12.5", ungrippable);
SOMA_STUDY_DOUBLE("GF-12.5-positive-grasp-seven", "Push-only frictionless grasps need seven fingers", "GF §12.5", positiveSeven);
SOMA_STUDY_DOUBLE("GF-12.5-form-closure", "Form closure = force closure for point fingers on polyhedra (dual linear programs)", "GF §12.5",
     formClosureStudy);
SOMA_STUDY_DOUBLE("GF-12.5-second-order-contact", "Second-order contact: v_z = 0 and k_x v_x² + k_y v_y² − ω_x v_y + ω_y v_x = 0", "GF §12.5",
     secondOrder);
SOMA_STUDY_DOUBLE("GF-12.5-curved-feasible-regions", "Feasible object velocities at a curved contact (erratum E12.3)", "GF §12.5", curvedRegions);
SOMA_STUDY_DOUBLE("GF-12.6-friction-cone", "The friction cone: semi-angle atan μ, lines in the α-plane (erratum E12.4)", "GF §12.6", frictionCone);
SOMA_STUDY_DOUBLE("GF-12.6-two-fingers-insufficient", "Two friction cones never span se*(3); three fingers do", "GF §12.6", twoFingers);
SOMA_STUDY_DOUBLE("GF-12.6-convex-cone-duality", "Dual cones: inclusion reverses, (C₁ + C₂)* = C₁* ∩ C₂*", "GF §12.6", coneDuality);
SOMA_STUDY_DOUBLE("GF-12.6-dual-friction-cone", "The dual of the friction cone leaves ω free (erratum E12.2)", "GF §12.6", dualFrictionCone);
SOMA_STUDY_DOUBLE("GF-12.6-planar-two-finger-grasp", "Planar two-finger grasps: each contact inside the other's cone", "GF §12.6", planarTwoFinger);
SOMA_STUDY_DOUBLE("GF-12.6-polyhedral-approximation", "Linearised friction cones: the LP answer converges like 1/k²", "GF §12.6", polyhedral);

}  // namespace soma::studies::gf12::SOMA_UNITY_ID
