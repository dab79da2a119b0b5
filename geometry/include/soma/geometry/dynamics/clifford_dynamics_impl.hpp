#pragma once
// SB's Cl(0,6,2) rigid-body dynamics: the definitions behind clifford_dynamics.hpp. Included only by the
// per-scalar instantiation TUs (soma_instantiate, cmake/SomaInstantiate.cmake) and by clifford_dynamics.cpp
// (the scalar-independent shuffleByDefinition).
#include "soma/geometry/dynamics/clifford_dynamics.hpp"

#include <vector>

namespace soma::clifford_dynamics {

namespace {
/// K_j: the e-bivector complementary to screw blade j inside e₁e₂e₃e.
constexpr std::array<SignedBlade, 6> complementBasis{
    signedBlade({e1, e}),  signedBlade({e2, e}),  signedBlade({e3, e}),
    signedBlade({e2, e3}), signedBlade({e3, e1}), signedBlade({e1, e2})};

/// Product of two signed blades without common generators.
constexpr SignedBlade joined(SignedBlade x, SignedBlade y) {
  return {x.blade | y.blade, x.sign * y.sign * Sig::outerSign(x.blade, y.blade)};
}

/// σ_ij of formElement: A ∨ ((σ P_i K_j) ∧ S_j) = P_i, evaluated on signed blades.
constexpr std::array<int, 36> formSigns = [] {
  std::array<int, 36> out{};
  const SignedBlade A = signedBlade({a1, a2, a3, a});
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const SignedBlade X = joined(joined(coScrewBasis[i], complementBasis[j]), screwBasis[j]);
      const int s = A.sign * X.sign * orientationSign() * Sig::regressiveSign(A.blade, X.blade);
      // the result blade is A & X = P_i's blade; coefficient s must equal P_i.sign·σ
      out[std::size_t(i * 6 + j)] = s * coScrewBasis[i].sign;
    }
  return out;
}();
static_assert(formSigns[0] != 0, "clifford_dynamics: P_0 K_0 ∧ S_0 must have a nonzero shuffle with A");
}  // namespace

template <class S> Bivector<S> screwElement(const SE3Tangent<S>& s) {
  Bivector<S> x;
  for (int j = 0; j < 6; ++j) x += element<S, gradeBit(2)>(screwBasis[std::size_t(j)], s.coeffs()(j));
  return x;
}
template <class S> SE3Tangent<S> screwOf(const Bivector<S>& x) {
  Vec6<S> v;
  for (int j = 0; j < 6; ++j) {
    const auto& b = screwBasis[std::size_t(j)];
    v(j) = b.sign > 0 ? x.coeff(b.blade) : S(-x.coeff(b.blade));
  }
  return SE3Tangent<S>(v);
}
template <class S> Bivector<S> coScrewElement(const Vec6<S>& lp) {
  Bivector<S> x;
  for (int i = 0; i < 6; ++i) x += element<S, gradeBit(2)>(coScrewBasis[std::size_t(i)], lp(i));
  return x;
}
template <class S> Vec6<S> coScrewOf(const Bivector<S>& x) {
  Vec6<S> v;
  for (int i = 0; i < 6; ++i) {
    const auto& b = coScrewBasis[std::size_t(i)];
    v(i) = b.sign > 0 ? x.coeff(b.blade) : S(-x.coeff(b.blade));
  }
  return v;
}

template <class S> Quadvector<S> elementA() {
  return element<S, gradeBit(4)>(signedBlade({a1, a2, a3, a}));
}
template <class S> Quadvector<S> elementE() {
  return element<S, gradeBit(4)>(signedBlade({e1, e2, e3, e}));
}
// SB §5, SB-5-Q0-evaluation: written as SB prints it, term by term.
template <class S> Quadvector<S> elementQ0() {
  Quadvector<S> q;
  q += element<S, gradeBit(4)>(signedBlade({a2, a3, e1, e}));
  q += element<S, gradeBit(4)>(signedBlade({a3, a1, e2, e}));
  q += element<S, gradeBit(4)>(signedBlade({a1, a2, e3, e}));
  q += element<S, gradeBit(4)>(signedBlade({a1, a, e2, e3}));
  q += element<S, gradeBit(4)>(signedBlade({a2, a, e3, e1}));
  q += element<S, gradeBit(4)>(signedBlade({a3, a, e1, e2}));
  return q;
}

