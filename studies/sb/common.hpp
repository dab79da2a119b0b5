#pragma once
// Helpers shared by the SB studies (sb/*.cpp), templated on the scalar S the study runs in: the
// fixed-seed draws (soma/studies/scalar_draws.hpp: drawn in double, cast to S), random motions and
// bodies built from them, SB's printed elements built literally (products of generators, in the order
// SB writes them), and small independent references (point-mass bodies). Nothing here is library code.
#include "soma/studies/scalar_draws.hpp"
#include "soma/geometry/dynamics/clifford_dynamics.hpp"
#include "soma/geometry/dynamics/free_body.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"
#include "soma/studies/study.hpp"

#include <random>
#include <string>
#include <vector>

namespace soma::studies::sb {

inline constexpr const char* kChapter = "SB — Rigid body dynamics in Cl(0,6,2)";
namespace c6 = soma::clifford_dynamics;
template <class S> using D = c6::Dense<S>;
template <class S> using Biv = c6::Bivector<S>;
template <class S> using Quad = c6::Quadvector<S>;
template <class S> using Ev = c6::Even<S>;
template <class S> using T6 = SE3Tangent<S>;
template <class S> using V6 = Vec6<S>;
template <class S> using M6 = Mat6<S>;

using draws::frac;
using draws::maxOf;
using draws::rv3;
using draws::rv6;
using draws::uni;

inline std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
/// min(a, b), propagating NaN as maxOf does (a miss that is NaN is not a miss).
template <class S> S minOf(const S& a, const S& b) { return -maxOf<S>(-a, -b); }
/// k ulps of unit-scale data: the rounding bound of a short computation (Tolerance::identity).
template <class S> S tol(int ulps) { return Tolerance<S>::identity(ulps); }

// 4th-order central differences at h = ε^(1/5): truncation h⁴|f⁽⁵⁾|/30 and rounding 3ε|f|/(2h) are both
// ≈ ε^(4/5); fdTol = 2048 ε^(4/5) (6.4e-10 in double) for O(1) derivatives (as gf15/common.hpp).
template <class S> S fdStep() { return Tolerance<S>::precision(4); }
template <class S> S fdTol() {
  using std::pow;
  return S(2048) * pow(Tolerance<S>::epsilon(), S(4) / S(5));
}
/// The 5-point central difference (8(f(h) − f(−h)) − (f(2h) − f(−2h)))/(12h) of f at 0.
template <class S, class F> auto cdiff(F&& f, const S& h) {
  using R = std::decay_t<decltype(f(S(0)))>;
  return R((S(8) * R(f(h) - f(S(-h))) - R(f(S(2 * h)) - f(S(-2 * h)))) / (S(12) * h));
}

/// A rigid motion: a rotation (SO3::Random, normalised in S) then a translation in [−2, 2]³.
template <class S> SE3<S> randMotion(std::mt19937_64& g) {
  const SO3<S> R = SO3<S>::Random(g);
  const Vec3<S> t = rv3<S>(g, -2, 2);
  return SE3<S>(R, t);
}
/// A body with principal moments in [0.3, 2], mass in [0.5, 3], centre of mass in [−1, 1]³.
template <class S> SpatialInertia<S> randBody(std::mt19937_64& g) {
  const Mat3<S> R = SO3<S>::Random(g).matrix();
  const Vec3<S> d = rv3<S>(g, 0.3, 2);
  const S m = uni<S>(g, 0.5, 3);
  const Vec3<S> c = rv3<S>(g);
  return SpatialInertia<S>(m, c, Mat3<S>(R * d.asDiagonal() * R.transpose()));
}
/// The product of generators in the order written (e.g. {a3, a1, e1} = a₃a₁e₁), times c, as a dense
/// element — SB's printed terms taken literally (repeated generators multiply by their square).
template <class S> D<S> word(std::initializer_list<int> gens, const std::type_identity_t<S>& c = S(1)) {
  D<S> out(c);
  for (int g : gens) out = D<S>(out * D<S>::generator(g));
  return out;
}
/// The even part of a dense element (SB's motors are even).
template <class S> Ev<S> toEven(const D<S>& x) { return x.template grades<c6::Sig::evenGrades>(); }
template <class X> auto mx(const X& x) { return x.maxAbs(); }
template <class Derived> typename Derived::Scalar mxm(const Eigen::MatrixBase<Derived>& m) { return m.cwiseAbs().maxCoeff(); }

/// SB §5's diagonal inertia as printed: d_x a₁ae₁e + d_y a₂ae₂e + d_z a₃ae₃e + m a₂a₃e₂e₃ + …
template <class S> D<S> printedDiagonalInertia(const S& dx, const S& dy, const S& dz, const S& m) {
  using namespace c6;
  return D<S>(word<S>({a1, a, e1, e}, dx) + word<S>({a2, a, e2, e}, dy) + word<S>({a3, a, e3, e}, dz) +
              word<S>({a2, a3, e2, e3}, m) + word<S>({a3, a1, e3, e1}, m) + word<S>({a1, a2, e1, e2}, m));
}

/// Independent reference body: point masses m_k at x_k. Momentum of a velocity s = (ω, v) by
/// summing particles (p = Σ m_k (v + ω × x_k), l = Σ x_k × m_k(v + ω × x_k)) — no 6×6 algebra.
template <class S> struct PointCloud {
  std::vector<S> m;
  std::vector<Vec3<S>> x;
  V6<S> momentum(const T6<S>& s) const {
    V6<S> out = V6<S>::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) {
      const Vec3<S> vel = s.lin() + s.ang().cross(x[k]);
      out.template head<3>() += x[k].cross(Vec3<S>(m[k] * vel));
      out.template tail<3>() += m[k] * vel;
    }
    return out;
  }
  /// (m, c, I_c) of the cloud, from the textbook sums.
  SpatialInertia<S> inertia() const {
    S M = 0;
    Vec3<S> c = Vec3<S>::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) M += m[k], c += m[k] * x[k];
    c /= M;
    Mat3<S> I = Mat3<S>::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) {
      const Vec3<S> r = x[k] - c;
      I += m[k] * (r.squaredNorm() * Mat3<S>::Identity() - r * r.transpose());
    }
    return SpatialInertia<S>(M, c, I);
  }
  PointCloud moved(const SE3<S>& g) const {
    PointCloud o = *this;
    for (auto& p : o.x) p = g.act(p);
    return o;
  }
};
template <class S> PointCloud<S> randCloud(std::mt19937_64& g, int n = 7) {
  PointCloud<S> c;
  for (int k = 0; k < n; ++k) c.m.push_back(uni<S>(g, 0.2, 1.5)), c.x.push_back(rv3<S>(g, -1, 1.5));
  return c;
}

}  // namespace soma::studies::sb
