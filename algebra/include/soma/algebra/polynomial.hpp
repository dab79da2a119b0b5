#pragma once
// Real roots of univariate polynomials (DESIGN §1 "polynomials"): all complex roots by the
// Aberth–Ehrlich simultaneous iteration (the companion matrix's eigenvalues without the QR:
// Eigen's EigenSolver for five scalars took ~10 min to compile), then Newton polish of the real
// ones in the working scalar. Used by the closed-form inverse kinematics (the quartic of a 3R
// arm, GF §5.2.1, and of Pieper robots, GF §10.3) and available to every other solver.
//
// Coefficients are ASCENDING: c[0] + c[1] x + ... + c[n] x^n.
// Leading coefficients below Tolerance<S>::epsilon() times the largest are dropped (a root at
// infinity: callers that substitute t = tan(θ/2) must rotate θ so that no root sits at θ = π).
// A complex eigenvalue x + iy is taken as real when |y| ≤ Tolerance<S>::input()·max(1, |x|):
// a double root splits into a pair with |y| ~ sqrt(eps) under round-off, and both copies are
// returned (multiplicity kept), each polished by Newton's method on the original polynomial.
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <complex>
#include <vector>

namespace soma {

/// Value of Σ c_k x^k by Horner's rule.
template <class S> S evalPolynomial(const std::vector<S>& c, const S& x) {
  S v = S(0);
  for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * x + *it;
  return v;
}

/// All roots (complex) of Σ c_k x^k (Aberth–Ehrlich); degree after dropping
/// negligible leading coefficients. Throws InvalidInput on NaN/infinite coefficients.
template <class S> std::vector<std::complex<S>> polynomialRoots(const std::vector<S>& c);

/// Real roots of Σ c_k x^k in ascending order (double roots twice), Newton-polished.
/// The zero polynomial throws InvalidInput (every x is a root).
template <class S> std::vector<S> realRoots(const std::vector<S>& c);

/// Real roots of c0 + c1 x + c2 x² + c3 x³ + c4 x⁴ (the quartic of GF §5.2.1): degree drops
/// handled (cubic, quadratic by the cancellation-free formula, linear), otherwise realRoots.
template <class S> std::vector<S> quarticRealRoots(const std::array<S, 5>& c);

/// Real roots of c0 + c1 x + c2 x² without cancellation (q = −(c1 + sign(c1)·√Δ)/2).
template <class S> std::vector<S> quadraticRealRoots(const S& c0, const S& c1, const S& c2);

#define SOMA_POLY_EXTERN(S)                                                                     \
  extern template std::vector<std::complex<S>> polynomialRoots<S>(const std::vector<S>&);      \
  extern template std::vector<S> realRoots<S>(const std::vector<S>&);                          \
  extern template std::vector<S> quarticRealRoots<S>(const std::array<S, 5>&);                 \
  extern template std::vector<S> quadraticRealRoots<S>(const S&, const S&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_POLY_EXTERN)
#undef SOMA_POLY_EXTERN

}  // namespace soma
