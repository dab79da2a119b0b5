// Screws (pitch, axis) and linear complexes (GF §6.4, §6.6); five scalars.
#include "soma/algebra/screw.hpp"
#include "soma/geometry/lines/linear_complex.hpp"

#include "../../support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
template <class S> S tol(int ulps = 512) { return Tolerance<S>::identity(ulps); }
}  // namespace

TEMPLATE_TEST_CASE("Screw axis and pitch: round trip, Ad-invariance, pitch quadrics (GF-6.4)", "[lines][screw]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(21);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 5 : 60;
  for (int k = 0; k < n; ++k) {
    const PluckerLine<S> ax = PluckerLine<S>::pointDirection(uniformVec<S, 3>(g, -2, 2), unitVec3<S>(g));
    const S h = uniform<S>(g, -3, 3), a = uniform<S>(g, 0.5, 2);
    const Vec6<S> s = screwFromAxis(ax, h, a);
    const ScrewAxis<S> sa = screwAxis(s);
    REQUIRE_FALSE(sa.infinitePitch);
    REQUIRE(abs(sa.pitch - h) <= tol<S>(2048));
    REQUIRE(abs(sa.amplitude - a) <= tol<S>());
    REQUIRE(sa.axis.sameAs(ax, tol<S>(2048)));
    // sᵀ Q_p s = 2|ω|²(h − p): zero exactly on the pitch-h quadric.
    const S p = uniform<S>(g, -3, 3);
    REQUIRE(abs(S(s.dot(pitchQuadric(p) * s)) - S(2) * a * a * (h - p)) <= tol<S>(4096) * S(16));
    const SE3<S> x = SE3Tangent<S>(uniformVec<S, 6>(g, -2, 2)).exp();
    REQUIRE(abs(screwPitch(Vec6<S>(lineAction(x) * s)) - h) <= tol<S>(4096) * S(4));
  }
  // Pitch 0 is a line; infinite pitch (0; v): a translation, axis at infinity.
  const PluckerLine<S> l = PluckerLine<S>::pointDirection(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(0), S(0), S(1)));
  REQUIRE(screwAxis(l.coords()).pitch == S(0));
  const ScrewAxis<S> t = screwAxis(screwTranslation(Vec3<S>(S(0), S(2), S(0))));
  REQUIRE(t.infinitePitch);
  REQUIRE(t.axis.isAtInfinity());
  REQUIRE(t.amplitude == S(2));
  REQUIRE(screwPitch(screwTranslation(Vec3<S>(S(1), S(0), S(0)))) == std::numeric_limits<S>::infinity());
  REQUIRE_THROWS_AS(screwAxis(Vec6<S>(Vec6<S>::Zero())), InvalidInput);
  // Pitch → ∞ as |ω| → 0 with v fixed: finite and growing like 1/|ω|.
  for (const S& w : {S(1) / S(1000), Tolerance<S>::epsilon()}) {
    Vec6<S> s;
    s << w, S(0), S(0), S(1), S(0), S(0);
    REQUIRE(abs(screwPitch(s) * w - S(1)) <= tol<S>());
  }
}

TEST_CASE("Screw axis agrees with the Chasles decomposition of exp(s) (algebra/screw.hpp)", "[lines][screw]") {
  auto& g = rng(22);
  for (int k = 0; k < 100; ++k) {
    const Vec6<double> s = uniformVec<double, 6>(g, -1, 1);
    const ScrewAxis<double> a = screwAxis(s);
    const Screw<double> c = screwOf(SE3Tangent<double>(s).exp());
    REQUIRE(std::abs(a.pitch - c.pitch) <= 1e-12);
    REQUIRE(a.axis.sameAs(PluckerLine<double>::pointDirection(c.point, c.axis), 1e-12));
  }
}

