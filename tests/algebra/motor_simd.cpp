// The float SIMD Cℓ(0,3,1) motor (clifford/motor_simd.hpp) against the generic Clifford product
// (Even<Signature<0,3,1>>) over random motors, points, lines and planes. Each closed form is
// compared with the generic product evaluated in double on the same float coefficients; the
// tolerance is the rounding bound of the float evaluation, γ_d · p̃ (Higham, Accuracy and
// Stability, §3.1: an expression of depth d in +, −, × has error ≤ γ_d times the same expression
// on the absolute values; γ_d = d·u/(1 − d·u), u = 2⁻²⁴), plus, for the sandwiches, the terms by
// which a float motor that is unit only to rounding (δ = |a|² − 1, σ = a·c) moves the closed form
// away from the sandwich (derived in the comments below).
#include "soma/algebra/clifford/motor_simd.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::clifford;
using PGA = Signature<0, 3, 1>;
using MD = Even<PGA, double>;
using MF = Even<PGA, float>;
using V3 = Eigen::Vector3d;
constexpr Blade kE1 = MotorF::kE1, kE2 = MotorF::kE2, kE3 = MotorF::kE3, kEn = MotorF::kEn;
constexpr Blade kE23 = MotorF::kE23, kE13 = MotorF::kE13, kE12 = MotorF::kE12;
constexpr Blade kE1n = MotorF::kE1n, kE2n = MotorF::kE2n, kE3n = MotorF::kE3n;

double gamma(int d) {
  const double u = std::ldexp(1.0, -24);
  return d * u / (1 - d * u);
}
template <class M> auto toDouble(const M& m) {
  Multivector<PGA, double, M::mask> r;
  for (int i = 0; i < m.size; ++i) r[i] = double(m[i]);
  return r;
}
V3 absCross(const V3& u, const V3& v) {  // |u| × |v| with every sign +
  const V3 a = u.cwiseAbs(), b = v.cwiseAbs();
  return V3(a.y() * b.z() + a.z() * b.y(), a.z() * b.x() + a.x() * b.z(),
            a.x() * b.y() + a.y() * b.x());
}
V3 lanes(simd::F4 v) { return V3(simd::lane(v, 1), simd::lane(v, 2), simd::lane(v, 3)); }

/// A random unit motor T·R built in the generic algebra (float coefficients): R = cos(θ/2) +
/// sin(θ/2)(u₁e₂e₃ + u₂e₃e₁ + u₃e₁e₂), T = 1 + ½(t₁e₁𝐞 + t₂e₂𝐞 + t₃e₃𝐞), |t| ≤ 2√3.
MF randomMotor(std::mt19937_64& g) {
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> u(-2, 2), ang(0, 2 * M_PI);
  V3 ax(nd(g), nd(g), nd(g));
  ax.normalize();
  const double th = ang(g);
  MD r(std::cos(th / 2));
  r.setCoeff(kE23, std::sin(th / 2) * ax.x());
  r.setCoeff(kE13, -std::sin(th / 2) * ax.y());
  r.setCoeff(kE12, std::sin(th / 2) * ax.z());
  MD t(1.0);
  t.setCoeff(kE1n, u(g) / 2);
  t.setCoeff(kE2n, u(g) / 2);
  t.setCoeff(kE3n, u(g) / 2);
  const MD m = MD(t * r);
  MF f;
  for (int i = 0; i < f.size; ++i) f[i] = float(m[i]);
  return f;
}
template <class M> M dagger(const M& m) {  // conjugate with 𝐞 ↦ −𝐞
  M d = m.conjugate();
  for (int i = 0; i < d.size; ++i)
    if (d.blade(i) & kEn) d[i] = -d[i];
  return d;
}

struct Defects {
  double delta, sigma;  // |a|² − 1 and a·c, in double from the float coefficients
  V3 av, cv, t;
  double aw, cw;
};
Defects defects(const MotorF& m) {
  Defects d;
  d.aw = simd::lane(m.real(), 0);
  d.cw = simd::lane(m.dual(), 0);
  d.av = lanes(m.real());
  d.cv = lanes(m.dual());
  d.delta = d.aw * d.aw + d.av.squaredNorm() - 1;
  d.sigma = d.aw * d.cw + d.av.dot(d.cv);
  d.t = 2 * (d.aw * d.cv - d.cw * d.av + d.av.cross(d.cv));
  return d;
}

