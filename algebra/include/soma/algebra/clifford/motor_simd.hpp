#pragma once
// Cℓ(0,3,1) motors in float, SIMD (SSE2 on x86-64, a scalar fallback elsewhere): composition
// and the action on points, lines and planes written out in closed form. The generic product
// of multivector.hpp (Even<Signature<0,3,1>, float>) stays the reference these are tested
// against (tests/algebra/motor_simd.cpp).
//
// Coordinates: the motor M is stored as the dual quaternion a + εc it corresponds to under the
// book's isomorphism (GF §9.3: e₂e₃ ↦ i, e₃e₁ ↦ j, e₁e₂ ↦ k, −e₁e₂e₃𝐞 ↦ ε; 𝐞 is the null
// generator, index 3): lanes (w, x, y, z) of `a` are the coefficients of 1, e₂e₃, e₃e₁, e₁e₂,
// lanes of `c` those of −e₁e₂e₃𝐞, e₁𝐞, e₂𝐞, e₃𝐞. A unit motor (|a| = 1, a·c = 0) is the motion
// x ↦ R x + t with R the rotation of a and t = 2 vec(c a*) (GF §9.2).
//   point  1 + x𝐞, moved by M P M† (M† = conjugate of M with 𝐞 ↦ −𝐞)   → 1 + (R x + t)𝐞
//   line   ℓ₁e₂e₃ + ℓ₂e₃e₁ + ℓ₃e₁e₂ + m₁e₁𝐞 + m₂e₂𝐞 + m₃e₃𝐞, moved by ⟨M L M̃⟩₂
//                                                        → (R ℓ, R m + t × R ℓ)
//   plane  n₁e₁ + n₂e₂ + n₃e₃ + δ𝐞 (the plane n·x = δ), moved by ⟨M Π M̃⟩₁  → (R n, δ + R n · t)
// The closed forms use |a| = 1 and a·c = 0; for a motor that is unit only to rounding (any float
// motor) they differ from the sandwich by (|a|² − 1) and a·c times the operand's size (the
// bounds in the test). Compose is the exact product (a₁a₂, a₁c₂ + c₁a₂) of the dual quaternions.
#include "soma/algebra/clifford/multivector.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#define SOMA_MOTOR_SIMD 1
#else
#define SOMA_MOTOR_SIMD 0
#endif

