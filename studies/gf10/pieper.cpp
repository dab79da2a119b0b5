// Studies of GF §10.3 (Pieper robots: three consecutive axes meeting or parallel), in the scalar
// asked for: the T³ robot, the PUMA 560, the count theorem, the algorithm on every triple position,
// the closing remark on singularities; and Fig. 10.2 (all postures of the T³ for one pose; double,
// as soma::render draws).
#include "soma/geometry/serial/closed_form_ik.hpp"
#include "soma/render/render.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <map>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;
using std::abs;
using std::atan2;
using std::cos;
using std::sin;
using std::sqrt;

using draws::frac;
using draws::maxOf;
using draws::minOf;  // soma/studies/scalar_draws.hpp

/// Joint values uniform in [−3, 3], drawn in double (the same on every rung) and cast to S.
template <class S> JointVector<S> randomQ(std::mt19937_64& g, int n) {
  std::uniform_real_distribution<double> u(-3, 3);
  JointVector<S> q(n);
  for (int i = 0; i < n; ++i) q(i) = scalarCast<S>(u(g));
  return q;
}

/// How far a returned posture may lie from the true q: to first order |Δq| ≤ r/σ_min(J(q)) for a pose
/// residual r, so max(√ε, 2r/σ_min). In double (r ~ 1e-14) √ε = 1.5e-8 decides unless σ_min < 1e-6; in
/// float, where r is ~1e-6 and σ_min down to 2e-5 (condition 1e5), a true posture lies up to 5e-3 rad
/// from its solution (measured on the 17 such draws: at most 0.83 r/σ_min).
template <class S> S jointTolerance(const SerialRobot<S>& robot, const JointVector<S>& q, const Solution<S>& sol) {
  return maxOf(Tolerance<S>::sqrtEpsilon(), S(2 * sol.worstResidual() / singularityMeasures(robot, q).smallestSingularValue));
}

/// The posture q is among the solutions: every joint within `tol` (sin of the difference; cos > 0).
template <class S> bool contains(const Solution<S>& sol, const JointVector<S>& q, const S& tol) {
  for (const auto& p : sol.postures) {
    bool same = true;
    for (int i = 0; i < q.size(); ++i)
      if (abs(sin(p(i) - q(i))) > tol || cos(p(i) - q(i)) < 0) same = false;
    if (same) return true;
  }
  return false;
}

/// Round trips over random joint vectors: worst residual, recovery rate, count histogram.
template <class S> struct Sweep {
  S worst = 0;
  int recovered = 0, odd = 0, over = 0, trials = 0;
  std::map<int, int> counts;
};
template <class S> Sweep<S> sweep(const SerialRobot<S>& robot, int trials, std::uint64_t seed, int maxCount) {
  std::mt19937_64 g(seed);
  Sweep<S> s;
  for (int k = 0; k < trials; ++k) {
    const JointVector<S> q = randomQ<S>(g, robot.dof());
    const auto sol = solveClosedForm(robot, robot.fk(q), IkMethod::Auto);
    s.worst = maxOf(s.worst, sol.worstResidual());
    if (contains(sol, q, jointTolerance(robot, q, sol))) ++s.recovered;
    if (sol.count() % 2) ++s.odd;
    if (int(sol.count()) > maxCount) ++s.over;
    ++s.counts[int(sol.count())];
    ++s.trials;
  }
  return s;
}
template <class S> std::string histogram(const Sweep<S>& s) {
  std::string h;
  for (const auto& [n, k] : s.counts) h += fmt::format("{}{}×{}", h.empty() ? "" : ", ", k, n);
  return h;
}
template <class S> void recordSweep(Context& c, const std::string& what, const Sweep<S>& s, int maxCount) {
  c.checkEqual(what + ": the true posture is among the solutions, each joint within max(√ε, 2r/σ_min) (random joints → pose → IK)",
               s.trials, s.recovered);
  c.checkEqual(what + ": counts are even", 0, s.odd);
  c.checkEqual(what + fmt::format(": counts ≤ {}", maxCount), 0, s.over);
  c.checkResidual(what + ": worst pose residual over all postures", s.worst, Tolerance<S>::identity(4096));
  c.note(what + ": posture counts " + histogram(s));
}

