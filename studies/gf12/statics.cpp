// Studies of GF chapter 12, §12.1–12.4 (double): co-screws and their coadjoint transformation,
// wrenches of forces and couples, wrench pitch and axis, the four-beam wrist force sensor
// (erratum E12.1), the end-effector wrench of a PUMA 560 from its joint torques, and the joint
// stiffness model (Cartesian stiffness, compliance, eigenscrews).
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/geometry/statics/grasp.hpp"
#include "soma/geometry/statics/robot_statics.hpp"
#include "soma/geometry/statics/wrench.hpp"
#include "soma/geometry/statics/wrist_sensor.hpp"
#include "soma/geometry/serial/example_robots.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf12::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 12 — Statics";
using V3 = Vec3<double>;
using V6 = Vec6<double>;
using M6 = Mat6<double>;
using W = Wrench<double>;
using T = SE3Tangent<double>;
using std::abs;

const double kTol = Tolerance<double>::identity(64);
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
V3 rv3(std::mt19937_64& g) { return V3(uni(g), uni(g), uni(g)); }
V6 rv6(std::mt19937_64& g) {
  V6 v;
  for (int i = 0; i < 6; ++i) v(i) = uni(g);
  return v;
}
template <class M> long long detail_rank(const M& m) { return wrenchSpan<double>(WrenchSet<double>(m)).rank; }
/// The displacement screw of the tool between two poses, to first order: log(T₁ T₀⁻¹) (spatial).
V6 spatialDisplacement(const SE3<double>& t0, const SE3<double>& t1) { return (t1 * t0.inverse()).log().coeffs(); }

// ---- §12.1 --------------------------------------------------------------------------------------
void pairing(Context& c) {
  auto g = std::mt19937_64(1211);
  double worst = 0, linear = 0;
  for (int i = 0; i < 200; ++i) {
    const W F(rv6(g));
    const T s1(rv6(g)), s2(rv6(g));
    const double a = uni(g), b = uni(g);
    linear = std::max(linear, abs(F(T(V6(a * s1.coeffs() + b * s2.coeffs()))) - a * F(s1) - b * F(s2)));
    worst = std::max(worst, abs(F(s1) - (F.moment().dot(s1.ang()) + F.force().dot(s1.lin()))));
  }
  c.checkResidual("𝓕(a s₁ + b s₂) = a 𝓕(s₁) + b 𝓕(s₂) (200 random)", linear, kTol);
  c.checkResidual("𝓕(s) = (Mᵀ, pᵀ)(ω; v) (200 random)", worst, kTol);
  c.note("Wrench<S> and SE3Tangent<S> are separate types; the only product between them is the pairing "
         "W(s). The invariance of the pairing under a rigid motion is the next study.");
}

void coadjoint(Context& c) {
  auto g = std::mt19937_64(1212);
  double inv = 0, mat = 0, hom = 0, wrong = 1e300;
  for (int i = 0; i < 200; ++i) {
    const SE3<double> x = SE3<double>::Random(g), y = SE3<double>::Random(g);
    const T s(rv6(g));
    const W F(rv6(g));
    const T s2(V6(x.adjoint() * s.coeffs()));
    inv = std::max(inv, abs(F.transformed(x)(s2) - F(s)));
    mat = std::max(mat, (coadjointMatrix(x) - M6(x.adjoint().inverse().transpose())).cwiseAbs().maxCoeff());
    hom = std::max(hom, (F.transformed(x * y).coeffs() - F.transformed(y).transformed(x).coeffs()).cwiseAbs().maxCoeff());
    wrong = std::min(wrong, abs(W(V6(x.adjoint() * F.coeffs()))(s2) - F(s)) / (1e-300 + abs(F(s))));
  }
  c.checkResidual("𝒲'ᵀ s' = 𝒲ᵀ s with 𝒲' = [[R, TR], [0, R]] 𝒲, s' = [[R, 0], [TR, R]] s (200 random g)", inv, kTol * 4);
  c.checkResidual("[[R, TR], [0, R]] = (Ad g)⁻ᵀ", mat, kTol);
  c.checkResidual("a representation: coadjoint(g h) = coadjoint(g) coadjoint(h)", hom, kTol * 4);
  c.record("a co-screw moved by the ADJOINT loses the pairing (smallest relative change over 200)", "> 1e-6",
           toString(wrong, 3), wrong, 1e-6, wrong > 1e-6);
}