namespace soma::clifford {

namespace simd {
#if SOMA_MOTOR_SIMD
using F4 = __m128;
inline F4 load(float w, float x, float y, float z) { return _mm_set_ps(z, y, x, w); }
inline float lane(F4 v, int i) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return f[i];
}
inline F4 add(F4 a, F4 b) { return _mm_add_ps(a, b); }
inline F4 sub(F4 a, F4 b) { return _mm_sub_ps(a, b); }
inline F4 mul(F4 a, F4 b) { return _mm_mul_ps(a, b); }
template <int i> inline F4 splat(F4 a) { return _mm_shuffle_ps(a, a, _MM_SHUFFLE(i, i, i, i)); }
/// lanes (i0, i1, i2, i3) of a.
#define SOMA_SHUF(a, i0, i1, i2, i3) _mm_shuffle_ps(a, a, _MM_SHUFFLE(i3, i2, i1, i0))
/// flip the sign of the lanes whose flag is 1.
template <int s0, int s1, int s2, int s3> inline F4 flip(F4 a) {
  const F4 m = _mm_castsi128_ps(_mm_set_epi32(s3 ? int(0x80000000u) : 0, s2 ? int(0x80000000u) : 0,
                                              s1 ? int(0x80000000u) : 0, s0 ? int(0x80000000u) : 0));
  return _mm_xor_ps(a, m);
}
/// Zero lane 0 (w).
inline F4 vecPart(F4 a) {
  return _mm_and_ps(a, _mm_castsi128_ps(_mm_set_epi32(-1, -1, -1, 0)));
}
#else
struct F4 {
  float v[4];
};
inline F4 load(float w, float x, float y, float z) { return F4{{w, x, y, z}}; }
inline float lane(F4 a, int i) { return a.v[i]; }
inline F4 add(F4 a, F4 b) { return F4{{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}}; }
inline F4 sub(F4 a, F4 b) { return F4{{a.v[0] - b.v[0], a.v[1] - b.v[1], a.v[2] - b.v[2], a.v[3] - b.v[3]}}; }
inline F4 mul(F4 a, F4 b) { return F4{{a.v[0] * b.v[0], a.v[1] * b.v[1], a.v[2] * b.v[2], a.v[3] * b.v[3]}}; }
template <int i> inline F4 splat(F4 a) { return F4{{a.v[i], a.v[i], a.v[i], a.v[i]}}; }
#define SOMA_SHUF(a, i0, i1, i2, i3) (::soma::clifford::simd::F4{{(a).v[i0], (a).v[i1], (a).v[i2], (a).v[i3]}})
template <int s0, int s1, int s2, int s3> inline F4 flip(F4 a) {
  return F4{{s0 ? -a.v[0] : a.v[0], s1 ? -a.v[1] : a.v[1], s2 ? -a.v[2] : a.v[2], s3 ? -a.v[3] : a.v[3]}};
}
inline F4 vecPart(F4 a) { return F4{{0.0f, a.v[1], a.v[2], a.v[3]}}; }
#endif

/// The parts of the Hamilton product a b (GF §2.1) in lanes (w, x, y, z), arranged so that one
/// sign flip (lane w of X) serves the whole product:
///   a b = a_w b + flip_w(X) − Y,
///   X = (a_x, a_x, a_y, a_z)(b_x, b_w, b_w, b_w) + (a_y, a_y, a_z, a_x)(b_y, b_z, b_x, b_y),
///   Y = (a_z, a_z, a_x, a_y)(b_z, b_y, b_z, b_x).
/// (lane w: a_w b_w − a_x b_x − a_y b_y − a_z b_z; lane x: a_w b_x + a_x b_w + a_y b_z − a_z b_y;
/// and cyclically.) Compose adds the X and Y of its two dual products before the one flip.
struct QParts {
  F4 w, x, y;  // a_w b, X, Y
};
inline QParts qparts(F4 a, F4 b) {
  const F4 x = add(mul(SOMA_SHUF(a, 1, 1, 2, 3), SOMA_SHUF(b, 1, 0, 0, 0)),
                   mul(SOMA_SHUF(a, 2, 2, 3, 1), SOMA_SHUF(b, 2, 3, 1, 2)));
  const F4 y = mul(SOMA_SHUF(a, 3, 3, 1, 2), SOMA_SHUF(b, 3, 2, 3, 1));
  return QParts{mul(splat<0>(a), b), x, y};
}
inline F4 qmul(F4 a, F4 b) {
  const QParts p = qparts(a, b);
  return sub(add(p.w, flip<1, 0, 0, 0>(p.x)), p.y);
}
/// u × v in lanes 1–3 (lane 0 of the result is u_w v_w − u_w v_w = 0).
inline F4 cross(F4 u, F4 v) {
  return sub(mul(SOMA_SHUF(u, 0, 2, 3, 1), SOMA_SHUF(v, 0, 3, 1, 2)),
             mul(SOMA_SHUF(u, 0, 3, 1, 2), SOMA_SHUF(v, 0, 2, 3, 1)));
}
/// u·v of lanes 1–3, in every lane.
inline F4 dot3(F4 u, F4 v) {
  const F4 p = mul(vecPart(u), v);
  const F4 s = add(p, SOMA_SHUF(p, 1, 0, 3, 2));  // (p0+p1, p1+p0, p2+p3, p3+p2)
  return add(SOMA_SHUF(s, 0, 0, 0, 0), SOMA_SHUF(s, 2, 2, 2, 2));
}
}  // namespace simd

/// A point 1 + x𝐞 (lanes: 1, x, y, z).
struct PointF {
  simd::F4 p;
  static PointF make(float x, float y, float z) { return PointF{simd::load(1.0f, x, y, z)}; }
  float x() const { return simd::lane(p, 1); }
  float y() const { return simd::lane(p, 2); }
  float z() const { return simd::lane(p, 3); }
};
/// A line (ℓ; m) (lanes 1–3 of d and m; lane 0 is 0).
struct LineF {
  simd::F4 d, m;
};
/// A plane n·x = δ (lanes: δ, n₁, n₂, n₃).
struct PlaneF {
  simd::F4 p;
};

/// A Cℓ(0,3,1) motor as the dual quaternion a + εc (see the header comment).
class MotorF {
 public:
  using PGA = Signature<0, 3, 1>;
  using Generic = Even<PGA, float>;

  MotorF() : a_(simd::load(1, 0, 0, 0)), c_(simd::load(0, 0, 0, 0)) {}
  MotorF(simd::F4 a, simd::F4 c) : a_(a), c_(c) {}

