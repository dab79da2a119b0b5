// Studies of GF chapter 3 — Subgroups, §3.7 (robot kinematics): joint matrices, forward
// kinematics as a product of conjugated joint matrices, tool-frame and relative moves.
// The joint matrices and the forward kinematics are computed here from the book's formulas
// (study scaffolding; the serial-robot library comes later).
#include "soma/algebra/screw.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/gf02_gf03_support.hpp"

#include <string>
#include <vector>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace gf23;
const char* const kChapter = "GF 3 — Subgroups";

/// The book's joint matrix about the x-axis: helical with pitch p per turn, revolute for p = 0.
// GF §3.7, GF-3.7-joint-matrices
template <class S> Mat4<S> jointXp(const S& p, const S& th) {
  return hom<S>(rotX<S>(th), Vec3<S>(p * th / (S(2) * pi<S>()), S(0), S(0)));
}
/// The book's prismatic joint matrix along x.
// GF §3.7, GF-3.7-joint-matrices
template <class S> Mat4<S> jointXt(const S& th) { return translation4<S>(Vec3<S>(th, S(0), S(0))); }

// ---- GF-3.7-joint-matrices --------------------------------------------------------------------
// GF §3.7, GF-3.7-joint-matrices: X_p(θ), X_t(θ) are one-parameter subgroups,
// X(θ1)X(θ2) = X(θ1 + θ2), X(θ)⁻¹ = X(−θ), equal to exp of the joint screw.
template <class S> void jointMatrices(Context& c) {
  using std::abs;
  using std::sin;
  auto g = rng(3701);
  const S tol = Tolerance<S>::identity(64);
  const Vec3<S> ex = Vec3<S>::Unit(0);
  S eSub(0), eInv(0), eExp(0), eSubT(0), eExpT(0);
  for (int t = 0; t < 100; ++t) {
    const S p = (t % 3 == 0) ? S(0) : uni<S>(g, -2, 2);
    const S a = uni<S>(g, -4, 4), b = uni<S>(g, -4, 4);
    eSub = std::max(eSub, maxAbs(Mat4<S>(jointXp(p, a) * jointXp(p, b) - jointXp(p, S(a + b)))));
    eInv = std::max(eInv, maxAbs(Mat4<S>(jointXp(p, a).inverse() - jointXp(p, S(-a)))));
    // exp of the twist (ω, v) = (e_x, p/2π e_x)·θ (library exponential)
    const SE3Tangent<S> s(Vec3<S>(ex * a), Vec3<S>(ex * (p / (S(2) * pi<S>()) * a)));
    eExp = std::max(eExp, maxAbs(Mat4<S>(s.exp().matrix() - jointXp(p, a))));
    eSubT = std::max(eSubT, maxAbs(Mat4<S>(jointXt(a) * jointXt(b) - jointXt(S(a + b)))));
    eExpT = std::max(eExpT, maxAbs(Mat4<S>(SE3Tangent<S>(Vec3<S>::Zero(), Vec3<S>(ex * a)).exp().matrix() - jointXt(a))));
  }
  c.checkResidual("X_p(θ1)X_p(θ2) = X_p(θ1 + θ2) (helical and revolute)", eSub, tol);
  c.checkResidual("X_p(θ)⁻¹ = X_p(−θ)", eInv, tol);
  c.checkResidual("X_p(θ) = exp θ(e_x, (p/2π) e_x) (library exponential)", eExp, tol);
  c.checkResidual("X_t(θ1)X_t(θ2) = X_t(θ1 + θ2)", eSubT, tol);
  c.checkResidual("X_t(θ) = exp θ(0, e_x)", eExpT, tol);
  // θ at 0, π, 2π: X_0(2π) = I, X_p(2π) = translation by p (one turn advances p)
  const S p = S(3) / S(4);
  c.checkResidual("X_p(0) = I", maxAbs(Mat4<S>(jointXp(p, S(0)) - Mat4<S>::Identity())), S(0));
  c.checkResidual("X_0(π) = diag(1, −1, −1, 1)",
                  maxAbs(Mat4<S>(jointXp(S(0), pi<S>()) - Mat4<S>(Vec4<S>(S(1), S(-1), S(-1), S(1)).asDiagonal()))), tol);
  c.checkResidual("X_0(2π) = I (revolute joint space is a circle)",
                  maxAbs(Mat4<S>(jointXp(S(0), S(2) * pi<S>()) - Mat4<S>::Identity())), tol);
  c.checkResidual("X_p(2π) = X_t(p): one turn advances the pitch p",
                  maxAbs(Mat4<S>(jointXp(p, S(2) * pi<S>()) - jointXt(p))), tol);
  // other axes by conjugation: G = R_y(−π/2) carries x to z, G X_0(θ) G⁻¹ = R_z(θ)
  const Mat4<S> gy = hom<S>(SO3<S>::fromAxisAngle(Vec3<S>::Unit(1), -pi<S>() / S(2)).matrix(), Vec3<S>::Zero());
  const S th = S(7) / S(10);
  c.checkResidual("conjugation G X_0(θ) G⁻¹ with G = R_y(−π/2) is the revolute about z",
                  maxAbs(Mat4<S>(gy * jointXp(S(0), th) * gy.inverse() - hom<S>(rotZ<S>(th), Vec3<S>::Zero()))), tol);
  // limits: p → ∞ with the advance s fixed: X_p(2πs/p) → X_t(s); the gap is exactly sin(2πs/p)
  const S s = S(1) / S(2);
  for (const S big : {S(1000), S(1000000)}) {
    const S phi = S(2) * pi<S>() * s / big;
    c.checkNear("p = " + toString(big, 3) + ": |X_p(2πs/p) − X_t(s)| = sin(2πs/p) (X_p cannot reach prismatic)",
                sin(phi), maxAbs(Mat4<S>(jointXp(big, phi) - jointXt(s))), tol);
  }
}

