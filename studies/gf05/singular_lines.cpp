// Studies of GF §5.2.3 (the singularities of 3R arms, seen as lines): the Jacobian's columns
// vᵢ × (p − rᵢ) and the line through p meeting all three axes at a singularity, the conical double
// points of the bifurcation surface where p lies on axis 1, and the gradient of det J when axes 1
// and 3 meet (a cuspidal edge). In double: they reuse soma's 3R code (SerialRobot's motions and
// spatial Jacobian, geometry/cuspidal's det J series and tool-point determinant), written in double.
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <Eigen/SVD>

#include <cmath>
#include <random>

namespace soma::studies::gf05lines::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
const char* kChapter = "GF 5 — A little kinematics";
const char* kWhyDouble = "reuses geometry/cuspidal's det J series and tool-point determinant, written in double";
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

Vec3<S> unit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  return Vec3<S>(n(g), n(g), n(g)).normalized();
}
Vec3<S> point(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-1, 1);
  return Vec3<S>(u(g), u(g), u(g));
}
double ang(std::mt19937_64& g) { return std::uniform_real_distribution<double>(-kPi, kPi)(g); }

/// A 3R arm from its home axes (vᵢ through rᵢ) and home tool point.
SerialRobot<S> arm(const std::array<Vec3<S>, 3>& v, const std::array<Vec3<S>, 3>& r, const Vec3<S>& tool) {
  std::vector<SerialJoint<S>> js(3);
  for (int i = 0; i < 3; ++i) {
    js[std::size_t(i)].axis = v[std::size_t(i)];
    js[std::size_t(i)].point = r[std::size_t(i)];
  }
  return SerialRobot<S>::fromPOE(js, SE3<S>(SO3<S>(), tool));
}
SerialRobot<S> randomArm(std::mt19937_64& g) {
  return arm({unit(g), unit(g), unit(g)}, {point(g), point(g), point(g)}, point(g));
}

/// The current axes at q: axis i moved by the motions of joints 1 … i−1 (SerialJoint::motion,
/// the book's e^{θS}), and the tool point.
struct Axes {
  std::array<Vec3<S>, 3> v, r;
  Vec3<S> p;
};
Axes currentAxes(const SerialRobot<S>& robot, const JointVector<S>& q) {
  Axes a;
  SE3<S> T;
  for (int i = 0; i < 3; ++i) {
    const auto& j = robot.joints()[std::size_t(i)];
    a.v[std::size_t(i)] = T.rotation().matrix() * j.axis;
    a.r[std::size_t(i)] = T.act(j.point);
    T = T * j.motion(q(i));
  }
  a.p = robot.fk(q).translation();
  return a;
}
/// GF §5.2.3: J = (v₁ × (p − r₁) | v₂ × (p − r₂) | v₃ × (p − r₃)), current axes.
Mat3<S> bookJacobian(const Axes& a) {
  Mat3<S> J;
  for (int i = 0; i < 3; ++i) J.col(i) = a.v[std::size_t(i)].cross(a.p - a.r[std::size_t(i)]);
  return J;
}
/// Distance between the line p + s d and the line r + t v (0 when they meet; parallel lines: the
/// distance of r from the first).
double lineDistance(const Vec3<S>& p, const Vec3<S>& d, const Vec3<S>& r, const Vec3<S>& v) {
  const Vec3<S> n = d.cross(v);
  if (n.norm() <= 1e-12 * d.norm() * v.norm()) return (r - p).cross(d).norm() / d.norm();
  return std::abs((r - p).dot(n)) / n.norm();
}
/// Left singular vector of the smallest singular value, and σ₃/σ₁.
Vec3<S> leftNull(const Mat3<S>& J, double* ratio = nullptr) {
  Eigen::JacobiSVD<Mat3<S>> svd(J, Eigen::ComputeFullU);
  if (ratio) *ratio = svd.singularValues()(2) / svd.singularValues()(0);
  return svd.matrixU().col(2);
}
double angleBetweenLines(const Vec3<S>& a, const Vec3<S>& b) {
  const double t = std::atan2(a.cross(b).norm(), a.dot(b));
  return std::min(t, kPi - t);
}

