#pragma once
// Cl(0,3,1), the Clifford algebra of points, lines and planes (GF §9.2, §10.1), in the book's basis.
//
// Generators e1, e2, e3 (square −1) and 𝐞 (square 0) are the generators e_0, e_1, e_2, e_3 of
// soma::clifford::Signature<0,3,1>; a basis blade is a bitmask (e1 = 1, e2 = 2, e3 = 4, 𝐞 = 8)
// with its factors in increasing order. The book writes some blades in cyclic order, so their
// stored coefficient carries a sign: e3e1 = −e1e3 and e3e1𝐞 = −e1e3𝐞 (catalogue note to
// GF-10.1.2). Everything in soma::pga reads and writes coefficients through the helpers below,
// which take the book's names, so the signs live in one place.
//
//   planes  (grade 1)  π = n_x e1 + n_y e2 + n_z e3 + d 𝐞                           GF §10.1.1
//   points  (grade 3)  p = w e1e2e3 + x e2e3𝐞 + y e3e1𝐞 + z e1e2𝐞 (w = 1: the book's) GF §10.1.2
//   lines   (grade 2)  ℓ = v_x e2e3 + v_y e3e1 + v_z e1e2 + u_x e1𝐞 + u_y e2𝐞 + u_z e3𝐞 GF §10.1.3
//   motors  (grades 0, 2, 4)  h = g + ½ t g 𝐞                                       GF §9.2–9.3
//
// Operator map (multivector.hpp): * geometric, ^ exterior (meet), & regressive, | left
// contraction, ~ reverse; conjugate() is the book's Clifford conjugation c*.
#include "soma/algebra/clifford/multivector.hpp"

namespace soma::pga {

using Cl031 = clifford::Signature<0, 3, 1>;
using clifford::Blade;
using clifford::gradeBit;

template <class S> using Grade1 = clifford::Vector<Cl031, S>;
template <class S> using Grade2 = clifford::Bivector<Cl031, S>;
template <class S> using Grade3 = clifford::Trivector<Cl031, S>;
template <class S> using Grade4 = clifford::Multivector<Cl031, S, gradeBit(4)>;
template <class S> using EvenElement = clifford::Even<Cl031, S>;
template <class S> using DenseElement = clifford::Dense<Cl031, S>;

/// The book's basis blades as (bitmask, sign of the book's ordering relative to the sorted one).
struct BookBlade {
  Blade mask;
  int sign;
};
namespace basis {
inline constexpr BookBlade e1{1, 1}, e2{2, 1}, e3{4, 1}, e{8, 1};
inline constexpr BookBlade e23{6, 1}, e31{5, -1}, e12{3, 1};
inline constexpr BookBlade e1e{9, 1}, e2e{10, 1}, e3e{12, 1};
inline constexpr BookBlade e123{7, 1};
inline constexpr BookBlade e23e{14, 1}, e31e{13, -1}, e12e{11, 1};
inline constexpr BookBlade e123e{15, 1};
}  // namespace basis

/// Coefficient of the book's blade b in the element m.
template <class S, clifford::GradeMask M>
S bookCoeff(const clifford::Multivector<Cl031, S, M>& m, BookBlade b) {
  const S c = m.coeff(b.mask);
  return b.sign < 0 ? S(-c) : c;
}
/// Sets the coefficient of the book's blade b.
template <class S, clifford::GradeMask M>
void setBookCoeff(clifford::Multivector<Cl031, S, M>& m, BookBlade b, const S& v) {
  m.setCoeff(b.mask, b.sign < 0 ? S(-v) : v);
}

/// Throws InvalidInput naming `who` and `what` unless every coordinate is finite.
template <class Derived>
void requireFiniteInput(const Eigen::MatrixBase<Derived>& x, const char* who, const char* what) {
  if (!allFinite(x))
    throw InvalidInput(std::string(who) + ": " + what + " has a NaN or infinite coordinate");
}

/// Largest |coefficient| of a 3-vector (a scale for relative thresholds; no square overflows).
template <class S> S maxAbs3(const Vec3<S>& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace soma::pga