// ---- §12.2 --------------------------------------------------------------------------------------
void wrenchOfForce(Context& c) {
  auto g = std::mt19937_64(1221);
  double power = 0, line = 0, eq = 0;
  for (int i = 0; i < 200; ++i) {
    const V3 r = rv3(g), F = rv3(g), w = rv3(g), v = rv3(g);
    const W Wr = W::ofForce(r, F);
    power = std::max(power, abs(F.dot(V3(w.cross(r) + v)) - Wr(T(w, v))));
    line = std::max(line, (W::ofForce(V3(r + uni(g, -5, 5) * F), F).coeffs() - Wr.coeffs()).cwiseAbs().maxCoeff());
    // equilibrium: three forces through a common point q summing to zero give the zero wrench
    const V3 q = rv3(g), F1 = rv3(g), F2 = rv3(g);
    const W sum = W::ofForce(V3(q + uni(g) * F1), F1) + W::ofForce(V3(q + uni(g) * F2), F2) +
                  W::ofForce(q, V3(-F1 - F2));
    eq = std::max(eq, sum.coeffs().cwiseAbs().maxCoeff());
  }
  c.checkResidual("power F·(ω × r + v) = 𝒲ᵀ s with 𝒲 = (r × F, F) (200 random)", power, kTol * 4);
  c.checkResidual("r' = r + λF on the line of action gives the same wrench", line, kTol * 16);
  c.checkResidual("three concurrent forces summing to 0: the wrenches sum to 0 (equilibrium)", eq, kTol * 4);
}

void couple(Context& c) {
  auto g = std::mt19937_64(1222);
  double worst = 0;
  bool allPure = true;
  for (int i = 0; i < 100; ++i) {
    const V3 r = rv3(g), F = rv3(g);
    const W s = W::ofForce(r, F) + W::ofForce(V3(-r), V3(-F));
    worst = std::max(worst, (s.coeffs() - W(V3(2 * r.cross(F)), V3::Zero()).coeffs()).cwiseAbs().maxCoeff());
    allPure = allPure && s.axis().pureTorque;
  }
  c.checkResidual("𝒲₁ + 𝒲₂ = (2 r × F, 0) (100 random)", worst, kTol);
  c.checkEqual("every such sum is a pure torque (infinite pitch)", "yes", allPure ? "yes" : "no");
}

void pitchAxis(Context& c) {
  auto g = std::mt19937_64(1223);
  double dp = 0, dax = 0, recon = 0;
  for (int i = 0; i < 200; ++i) {
    const V3 r = rv3(g), F = rv3(g);
    const double p = uni(g, -3, 3);
    const W w = W::ofPitch(r, F, p);
    const auto a = w.axis();
    dp = std::max(dp, abs(a.pitch - p));
    dax = std::max(dax, (a.point - r).cross(F).norm() + abs(a.point.dot(F)));
    recon = std::max(recon, (a.point.cross(F) + a.pitch * F - w.moment()).norm());
  }
  c.checkResidual("p = τ·F / F·F recovers the pitch of (r × F + pF, F) (200 random)", dp, kTol * 16);
  c.checkResidual("r₀ = F × τ/|F|² lies on the line through r along F, nearest the origin", dax, kTol * 16);
  c.checkResidual("r₀ × F + p F = τ", recon, kTol * 16);
  // F → 0: the pitch grows like 1/|F|; below Tolerance::rank·|τ| it is called infinite
  const V3 tau(0.3, -0.2, 1.0);
  const double rk = Tolerance<double>::rank() * tau.norm();
  c.checkEqual("|F| = 4·rank·|τ|: finite pitch", "finite", W(tau, V3(0, 0, 4 * rk)).axis().pureTorque ? "infinite" : "finite");
  c.checkEqual("|F| = rank·|τ|/4: infinite pitch (pure torque)", "infinite", W(tau, V3(0, 0, rk / 4)).axis().pureTorque ? "infinite" : "finite");
}