TEST_CASE("SIMD float motor: compose equals the generic Even product", "[clifford][motor_simd]") {
  std::mt19937_64 g(2212);
  for (int n = 0; n < 2000; ++n) {
    const MF a = randomMotor(g), b = randomMotor(g);
    const MotorF sa = MotorF::fromGeneric(a), sb = MotorF::fromGeneric(b);
    const MF got = (sa * sb).toGeneric();
    const MD want = MD(toDouble(a) * toDouble(b));
    const MF generic = MF(a * b);
    double n1a = 0, n1b = 0;
    for (int i = 0; i < a.size; ++i) n1a += std::abs(double(a[i])), n1b += std::abs(double(b[i]));
    // every coefficient is a sum of at most 8 products: γ₈ Σ|terms| ≤ γ₈ ‖a‖₁‖b‖₁
    const double tol = gamma(8) * n1a * n1b;
    for (int i = 0; i < got.size; ++i) {
      INFO("motor " << n << " blade " << int(got.blade(i)));
      CHECK(std::abs(double(got[i]) - want[i]) <= tol);
      CHECK(std::abs(double(got[i]) - double(generic[i])) <= 2 * tol);
    }
  }
}

TEST_CASE("SIMD float motor: points, lines and planes equal the generic sandwiches",
          "[clifford][motor_simd]") {
  std::mt19937_64 g(2213);
  std::uniform_real_distribution<double> u(-3, 3);
  int onPlane = 0;
  for (int n = 0; n < 2000; ++n) {
    const MF mf = randomMotor(g);
    const MD md = toDouble(mf);
    const MotorF m = MotorF::fromGeneric(mf);
    const Defects df = defects(m);
    INFO("motor " << n << ", |a|^2 - 1 = " << df.delta << ", a.c = " << df.sigma);

    // ---- point: x' = x + 2[a_v × (a_w x + a_v × x + c_v) + a_w c_v − c_w a_v], depth 9.
    // The closed form is |a|²R x + (1 − |a|²)x + t, the sandwich |a|²R x + t (weight |a|²):
    // they differ by |δ||x|.
    const V3 x(float(u(g)), float(u(g)), float(u(g)));
    {
      MD p(1.0);
      p.setCoeff(kE1n, x.x());
      p.setCoeff(kE2n, x.y());
      p.setCoeff(kE3n, x.z());
      const MD want = MD(MD(md * p) * dagger(md));
      const PointF got = m(PointF::make(float(x.x()), float(x.y()), float(x.z())));
      const V3 inner = std::abs(df.aw) * x.cwiseAbs() + absCross(df.av, x) + df.cv.cwiseAbs();
      const V3 pt = x.cwiseAbs() + 2 * (absCross(df.av, inner) + std::abs(df.aw) * df.cv.cwiseAbs() +
                                         std::abs(df.cw) * df.av.cwiseAbs());
      const V3 w(want.coeff(kE1n), want.coeff(kE2n), want.coeff(kE3n));
      const V3 gv(got.x(), got.y(), got.z());
      for (int k = 0; k < 3; ++k)
        CHECK(std::abs(gv(k) - w(k)) <= gamma(10) * pt(k) + std::abs(df.delta) * x.norm());
      CHECK(simd::lane(got.p, 0) == 1.0f);
    }

    // ---- line (ℓ; m): ℓ' = R ℓ, m' = R m + t × R ℓ (depth 9). Closed form minus sandwich:
    // (1 − |a|²)(ℓ; m) from the rotations, t × (1 − |a|²)(ℓ − Rℓ) and the sandwich's extra 2σRℓ:
    // ≤ |δ|(|ℓ| + |m|) + 2|δ||t||ℓ| + 2|σ||ℓ|.
    const V3 ld(float(u(g)), float(u(g)), float(u(g))), lm(float(u(g)), float(u(g)), float(u(g)));
    {
      Bivector<PGA, double> l;
      l.setCoeff(kE23, ld.x());
      l.setCoeff(kE13, -ld.y());
      l.setCoeff(kE12, ld.z());
      l.setCoeff(kE1n, lm.x());
      l.setCoeff(kE2n, lm.y());
      l.setCoeff(kE3n, lm.z());
      const auto want = MD(MD(md * l) * ~md).grade<2>();
      const LineF got = m(LineF{simd::load(0, float(ld.x()), float(ld.y()), float(ld.z())),
                                simd::load(0, float(lm.x()), float(lm.y()), float(lm.z()))});
      auto rotAbs = [&](const V3& v) {  // p̃ of v + 2 a_v × (a_w v + a_v × v)
        return V3(v.cwiseAbs() + 2 * absCross(df.av, std::abs(df.aw) * v.cwiseAbs() + absCross(df.av, v)));
      };
      const V3 tAbs = 2 * (std::abs(df.aw) * df.cv.cwiseAbs() + std::abs(df.cw) * df.av.cwiseAbs() +
                           absCross(df.av, df.cv));
      const V3 dAbs = rotAbs(ld), mAbs = rotAbs(lm) + absCross(tAbs, dAbs);
      const double defect = std::abs(df.delta) * (ld.norm() + lm.norm()) +
                            2 * std::abs(df.delta) * df.t.norm() * ld.norm() +
                            2 * std::abs(df.sigma) * ld.norm();
      const V3 wd(want.coeff(kE23), -want.coeff(kE13), want.coeff(kE12));
      const V3 wm(want.coeff(kE1n), want.coeff(kE2n), want.coeff(kE3n));
      const V3 gd = lanes(got.d), gm = lanes(got.m);
      for (int k = 0; k < 3; ++k) {
        CHECK(std::abs(gd(k) - wd(k)) <= gamma(10) * dAbs(k) + defect);
        CHECK(std::abs(gm(k) - wm(k)) <= gamma(10) * mAbs(k) + defect);
      }
    }

    // ---- plane n·x = δ: n' = R n, δ' = δ + n'·t (depth 11). Closed form minus sandwich: the
    // rotation as for lines, (1 − |a|²)(n − Rn) in n' and δ', t·(that) and 2σ|n| from the dual
    // part: ≤ |δ|(2|n| + |δ_plane|) + 2|δ||t||n| + 2|σ||n|.
    const V3 pn(float(u(g)), float(u(g)), float(u(g)));
    const double pd = float(u(g));
    {
      Vector<PGA, double> pl;
      pl.setCoeff(kE1, pn.x());
      pl.setCoeff(kE2, pn.y());
      pl.setCoeff(kE3, pn.z());
      pl.setCoeff(kEn, pd);
      const auto want = (md * pl * ~md).template grade<1>();
      const PlaneF got = m(PlaneF{simd::load(float(pd), float(pn.x()), float(pn.y()), float(pn.z()))});
      const V3 nAbs = V3(pn.cwiseAbs() +
                         2 * absCross(df.av, std::abs(df.aw) * pn.cwiseAbs() + absCross(df.av, pn)));
      const V3 tAbs = 2 * (std::abs(df.aw) * df.cv.cwiseAbs() + std::abs(df.cw) * df.av.cwiseAbs() +
                           absCross(df.av, df.cv));
      const double dAbs = std::abs(pd) + nAbs.dot(tAbs);
      const double defect = std::abs(df.delta) * (2 * pn.norm() + std::abs(pd)) +
                            2 * std::abs(df.delta) * df.t.norm() * pn.norm() +
                            2 * std::abs(df.sigma) * pn.norm();
      const V3 wn(want.coeff(kE1), want.coeff(kE2), want.coeff(kE3));
      const V3 gn = lanes(got.p);
      for (int k = 0; k < 3; ++k) CHECK(std::abs(gn(k) - wn(k)) <= gamma(12) * nAbs(k) + defect);
      CHECK(std::abs(double(simd::lane(got.p, 0)) - want.coeff(kEn)) <= gamma(12) * dAbs + defect);

      // incidence: a point of the plane, moved, lies on the moved plane (n'·x' = δ')
      const V3 on = pn * (pd / pn.squaredNorm());
      const PointF q = m(PointF::make(float(on.x()), float(on.y()), float(on.z())));
      const double lhs = lanes(got.p).dot(V3(q.x(), q.y(), q.z()));
      const double scale = pn.norm() * (on.norm() + df.t.norm() + 1) + std::abs(pd);
      if (std::abs(lhs - double(simd::lane(got.p, 0))) <= 64 * gamma(12) * scale) ++onPlane;
    }
  }
  CHECK(onPlane == 2000);
}

}  // namespace SOMA_UNITY_ID