TEMPLATE_TEST_CASE("Linear complex: equation, axis, pitch, 4×4 matrix, null polarity (GF-6.6)", "[lines][complex]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(23);
  const int n = std::is_same_v<S, mpfr::mpreal> ? 4 : 30;
  for (int k = 0; k < n; ++k) {
    const Vec6<S> s = uniformVec<S, 6>(g);
    const LinearComplex<S> c(s);
    REQUIRE(abs(c.pitch() - s.template head<3>().dot(s.template tail<3>()) / s.template head<3>().squaredNorm()) <= tol<S>());
    // det X = (α·b)²; yᵀX x = b·ω + α·v for the line ω = x₀y − y₀x, v = x × y (E6.5).
    const Mat4<S> x = c.matrix4();
    const S ab = c.alpha().dot(c.b());
    REQUIRE(abs(x.determinant() - ab * ab) <= tol<S>(4096));
    const Vec4<S> xp = uniformVec<S, 4>(g), yp = uniformVec<S, 4>(g);  // (x₁, x₂, x₃, x₀)
    const Vec3<S> xv = xp.template head<3>(), yv = yp.template head<3>();
    Vec6<S> l;
    l << Vec3<S>(xp(3) * yv - yp(3) * xv), Vec3<S>(xv.cross(yv));
    REQUIRE(abs(S(yp.dot(x * xp)) - reciprocalProduct(s, l)) <= tol<S>(4096));
    // Lines through y in its null plane are complex lines; the null point of the null plane is y.
    const Vec3<S> y = uniformVec<S, 3>(g, -2, 2);
    for (const S& th : {S(0), S(1), S(2)}) REQUIRE(c.contains(c.lineThrough(y, th), tol<S>(4096)));
    const Vec4<S> yh = c.nullPoint(c.nullPlane(y));
    REQUIRE((yh.template tail<3>() / yh(0) - y).norm() <= tol<S>(1 << 16));
    // The axis: a line along α; it is a complex line only for pitch 0 (⟨s, axis⟩ = h|α|).
    REQUIRE(kleinDefect(c.axis().coords()) <= tol<S>(1024));
    REQUIRE(abs(reciprocalProduct(s, c.axis().coords()) - c.pitch() * c.alpha().norm()) <= tol<S>(4096));
    // Rigid symmetries fix the screw and map complex lines to complex lines (E6.1 form of t).
    const SE3<S> sym = c.symmetry(uniform<S>(g, -3, 3), uniform<S>(g));
    REQUIRE((lineAction(sym) * s - s).norm() <= tol<S>(4096) * S(4));
    REQUIRE(c.contains(c.lineThrough(y, S(1)).transformed(sym), tol<S>(1 << 14)));
  }
  // Symmetry at θ = π.
  const LinearComplex<S> c0(Vec6<S>((Vec6<S>() << S(1), S(2), S(0), S(3), S(-1), S(2)).finished()));
  REQUIRE((lineAction(c0.symmetry(pi<S>(), S(1))) * c0.screw() - c0.screw()).norm() <= tol<S>(4096));
}

TEMPLATE_TEST_CASE("Singular and infinite-pitch complexes, both sides of α·b = 0", "[lines][complex]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(24);
  const PluckerLine<S> m = PluckerLine<S>::pointDirection(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(1), S(1)));
  const LinearComplex<S> c = LinearComplex<S>::singular(m);
  REQUIRE(c.isSingular());
  for (int k = 0; k < 10; ++k) {
    // Any line meeting m is in the singular complex.
    const PluckerLine<S> l = PluckerLine<S>::pointDirection(m.pointAt(uniform<S>(g)), uniformVec<S, 3>(g));
    REQUIRE(c.contains(l, tol<S>(1024)));
  }
  REQUIRE_THROWS_AS(c.nullPoint(pga::Plane<S>(Vec3<S>(S(0), S(0), S(1)), S(0))), InvalidInput);
  REQUIRE_THROWS_AS(c.nullPlane(m.pointAt(S(1) / S(3))), InvalidInput);  // y on the singular line
  // Just off singular (pitch δ): not singular on the far side of the threshold.
  const S eps = Tolerance<S>::epsilon();
  REQUIRE(LinearComplex<S>::fromAxisPitch(m, eps).isSingular());
  REQUIRE_FALSE(LinearComplex<S>::fromAxisPitch(m, S(1) / S(1000)).isSingular());
  // Infinite pitch α = 0: the lines perpendicular to b.
  const LinearComplex<S> ci(screwTranslation(Vec3<S>(S(0), S(0), S(1))));
  REQUIRE(ci.isInfinitePitch());
  REQUIRE(ci.pitch() == std::numeric_limits<S>::infinity());
  REQUIRE(ci.contains(PluckerLine<S>::pointDirection(uniformVec<S, 3>(g), Vec3<S>(S(1), S(2), S(0)))));
  REQUIRE_FALSE(ci.contains(PluckerLine<S>::pointDirection(uniformVec<S, 3>(g), Vec3<S>(S(1), S(2), S(1)))));
  // Null point of a plane parallel to the axis is at infinity (x₀ = 0).
  const LinearComplex<S> cz = LinearComplex<S>::fromAxisPitch(PluckerLine<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitZ()), S(1) / S(2));
  const Vec4<S> pinf = cz.nullPoint(pga::Plane<S>(Vec3<S>(S(1), S(0), S(0)), S(1)));  // the plane x = 1
  REQUIRE(abs(pinf(0)) <= tol<S>() * pinf.norm());
}

}  // namespace SOMA_UNITY_ID