// ---- §12.3 --------------------------------------------------------------------------------------
/// The resolved force matrix with row 2 = (0, −l, 0, 0, 0, −l, 0, 0).
// GF §12.3 line 7410 as printed (erratum E12.1)
Mat68<double> resolvedForceMatrixAsPrinted(double l) {
  Mat68<double> a = resolvedForceMatrix<double>(l);
  a(1, 5) = -l;
  return a;
}

void wristSensor(Context& c) {
  auto g = std::mt19937_64(1231);
  const double l = 0.035;  // 35 mm beams
  double corr = 0, book = 0, printed = 0, calib = 0;
  for (int i = 0; i < 100; ++i) {
    Vec8<double> w;
    for (int k = 0; k < 8; ++k) w(k) = uni(g, -50, 50);
    W tot;
    for (const auto& x : wristSensorWrenches<double>(l, w)) tot += x;
    V6 bk;
    bk << l * (w(3) - w(7)), l * (w(5) - w(1)), l * (w(0) - w(2) - w(4) + w(6)), w(2) + w(6), w(0) + w(4),
        w(1) + w(3) + w(5) + w(7);
    book = std::max(book, (bk - tot.coeffs()).cwiseAbs().maxCoeff());
    corr = std::max(corr, (resolvedForceMatrix<double>(l) * w - tot.coeffs()).cwiseAbs().maxCoeff());
    printed = std::max(printed, (resolvedForceMatrixAsPrinted(l) * w - tot.coeffs()).cwiseAbs().maxCoeff());
    const W target(V6(rv6(g) * 10));
    calib = std::max(calib, (resolvedForceMatrix<double>(l) * wristSensorSignals<double>(l, target) - target.coeffs()).cwiseAbs().maxCoeff());
  }
  c.checkResidual("Σ 𝒲_i (from the beam geometry) = the printed total 𝒲_tot (100 random w)", book, 1e-12);
  c.checkResidual("Σ 𝒲_i = corrected resolved force matrix · w, row 2 = (0, −l, 0, 0, 0, +l, 0, 0)", corr, 1e-12);
  c.checkPrintedFails("resolved force matrix row 2 = (0, −l, 0, 0, 0, −l, 0, 0) · w = 𝒲_tot", "E12.1", printed, 1e-12);
  c.checkResidual("calibration: the minimum-norm gauge signals for a wrench reproduce it", calib, 1e-10);
  c.checkEqual("rank of the resolved force matrix, l = 35 mm", 6, detail_rank(resolvedForceMatrix<double>(l)));
  c.checkEqual("rank at l = 0 (moments unmeasurable)", 3, detail_rank(resolvedForceMatrix<double>(0.0)));
  c.note("Geometry of Fig. 12.2 read off the eight printed wrenches: beams end at (±l, 0, 0), (0, ±l, 0); at +x w₁ ∥ y, "
         "w₂ ∥ z; at +y w₃ ∥ x, w₄ ∥ z; at −x w₅ ∥ y, w₆ ∥ z; at −y w₇ ∥ x, w₈ ∥ z. The printed total (line 7406) is "
         "right; the printed matrix (line 7410) has −l at (2, 6) where the total l(w₆ − w₂) needs +l (erratum E12.1).");
}