SOMA_STUDY({.id = "GF-3.7-joint-matrices",
            .title = "Joint matrices X_p(θ), X_t(θ) as one-parameter subgroups",
            .source = "GF §3.7",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { jointMatrices<S>(c); }); }});

// ---- GF-3.7-offset-revolute-example -----------------------------------------------------------
/// The matrix as the book prints it (erratum E3.3: the (2,4) entry should be −sin θ).
// GF §3.7, GF-3.7-offset-revolute-example (as printed)
template <class S> Mat4<S> offsetRevolutePrinted(const S& th) {
  using std::cos;
  using std::sin;
  return hom<S>(rotX<S>(th), Vec3<S>(S(0), S(1) - cos(th), sin(th)));
}
// GF §3.7, GF-3.7-offset-revolute-example (corrected, erratum E3.3): (I − R)x.
template <class S> Mat4<S> offsetRevoluteCorrected(const S& th) {
  using std::cos;
  using std::sin;
  return hom<S>(rotX<S>(th), Vec3<S>(S(0), S(1) - cos(th), -sin(th)));
}

// GF §3.7, GF-3.7-offset-revolute-example: rotation about the x-parallel line through (0, 1, 0).
template <class S> void offsetRevolute(Context& c) {
  using std::abs;
  using std::sin;
  const S tol = Tolerance<S>::identity(64);
  const Vec3<S> x(S(0), S(1), S(0));
  const Vec4<S> xh(S(0), S(1), S(0), S(1));
  for (const auto& [label, th] : std::vector<std::pair<std::string, S>>{
           {"θ = π/2", pi<S>() / S(2)}, {"θ = 0.7", S(7) / S(10)}, {"θ = π", pi<S>()}}) {
    const Mat4<S> conj = translation4<S>(x) * jointXp(S(0), th) * translation4<S>(Vec3<S>(-x));
    c.checkResidual(label + ": T(x) X_0(θ) T(−x) = corrected matrix (translation (0, 1 − cos θ, −sin θ))",
                    maxAbs(Mat4<S>(conj - offsetRevoluteCorrected(th))), tol);
    c.checkResidual(label + ": = library screwMotion(e_x, (0,1,0), 0, θ)",
                    maxAbs(Mat4<S>(screwMotion<S>(Vec3<S>::Unit(0), x, S(0), th).matrix() - conj)), tol);
    c.checkResidual(label + ": the corrected matrix fixes the axis point (0, 1, 0)",
                    maxAbs(Vec4<S>(offsetRevoluteCorrected(th) * xh - xh)), tol);
    const Vec4<S> moved = offsetRevolutePrinted(th) * xh;
    const S miss = maxAbs(Vec4<S>(moved - xh));
    if (abs(sin(th)) > S(1) / S(10)) {
      c.recordIn(label + ": printed matrix moves (0, 1, 0) to (0, 1, 2 sin θ) (miss > 0.1)", "fails (erratum E3.3)",
                 io::numberText(S(moved(2))), miss, S(1) / S(10), miss > S(1) / S(10));
      c.checkNear(label + ": the printed image's z equals 2 sin θ", S(2) * sin(th), moved(2), tol);
    } else {
      c.checkResidual(label + ": printed and corrected agree where sin θ = 0", miss, tol);
    }
  }
}