// GF §10.3, GF-10.3-pieper-theorem
template <class S> void pieperTheorem(Context& c) {
  const Sweep<S> t3 = sweep(t3Robot<S>(), 200, 101, 8), pm = sweep(puma560Robot<S>(), 200, 102, 8);
  recordSweep(c, "T³ (axes 2-4 parallel)", t3, 8);
  recordSweep(c, "PUMA 560 (axes 4-6 meet)", pm, 8);
  c.checkEqual("T³: 8 postures occur", 1, t3.counts.count(8) ? 1 : 0);
  c.checkEqual("T³: 4-posture poses occur (one branch unreachable, as the catalogue observed)", 1,
               t3.counts.count(4) ? 1 : 0);
  c.checkEqual("PUMA 560: 8 postures occur", 1, pm.counts.count(8) ? 1 : 0);
}

// GF §10.3.1, GF-10.3.1-pieper-algorithm (errata E10.2, E10.3: the fixed-point equation uses
// a4*a3*a2*, and k' = a1* k a6* a5*, as implemented)
template <class S> void pieperAlgorithm(Context& c) {
  std::mt19937_64 g(103);
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(-1, 1);
  // Draws in double (the same on every rung), cast to S.
  auto unit = [&] {
    const double x = n(g), y = n(g), z = n(g);
    const Vec3<S> v(scalarCast<S>(x), scalarCast<S>(y), scalarCast<S>(z));
    return Vec3<S>(v / sqrt(v.squaredNorm()));
  };
  auto uv = [&] {
    const double x = u(g), y = u(g), z = u(g);
    return Vec3<S>(scalarCast<S>(x), scalarCast<S>(y), scalarCast<S>(z));
  };
  for (int first = 0; first < 4; ++first)
    for (bool concurrent : {true, false}) {
      Sweep<S> all;
      for (int k = 0; k < 25; ++k) {
        std::vector<SerialJoint<S>> js(6);
        for (auto& j : js) {
          j.axis = unit();
          j.point = uv();
        }
        const Vec3<S> p = uv(), d = unit();
        for (int i = first; i < first + 3; ++i) (concurrent ? js[i].point : js[i].axis) = concurrent ? p : d;
        const auto robot = SerialRobot<S>::fromPOE(js, SE3<S>::Random(g));
        const Sweep<S> s = sweep(robot, 4, 200 + k, 8);
        all.worst = maxOf(all.worst, s.worst);
        all.recovered += s.recovered, all.odd += s.odd, all.over += s.over, all.trials += s.trials;
        for (const auto& [m, cnt] : s.counts) all.counts[m] += cnt;
      }
      recordSweep(c, fmt::format("axes {}-{} {} (25 random robots × 4 poses)", first + 1, first + 3,
                                 concurrent ? "meet" : "parallel"), all, 8);
    }
}