// ---- §12.4 --------------------------------------------------------------------------------------
void jointTorques(Context& c) {
  auto g = std::mt19937_64(1241);
  const auto robot = puma560Robot<double>();
  double vw = 0, inv = 0, fd = 0, links = 0;
  for (int i = 0; i < 50; ++i) {
    JointVector<double> q(6);
    for (int k = 0; k < 6; ++k) q(k) = uni(g, -2.5, 2.5);
    q(4) = uni(g, 0.3, 2.5);  // away from the wrist singularity θ₅ = 0
    const ScrewColumns<double> J = robot.spatialJacobian(q);
    const W Wt(rv6(g));
    const VecX<double> w = jointEfforts<double>(J, Wt);
    const V6 qd = rv6(g);
    vw = std::max(vw, abs(Wt(T(V6(J * qd))) - w.dot(qd)));
    const auto ee = endEffectorWrench<double>(J, w);
    inv = std::max(inv, (ee.wrench.coeffs() - Wt.coeffs()).cwiseAbs().maxCoeff() / ee.condition);
    // virtual work without the Jacobian: the tool displacement for δθ = h q̇, paired with 𝒲
    const double h = 1e-6;
    const V6 dx = (spatialDisplacement(robot.fk(q), robot.fk(JointVector<double>(q + h * qd))) -
                   spatialDisplacement(robot.fk(q), robot.fk(JointVector<double>(q - h * qd)))) / (2 * h);
    fd = std::max(fd, abs(Wt(T(dx)) - w.dot(qd)));
    // link by link (Fig. 12.3): 𝒲_i = 𝒲_tot − ℛ_i with ℛ_i(s_i) = 0 gives w_i = 𝒲_i(s_i)
    for (int k = 0; k < 6; ++k) {
      V6 R = rv6(g);
      const V6 sk = J.col(k);
      R -= (R.dot(sk) / sk.squaredNorm()) * sk;
      links = std::max(links, abs(W(V6(Wt.coeffs() - R))(T(sk)) - w(k)));
    }
  }
  c.checkResidual("virtual work 𝒲ᵀ(J θ̇) = wᵀ θ̇, PUMA 560 (50 random postures)", vw, kTol * 4);
  c.checkResidual("𝒲_tot = (J⁻¹)ᵀ w recovers the wrench (error / cond J)", inv, kTol * 4);
  c.checkResidual("virtual work by central differences of the FK (no Jacobian), h = 1e-6", fd, 1e-8);
  c.checkResidual("link by link: w_i = (𝒲_tot − ℛ_i)(s_i) with ℛ_i(s_i) = 0", links, kTol * 16);
  // at the wrist singularity θ₅ = 0 one wrench direction is held by the structure
  JointVector<double> q(6);
  q << 0.3, -0.5, 0.7, 0.2, 0.0, -0.4;
  const ScrewColumns<double> J = robot.spatialJacobian(q);
  const auto ee = endEffectorWrench<double>(J, jointEfforts<double>(J, W(rv6(g))));
  c.checkEqual("rank of J at the wrist singularity θ₅ = 0", 5, ee.rank);
  c.checkEqual("structure wrenches (no joint effort balances them)", 1, (long long)ee.structureWrenches.size());
  c.checkResidual("the structure wrench pairs to 0 with every joint screw",
                  (J.transpose() * ee.structureWrenches[0].coeffs()).cwiseAbs().maxCoeff(), kTol * 16);
  q(4) = 1e-3;
  const auto near = endEffectorWrench<double>(robot.spatialJacobian(q), VecX<double>(VecX<double>::Ones(6)));
  c.note("At θ₅ = 1e-3 the Jacobian has rank 6 with condition " + toString(near.condition, 4) +
         ": the wrench J⁻ᵀ w exists but amplifies joint-torque errors by that factor.");
}