// ---- GF-5.2.3-position-jacobian-singular-line -------------------------------------------------
void singularLine(Context& c) {
  std::mt19937_64 g(523);
  // (i) The columns vᵢ × (p − rᵢ) (current axes from the joints' motions) are the velocities of p:
  // central differences of the forward kinematics, h = ε^{1/3}.
  {
    double worst = 0;
    const double h = std::cbrt(kEps);
    for (int k = 0; k < 20; ++k) {
      const auto robot = randomArm(g);
      JointVector<S> q(3);
      q << ang(g), ang(g), ang(g);
      const Mat3<S> J = bookJacobian(currentAxes(robot, q));
      for (int i = 0; i < 3; ++i) {
        JointVector<S> qp = q, qm = q;
        qp(i) += h;
        qm(i) -= h;
        const Vec3<S> fd = (robot.fk(qp).translation() - robot.fk(qm).translation()) / (2 * h);
        worst = std::max(worst, (fd - J.col(i)).norm() / robot.lengthScale());
      }
    }
    c.checkResidual("J = (v₁×(p−r₁) | v₂×(p−r₂) | v₃×(p−r₃)), current axes, = ∂p/∂θ by central differences "
                    "(20 random arms; error O(ε^{2/3}), tolerance 64 ε^{2/3})",
                    worst, 64 * std::cbrt(kEps) * std::cbrt(kEps));
  }
  // (ii) The catalogue's instance (verify/ch01-05/ch05_gradient.py): axes 1 and 3 meet at r, p in
  // their plane; the line through p and the point where axis 2 pierces that plane is dᵀJ = 0.
  {
    const Vec3<S> v1 = unit(g), v2 = unit(g), v3 = unit(g), r = point(g), r2 = point(g);
    const Vec3<S> n13 = v1.cross(v3);
    const Vec3<S> p = r + 0.6 * v1 - 0.3 * v3;
    const double lam = (r - r2).dot(n13) / v2.dot(n13);
    const Vec3<S> X2 = r2 + lam * v2;
    const Vec3<S> d = (X2 - p).normalized();
    const Axes a{{v1, v2, v3}, {r, r2, r}, p};
    const Vec3<S> dJ = d.transpose() * bookJacobian(a);
    c.checkResidual("axes 1, 3 meeting, p in their plane: the line from p to axis 2 ∩ that plane is a left null "
                    "vector, |dᵀJ| (tolerance 16ε)",
                    dJ.cwiseAbs().maxCoeff(), 16 * kEps);
  }
  // (iii) At random singular configurations of random arms (det J(θ₂, θ₃) = 0 solved exactly in θ₃
  // by geometry/cuspidal's det J series), the left null vector d of J (SVD) spans a line through p
  // that meets all three axes; at regular configurations the line through p meeting axes 2 and 3
  // misses axis 1 (the converse).
  int singular = 0, regularMiss = 0, regular = 0;
  double worstMeet = 0, worstSigma = 0, worstNormal = 0;
  for (int k = 0; k < 10; ++k) {
    const auto robot = randomArm(g);
    const DetJSeries dj = detJSeries(robot);
    const double L = robot.lengthScale();
    for (int m = 0; m < 6; ++m) {
      const double t2 = ang(g);
      for (double t3 : dj.rootsInTheta3(t2)) {
        JointVector<S> q(3);
        q << ang(g), t2, t3;
        const Axes a = currentAxes(robot, q);
        double ratio = 0;
        const Vec3<S> d = leftNull(bookJacobian(a), &ratio);
        worstSigma = std::max(worstSigma, ratio);
        double meet = 0;
        for (int i = 0; i < 3; ++i) meet = std::max(meet, lineDistance(a.p, d, a.r[std::size_t(i)], a.v[std::size_t(i)]) / L);
        worstMeet = std::max(worstMeet, meet);
        ++singular;
        // The line is normal to the bifurcation surface: chords to nearby singular points (θ₁ + δ,
        // and along det J = 0) make an angle O(δ) with the plane ⊥ d.
        const double delta = 1e-5;
        JointVector<S> q1 = q;
        q1(0) += delta;
        double chord = std::abs(d.dot((robot.fk(q1).translation() - a.p).normalized()));
        double best = 0, bestDist = 1e-2;  // the root of det J(θ₂ + δ, ·) on this branch
        bool near = false;
        for (double t : dj.rootsInTheta3(t2 + delta))
          if (std::abs(std::remainder(t - t3, 2 * kPi)) < bestDist) best = t, bestDist = std::abs(std::remainder(t - t3, 2 * kPi)), near = true;
        if (near) {
          JointVector<S> q2 = q;
          q2(1) = t2 + delta;
          q2(2) = best;
          chord = std::max(chord, std::abs(d.dot((robot.fk(q2).translation() - a.p).normalized())));
        }
        worstNormal = std::max(worstNormal, chord);
      }
      // a regular configuration: the line through p meeting axes 2, 3 (the planes' intersection)
      JointVector<S> q(3);
      q << ang(g), t2, ang(g);
      const Axes a = currentAxes(robot, q);
      if (std::abs(dj.value(t2, q(2))) < 1e-3 * dj.scale) continue;
      ++regular;
      const Mat3<S> J = bookJacobian(a);
      const Vec3<S> d = J.col(1).cross(J.col(2));
      regularMiss += lineDistance(a.p, d, a.r[0], a.v[0]) / L > 1e-6;
    }
  }
  c.note(fmt::format("{} singular configurations of 10 random arms (θ₃ roots of det J for 6 θ₂ each).", singular));
  c.recordIn("… they are singular: σ₃/σ₁ of J at the roots (largest)", "≤ 1e-12", fmt::format("{:.2g}", worstSigma), worstSigma,
             1e-12, worstSigma <= 1e-12 && singular >= 20);
  c.checkResidual("… the left null vector's line through p meets all three axes (largest distance / L)", worstMeet, 1e-10);
  c.checkResidual("… and is normal to the bifurcation surface: chords to singular points δ = 1e-5 away are ⊥ d to O(δ)",
                  worstNormal, 1e-3);
  c.checkEqual("at regular configurations the line through p meeting axes 2, 3 misses axis 1 (converse)", regular, regularMiss);
}

