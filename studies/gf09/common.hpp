#pragma once
// Helpers shared by the studies of GF chapter 9, §9.1–9.3 (gf09/clifford.cpp, gf09/euclidean.cpp):
// the book's generators as soma blades, the isomorphism Cℓ⁺(0,3,1) ≅ H ⊗ D of §9.3 written out
// coefficient by coefficient (the independent route to soma's DualQuaternion), random draws.
// Everything is templated on the scalar S: the studies run in the scalar asked for (--scalar).
#include "soma/algebra/clifford/multivector.hpp"
#include "soma/algebra/dual_quaternion.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <random>
#include <string>

namespace soma::studies::gf09 {

inline constexpr const char* kChapter = "GF 9 — Clifford algebra";
using namespace soma::clifford;
using std::abs;
using std::cos;
using std::sin;
using std::sqrt;
using std::tan;

inline std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
using draws::frac;
using draws::maxOf;
using draws::uni;  // soma/studies/scalar_draws.hpp
template <class S> Vec3<S> randVec(std::mt19937_64& g) {
  const S x = uni<S>(g), y = uni<S>(g), z = uni<S>(g);
  return Vec3<S>(x, y, z);
}
template <class S> Vec3<S> randUnit(std::mt19937_64& g) {
  Vec3<S> v;
  do v = randVec<S>(g);
  while (v.squaredNorm() < S(1) / S(10));
  return v / sqrt(v.squaredNorm());
}
template <class S> std::string str(const S& x) { return toString(toDouble(x), 6); }

/// A product of generators in the given order (0-based indices), e.g. gen<Sig>({1, 2}) = e₂e₃
/// in the book's 1-based names.
template <class Sig, class S> Dense<Sig, S> gens(std::initializer_list<int> idx) {
  Dense<Sig, S> m(S(1));
  for (int i : idx) m = Dense<Sig, S>(m * Vector<Sig, S>::generator(i));
  return m;
}

// ---- Cℓ(0,3,1): e₁, e₂, e₃ ↦ indices 0, 1, 2, the null 𝐞 ↦ index 3 (GF §9.2) -------------
using PGA = Signature<0, 3, 1>;
template <class S> using Motor = Even<PGA, S>;
template <class S> using PDense = Dense<PGA, S>;
inline constexpr Blade kE23 = 0b0110, kE13 = 0b0101, kE12 = 0b0011;
inline constexpr Blade kE1n = 0b1001, kE2n = 0b1010, kE3n = 0b1100, kI = 0b1111;

/// a + εc ↦ a₀ + a₁e₂e₃ + a₂e₃e₁ + a₃e₁e₂ + c₁e₁𝐞 + c₂e₂𝐞 + c₃e₃𝐞 − c₀e₁e₂e₃𝐞
/// (GF §9.3: e₂e₃ ↦ i, e₃e₁ ↦ j, e₁e₂ ↦ k, −e₁e₂e₃𝐞 ↦ ε; e₃e₁ = −e₁e₃).
template <class S> Motor<S> toMotor(const Vec4<S>& a, const Vec4<S>& c) {
  Motor<S> m;
  m.setCoeff(0, a(0));
  m.setCoeff(kE23, a(1));
  m.setCoeff(kE13, -a(2));
  m.setCoeff(kE12, a(3));
  m.setCoeff(kE1n, c(1));
  m.setCoeff(kE2n, c(2));
  m.setCoeff(kE3n, c(3));
  m.setCoeff(kI, -c(0));
  return m;
}
template <class S> Motor<S> toMotor(const DualQuaternion<S>& h) {
  return toMotor(soma::detail::studyOrder(h.real()), soma::detail::studyOrder(h.dual()));
}
/// The 8 coefficients (a₀…a₃, c₀…c₃) of a motor's dual-quaternion image.
template <class S> Vec8<S> dqCoeffs(const Motor<S>& m) {
  Vec8<S> v;
  v << m.coeff(0), m.coeff(kE23), -m.coeff(kE13), m.coeff(kE12), -m.coeff(kI), m.coeff(kE1n),
      m.coeff(kE2n), m.coeff(kE3n);
  return v;
}
template <class S> Vec8<S> dqCoeffs(const DualQuaternion<S>& h) {
  Vec8<S> v;
  v << soma::detail::studyOrder(h.real()), soma::detail::studyOrder(h.dual());
  return v;
}
/// Vector x = x₁e₁ + x₂e₂ + x₃e₃ and the point 1 + x𝐞 (GF §9.2).
template <class S> Vector<PGA, S> vec3(const Vec3<S>& x) {
  Vector<PGA, S> v;
  for (int i = 0; i < 3; ++i) v.setCoeff(Blade(1) << i, x(i));
  return v;
}
template <class S> Motor<S> point(const Vec3<S>& x) {
  Motor<S> p(S(1));
  p.setCoeff(kE1n, x(0));
  p.setCoeff(kE2n, x(1));
  p.setCoeff(kE3n, x(2));
  return p;
}
template <class S> Vec3<S> pointOf(const Motor<S>& p) { return Vec3<S>(p.coeff(kE1n), p.coeff(kE2n), p.coeff(kE3n)); }
/// The null generator 𝐞 as a vector.
template <class S> Vector<PGA, S> nullE() { return Vector<PGA, S>::generator(3); }
/// M ↦ (M with 𝐞 ↦ −𝐞)*: for M = g + ½tg𝐞 this is (g − ½tg𝐞)*, the right factor of the
/// point action of GF §9.2.
template <class S, GradeMask A> Multivector<PGA, S, A> dagger(const Multivector<PGA, S, A>& m) {
  auto d = m.conjugate();
  for (int i = 0; i < d.size; ++i)
    if (d.blade(i) & 0b1000) d[i] = -d[i];
  return d;
}
/// g + ½ t g 𝐞 from a rotor g of Cℓ⁺(0,3,0) ⊂ Cℓ⁺(0,3,1) and a translation t (GF §9.2).
template <class S> Motor<S> motor(const Motor<S>& g, const Vec3<S>& t) {
  return Motor<S>(g + Motor<S>(Dense<PGA, S>(vec3(t) * g * nullE<S>()).template grades<PGA::evenGrades>() / S(2)));
}
/// A random rotor cos(θ/2) + sin(θ/2)·(unit bivector of e₂e₃, e₃e₁, e₁e₂) of Cℓ⁺(0,3,0).
template <class S> Motor<S> randomRotor(std::mt19937_64& g) {
  const Vec3<S> a = randUnit<S>(g);
  const S th = uni<S>(g, 0, 3), c = cos(th / S(2)), s = sin(th / S(2));
  return toMotor(Vec4<S>(c, s * a(0), s * a(1), s * a(2)), Vec4<S>(Vec4<S>::Zero()));
}
/// The twist (ω; v) as the bivector ½(ω₁e₂e₃ + ω₂e₃e₁ + ω₃e₁e₂ + v₁e₁𝐞 + v₂e₂𝐞 + v₃e₃𝐞),
/// the image of ½ω + ε½v (GF §9.3, seed 5742).
template <class S> Bivector<PGA, S> twistBivector(const Vec3<S>& w, const Vec3<S>& v) {
  Bivector<PGA, S> b;
  b.setCoeff(kE23, w(0) / S(2));
  b.setCoeff(kE13, -w(1) / S(2));
  b.setCoeff(kE12, w(2) / S(2));
  b.setCoeff(kE1n, v(0) / S(2));
  b.setCoeff(kE2n, v(1) / S(2));
  b.setCoeff(kE3n, v(2) / S(2));
  return b;
}
template <class S> Vec6<S> twistOf(const Bivector<PGA, S>& b) {
  Vec6<S> t;
  t << S(2) * b.coeff(kE23), S(-2) * b.coeff(kE13), S(2) * b.coeff(kE12), S(2) * b.coeff(kE1n),
      S(2) * b.coeff(kE2n), S(2) * b.coeff(kE3n);
  return t;
}

}  // namespace soma::studies::gf09