SOMA_STUDY({.id = "GF-3.7-offset-revolute-example",
            .title = "Revolute about the x-parallel line through (0,1,0): erratum E3.3",
            .source = "GF §3.7",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { offsetRevolute<S>(c); }); }});

// ---- forward kinematics scaffolding -----------------------------------------------------------
/// A standard DH row A = Rz(θ)·Tz(d)·Tx(a)·Rx(α); the joint variable adds to θ (R) or d (P).
template <class S> struct DH {
  bool prismatic;
  S a, alpha, d, theta;
};
template <class S> Mat4<S> dhMatrix(const DH<S>& j, const S& q) {
  using std::cos;
  using std::sin;
  const S th = j.prismatic ? j.theta : S(j.theta + q);
  const S d = j.prismatic ? S(j.d + q) : j.d;
  return hom<S>(rotZ<S>(th), Vec3<S>::Zero()) * translation4<S>(Vec3<S>(S(0), S(0), d)) *
         translation4<S>(Vec3<S>(j.a, S(0), S(0))) * hom<S>(rotX<S>(j.alpha), Vec3<S>::Zero());
}
/// Independent method: the DH product T(q) = Π A_i(q_i).
template <class S> Mat4<S> dhForward(const std::vector<DH<S>>& arm, const std::vector<S>& q) {
  Mat4<S> t = Mat4<S>::Identity();
  for (std::size_t i = 0; i < arm.size(); ++i) t = t * dhMatrix(arm[i], q[i]);
  return t;
}
/// The book's joint matrices placed at the home axes: A_i(θ) = (F_{i−1} G) X(θ) (F_{i−1} G)⁻¹
/// with F_{i−1} the home frame of joint i (whose z-axis is the joint axis) and G = R_y(−π/2)
/// carrying the book's x-axis joint onto z.
// GF §3.7, GF-3.7-forward-kinematics
template <class S> std::vector<Mat4<S>> homeJointPlacements(const std::vector<DH<S>>& arm) {
  const Mat4<S> gy = hom<S>(SO3<S>::fromAxisAngle(Vec3<S>::Unit(1), -pi<S>() / S(2)).matrix(), Vec3<S>::Zero());
  std::vector<Mat4<S>> place;
  Mat4<S> f = Mat4<S>::Identity();
  for (const auto& j : arm) {
    place.push_back(f * gy);
    f = f * dhMatrix(j, S(0));
  }
  return place;
}
template <class S> Mat4<S> bookJoint(const Mat4<S>& place, bool prismatic, const S& q) {
  return place * (prismatic ? jointXt(q) : jointXp(S(0), q)) * place.inverse();
}
/// K(θ) = A_1(θ1) A_2(θ2) ⋯ A_n(θn). GF §3.7, GF-3.7-forward-kinematics
template <class S>
Mat4<S> bookForward(const std::vector<DH<S>>& arm, const std::vector<Mat4<S>>& place, const std::vector<S>& q) {
  Mat4<S> k = Mat4<S>::Identity();
  for (std::size_t i = 0; i < arm.size(); ++i) k = k * bookJoint(place[i], arm[i].prismatic, q[i]);
  return k;
}
/// PUMA 560 (standard DH, metres) and the Stanford arm (joint 3 prismatic).
template <class S> std::vector<DH<S>> puma() {
  const S h = pi<S>() / S(2);
  return {{false, S(0), h, S(0), S(0)},
          {false, S(4318) / S(10000), S(0), S(0), S(0)},
          {false, S(203) / S(10000), -h, S(15005) / S(100000), S(0)},
          {false, S(0), h, S(4318) / S(10000), S(0)},
          {false, S(0), -h, S(0), S(0)},
          {false, S(0), S(0), S(0), S(0)}};
}
template <class S> std::vector<DH<S>> stanford() {
  const S h = pi<S>() / S(2);
  return {{false, S(0), -h, S(412) / S(1000), S(0)},
          {false, S(0), h, S(154) / S(1000), S(0)},
          {true, S(0), S(0), S(3) / S(10), -h},
          {false, S(0), -h, S(0), S(0)},
          {false, S(0), h, S(0), S(0)},
          {false, S(0), S(0), S(263) / S(1000), S(0)}};
}

