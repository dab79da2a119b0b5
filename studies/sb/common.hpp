#pragma once
// Helpers shared by the SB studies (sb_*.cpp): fixed-seed draws, SB's printed elements built
// literally (products of generators, in the order SB writes them), and small independent
// references (point-mass bodies). Nothing here is library code.
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
using D = c6::Dense<double>;
using Biv = c6::Bivector<double>;
using Quad = c6::Quadvector<double>;
using Ev = c6::Even<double>;
using T6 = SE3Tangent<double>;
using V6 = Vec6<double>;
using M6 = Mat6<double>;

inline std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
inline double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
inline V6 randV6(std::mt19937_64& g) {
  V6 v;
  for (int i = 0; i < 6; ++i) v(i) = uni(g);
  return v;
}
inline Vec3<double> randV3(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return {uni(g, lo, hi), uni(g, lo, hi), uni(g, lo, hi)};
}
inline SE3<double> randMotion(std::mt19937_64& g) { return SE3<double>(SO3<double>::Random(g), randV3(g, -2, 2)); }
inline SpatialInertia<double> randBody(std::mt19937_64& g) {
  const Mat3<double> R = SO3<double>::Random(g).matrix();
  const Vec3<double> d = randV3(g, 0.3, 2);
  return SpatialInertia<double>(uni(g, 0.5, 3), randV3(g), Mat3<double>(R * d.asDiagonal() * R.transpose()));
}

/// The product of generators in the order written (e.g. {a3, a1, e1} = a₃a₁e₁), times c, as a dense
/// element — SB's printed terms taken literally (repeated generators multiply by their square).
inline D word(std::initializer_list<int> gens, double c = 1) {
  D out(c);
  for (int g : gens) out = D(out * D::generator(g));
  return out;
}
/// The even part of a dense element (SB's motors are even).
inline Ev toEven(const D& x) { return x.grades<c6::Sig::evenGrades>(); }
template <class X> double mx(const X& x) { return x.maxAbs(); }
inline double mxm(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

/// SB §5's diagonal inertia as printed: d_x a₁ae₁e + d_y a₂ae₂e + d_z a₃ae₃e + m a₂a₃e₂e₃ + …
inline D printedDiagonalInertia(double dx, double dy, double dz, double m) {
  using namespace c6;
  return D(word({a1, a, e1, e}, dx) + word({a2, a, e2, e}, dy) + word({a3, a, e3, e}, dz) +
           word({a2, a3, e2, e3}, m) + word({a3, a1, e3, e1}, m) + word({a1, a2, e1, e2}, m));
}

/// Independent reference body: point masses m_k at x_k. Momentum of a velocity s = (ω, v) by
/// summing particles (p = Σ m_k (v + ω × x_k), l = Σ x_k × m_k(v + ω × x_k)) — no 6×6 algebra.
struct PointCloud {
  std::vector<double> m;
  std::vector<Vec3<double>> x;
  V6 momentum(const T6& s) const {
    V6 out = V6::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) {
      const Vec3<double> vel = s.lin() + s.ang().cross(x[k]);
      out.head<3>() += x[k].cross(m[k] * vel);
      out.tail<3>() += m[k] * vel;
    }
    return out;
  }
  /// (m, c, I_c) of the cloud, from the textbook sums.
  SpatialInertia<double> inertia() const {
    double M = 0;
    Vec3<double> c = Vec3<double>::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) M += m[k], c += m[k] * x[k];
    c /= M;
    Mat3<double> I = Mat3<double>::Zero();
    for (std::size_t k = 0; k < m.size(); ++k) {
      const Vec3<double> r = x[k] - c;
      I += m[k] * (r.squaredNorm() * Mat3<double>::Identity() - r * r.transpose());
    }
    return SpatialInertia<double>(M, c, I);
  }
  PointCloud moved(const SE3<double>& g) const {
    PointCloud o = *this;
    for (auto& p : o.x) p = g.act(p);
    return o;
  }
};
inline PointCloud randCloud(std::mt19937_64& g, int n = 7) {
  PointCloud c;
  for (int k = 0; k < n; ++k) c.m.push_back(uni(g, 0.2, 1.5)), c.x.push_back(randV3(g, -1, 1.5));
  return c;
}

}  // namespace soma::studies::sb