  /// From the generic even element (GF §9.3 isomorphism).
  static MotorF fromGeneric(const Generic& m) {
    return MotorF(simd::load(m.coeff(0), m.coeff(kE23), -m.coeff(kE13), m.coeff(kE12)),
                  simd::load(-m.coeff(kI), m.coeff(kE1n), m.coeff(kE2n), m.coeff(kE3n)));
  }
  Generic toGeneric() const {
    Generic m;
    m.setCoeff(0, simd::lane(a_, 0));
    m.setCoeff(kE23, simd::lane(a_, 1));
    m.setCoeff(kE13, -simd::lane(a_, 2));
    m.setCoeff(kE12, simd::lane(a_, 3));
    m.setCoeff(kI, -simd::lane(c_, 0));
    m.setCoeff(kE1n, simd::lane(c_, 1));
    m.setCoeff(kE2n, simd::lane(c_, 2));
    m.setCoeff(kE3n, simd::lane(c_, 3));
    return m;
  }
  simd::F4 real() const { return a_; }
  simd::F4 dual() const { return c_; }

  /// M₁M₂ = (a₁a₂, a₁c₂ + c₁a₂): three Hamilton products, the dual two sharing one sign flip.
  MotorF operator*(const MotorF& o) const {
    using namespace simd;
    const QParts p = qparts(a_, o.c_), q = qparts(c_, o.a_);
    const F4 dual = sub(add(add(p.w, q.w), flip<1, 0, 0, 0>(add(p.x, q.x))), add(p.y, q.y));
    return MotorF(qmul(a_, o.a_), dual);
  }

  /// t = 2 vec(c a*) = 2 (a_w c_v − c_w a_v + a_v × c_v), in lanes 1–3.
  simd::F4 translation() const {
    using namespace simd;
    const F4 t = sub(add(mul(splat<0>(a_), c_), cross(a_, c_)), mul(splat<0>(c_), a_));
    return vecPart(add(t, t));
  }
  /// R v = v + 2 a_v × (a_w v + a_v × v) (lanes 1–3; lane 0 of v must be 0 or is kept).
  simd::F4 rotate(simd::F4 v) const {
    using namespace simd;
    const F4 u = cross(a_, add(mul(splat<0>(a_), v), cross(a_, v)));
    return add(v, add(u, u));
  }

  /// M P M† = 1 + (R x + t)𝐞: x + 2[a_v × (a_w x + a_v × x + c_v) + a_w c_v − c_w a_v] (two cross
  /// products; the rotation and translation share the outer one).
  PointF operator()(const PointF& pt) const {
    using namespace simd;
    const F4 x = vecPart(pt.p);
    const F4 inner = add(add(mul(splat<0>(a_), x), cross(a_, x)), c_);
    const F4 u = vecPart(sub(add(cross(a_, inner), mul(splat<0>(a_), c_)), mul(splat<0>(c_), a_)));
    return PointF{add(pt.p, add(u, u))};
  }
  /// ⟨M L M̃⟩₂ = (R ℓ, R m + t × R ℓ).
  LineF operator()(const LineF& l) const {
    using namespace simd;
    const F4 d = rotate(l.d);
    return LineF{d, add(rotate(l.m), cross(translation(), d))};
  }
  /// ⟨M Π M̃⟩₁ = (R n, δ + R n · t).
  PlaneF operator()(const PlaneF& pl) const {
    using namespace simd;
    const F4 n = rotate(vecPart(pl.p));
    const F4 dt = dot3(n, translation());
    // lane 0: δ + n'·t, lanes 1–3: n'
    return PlaneF{add(n, vecPartComplement(add(splat<0>(pl.p), dt)))};
  }

  // Blades of Cℓ(0,3,1), generators e₁, e₂, e₃, 𝐞 ↦ bits 0–3.
  static constexpr Blade kE1 = 0b0001, kE2 = 0b0010, kE3 = 0b0100, kEn = 0b1000;
  static constexpr Blade kE23 = 0b0110, kE13 = 0b0101, kE12 = 0b0011;
  static constexpr Blade kE1n = 0b1001, kE2n = 0b1010, kE3n = 0b1100, kI = 0b1111;

 private:
  /// Lane 0 of v, other lanes 0.
  static simd::F4 vecPartComplement(simd::F4 v) {
    return simd::sub(v, simd::vecPart(v));
  }
  simd::F4 a_, c_;
};

}  // namespace soma::clifford

#undef SOMA_SHUF  // used only by the inline definitions above