// GF §10.3.2: the book's intermediate formulas of the T³ solution, printed and corrected, evaluated
// at the postures of a pose (E10.4, E10.5, E10.6, E10.8). k = T M⁻¹ = (R, t) (rotation φ about v);
// the plane a₁πa₁* has normal n = (cos θ₁, sin θ₁, 0) through 0, and k*(·)k moves it by k⁻¹.
template <class S>
void t3PrintedForms(Context& c, const SerialRobot<S>& robot, const SE3<S>& T, const Solution<S>& sol, const S& l1,
                    const S& l2, const S& l3) {
  // The corrected forms are a few products of O(1) numbers: rounding within 64 ε (1.4e-14 in double);
  // the printed forms must miss by more than 10³ times that (checkPrintedFails).
  const S tol = Tolerance<S>::identity(64);
  const SE3<S> k = T * robot.home().inverse();
  const Mat3<S> R = k.rotation().matrix();
  const Vec3<S> t = k.translation(), tp = -R.transpose() * t;  // t′ = −Rᵀt: the translation of k⁻¹
  const S L = l1 + l2 + l3;
  const Eigen::AngleAxis<S> aa(R);
  const Vec3<S> v = aa.axis();
  const S phi = aa.angle();
  const S huge = std::numeric_limits<float>::max();
  S printedD = huge, corrD = 0, worstAlpha = 0, printedAlpha = huge, typoAlpha = huge;
  // α, β as printed after the OCR repairs (t_z − l₁ − l₂ − l₃; α's last term v_x(v·w)), in terms of a
  // translation u: α = (R w)_x, β = (R w)_y with w = u − L e₃ (the book's expansion of R).
  auto alphaBeta = [&](const Vec3<S>& u) {
    const Vec3<S> w(u.x(), u.y(), u.z() - L);
    const Vec3<S> Rw = cos(phi) * w + sin(phi) * v.cross(w) + (S(1) - cos(phi)) * v * v.dot(w);
    return Vec2<S>(Rw.x(), Rw.y());
  };
  for (const auto& p : sol.postures) {
    const Vec3<S> n(cos(p(0)), sin(p(0)), S(0)), N = R.transpose() * n;
    // D − L N_z = 0 at every posture: with D = N·(−Rᵀt) (corrected), not N·t (printed).
    corrD = maxOf(corrD, abs(N.dot(tp) - L * N.z()));
    printedD = minOf(printedD, abs(N.dot(t) - L * N.z()));
    // α cos θ₁ + β sin θ₁ = 0 (γ = 0): corrected with t′; the typo-repaired α, β with t fail (E10.4).
    const Vec2<S> ab = alphaBeta(tp), abPrinted = alphaBeta(t);
    worstAlpha = maxOf(worstAlpha, abs(ab.x() * n.x() + ab.y() * n.y()));
    printedAlpha = minOf(printedAlpha, abs(abPrinted.x() * n.x() + abPrinted.y() * n.y()));
    // α with its printed typo "t_y − l₁ − l₂ − l₂" in the first line (and t′): E10.5.
    const Vec3<S> w(tp.x(), tp.y(), tp.z() - L);
    const S alphaTypo = ((1 - v.x() * v.x()) * w.x() - v.x() * v.y() * w.y() - v.x() * v.z() * (tp.y() - l1 - 2 * l2)) * cos(phi) +
                        (v.y() * w.z() - v.z() * w.y()) * sin(phi) + v.x() * v.dot(w);
    typoAlpha = minOf(typoAlpha, abs(alphaTypo * n.x() + ab.y() * n.y()));
  }
  c.checkResidual("D − (l1+l2+l3)N_z = 0 at every posture with D = N·(−Rᵀt) (corrected, E10.4)", corrD, tol);
  c.checkPrintedFails("D = N_x t_x + N_y t_y + N_z t_z: D − (l1+l2+l3)N_z at the postures (smallest)", "E10.4", printedD, tol);
  c.checkResidual("α cos θ1 + β sin θ1 = 0 (γ = 0) with α, β in t′ = −Rᵀt (E10.4, E10.5 repaired)", worstAlpha, tol);
  c.checkPrintedFails("… the same α, β in t as printed (smallest over the postures)", "E10.4", printedAlpha, tol);
  c.checkPrintedFails("… α with the printed \"t_y − l1 − l2 − l2\" (smallest)", "E10.5", typoAlpha, tol);
  // The rotor printed r = cos φ/2 + v_x sin φ/2 e₂e₃ + v_y sin φ/2 e₃e₁ + v_x sin φ/2 e₁e₂ is not a unit
  // rotor unless v_x = ±v_z: |r r̃ − 1| = sin²(φ/2)|v_x² − v_z²| (E10.5: the last v_x is v_z).
  {
    const S s = sin(phi / 2);
    const S printedNorm = abs(cos(phi / 2) * cos(phi / 2) + s * s * (2 * v.x() * v.x() + v.y() * v.y()) - 1);
    const S corrNorm = abs(cos(phi / 2) * cos(phi / 2) + s * s * v.squaredNorm() - 1);
    c.checkResidual("rotor cos φ/2 + sin φ/2 (v_x e₂e₃ + v_y e₃e₁ + v_z e₁e₂) is a unit rotor (E10.5 corrected)", corrNorm, Tolerance<S>::identity(16));
    c.checkPrintedFails("… with v_x in place of v_z as printed: |r r̃ − 1|", "E10.5", printedNorm, Tolerance<S>::identity(16));
  }
  // E10.6 and E10.8: the position of axis 4 after a₂a₃ (LHS) and after k′ = a₂a₃a₄ (RHS), in the
  // yz-plane: X e₂𝐞 + Y e₃𝐞 with X = z, Y = −y of the moved axis point (0, 0, l₁ + l₂).
  S lhsCorr = 0, lhsPrinted = huge, rhsCorr = 0, rhsPrinted = huge, theta2Corr = 0;
  for (const auto& p : sol.postures) {
    const Vec3<S> r4 = robot.joints()[1].motion(p(1)).act(robot.joints()[2].motion(p(2)).act(robot.joints()[3].point));
    const S c2 = cos(p(1)), s2 = sin(p(1)), c3 = cos(p(2)), s3 = sin(p(2));
    auto lhs = [&](const S& lk) {
      return Vec2<S>(c2 * (l1 + l2 * c3) - lk * s2 * s3, s2 * (l1 + l2 * c3) + lk * c2 * s3);
    };
    const Vec2<S> truth(r4.z(), -r4.y());
    lhsCorr = maxOf(lhsCorr, (lhs(l2) - truth).norm());
    lhsPrinted = minOf(lhsPrinted, (lhs(l1) - truth).norm());
    const SE3<S> kp = robot.joints()[1].motion(p(1)) * robot.joints()[2].motion(p(2)) * robot.joints()[3].motion(p(3));
    const Mat3<S> Rp = kp.rotation().matrix();
    const S phip = atan2(Rp(2, 1), Rp(1, 1));  // rotation about x
    const Vec3<S> tt = kp.translation();
    const Vec2<S> xyCorr((l1 + l2) * cos(phip) + tt.z(), (l1 + l2) * sin(phip) - tt.y());
    const Vec2<S> xyPrinted((l2 + l3) * cos(phip) + tt.z(), (l2 + l3) * sin(phip) - tt.z());
    rhsCorr = maxOf(rhsCorr, (xyCorr - truth).norm());
    rhsPrinted = minOf(rhsPrinted, (xyPrinted - truth).norm());
    // θ₂ from the corrected X, Y (the book's formula printed next to them)
    const S s2sq = l1 * l1 + l2 * l2 + 2 * l1 * l2 * c3;
    const S cc = (xyCorr.x() * (l1 + l2 * c3) + xyCorr.y() * l2 * s3) / s2sq,
                 ss = (xyCorr.y() * (l1 + l2 * c3) - xyCorr.x() * l2 * s3) / s2sq;
    theta2Corr = maxOf(theta2Corr, S(sqrt((cc - c2) * (cc - c2) + (ss - s2) * (ss - s2))));
  }
  c.checkResidual("a₂a₃ℓ₄a₃*a₂* = e₂e₃ + (cos θ2(l1 + l2 cos θ3) − l2 sin θ2 sin θ3)e₂𝐞 + (… + l2 cos θ2 sin θ3)e₃𝐞 "
                  "(E10.6 corrected)", lhsCorr, tol);
  c.checkPrintedFails("… with l1 in both sin θ3 terms as printed (smallest)", "E10.6", lhsPrinted, tol);
  c.checkResidual("X = (l1+l2) cos φ′ + t′_z, Y = (l1+l2) sin φ′ − t′_y (E10.8 corrected)", rhsCorr, tol);
  c.checkPrintedFails("… X = (l2+l3) cos φ′ + t′_z, Y = (l2+l3) sin φ′ − t′_z as printed (smallest)", "E10.8", rhsPrinted, tol);
  c.checkResidual("θ2 from the corrected X, Y by the book's cos θ2, sin θ2 formulas (every posture)", theta2Corr, tol);
}