// ---- GF-3.7-forward-kinematics ----------------------------------------------------------------
// GF §3.7, GF-3.7-forward-kinematics: K(θ) = A_1(θ1)⋯A_6(θ6) from a home configuration, checked
// against the DH product (K(θ) = T(θ) T(0)⁻¹), K(0) = I and 2π-periodicity.
template <class S> void forwardKinematics(Context& c) {
  auto g = rng(3702);
  const S tol = Tolerance<S>::identity(256);
  for (const auto& [name, arm] : std::vector<std::pair<std::string, std::vector<DH<S>>>>{
           {"PUMA 560", puma<S>()}, {"Stanford arm (RRPRRR)", stanford<S>()}}) {
    const auto place = homeJointPlacements(arm);
    const std::vector<S> zero(6, S(0));
    const Mat4<S> t0 = dhForward(arm, zero);
    c.checkResidual(name + ": K(0) = I", maxAbs(Mat4<S>(bookForward(arm, place, zero) - Mat4<S>::Identity())), tol);
    S eDH(0), ePer(0), eTurns(0), eBig(0);
    for (int t = 0; t < 50; ++t) {
      std::vector<S> q(6);
      for (auto& v : q) v = uni<S>(g, -3, 3);
      const Mat4<S> k = bookForward(arm, place, q);
      eDH = std::max(eDH, maxAbs(Mat4<S>(k - dhForward(arm, q) * t0.inverse())));
      const int i = t % 6;
      if (!arm[std::size_t(i)].prismatic) {
        std::vector<S> q2 = q;
        q2[std::size_t(i)] += S(2) * pi<S>();
        ePer = std::max(ePer, maxAbs(Mat4<S>(bookForward(arm, place, q2) - k)));
        q2[std::size_t(i)] = q[std::size_t(i)] + S(2000) * pi<S>();  // 1000 full turns
        eTurns = std::max(eTurns, maxAbs(Mat4<S>(bookForward(arm, place, q2) - k)));
      } else {
        std::vector<S> q2 = q;
        q2[std::size_t(i)] = S(1000);  // long prismatic travel
        eBig = std::max(eBig, maxAbs(Mat4<S>(bookForward(arm, place, q2) - dhForward(arm, q2) * t0.inverse())) / S(1000));
      }
    }
    c.checkResidual(name + ": K(θ) = T_DH(θ) T_DH(0)⁻¹ (50 random θ; independent DH product)", eDH, tol);
    c.checkResidual(name + ": K(θ + 2π e_i) = K(θ) (revolute joints, joint space a torus; tolerance × (3 + 2π), the size of θ)",
                    ePer, tol * (S(3) + S(2) * pi<S>()));
    c.checkResidual(name + ": 1000 full turns of a joint (tolerance × 6283, the size of θ)", eTurns, tol * S(6283));
    if (name != "PUMA 560")
      c.checkResidual(name + ": prismatic travel 1000: agreement relative to the travel", eBig, tol);
  }
  c.note("Home configuration: all joint variables 0 in the DH tables (PUMA 560: a2 = 0.4318, a3 = "
         "0.0203, d3 = 0.15005, d4 = 0.4318; Stanford: d1 = 0.412, d2 = 0.154, d3 = 0.3 + q3, d6 = 0.263). "
         "A_i is the book's X_0 / X_t conjugated onto the home axis of joint i.");
}