// ---- GF-5.2.3-conical-double-points -----------------------------------------------------------
void conicalDoublePoints(Context& c) {
  std::mt19937_64 g(524);
  // An arm whose tool point lies on axis 1 at q = 0: p₀ = r₁ + 0.8 v₁.
  const Vec3<S> v1 = unit(g), r1 = point(g);
  const std::array<Vec3<S>, 3> v{v1, unit(g), unit(g)}, r{r1, point(g), point(g)};
  const auto robot = arm(v, r, r1 + 0.8 * v1);
  JointVector<S> q0 = JointVector<S>::Zero(3);
  const Axes a0 = currentAxes(robot, q0);
  const Mat3<S> J0 = bookJacobian(a0);
  const Vec3<S> d0 = leftNull(J0);
  c.checkResidual("p on axis 1: column 1 of J vanishes, det J = 0 (toolPointJacobianDet / L³)",
                  std::abs(toolPointJacobianDet(robot, q0)) / std::pow(robot.lengthScale(), 3), 64 * kEps);
  {
    const Vec3<S> sv = Eigen::JacobiSVD<Mat3<S>>(J0).singularValues();
    const double r2 = sv(1) / sv(0);
    c.recordIn("… J keeps rank 2 (σ₂/σ₁): one left null vector", "> 1e-3", fmt::format("{:.3g}", r2), r2, 1e-3, r2 > 1e-3);
  }
  // The book's two constructions: the plane of p and axis 2 meets axis 3 at X₃, the plane of p and
  // axis 3 meets axis 2 at X₂; lines pX₃ and pX₂.
  {
    const Vec3<S> n2 = a0.v[1].cross(a0.p - a0.r[1]), n3 = a0.v[2].cross(a0.p - a0.r[2]);
    const Vec3<S> X3 = a0.r[2] + ((a0.p - a0.r[2]).dot(n2) / a0.v[2].dot(n2)) * a0.v[2];
    const Vec3<S> X2 = a0.r[1] + ((a0.p - a0.r[1]).dot(n3) / a0.v[1].dot(n3)) * a0.v[1];
    const double between = angleBetweenLines(X3 - a0.p, X2 - a0.p);
    c.checkResidual("the book's two lines through p (via the plane of axis 2, via the plane of axis 3) are one line: "
                    "angle between them (rad; 1e-12)",
                    between, 1e-12);
    c.checkResidual("… and it is the left null vector of J (angle, rad)", angleBetweenLines(X3 - a0.p, d0), 1e-12);
  }
  // The second normal comes from turning joint 1: the configurations θ₁ and θ₁ + π put their
  // generators in one meridian plane. The singular set in joint space is θ₁ × {det J(θ₂, θ₃) = 0};
  // through (0, 0) runs a smooth curve, whose image has tangent t at p. Turning about axis 1 sweeps
  // that line into the cone ρ = k|z| (z along axis 1 from p, k = |t⊥|/|t·v₁|).
  const DetJSeries dj = detJSeries(robot);
  auto curvePoint = [&](double t2) {  // the root θ₃ of det J(t2, ·) nearest 0
    double best = 1e9;
    for (double t : dj.rootsInTheta3(t2))
      if (std::abs(std::remainder(t, 2 * kPi)) < std::abs(best)) best = std::remainder(t, 2 * kPi);
    return best;
  };
  c.recordIn("the singular curve det J = 0 passes through (θ₂, θ₃) = (0, 0)", "< 1e-9", fmt::format("{:.2g}", std::abs(curvePoint(0))),
             std::abs(curvePoint(0)), 1e-9, std::abs(curvePoint(0)) < 1e-9);
  auto image = [&](double th1, double t2) {
    JointVector<S> q(3);
    q << th1, t2, curvePoint(t2);
    return Vec3<S>(robot.fk(q).translation());
  };
  const double e0 = 1e-6;
  const Vec3<S> t = (image(0, e0) - image(0, -e0)) / (2 * e0);
  const Vec3<S> p = a0.p;
  const double k = (t - t.dot(v1) * v1).norm() / std::abs(t.dot(v1));
  c.note(fmt::format("cone slope k = |t⊥| / |t·v₁| = {:.6f} (t by central differences along the singular curve).", k));
  // (a) The tangent cone is quadratic: surface points q at distance ~ε from p satisfy
  // ρ² − k²z² = O(ε³), so |ρ² − k²z²| / |q − p|² → 0 linearly: measured at ε = 1e-3 and 1e-4.
  auto coneDefect = [&](double eps) {
    double worst = 0;
    for (int m = 0; m < 12; ++m)
      for (double s : {eps, -eps}) {
        const Vec3<S> q = image(2 * kPi * m / 12, s) - p;
        const double z = q.dot(v1), rho2 = (q - z * v1).squaredNorm();
        worst = std::max(worst, std::abs(rho2 - k * k * z * z) / q.squaredNorm());
      }
    return worst;
  };
  const double c3 = coneDefect(1e-3), c4 = coneDefect(1e-4);
  c.recordIn("the bifurcation surface near p is the cone ρ² = k²z²: |ρ² − k²z²| / |q − p|² over 24 surface points at "
             "ε = 1e-4 (12 turns of joint 1, both sides of the curve)",
             "≤ 1e-3", fmt::format("{:.3g}", c4), c4, 1e-3, c4 <= 1e-3);
  c.checkNear("… and the defect is O(ε): ratio of the defects at ε = 1e-3 and 1e-4 (expected 10, ±20%)", 10.0, c3 / c4, 2.0);
  // (b) Two normals in a meridian section: the left null vectors at θ₁ = 0 and θ₁ = π (the same
  // meridian plane) make the angle the cone predicts between the normals of its two generators,
  // 2 atan(1/k) (as lines), and each is ⊥ its generator.
  {
    JointVector<S> qpi = q0;
    qpi(0) = kPi;
    const Vec3<S> dpi = leftNull(bookJacobian(currentAxes(robot, qpi)));
    double expected = 2 * std::atan(1 / k);
    expected = std::min(expected, kPi - expected);
    c.checkNear("two normal lines at p in one meridian plane: angle between the null vectors at θ₁ = 0 and π = "
                "2 atan(1/k) (as lines; tolerance 1e-6 from the central-difference slope)",
                expected, angleBetweenLines(d0, dpi), 1e-6);
    c.checkResidual("… the normal at θ₁ = 0 is ⊥ the generator t (|d·t|/|t|)", std::abs(d0.dot(t)) / t.norm(), 1e-6);
    double meet = 0;
    const Axes api = currentAxes(robot, qpi);
    for (int i = 0; i < 3; ++i) meet = std::max(meet, lineDistance(api.p, dpi, api.r[std::size_t(i)], api.v[std::size_t(i)]));
    c.checkResidual("… the normal at θ₁ = π meets all three axes of that configuration (distance / L)", meet / robot.lengthScale(), 1e-12);
  }
}

