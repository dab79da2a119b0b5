// Studies of GF chapter 4, §4.6: the double cover SU(2) → SO(3), the quaternion Lie algebra,
// ideals and semisimplicity.
#include "gf04/common.hpp"

#include <Eigen/LU>

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

/// The SU(2) image of a quaternion w + xi + yj + zk under i ↦ 2σx, j ↦ 2σy, k ↦ 2σz (GF §4.6).
template <class S> CMat<Mat2<S>> su2Of(const Quat<S>& q) {
  Mat2<S> re, im;
  re << q.w(), q.y(), -q.y(), q.w();
  im << q.x(), q.z(), q.z(), -q.x();
  return {re, im};
}

// ---- GF §4.6, GF-4.6-soup-plate-double-cover --------------------------------------------------
template <class S> void soupPlate(Context& c) {
  auto g = rng(62);
  const Vec3<S> a = randomUnit<S>(g);
  const S tol = Tolerance<S>::identity(64);
  const CMat<Mat2<S>> I2{Mat2<S>::Identity(), Mat2<S>::Zero()};
  const Quat<S> q2 = SO3Tangent<S>(Vec3<S>(a * (S(2) * pi<S>()))).exp().quaternion();
  const Quat<S> q4 = SO3Tangent<S>(Vec3<S>(a * (S(4) * pi<S>()))).exp().quaternion();
  c.checkResidual("lift cos(θ/2) I + sin(θ/2) R(a) at θ = 2π is −I₂", (su2Of(q2) + I2).maxAbs(), tol * S(8));
  c.checkResidual("… at θ = 4π is I₂", (su2Of(q4) - I2).maxAbs(), tol * S(8));
  c.checkResidual("both project to I₃ in SO(3)",
                  maxOf(maxAbs(Mat3<S>(rotationFromQuaternion(q2) - Mat3<S>::Identity())),
                        maxAbs(Mat3<S>(rotationFromQuaternion(q4) - Mat3<S>::Identity()))),
                  tol * S(8));
  // Track the lift of a sampled loop continuously (sign closest to the previous sample) from the
  // rotation matrices alone: one turn ends at −q₀ (not contractible), two turns at +q₀.
  for (const int turns : {1, 2}) {
    const int n = 48 * turns;
    Quat<S> prev = quaternionFromRotation<S>(Mat3<S>::Identity());
    const Quat<S> q0 = prev;
    int flips = 0;
    for (int k = 1; k <= n; ++k) {
      const S th = S(2) * pi<S>() * S(k) / S(48);
      Quat<S> q = quaternionFromRotation<S>(SO3Tangent<S>(Vec3<S>(a * th)).exp().matrix());
      if (q.coeffs().dot(prev.coeffs()) < S(0)) {
        q.coeffs() = -q.coeffs();
        ++flips;
      }
      prev = q;
    }
    const S endSign = prev.coeffs().dot(q0.coeffs());
    c.checkNear(std::to_string(turns) + (turns == 1 ? " turn (2π)" : " turns (4π)") +
                    ": continuous lift ends at " + (turns == 1 ? "−q₀" : "+q₀"),
                turns == 1 ? S(-1) : S(1), endSign, tol * S(8));
    c.note(std::to_string(turns) + " turn(s): the w ≥ 0 chart had to be sign-corrected at " + std::to_string(flips) +
           " of " + std::to_string(n) + " samples to keep the lift continuous.");
  }
}
SOMA_STUDY_SCALAR("GF-4.6-soup-plate-double-cover",
           "SU(2) double covers SO(3): the 2π loop lifts to a path I → −I, the 4π loop closes",
           "GF §4.6", soupPlate);