SOMA_STUDY({.id = "GF-3.7-forward-kinematics",
            .title = "Forward kinematics K(θ) = A1(θ1)⋯A6(θ6) vs the DH product",
            .source = "GF §3.7",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { forwardKinematics<S>(c); }); }});

// ---- GF-3.7-tool-frame-and-relative-moves -----------------------------------------------------
// GF §3.7, GF-3.7-tool-frame-and-relative-moves: (K(θ)B)⁻¹ = B⁻¹A_6(−θ6)⋯A_1(−θ1); a passive
// target K* gives K(θ) = (BK*)⁻¹; a move K_Δ in the tool frame gives
// (K_cB)K_Δ(K_cB)⁻¹K_c = K_cBK_ΔB⁻¹.
template <class S> void toolFrame(Context& c) {
  using std::abs;
  auto g = rng(3703);
  const S tol = Tolerance<S>::identity(256);
  const auto d = [](const Mat4<S>& a, const Mat4<S>& b) { return maxAbs(Mat4<S>(a - b)); };
  S eId(0), eIdB(0), eIdD(0);
  for (int t = 0; t < 100; ++t) {
    const Mat4<S> kc = SE3<S>::Random(g).matrix(), b = SE3<S>::Random(g).matrix(), kd = SE3<S>::Random(g).matrix();
    const Mat4<S> lhs = (kc * b) * kd * (kc * b).inverse() * kc;
    eId = std::max(eId, d(lhs, kc * b * kd * b.inverse()));
    // B = I and K_Δ = I reduce exactly
    const Mat4<S> I = Mat4<S>::Identity();
    eIdB = std::max(eIdB, d(kc * I * kd * I.inverse(), kc * kd));
    eIdD = std::max(eIdD, d(kc * b * I * b.inverse(), kc));
  }
  c.checkResidual("(K_cB)K_Δ(K_cB)⁻¹K_c = K_cBK_ΔB⁻¹ (100 random)", eId, tol);
  c.checkResidual("B = I: K = K_cK_Δ", eIdB, S(0));
  c.checkResidual("K_Δ = I: K = K_c", eIdD, tol);
  // With the PUMA: tool-frame kinematics and the round trip through a passive target.
  const auto arm = puma<S>();
  const auto place = homeJointPlacements(arm);
  const std::vector<S> zero(6, S(0));
  const Mat4<S> tool = SE3<S>(SO3<S>(), Vec3<S>(S(0), S(0), S(1) / S(10))).matrix();  // 0.1 m tool offset
  const Mat4<S> B = dhForward(arm, zero) * tool;  // base → tool frame at home
  S ePass(0), eAinv(0), eDH(0), eRound(0);
  for (int t = 0; t < 30; ++t) {
    std::vector<S> q(6);
    for (auto& v : q) v = uni<S>(g, -3, 3);
    const Mat4<S> k = bookForward(arm, place, q);
    Mat4<S> prod = B.inverse();
    for (int i = 5; i >= 0; --i) prod = prod * bookJoint(place[std::size_t(i)], false, S(-q[std::size_t(i)]));
    ePass = std::max(ePass, d((k * B).inverse(), prod));
    for (int i = 0; i < 6; ++i)
      eAinv = std::max(eAinv, d(bookJoint(place[std::size_t(i)], false, q[std::size_t(i)]).inverse(),
                                bookJoint(place[std::size_t(i)], false, S(-q[std::size_t(i)]))));
    // K(θ)B is the DH pose of the tool: its inverse is the passive tool-frame map
    eDH = std::max(eDH, d((k * B).inverse(), (dhForward(arm, q) * tool).inverse()));
    const Mat4<S> kstar = (k * B).inverse();  // passive target
    eRound = std::max(eRound, d((B * kstar).inverse(), k));
  }
  c.checkResidual("PUMA: (K(θ)B)⁻¹ = B⁻¹A_6(−θ6)⋯A_1(−θ1)", ePass, tol);
  c.checkResidual("A_i(θ)⁻¹ = A_i(−θ) (one-parameter subgroups)", eAinv, tol);
  c.checkResidual("(K(θ)B)⁻¹ = (T_DH(θ)·tool)⁻¹ (independent)", eDH, tol);
  c.checkResidual("passive target K* = (K(θ)B)⁻¹ converts back: (BK*)⁻¹ = K(θ)", eRound, tol);
  // Round trip to the joint angles: Newton on the spatial log from a nearby start.
  {
    std::vector<S> q(6);
    for (auto& v : q) v = uni<S>(g, -2, 2);
    const Mat4<S> target = bookForward(arm, place, q);
    std::vector<S> x = q;
    for (auto& v : x) v += uni<S>(g, -0.05, 0.05);
    Mat6<S> jac = Mat6<S>::Identity();
    for (int it = 0; it < 30; ++it) {
      const Mat4<S> k = bookForward(arm, place, x);
      const SE3<S> err = SE3<S>::fromMatrix(Mat4<S>(target * k.inverse()));
      const Vec6<S> e = err.log().coeffs();
      if (maxAbs(e) <= Tolerance<S>::epsilon() * S(4)) break;
      // spatial Jacobian: column i = Ad(A_1⋯A_{i−1}) s_i, s_i the home screw of joint i
      Mat4<S> pre = Mat4<S>::Identity();
      for (int i = 0; i < 6; ++i) {
        const Mat4<S> pl = pre * place[std::size_t(i)];
        const SE3<S> ps = SE3<S>::fromMatrix(pl);
        jac.col(i) = ps.adjoint() * (Vec6<S>() << Vec3<S>::Unit(0), Vec3<S>::Zero()).finished();
        pre = pre * bookJoint(place[std::size_t(i)], false, x[std::size_t(i)]);
      }
      const Vec6<S> dx = jac.fullPivLu().solve(e);
      for (int i = 0; i < 6; ++i) x[std::size_t(i)] += dx(i);
    }
    S eq(0);
    for (int i = 0; i < 6; ++i) eq = std::max(eq, abs(x[std::size_t(i)] - q[std::size_t(i)]));
    // the target and K(x) are rounded to tol·(1 + |t|) in twist coordinates (t the target's
    // translation); Newton's fixed point then lies within ‖J⁻¹‖ times that of θ
    const S fkError = tol * (S(1) + Vec3<S>(target.template topRightCorner<3, 1>()).norm());
    c.checkResidual("round trip FK → target → Newton from θ + U(±0.05) recovers θ (‖J⁻¹‖·tol(1 + |t|))", eq,
                    Mat6<S>(jac.fullPivLu().inverse()).norm() * fkError);
  }
}

SOMA_STUDY({.id = "GF-3.7-tool-frame-and-relative-moves",
            .title = "Tool-frame kinematics, passive targets and moves in the tool frame",
            .source = "GF §3.7",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { toolFrame<S>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