// GF §10.3.2, GF-10.3.2-T3-robot (E10.4–E10.8 corrected forms)
template <class S> void t3Example(Context& c) {
  const S l1 = frac<S>(9, 10), l2 = frac<S>(7, 10), l3 = frac<S>(1, 4);
  const auto robot = t3Robot(l1, l2, l3);
  JointVector<S> q(6);
  q << frac<S>(2, 5), frac<S>(-7, 10), frac<S>(11, 10), frac<S>(1, 2), frac<S>(7, 20), frac<S>(-6, 5);
  const SE3<S> T = robot.fk(q);
  const auto sol = solvePieper(robot, T);
  c.checkEqual("the catalogue's instance θ = (0.4, −0.7, 1.1, 0.5, 0.35, −1.2) is recovered", 1, contains(sol, q, jointTolerance(robot, q, sol)) ? 1 : 0);
  c.checkResidual("every posture reproduces k", sol.worstResidual(), Tolerance<S>::identity(4096));
  c.note(fmt::format("postures at this pose: {}", sol.count()));
  // Joints 2-4 parallel: the planar motion E2E3E4 turns by θ2 + θ3 + θ4 = φ' about x.
  for (std::size_t k = 0; k < sol.count(); ++k) {
    const auto& p = sol.postures[k];
    const SE3<S> X = robot.joints()[0].motion(p(0)).inverse() * T * robot.home().inverse() *
                     robot.joints()[5].motion(p(5)).inverse() * robot.joints()[4].motion(p(4)).inverse();
    const Mat3<S> R = X.rotation();
    const S phi = atan2(R(2, 1), R(1, 1));
    const S sum = p(1) + p(2) + p(3);
    // The postures reproduce k to the IK's residual bound 4096 ε (9.1e-13 in double, 1e-12 before).
    c.checkResidual(fmt::format("posture {}: θ4 = φ′ − θ2 − θ3 (planar sum; 4096 ε)", k + 1),
                    abs(sin((phi - sum) / 2)), Tolerance<S>::identity(4096));
    // Cosine rule (E10.7: l2², not l1²): s² = l1² + l2² + 2 l1 l2 cos θ3 is the squared distance
    // between axis 2 and axis 4 after the motion, i.e. |P(r4') − r2|².
    const Vec3<S> r4 = robot.joints()[1].motion(p(1)).act(robot.joints()[2].motion(p(2)).act(robot.joints()[3].point));
    const S s2 = Vec2<S>(r4.y(), r4.z()).squaredNorm();
    c.checkResidual(fmt::format("posture {}: s² = l1² + l2² + 2 l1 l2 cos θ3 (E10.7; 4096 ε)", k + 1),
                    abs(s2 - (l1 * l1 + l2 * l2 + 2 * l1 * l2 * cos(p(2)))), Tolerance<S>::identity(4096));
  }
  // Printed E10.7 form cos θ3 = (s² − l1² − l1²)/2 l1 l2 fails.
  const S s2 = l1 * l1 + l2 * l2 + 2 * l1 * l2 * cos(q(2));
  const S printed = (s2 - 2 * l1 * l1) / (2 * l1 * l2);
  c.checkPrintedFails("cos θ3 = (s² − l1² − l1²)/2l1l2: |printed − cos θ3|", "E10.7", abs(printed - cos(q(2))),
                      Tolerance<S>::identity(64));
  t3PrintedForms(c, robot, T, sol, l1, l2, l3);
}