template <class S> Quadvector<S> formElement(const Mat6<S>& M) {
  Quadvector<S> N;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      if (M(i, j) == S(0)) continue;
      const SignedBlade X = joined(coScrewBasis[std::size_t(i)], complementBasis[std::size_t(j)]);
      const S c = formSigns[std::size_t(i * 6 + j)] > 0 ? M(i, j) : S(-M(i, j));
      N += element<S, gradeBit(4)>(X, c);
    }
  return N;
}
template <class S> Mat6<S> formMatrix(const Quadvector<S>& N) {
  Mat6<S> out;
  for (int j = 0; j < 6; ++j) {
    Vec6<S> unit = Vec6<S>::Zero();
    unit(j) = S(1);
    out.col(j) = coScrewOf(momentum(N, screwElement(SE3Tangent<S>(unit))));
  }
  return out;
}

template <class S> Bivector<S> momentum(const Quadvector<S>& N, const Bivector<S>& s) {
  return shuffle(elementA<S>(), clifford::outer(N, s));
}
template <class S> S pairing(const Bivector<S>& P, const Bivector<S>& s) {
  return shuffle(P, clifford::outer(elementQ0<S>(), s)).scalarPart();
}
template <class S> S kineticEnergy(const Quadvector<S>& N, const Bivector<S>& s) {
  return shuffle(bar(s), clifford::outer(N, s)).scalarPart() / S(2);
}

template <class S> Even<S> motorElement(const SE3<S>& g) {
  const auto& q = g.quaternion();
  Even<S> r(q.w());
  r += Even<S>(element<S, gradeBit(2)>(signedBlade({e2, e3}), q.x()));
  r += Even<S>(element<S, gradeBit(2)>(signedBlade({e3, e1}), q.y()));
  r += Even<S>(element<S, gradeBit(2)>(signedBlade({e1, e2}), q.z()));
  const Vec3<S>& t = g.translation();
  Even<S> tr(S(1));
  tr += Even<S>(element<S, gradeBit(2)>(signedBlade({e1, e}), t.x() / S(2)));
  tr += Even<S>(element<S, gradeBit(2)>(signedBlade({e2, e}), t.y() / S(2)));
  tr += Even<S>(element<S, gradeBit(2)>(signedBlade({e3, e}), t.z() / S(2)));
  return Even<S>(tr * r);
}
template <class S> Bivector<S> actScrew(const Even<S>& g, const Bivector<S>& s) {
  return ((g * s) * g.conjugate()).template grade<2>();
}
template <class S> Bivector<S> actCoScrew(const Even<S>& g, const Bivector<S>& P) {
  const Even<S> gb = bar(g);
  return ((gb * P) * gb.conjugate()).template grade<2>();
}
template <class S> Quadvector<S> actInertia(const Even<S>& g, const Quadvector<S>& N) {
  const Even<S> G = Even<S>(g * bar(g));
  return ((G * N) * G.conjugate()).template grade<4>();
}

template <class S> Bivector<S> coadjoint(const Bivector<S>& s, const Bivector<S>& P) {
  const Bivector<S> sb = bar(s);
  return ((sb * P - P * sb) / S(2)).template grade<2>();
}
template <class S> Quadvector<S> inertiaDerivative(const Quadvector<S>& N, const Bivector<S>& s) {
  const Bivector<S> sb = bar(s);
  return ((s * N - N * s + sb * N - N * sb) / S(2)).template grade<4>();
}

namespace {
template <class S> auto coriolisE(const Quadvector<S>& N, const Bivector<S>& s) {
  const Bivector<S> sb = bar(s);
  return clifford::outer(sb * N - N * sb, s) / S(2);
}
}  // namespace