// ---- GF §4.6, GF-4.6-quaternion-lie-algebra ----------------------------------------------------
template <class S> void quaternionLieAlgebra(Context& c) {
  auto g = rng(63);
  const S tol = Tolerance<S>::identity(64);
  // Tangent at 1 of a unit-quaternion path is pure: q̇* + q̇ = 0.
  const Vec3<S> w = randomVec<S, 3>(g);
  const Vec4<S> qd = derivative<S>([&](const S& t) {
    return Vec4<S>(SO3Tangent<S>(Vec3<S>(w * t)).exp().quaternion().coeffs());
  });
  c.checkResidual("d/dt of a unit-quaternion path at 1 is pure (q̇* + q̇ = 2 Re q̇ = 0)", abs(S(2) * qd(3)), fdTolerance<S>());
  c.checkResidual("… and equals ω/2", maxAbs(Vec3<S>(qd.template head<3>() - w / S(2))), fdTolerance<S>());
  // [i/2, j/2] = k/2 = ij/2 and cyclic, exactly.
  const S h = S(1) / S(2);
  const Quat<S> i(S(0), h, S(0), S(0)), j(S(0), S(0), h, S(0)), k(S(0), S(0), S(0), h);
  auto com = [](const Quat<S>& p, const Quat<S>& q) {
    return Vec4<S>(quaternionProduct(p, q).coeffs() - quaternionProduct(q, p).coeffs());
  };
  const S cyc = maxOf(maxAbs(Vec4<S>(com(i, j) - k.coeffs())),
                      maxOf(maxAbs(Vec4<S>(com(j, k) - i.coeffs())), maxAbs(Vec4<S>(com(k, i) - j.coeffs()))));
  c.checkResidual("[i/2, j/2] = k/2, [j/2, k/2] = i/2, [k/2, i/2] = j/2 (exact)", cyc, S(0));
  const Quat<S> I1(S(0), S(1), S(0), S(0)), J1(S(0), S(0), S(1), S(0)), K1(S(0), S(0), S(0), S(1));
  c.checkResidual("k/2 = ij/2 (exact)", maxAbs(Vec4<S>(quaternionProduct(I1, J1).coeffs() / S(2) - k.coeffs())), S(0));
  // i ↦ 2σx, j ↦ 2σy, k ↦ 2σz preserves brackets (random pure quaternions).
  S iso(0);
  for (int n = 0; n < 50; ++n) {
    const Vec3<S> p = randomVec<S, 3>(g), q = randomVec<S, 3>(g);
    const Quat<S> P(S(0), p(0), p(1), p(2)), Q(S(0), q(0), q(1), q(2));
    const Vec4<S> pq = com(P, Q);
    const Quat<S> br(pq(3), pq(0), pq(1), pq(2));
    const CMat<Mat2<S>> A = su2Of(P), B = su2Of(Q);
    iso = maxOf(iso, (su2Of(br) - (A * B - B * A)).maxAbs());
  }
  c.checkResidual("φ([p, q]) = [φ(p), φ(q)] for φ: i ↦ 2σx, j ↦ 2σy, k ↦ 2σz (50 random pairs)", iso, tol);
}
SOMA_STUDY_SCALAR("GF-4.6-quaternion-lie-algebra",
           "Lie algebra of unit quaternions = pure quaternions, isomorphic to su(2)", "GF §4.6",
           quaternionLieAlgebra);

// ---- GF §4.6, GF-4.6-ideals-semisimplicity -----------------------------------------------------
template <class S> void idealsSemisimplicity(Context& c) {
  auto g = rng(64);
  S ideal(0), quotient(0), normal(0), abelian(0);
  int fullRank = 0;
  for (int n = 0; n < 100; ++n) {
    const SE3Tangent<S> s(randomVec<S, 6>(g)), s2(randomVec<S, 6>(g));
    const SE3Tangent<S> t(Vec3<S>::Zero(), randomVec<S, 3>(g)), t2(Vec3<S>::Zero(), randomVec<S, 3>(g));
    ideal = maxOf(ideal, maxAbs(bracket(s, t).ang()));
    quotient = maxOf(quotient, maxAbs(Vec3<S>(bracket(s + t, s2 + t2).ang() - s.ang().cross(s2.ang()))));
    normal = maxOf(normal, maxAbs(Vec3<S>((SE3<S>::Random(g).adjoint() * t.coeffs()).template head<3>())));
    abelian = maxOf(abelian, maxAbs(bracket(t, t2).coeffs()));
    // so(3) has no proper ideal: x and [e_i, x] span all of so(3).
    const Vec3<S> x = randomVec<S, 3>(g);
    Eigen::Matrix<S, 3, 4> span;
    span << x, Vec3<S>(Vec3<S>::UnitX().cross(x)), Vec3<S>(Vec3<S>::UnitY().cross(x)), Vec3<S>(Vec3<S>::UnitZ().cross(x));
    Eigen::FullPivLU<MatX<S>> lu{MatX<S>(span)};
    lu.setThreshold(Tolerance<S>::rank());
    fullRank += lu.rank() == 3;
  }
  c.checkResidual("translations are an ideal: [s, (0; v)] has ω-part 0 (100 random)", ideal, S(0));
  c.checkResidual("translations are abelian: [(0; v₁), (0; v₂)] = 0", abelian, S(0));
  c.checkResidual("quotient se(3)/ℝ³ ≅ so(3): ω-part of [s₁ + t₁, s₂ + t₂] = ω₁ × ω₂", quotient, Tolerance<S>::identity(8));
  c.checkResidual("normal subgroup ℝ³ ↔ ideal: Ad(g)(0; v) has ω-part 0", normal, S(0));
  c.checkEqual("so(3): the ideal generated by any x ≠ 0 is all of so(3) (100 random x)", 100, fullRank);
  c.checkNear("so(3) semisimple: det of its Killing form = −8 (non-degenerate)", S(-8),
              killingForm<SO3Tangent<S>>().determinant(), S(0));
  c.checkNear("se(3) not semisimple: det of its Killing form = 0", S(0), killingForm<SE3Tangent<S>>().determinant(), S(0));
}
SOMA_STUDY_SCALAR("GF-4.6-ideals-semisimplicity",
           "Ideals ↔ normal subgroups; translations are an abelian ideal of se(3); so(3) semisimple",
           "GF §4.6", idealsSemisimplicity);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