// GF §10.3.3, GF-10.3.3-PUMA (E10.9: a4a5a6 = a3*a2*a1* k)
template <class S> void pumaExample(Context& c) {
  const auto robot = puma560Robot<S>();
  const auto tri = findPieperTriple(robot);
  c.checkEqual("PUMA 560: axes 4-6 meet (Pieper triple found at joint 4)", 4, tri.first + 1);
  const Sweep<S> s = sweep(robot, 300, 104, 8);
  recordSweep(c, "PUMA 560", s, 8);
  // a4a5a6 = a3* a2* a1* k (E10.9) against the printed k a1* a2* a3*.
  std::mt19937_64 g(105);
  const JointVector<S> q = randomQ<S>(g, 6);
  SE3<S> e123, e456;
  for (int i = 0; i < 3; ++i) e123 = e123 * robot.joints()[i].motion(q(i));
  for (int i = 3; i < 6; ++i) e456 = e456 * robot.joints()[i].motion(q(i));
  const SE3<S> k = robot.fk(q) * robot.home().inverse();
  // Six joint motions composed and inverted: rounding within 64 ε (1.4e-14 in double).
  c.checkResidual("a4a5a6 = a3*a2*a1* k (corrected, E10.9; 64 ε)", poseResidual(e456, SE3<S>(e123.inverse() * k), S(1)),
                  Tolerance<S>::identity(64));
  c.checkPrintedFails("a4a5a6 = k a1*a2*a3*", "E10.9", poseResidual(e456, SE3<S>(k * e123.inverse()), S(1)),
                      Tolerance<S>::identity(64));
}

// GF §10.3, GF-10.3-closing-remarks: singular ⇔ joint screws dependent (a reciprocal screw exists)
template <class S> void closingRemarks(Context& c) {
  const auto robot = t3Robot<S>();
  JointVector<S> q(6);
  q << frac<S>(3, 10), frac<S>(-3, 5), frac<S>(9, 10), frac<S>(2, 5), pi<S>() / 2, frac<S>(1, 5);  // θ5 = π/2: axis 6 parallel to axes 2-4
  const auto m = singularityMeasures(robot, q);
  c.checkEqual("T³ at θ5 = π/2: rank of the joint screws", 5, m.rank);
  const auto sol = solvePieper(robot, robot.fk(q));
  c.checkEqual("… and the IK reports the singularity (a continuum)", 1, sol.continuum ? 1 : 0);
  c.checkResidual("… with every returned posture on the pose (the IK's bound 4096 ε)", sol.worstResidual(),
                  Tolerance<S>::identity(4096));
  q(4) = pi<S>() / 2 - frac<S>(3, 10);
  c.checkEqual("T³ at θ5 = π/2 − 0.3: rank 6", 6, singularityMeasures(robot, q).rank);
}