template <class S>
clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)> eFormLeft(
    const Quadvector<S>& N, const Bivector<S>& s, const Bivector<S>& sdot) {
  using R = clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)>;
  R out(coriolisE(N, s));
  out += R(clifford::outer(N, sdot));
  return out;
}
template <class S> Hexavector<S> eFormRight(const Bivector<S>& W) {
  return (W * elementE<S>()).template grade<6>();
}

template <class S>
CliffordAcceleration<S> rigidBodyAcceleration(const Quadvector<S>& N, const Bivector<S>& s,
                                              const Bivector<S>& W) {
  using R = clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)>;
  constexpr int m = Hexavector<S>::size;
  Eigen::Matrix<S, m, 6> M;
  for (int j = 0; j < 6; ++j) {
    const Hexavector<S> col = clifford::outer(N, element<S, gradeBit(2)>(screwBasis[std::size_t(j)]));
    for (int r = 0; r < m; ++r) M(r, j) = col[r];
  }
  const R cor(coriolisE(N, s));
  const R rhs = R(eFormRight(W)) - cor;
  const Hexavector<S> rhs6 = rhs.template grade<6>();
  Eigen::Matrix<S, m, 1> b;
  for (int r = 0; r < m; ++r) b(r) = rhs6[r];
  const Eigen::Matrix<S, 6, 1> x = M.colPivHouseholderQr().solve(b);
  Bivector<S> sdot;
  for (int j = 0; j < 6; ++j) sdot += element<S, gradeBit(2)>(screwBasis[std::size_t(j)], x(j));
  const S res = (eFormLeft(N, s, sdot) - R(eFormRight(W))).maxAbs();
  return {sdot, res};
}

#define SOMA_INSTANTIATE_CLIFFORD_DYNAMICS(S) namespace clifford_dynamics {                                           \
  template Bivector<S> screwElement<S>(const SE3Tangent<S>&);                                 \
  template SE3Tangent<S> screwOf<S>(const Bivector<S>&);                                      \
  template Bivector<S> coScrewElement<S>(const Vec6<S>&);                                     \
  template Vec6<S> coScrewOf<S>(const Bivector<S>&);                                          \
  template Quadvector<S> elementA<S>();                                                       \
  template Quadvector<S> elementE<S>();                                                       \
  template Quadvector<S> elementQ0<S>();                                                      \
  template Quadvector<S> formElement<S>(const Mat6<S>&);                                      \
  template Mat6<S> formMatrix<S>(const Quadvector<S>&);                                       \
  template Bivector<S> momentum<S>(const Quadvector<S>&, const Bivector<S>&);                 \
  template S pairing<S>(const Bivector<S>&, const Bivector<S>&);                              \
  template S kineticEnergy<S>(const Quadvector<S>&, const Bivector<S>&);                      \
  template Even<S> motorElement<S>(const SE3<S>&);                                            \
  template Bivector<S> actScrew<S>(const Even<S>&, const Bivector<S>&);                       \
  template Bivector<S> actCoScrew<S>(const Even<S>&, const Bivector<S>&);                     \
  template Quadvector<S> actInertia<S>(const Even<S>&, const Quadvector<S>&);                 \
  template Bivector<S> coadjoint<S>(const Bivector<S>&, const Bivector<S>&);                  \
  template Quadvector<S> inertiaDerivative<S>(const Quadvector<S>&, const Bivector<S>&);      \
  template clifford::Multivector<Sig, S, gradeBit(4) | gradeBit(6) | gradeBit(8)>             \
  eFormLeft<S>(const Quadvector<S>&, const Bivector<S>&, const Bivector<S>&);                 \
  template Hexavector<S> eFormRight<S>(const Bivector<S>&);                                   \
  template CliffordAcceleration<S> rigidBodyAcceleration<S>(const Quadvector<S>&,             \
                                                            const Bivector<S>&,               \
                                                            const Bivector<S>&); }

}  // namespace soma::clifford_dynamics
