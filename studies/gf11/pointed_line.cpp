// GF §11.3, GF-11.3-pointed-line-clifford: a pointed line as the mixed-grade element
// f₁₂ = (p + ℓ)/√2 of Cl(0,3,1) (points and lines of ch. 10), moved by f' = h f h*; f f* = 1
// holds for every pointed line, gives ℓℓ* = 1 and pℓ* + ℓp* = 0, but only pp* + ℓℓ* = 2 (the
// e₁e₂e₃ coefficient of p must be fixed to 1 separately). Double precision.
#include "soma/geometry/pga/motor.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf11pointed::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
constexpr const char* kChapter = "GF 11 — The Study quadric";

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(g); }
Vec3<S> vec3(std::mt19937_64& g) { return Vec3<S>(uni(g), uni(g), uni(g)); }

/// f = (p + ℓ)/√2 and the largest coefficient of f f* − 1.
template <class P, class L> auto flagElement(const P& p, const L& l) {
  return (p.element() + l.element()) * (S(1) / std::sqrt(S(2)));
}
template <class F> double unitDefect(const F& f) {
  const auto ff = f * f.conjugate();
  return clifford::maxAbsDiff(ff, clifford::Multivector<pga::Cl031, S, 1>(S(1)));
}

void pointedLine(Context& c) {
  auto g = rng(1133);
  double worstOn = 0, worstMoved = 0, worstIncidence = 0, worstParts = 0;
  for (int n = 0; n < 100; ++n) {
    const Vec3<S> q = vec3(g) * 3, v = vec3(g).normalized();
    const Vec3<S> x = q + uni(g, -2, 2) * v;  // the point, on the line through q along v
    const pga::Point<S> p(x);
    const pga::Line<S> l = pga::Line<S>::throughPoint(q, v);
    const auto f = flagElement(p, l);
    worstOn = std::max(worstOn, unitDefect(f));
    // The grades of f f*: pp* + ℓℓ* = 2 (scalar) and pℓ* + ℓp* (its other parts) vanish.
    const auto pp = p.element() * p.element().conjugate();
    const auto ll = l.element() * l.element().conjugate();
    const auto cross = p.element() * l.element().conjugate() + l.element() * p.element().conjugate();
    worstParts = std::max({worstParts, std::abs(pp.scalarPart() + ll.scalarPart() - 2),
                           clifford::maxAbsDiff(cross, clifford::Multivector<pga::Cl031, S, 1>(S(0)))});
    // f' = h f h* is the pointed line moved by h: (h p h* + h ℓ h*)/√2, still f'f'* = 1, the point
    // g(x) on the line g(ℓ).
    const SE3<S> m(SO3<S>::Random(g), vec3(g) * 2);
    const pga::Motor<S> h = pga::Motor<S>::fromSE3(m);
    const auto moved = h.element() * f * h.element().conjugate();
    const pga::Point<S> p2(m.act(x));
    const pga::Line<S> l2 = pga::Line<S>::throughPoint(m.act(q), m.rotation() * v);
    worstMoved = std::max({worstMoved, clifford::maxAbsDiff(moved, flagElement(p2, l2)), unitDefect(moved)});
    worstIncidence = std::max(worstIncidence, (h(l).moment() - Vec3<S>(m.act(x).cross(h(l).direction()))).norm());
  }
  c.checkResidual("f f* = 1 for 100 random pointed lines (every coefficient of f f* − 1)", worstOn, Tolerance<S>::identity(256));
  c.checkResidual("… its parts: pp* + ℓℓ* = 2 and pℓ* + ℓp* = 0", worstParts, Tolerance<S>::identity(256));
  c.checkResidual("h f h* = (h p h* + h ℓ h*)/√2, the moved pointed line, with f'f'* = 1", worstMoved,
                  Tolerance<S>::identity(1024));
  c.checkResidual("… the moved point lies on the moved line (u = x × v)", worstIncidence, Tolerance<S>::identity(1024));
  // A point off the line: f f* − 1 is the incidence part, linear in the distance δ.
  const Vec3<S> q(0.3, -0.2, 0.5), v = Vec3<S>(1, 2, 2) / 3, off = v.unitOrthogonal();
  const pga::Line<S> l = pga::Line<S>::throughPoint(q, v);
  const double d1 = unitDefect(flagElement(pga::Point<S>(Vec3<S>(q + 1e-3 * off)), l));
  const double d2 = unitDefect(flagElement(pga::Point<S>(Vec3<S>(q + 1e-6 * off)), l));
  c.checkNear("a point 1e-3 and 1e-6 off the line: |f f* − 1| falls by 1000 (linear in the distance)", 1000.0, d1 / d2, 1e-3 * 1000);
  // The book's caveat: f f* = 1 gives only pp* + ℓℓ* = 2. A point of weight w = 1.2 on a line with
  // |v| = √(2 − w²) satisfies f f* = 1 too; the e₁e₂e₃ coefficient = 1 must be imposed separately.
  const double w = 1.2, s = std::sqrt(2 - w * w);
  const pga::Point<S> heavy(w, Vec3<S>(w * (q + 0.7 * v)));
  const pga::Line<S> light = pga::Line<S>::throughPoint(q, Vec3<S>(s * v));
  c.checkResidual("weight-1.2 point on a line with |v|² = 2 − 1.44: f f* = 1 as well", unitDefect(flagElement(heavy, light)),
                  Tolerance<S>::identity(256));
  c.checkNear("… so f f* = 1 does not fix the weight: e₁e₂e₃ coefficient of p", 1.2, heavy.weight(), 0.0);
}

SOMA_STUDY({.id = "GF-11.3-pointed-line-clifford",
            .title = "Pointed lines f = (p + ℓ)/√2 in Cl(0,3,1): f f* = 1, f' = h f h*",
            .source = "GF §11.3",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = pointedLine});

}  // namespace
}  // namespace soma::studies::gf11pointed::SOMA_UNITY_ID