// GF Fig. 10.2, GF-10.3.2-fig10.2-T3: all postures of the T³ for one pose, drawn together.
void t3Figure(Context& c) {
  using S = double;
  const auto robot = t3Robot<S>();
  // The catalogue's instance has 4 postures; draw the first pose of a fixed-seed sequence with 8.
  std::mt19937_64 g(107);
  JointVector<S> q = randomQ<S>(g, 6);
  while (solvePieper(robot, robot.fk(q)).count() != 8) q = randomQ<S>(g, 6);
  const SE3<S> T = robot.fk(q);
  const auto sol = solvePieper(robot, T);
  c.checkEqual("postures drawn", 8, int(sol.count()));
  c.checkResidual("worst residual of the drawn postures", sol.worstResidual(), Tolerance<S>::identity(4096));
  if (!c.makeFigures()) return;
  rd::Scene scene;
  scene.title = fmt::format("T³ robot (GF Fig. 10.2): all {} postures for one tool pose", sol.count());
  const rd::Color colors[] = {rd::palette::blue,   rd::palette::vermillion, rd::palette::bluishGreen,
                              rd::palette::orange, rd::palette::reddishPurple, rd::palette::skyBlue,
                              rd::palette::darkGrey, rd::palette::yellow};
  for (std::size_t k = 0; k < sol.count(); ++k) {
    const auto fr = robot.frames(sol.postures[k]);
    rd::Tube tube;
    tube.c = colors[k % 8];
    tube.radius = 0.022;
    // Links: base → joint points (moved) → tool.
    for (const auto& f : fr) tube.p.push_back(f.translation());
    scene.add(tube);
    rd::Points joints;
    joints.c = colors[k % 8];
    joints.radius = 0.035;
    for (std::size_t i = 0; i + 1 < fr.size(); ++i) joints.p.push_back(fr[i].translation());
    scene.add(joints);
    // The wrist flip (θ5 → −θ5, θ4, θ6 ± π) leaves the links in place: show joint 5's frame.
    scene.add(rd::Frame{fr[4].matrix(), 0.12});
  }
  scene.add(rd::Frame{T.matrix(), 0.3});
  scene.add(rd::Frame{Mat4<S>::Identity(), 0.3});
  rd::Label l;
  l.at = T.translation();
  l.text = "tool pose k";
  scene.add(l);
  const std::string file = "GF-10.3.2-fig10.2-T3.png";
  rd::renderPng(scene, Eigen::Vector3d(-1.0, -0.8, -0.45), {1200, 1000}, c.figurePath(file));
  c.figure(file, fmt::format("The T³ robot (joints 2-4 parallel, l = (0.9, 0.7, 0.25)): the {} postures that "
                             "place the tool at one pose, one colour each (tubes through the joint axis "
                             "points, dots at the joints, joint 5's frame showing the wrist flip — the "
                             "two wrist postures share their links), with the base and tool frames.", sol.count()));
}

const std::string kChapter = "GF 10 — Points, lines, planes; Pieper robots";

SOMA_STUDY_SCALAR("GF-10.3-pieper-theorem", "Pieper robots have at most 8 postures (T³ and PUMA counts)", "GF §10.3",
                  pieperTheorem);
SOMA_STUDY_SCALAR("GF-10.3.1-pieper-algorithm", "Pieper's decoupling for every triple position, meeting or parallel",
                  "GF §10.3.1", pieperAlgorithm);
SOMA_STUDY_SCALAR("GF-10.3.2-T3-robot",
                  "The T³ robot: closed-form IK, planar sum, cosine rule and the printed intermediate forms (E10.4–E10.8)",
                  "GF §10.3.2", t3Example);
SOMA_STUDY_SCALAR("GF-10.3.3-PUMA", "The PUMA 560: 8 postures, the wrist split a4a5a6 = a3*a2*a1*k (E10.9)", "GF §10.3.3",
                  pumaExample);
SOMA_STUDY_SCALAR("GF-10.3-closing-remarks", "Singularities: dependent joint screws (T³ at θ5 = π/2)", "GF §10.3",
                  closingRemarks);
// Fig. 10.2 stays in double: soma::render draws double geometry.
constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";
SOMA_STUDY_DOUBLE("GF-10.3.2-fig10.2-T3", "Fig. 10.2: all postures of the T³ for one pose", "GF §10.3.2, Fig. 10.2", t3Figure);

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
