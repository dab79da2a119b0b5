#pragma once
// Linear line complexes (GF §6.6): the lines l = (ω; v) with b·ω + α·v = 0, i.e. the lines
// reciprocal to the screw s = (α; b) (⟨s, l⟩ = 0). Pitch α·b/α·α, axis (α; b − (α·b/α·α)α);
// singular (all lines meeting one line) when α·b = 0; infinite pitch (α = 0) gives the lines
// perpendicular to b. The null polarity sends a point to the plane of the complex lines through it.
#include "soma/geometry/lines/screw_axis.hpp"
#include "soma/geometry/pga/plane.hpp"

#include <Eigen/LU>

namespace soma {

template <class S> class LinearComplex {
 public:
  /// The complex of lines reciprocal to the screw s = (α; b). Throws for s = 0 or a NaN.
  // GF §6.6, GF-6.6-linear-complex
  explicit LinearComplex(const Vec6<S>& s) : s_(s) {
    if (!allFinite(s)) throw InvalidInput("LinearComplex: a coordinate of the screw is NaN or infinite");
    if (s.squaredNorm() == S(0)) throw InvalidInput("LinearComplex: the zero screw defines no complex");
  }
  /// The complex with the given axis (a finite line) and pitch h: s = (u; m + h u).
  // GF §6.6, GF-6.6-linear-complex
  static LinearComplex fromAxisPitch(const PluckerLine<S>& axis, const S& pitch) {
    return LinearComplex(screwFromAxis(axis, pitch));
  }
  /// The singular complex of all lines meeting l. GF §6.6, GF-6.6-linear-complex
  static LinearComplex singular(const PluckerLine<S>& l) { return LinearComplex(l.coords()); }

  const Vec6<S>& screw() const { return s_; }
  Vec3<S> alpha() const { return s_.template head<3>(); }
  Vec3<S> b() const { return s_.template tail<3>(); }

  /// Pitch α·b/α·α (+∞ for α = 0). GF §6.6, GF-6.6-linear-complex
  S pitch() const { return screwPitch(s_); }
  /// Axis (α; b − pα) as a unit line (the line at infinity (0; b) for α = 0).
  // GF §6.6, GF-6.6-complex-symmetries
  PluckerLine<S> axis() const { return screwAxis(s_).axis; }
  /// α·b = 0 to tolerance relative to |α||b| (then every complex line meets the line s).
  // GF §6.6, GF-6.6-linear-complex (tangent hyperplane of the Klein quadric)
  bool isSingular(const S& tol = Tolerance<S>::identity()) const { return kleinDefect(s_) <= tol; }
  bool isInfinitePitch() const { return alpha().squaredNorm() == S(0); }

  /// The value b·ω + α·v of the complex's equation on l (relative to |s||l|).
  S relativeResidual(const PluckerLine<S>& l) const {
    using std::abs;
    using std::sqrt;
    const Vec6<S> c = l.coords();
    return abs(reciprocalProduct(s_, c)) / sqrt(s_.squaredNorm() * c.squaredNorm());
  }
  bool contains(const PluckerLine<S>& l, const S& tol = Tolerance<S>::identity()) const {
    return relativeResidual(l) <= tol;
  }

  /// The 4×4 antisymmetric X with yᵀX x = b·ω + α·v for the line ω = x₀y − y₀x, v = x × y;
  /// homogeneous points ordered (x₁, x₂, x₃, x₀); det X = (α·b)². GF §6.6, GF-6.6-complex-4x4 (E6.5)
  Mat4<S> matrix4() const {
    const Vec3<S> a = alpha(), bb = b();
    Mat4<S> x;
    x << S(0), -a(2), a(1), bb(0),   //
        a(2), S(0), -a(0), bb(1),    //
        -a(1), a(0), S(0), bb(2),    //
        -bb(0), -bb(1), -bb(2), S(0);
    return x;
  }

  /// Null plane of the finite point y: n·x = b·y with n = b + α × y (every complex line through y
  /// lies in it), as the plane of geometry/pga (n·r = d). For a point on the line of a singular complex, or on the axis of an infinite-pitch...
  /// n = 0: every line through y is in the complex; throws then.
  // GF §6.6, GF-6.6-complex-4x4 (the C_i corrected, erratum E6.6)
  pga::Plane<S> nullPlane(const Vec3<S>& y) const {
    const Vec3<S> n = b() + alpha().cross(y);
    const S e = Tolerance<S>::identity();
    if (n.squaredNorm() <= e * e * (b().squaredNorm() + alpha().squaredNorm() * y.squaredNorm()))
      throw InvalidInput("LinearComplex::nullPlane: every line through y is in the complex (y on the singular line)");
    return pga::Plane<S>(n, S(b().dot(y)));
  }
  /// Null point of a plane: the point through which all complex lines in the plane pass, as a
  /// homogeneous (x₀; x) (x₀ = 0: at infinity, for planes parallel to the axis). Solves the
  /// null polarity of matrix4(). Throws for a singular complex. GF §6.6, GF-6.6-complex-4x4
  Vec4<S> nullPoint(const pga::Plane<S>& p) const {
    if (isSingular()) throw InvalidInput("LinearComplex::nullPoint: the complex is singular (no null polarity)");
    // Plane coefficients in the order (x₁, x₂, x₃, x₀): π = (n, −d) for n·x = d; the null plane of y
    // is Xᵀ y (row yᵀX).
    Vec4<S> pi;
    pi << p.normal(), S(-p.distance());
    const Mat4<S> xt = matrix4().transpose();
    const Vec4<S> y = xt.fullPivLu().solve(pi);
    Vec4<S> out;
    out << y(3), y.template head<3>();
    return out;
  }

  /// The complex line through y in its null plane at angle θ (a pencil: θ ∈ [0, π) covers it once).
  // GF §6.6, GF-6.6-complex-4x4
  PluckerLine<S> lineThrough(const Vec3<S>& y, const S& theta) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const Vec3<S> n0 = nullPlane(y).normal();
    const Vec3<S> n = n0 / sqrt(n0.squaredNorm());
    Vec3<S> e1 = n.unitOrthogonal();
    const Vec3<S> e2 = n.cross(e1);
    return PluckerLine<S>::pointDirection(y, Vec3<S>(cos(theta) * e1 + sin(theta) * e2));
  }

  /// A rigid symmetry of the complex: rotation θ about α (unit) then translation
  /// t = α × (I − R) b / |α|² − λα (convention A, E6.1): Ad(g) s = s. GF §6.6, GF-6.6-complex-symmetries
  SE3<S> symmetry(const S& theta, const S& lambda) const {
    using std::sqrt;
    if (isInfinitePitch()) throw InvalidInput("LinearComplex::symmetry: infinite-pitch complex (α = 0)");
    const Vec3<S> a = alpha();
    const S aa = a.squaredNorm();
    const SO3<S> r = SO3<S>::fromAxisAngle(Vec3<S>(a / sqrt(aa)), theta);
    const Vec3<S> t = a.cross(Vec3<S>(b() - r.act(b()))) / aa - lambda * a;
    return SE3<S>(r, t);
  }

 private:
  Vec6<S> s_;
};

extern template class LinearComplex<float>;
extern template class LinearComplex<double>;
extern template class LinearComplex<long double>;
extern template class LinearComplex<__float128>;
extern template class LinearComplex<mpfr::mpreal>;

}  // namespace soma
