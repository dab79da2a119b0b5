#pragma once
// The bi-invariant geometry of SE(3) (GF §15.1): the invariant metrics Q_p = αQ₀ + βQ∞ on se(3),
// the structure constants, the symmetric metric connection ∇_X Y = ½[X, Y] of a bi-invariant
// metric, its curvature R(X, Y)Z = ¼[[X, Y], Z] and the sectional curvature K(X, Z) = ¼Q([X,Z],[X,Z]).
//
// Conventions (GF ch. 13–15): screws s = (ω, v), [a, b] = ad(a) b with ad(s) = [[Ω, 0], [V, Ω]];
// Q₀ = [[0, I], [I, 0]] (the reciprocal product), Q∞ = diag(I₃, 0) (the book's normalisation of the
// Killing form; the true Killing form is −4 diag(I₃, 0), erratum E4.10 — the scale is absorbed in β).
// Definitions and the instantiation for the five scalars: geometry/src/riemannian/invariant_metric.cpp.
#include "soma/algebra/se3.hpp"

#include <array>

namespace soma {

/// Q_p = αQ₀ + βQ∞. GF §15.1 line 9519, GF-15.1-Qp-null-geodesics
template <class S> struct InvariantMetric {
  S alpha = S(1), beta = S(0);
  /// The 6×6 matrix αQ₀ + βQ∞.
  Mat6<S> matrix() const;
  /// Q_p(a, b) = aᵀ Q_p b.
  S operator()(const Vec6<S>& a, const Vec6<S>& b) const;
  /// p = −β/(2α): pitch-p screws are null, Q_p(s, s) = 0. InvalidInput if α = 0 (Q_p = βQ∞ is
  /// degenerate and no pitch is null, GF-15.1-biinvariant-connection extreme).
  S nullPitch() const;
  /// The metric whose null screws have pitch p: α = 1, β = −2p. GF §15.1 line 9521
  static InvariantMetric withNullPitch(const S& p);
};

/// Q₀ = [[0, I₃], [I₃, 0]] and Q∞ = diag(I₃, 0). GF §15.1 line 9517 (via §7.5)
template <class S> Mat6<S> reciprocalProductMatrix();
template <class S> Mat6<S> killingMatrixQinf();

/// Structure constants in the coordinate basis X_i = e_i: C[k](i, j) = C^k_ij, [X_i, X_j] = C^k_ij X_k.
/// GF §15.1 line 9420, GF-15.1-invariant-metric-identity
template <class S> std::array<Mat6<S>, 6> structureConstants();

/// max over basis triples of |C^l_ij Q_lk + C^l_ik Q_lj| (zero iff Q is ad-invariant).
/// GF §15.1 line 9437, GF-15.1-invariant-metric-identity
template <class S> S invarianceDefect(const Mat6<S>& Q);

/// The Christoffel symbols of the bi-invariant connection in the Lie-algebra frame:
/// Γ[k](i, j) = Γ^k_ij = −½C^k_ij. GF §15.1 line 9491, GF-15.1-biinvariant-connection
template <class S> std::array<Mat6<S>, 6> biinvariantChristoffel();

/// ∇_X Y = ½[X, Y] for left-invariant fields X, Y. GF §15.1 line 9495
template <class S> Vec6<S> biinvariantCovariant(const Vec6<S>& X, const Vec6<S>& Y);

/// R(X, Y)Z = −∇_X∇_Y Z + ∇_Y∇_X Z + ∇_[X,Y] Z (Milnor's sign), evaluated from ∇ = ½[ , ] on
/// left-invariant fields. GF §15.3 line 9736, GF-15.3-curvature-stability
template <class S> Vec6<S> curvatureFromConnection(const Vec6<S>& X, const Vec6<S>& Y, const Vec6<S>& Z);
/// The closed form R(X, Y)Z = ¼[[X, Y], Z]. GF §15.3 line 9744 (Milnor §21)
template <class S> Vec6<S> curvature(const Vec6<S>& X, const Vec6<S>& Y, const Vec6<S>& Z);
/// K(X, Z) = Q(R(X, Z)X, Z) = ¼Q([X, Z], [X, Z]). GF §15.3 line 9752
template <class S> S sectionalCurvature(const InvariantMetric<S>& Q, const Vec6<S>& X, const Vec6<S>& Z);

#define SOMA_INVARIANT_METRIC_EXTERN(S)                                                                   \
  extern template struct InvariantMetric<S>;                                                              \
  extern template Mat6<S> reciprocalProductMatrix<S>();                                                   \
  extern template Mat6<S> killingMatrixQinf<S>();                                                         \
  extern template std::array<Mat6<S>, 6> structureConstants<S>();                                         \
  extern template S invarianceDefect<S>(const Mat6<S>&);                                                  \
  extern template std::array<Mat6<S>, 6> biinvariantChristoffel<S>();                                     \
  extern template Vec6<S> biinvariantCovariant<S>(const Vec6<S>&, const Vec6<S>&);                        \
  extern template Vec6<S> curvatureFromConnection<S>(const Vec6<S>&, const Vec6<S>&, const Vec6<S>&);     \
  extern template Vec6<S> curvature<S>(const Vec6<S>&, const Vec6<S>&, const Vec6<S>&);                   \
  extern template S sectionalCurvature<S>(const InvariantMetric<S>&, const Vec6<S>&, const Vec6<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_INVARIANT_METRIC_EXTERN)
#undef SOMA_INVARIANT_METRIC_EXTERN

}  // namespace soma