// ---- GF-5.2.3-det-gradient-cuspidal-edge ------------------------------------------------------
void detGradient(Context& c) {
  std::mt19937_64 g(525);
  auto detJ = [](const Axes& a) { return bookJacobian(a).determinant(); };
  // (i) The general formula: ∇_q det J = Σ (vᵢ × q)·(cⱼ × cₖ) (cyclic), with p moved and the axes
  // fixed, against central differences, at random (non-special) data.
  const double h = std::cbrt(kEps), fdTol = 64 * h * h;  // det J is cubic in p: error O(h²) + ε/h
  double worstGeneral = 0;
  for (int k = 0; k < 20; ++k) {
    Axes a{{unit(g), unit(g), unit(g)}, {point(g), point(g), point(g)}, point(g)};
    const Vec3<S> q = unit(g);
    Axes ap = a, am = a;
    ap.p += h * q;
    am.p -= h * q;
    const double fd = (detJ(ap) - detJ(am)) / (2 * h);
    const Mat3<S> J = bookJacobian(a);
    double formula = 0;
    for (int i = 0; i < 3; ++i)
      formula += a.v[std::size_t(i)].cross(q).dot(J.col((i + 1) % 3).cross(J.col((i + 2) % 3)));
    worstGeneral = std::max(worstGeneral, std::abs(fd - formula));
  }
  c.checkResidual("∇_q det J = Σ (vᵢ × q)·((vⱼ × (p − rⱼ)) × (vₖ × (p − rₖ))) vs central differences (20 random, 64 ε^{2/3})",
                  worstGeneral, fdTol);
  // (ii) Axes 1, 3 meeting at r, p in their plane (the catalogue's instance): det J = 0 there, the
  // book's −(q·(v₁ × v₃))((p − r)·(v₂ × (p − r₂))) equals the directional derivative, and it vanishes
  // for q in the plane. The derivative is taken twice: of the book's J, and of soma's tool-point
  // determinant (spatial Jacobian) of a robot whose home configuration is this one, tool at p + hq.
  const Vec3<S> v1 = unit(g), v2 = unit(g), v3 = unit(g), r = point(g), r2 = point(g);
  const Vec3<S> n13 = v1.cross(v3);
  const Vec3<S> p = r + 0.45 * v1 - 0.7 * v3;
  const Axes a{{v1, v2, v3}, {r, r2, r}, p};
  c.checkResidual("axes 1, 3 meeting and p in their plane: det J = 0 (16ε)", std::abs(detJ(a)), 16 * kEps);
  double worstBook = 0, worstSoma = 0, inPlane = 0;
  const JointVector<S> q0 = JointVector<S>::Zero(3);
  for (int k = 0; k < 4; ++k) {
    const Vec3<S> q = k < 3 ? unit(g) : Vec3<S>(n13.cross(unit(g)).normalized());  // the last one in the plane
    const double formula = -q.dot(n13) * (p - r).dot(v2.cross(p - r2));
    Axes ap = a, am = a;
    ap.p += h * q;
    am.p -= h * q;
    const double fd = (detJ(ap) - detJ(am)) / (2 * h);
    const double fdSoma = (toolPointJacobianDet(arm(a.v, a.r, p + h * q), q0) - toolPointJacobianDet(arm(a.v, a.r, p - h * q), q0)) / (2 * h);
    if (k < 3) {
      worstBook = std::max(worstBook, std::abs(fd - formula));
      worstSoma = std::max(worstSoma, std::abs(fdSoma - formula));
      c.note(fmt::format("direction {}: central difference {:.8f}, formula {:.8f}", k + 1, fd, formula));
    } else {
      inPlane = std::max({std::abs(formula), std::abs(fd), std::abs(fdSoma)});
    }
  }
  c.checkResidual("∇_q det J = −(q·(v₁×v₃))((p − r)·(v₂×(p − r₂))) vs central differences of the book's J (3 random q, 64 ε^{2/3})",
                  worstBook, fdTol);
  c.checkResidual("… and of soma's toolPointJacobianDet (spatial Jacobian) with the tool moved", worstSoma, fdTol);
  c.checkResidual("… q in the plane of axes 1, 3: the gradient vanishes (formula and both differences)", inPlane, fdTol);
  // (iii) The book's reduced formula is the general one at such a point (20 random instances).
  double worstReduce = 0;
  for (int k = 0; k < 20; ++k) {
    const Vec3<S> w1 = unit(g), w2 = unit(g), w3 = unit(g), rr = point(g), rr2 = point(g);
    const Vec3<S> pp = rr + std::uniform_real_distribution<double>(-1, 1)(g) * w1 + std::uniform_real_distribution<double>(-1, 1)(g) * w3;
    const Axes b{{w1, w2, w3}, {rr, rr2, rr}, pp};
    const Mat3<S> J = bookJacobian(b);
    const Vec3<S> q = unit(g);
    double general = 0;
    for (int i = 0; i < 3; ++i) general += b.v[std::size_t(i)].cross(q).dot(J.col((i + 1) % 3).cross(J.col((i + 2) % 3)));
    worstReduce = std::max(worstReduce, std::abs(general + q.dot(w1.cross(w3)) * (pp - rr).dot(w2.cross(pp - rr2))));
  }
  c.checkResidual("the reduced formula = the three-term sum whenever r₁ = r₃ and (p − r)·(v₁×v₃) = 0 (20 random, 64ε)",
                  worstReduce, 64 * kEps);
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-5.2.3-position-jacobian-singular-line",
                  "J = (vᵢ × (p − rᵢ)); singular ⇔ a line through p meets all three axes, normal to the bifurcation surface",
                  "GF §5.2.3", singularLine);
SOMA_STUDY_DOUBLE("GF-5.2.3-conical-double-points",
                  "p on axis 1: a conical double point of the bifurcation surface (two normals in a meridian section)",
                  "GF §5.2.3", conicalDoublePoints);
SOMA_STUDY_DOUBLE("GF-5.2.3-det-gradient-cuspidal-edge",
                  "∇ det J = −(q·(v₁×v₃))((p−r)·(v₂×(p−r₂))) when axes 1, 3 meet: zero in their plane (cuspidal edge)",
                  "GF §5.2.3", detGradient);

}  // namespace soma::studies::gf05lines::SOMA_UNITY_ID