void stiffness(Context& c) {
  auto g = std::mt19937_64(1242);
  const auto robot = puma560Robot<double>();
  JointVector<double> q(6);
  q << 0.3, -0.5, 0.7, 0.2, 1.1, -0.4;
  const ScrewColumns<double> J = robot.spatialJacobian(q);
  VecX<double> k(6);
  k << 2.0e5, 2.0e5, 1.0e5, 2.0e4, 2.0e4, 1.0e4;  // N·m/rad, stiff base, soft wrist
  const M6 Kx = cartesianStiffness<double>(J, k), C = compliance<double>(J, k);
  c.checkResidual("C · (J⁻¹)ᵀ K J⁻¹ = I₆", (C * Kx - M6::Identity()).cwiseAbs().maxCoeff(), 1e-9);
  c.checkResidual("C is symmetric", (C - C.transpose()).cwiseAbs().maxCoeff(), kTol);
  // deflection under a small wrench, by FK: joints give δθ = K⁻¹ Jᵀ 𝒲, the tool moves δx ≈ C 𝒲
  const W Wt(rv6(g));
  double e1 = 0, e2 = 0;
  for (const double scale : {1.0, 0.1}) {
    const W Ws = Wt * scale;
    const VecX<double> dth = jointEfforts<double>(J, Ws).cwiseQuotient(k);
    const V6 dx = spatialDisplacement(robot.fk(q), robot.fk(JointVector<double>(q + dth)));
    (scale == 1.0 ? e1 : e2) = (dx - C * Ws.coeffs()).norm() / (C * Ws.coeffs()).norm();
  }
  c.checkResidual("δx from the FK of the deflected joints = C 𝒲 to first order (relative error, |𝒲| ~ 1 N)", e1, 1e-3);
  c.record("relative error falls ∝ |𝒲| (second-order remainder): ratio for 𝒲/10", "≈ 0.1", toString(e2 / e1, 4),
           abs(e2 / e1 - 0.1), 0.02, abs(e2 / e1 - 0.1) <= 0.02);
  // eigenscrews: K s = λ Q₀ s
  const auto es = stiffnessEigenscrews<double>(Kx);
  M6 Q0 = M6::Zero();
  Q0.topRightCorner<3, 3>().setIdentity();
  Q0.bottomLeftCorner<3, 3>().setIdentity();
  double res = 0, orth = 0;
  std::string list;
  for (int i = 0; i < 6; ++i) {
    const V6 s = es[std::size_t(i)].screw.coeffs();
    res = std::max(res, (Kx * s - es[std::size_t(i)].stiffness * Q0 * s).norm() / Kx.norm() / s.norm());
    for (int j = 0; j < i; ++j) orth = std::max(orth, abs(s.dot(Q0 * es[std::size_t(j)].screw.coeffs())));
    list += (i ? ", " : "") + toString(es[std::size_t(i)].stiffness, 4) + " (pitch " + toString(es[std::size_t(i)].pitch, 3) + " m)";
  }
  c.checkResidual("eigenscrews K s = λ Q₀ s (relative residual)", res, 1e-12);
  c.checkResidual("eigenscrews are Q₀-orthogonal (reciprocal)", orth, 1e-9);
  c.note("Eigenscrews of the PUMA's Cartesian stiffness at q = (0.3, −0.5, 0.7, 0.2, 1.1, −0.4), k = (2e5, 2e5, 1e5, "
         "2e4, 2e4, 1e4) N·m/rad: a twist about eigenscrew s is resisted by a wrench on the same screw axis. λ: " + list + ".");
  // a rigid joint (k = ∞) removes its column from the compliance; singular J: C loses rank
  q(4) = 0;
  const M6 Cs = compliance<double>(robot.spatialJacobian(q), k);
  c.checkEqual("rank of C at the wrist singularity θ₅ = 0", 5, detail_rank(Cs));
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-12.1-coscrew-pairing", "Co-screws are linear functionals on se(3): the pairing 𝓕(s) = Mᵀω + pᵀv", "GF §12.1", pairing);
SOMA_STUDY_DOUBLE("GF-12.1-coadjoint-representation", "Co-screws move by the coadjoint [[R, TR], [0, R]] = Ad⁻ᵀ, keeping the pairing",
     "GF §12.1", coadjoint);
SOMA_STUDY_DOUBLE("GF-12.2-wrench-of-a-force", "The wrench of a force (r × F, F): power, line of action, equilibrium", "GF §12.2", wrenchOfForce);
SOMA_STUDY_DOUBLE("GF-12.2-couple-pure-torque", "A couple is a pure torque (2 r × F, 0)", "GF §12.2", couple);
SOMA_STUDY_DOUBLE("GF-12.2-wrench-pitch-axis", "Pitch τ·F/F·F and axis of a wrench; infinite pitch for F = 0", "GF §12.2", pitchAxis);
SOMA_STUDY_DOUBLE("GF-12.3-wrist-force-sensor", "The four-beam wrist force sensor and its resolved force matrix (erratum E12.1)",
     "GF §12.3", wristSensor);
SOMA_STUDY_DOUBLE("GF-12.4-joint-torques-to-wrench", "𝒲_totᵀ J = (w₁…w₆): the end-effector wrench of a PUMA 560", "GF §12.4", jointTorques);
SOMA_STUDY_DOUBLE("GF-12.4-stiffness-compliance", "Stiffness (J⁻¹)ᵀKJ⁻¹, compliance JK⁻¹Jᵀ and the eigenscrews", "GF §12.4", stiffness);

}  // namespace soma::studies::gf12::SOMA_UNITY_ID
