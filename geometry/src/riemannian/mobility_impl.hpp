#pragma once
// GF §15.2: mobility of single-loop mechanisms. Definitions; instantiated one scalar per TU by soma_instantiate (cmake/SomaInstantiate.cmake).
#include "soma/geometry/riemannian/mobility.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

namespace soma {
namespace {
template <class S> Vec6<S> br(const Vec6<S>& a, const Vec6<S>& b) { return SE3Tangent<S>(a).ad() * b; }

/// Orthonormal basis of the span of the columns of M (6×N, any N), from the thin SVD of Mᵀ
/// (Mᵀ = UΣVᵀ, so the column space of M is spanned by the columns of V with σ > Tolerance::rank()·σ_max).
template <class S> ScrewMatrix<S> spanBasis(const DgMatrix<S>& M) {
  if (M.cols() == 0) return ScrewMatrix<S>(6, 0);
  detail::SmallMat<S> u, v;
  std::vector<S> sig;
  detail::smallSvd<S>(detail::SmallMat<S>(M.transpose()), u, sig, v);
  if (sig.empty() || !(sig[0] > S(0))) return ScrewMatrix<S>(6, 0);
  int r = 0;
  for (const S& x : sig)
    if (x > S(64) * Tolerance<S>::rank() * sig[0]) ++r;
  return ScrewMatrix<S>(v.leftCols(r));
}
template <class S> DgMatrix<S> columns(const std::vector<Vec6<S>>& s) {
  DgMatrix<S> M(6, Eigen::Index(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) M.col(Eigen::Index(i)) = s[i];
  return M;
}
template <class S> void checkScrews(const std::vector<Vec6<S>>& s, const char* fn) {
  if (s.empty()) throw InvalidInput(std::string(fn) + ": the list of joint screws is empty");
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!allFinite(s[i])) throw InvalidInput(std::string(fn) + ": screw " + std::to_string(i + 1) + " has a NaN or infinite entry");
}
}  // namespace

template <class S> int screwSystemDimension(const std::vector<Vec6<S>>& screws) {
  checkScrews(screws, "screwSystemDimension");
  return int(spanBasis<S>(columns(screws)).cols());
}
template <class S> int infinitesimalMobility(const std::vector<Vec6<S>>& screws) {
  return int(screws.size()) - screwSystemDimension(screws);
}

// GF §15.2 line 9658: Δ∞ by iterated brackets until the dimension stops growing
template <class S> ScrewMatrix<S> completionAlgebra(const std::vector<Vec6<S>>& screws) {
  checkScrews(screws, "completionAlgebra");
  ScrewMatrix<S> B = spanBasis<S>(columns(screws));
  for (int it = 0; it < 6; ++it) {
    const Eigen::Index k = B.cols();
    DgMatrix<S> M(6, k + k * (k - 1) / 2);
    M.leftCols(k) = B;
    Eigen::Index c = k;
    for (Eigen::Index i = 0; i < k; ++i)
      for (Eigen::Index j = i + 1; j < k; ++j) M.col(c++) = br<S>(Vec6<S>(B.col(i)), Vec6<S>(B.col(j)));
    ScrewMatrix<S> N = spanBasis<S>(M);
    if (N.cols() == k) return B;
    B = N;
  }
  return B;
}
template <class S> int completionMobility(const std::vector<Vec6<S>>& screws) {
  return int(screws.size()) - int(completionAlgebra(screws).cols());
}

template <class S> S subalgebraDefect(const std::vector<Vec6<S>>& screws) {
  checkScrews(screws, "subalgebraDefect");
  const ScrewMatrix<S> B = spanBasis<S>(columns(screws));
  S scale = S(0), worst = S(0);
  for (const auto& s : screws) scale = std::max<S>(scale, s.squaredNorm());
  for (std::size_t i = 0; i < screws.size(); ++i)
    for (std::size_t k = i + 1; k < screws.size(); ++k) {
      const Vec6<S> b = br<S>(screws[i], screws[k]);
      const Vec6<S> out = b - B * (B.transpose() * b);
      worst = std::max<S>(worst, out.norm());
    }
  return scale > S(0) ? S(worst / scale) : S(0);
}
// GF §15.2 line 9680: [s_i, s_k] ∈ Δ₁
template <class S> bool isSubalgebra(const std::vector<Vec6<S>>& screws) {
  return subalgebraDefect(screws) <= Tolerance<S>::identity(1024);
}

// GF §15.2 Table 15.1 (lines 9688–9704)
template <class S> std::vector<SubalgebraRow<S>> table15_1(const S& p) {
  using std::abs;
  if (!isFinite(p) || !(abs(p) > Tolerance<S>::epsilon()))
    throw InvalidInput("table15_1: the pitch p of the H_p rows must be finite and non-zero");
  auto e = [](int i) { return Vec6<S>(Vec6<S>::Unit(i)); };
  Vec6<S> hp = e(0);
  hp(3) = p;
  return {{"R", "IIB", {e(3)}},
          {"H_p", "IA (p != 0)", {hp}},
          {"SO(2)", "IA (p = 0)", {e(0)}},
          {"R^2", "IIC", {e(3), e(4)}},
          {"SO(2) x R", "IB0", {e(0), e(3)}},
          {"R^3", "IID", {e(3), e(4), e(5)}},
          {"SO(3)", "IIA (p = 0)", {e(0), e(1), e(2)}},
          {"SE(2)", "IIC (p = 0)", {e(0), e(4), e(5)}},
          {"H_p x| R^2", "IIC (p != 0)", {hp, e(4), e(5)}},
          {"SE(2) x R", "IIC-bar", {e(0), e(3), e(4), e(5)}}};
}

// Bennett (1903); DH Rz(θ)Tx(a)Rx(α) closes at θ₃ = −θ₁, θ₄ = −θ₂
template <class S> std::vector<Vec6<S>> bennettLoop(const S& a, const S& alpha, const S& beta, const S& theta1) {
  using std::abs;
  using std::atan;
  using std::cos;
  using std::sin;
  using std::tan;
  const S pi_ = pi<S>();
  if (!(a > S(0)) || !(alpha > S(0) && alpha < pi_) || !(beta > S(0) && beta < pi_) ||
      !(abs(alpha - beta) > Tolerance<S>::input()) || !isFinite(theta1))
    throw InvalidInput("bennettLoop: need a > 0, twists alpha, beta in (0, pi) with alpha != beta, finite theta1");
  const S b = a * sin(beta) / sin(alpha);
  const S K = sin((beta + alpha) / S(2)) / sin((beta - alpha) / S(2));
  const S t2 = S(2) * atan(K / tan(theta1 / S(2)));
  const S th[4] = {theta1, t2, -theta1, -t2};
  const S len[4] = {a, b, a, b}, tw[4] = {alpha, beta, alpha, beta};
  std::vector<Vec6<S>> s;
  SE3<S> F = SE3<S>::Identity();
  for (int i = 0; i < 4; ++i) {
    const Vec3<S> w = F.rotation().col(2), q = F.translation();
    Vec6<S> x;
    x << w, q.cross(w);
    s.push_back(x);
    const SE3<S> Rz(SO3<S>::fromAxisAngle(Vec3<S>::UnitZ(), th[i]), Vec3<S>::Zero());
    const SE3<S> TxRx(SO3<S>::fromAxisAngle(Vec3<S>::UnitX(), tw[i]), Vec3<S>(len[i], S(0), S(0)));
    F = F.compose(Rz).compose(TxRx);
  }
  return s;
}

template <class S> S loopResidual(const std::vector<Vec6<S>>& screws, const DgVector<S>& theta) {
  const JointSpaceGeometry<S> geo(screws);
  return geo.forward(theta).log().coeffs().template lpNorm<Eigen::Infinity>();
}

template <class S> LoopTrace<S> traceLoop(const std::vector<Vec6<S>>& screws, const S& stepLength, int steps) {
  using std::sqrt;
  checkScrews(screws, "traceLoop");
  if (!(stepLength > S(0)) || steps < 0) throw InvalidInput("traceLoop: stepLength must be > 0 and steps >= 0");
  const JointSpaceGeometry<S> geo(screws);
  const int n = geo.dof();
  LoopTrace<S> out;
  DgVector<S> th = DgVector<S>::Zero(n);
  out.path.push_back(th);
  auto kernel = [&](const DgVector<S>& t, int& dim) {  // null space of J(θ) from its thin SVD
    const ScrewMatrix<S> J = geo.screws(t);
    detail::SmallMat<S> u, v;
    std::vector<S> sig;
    detail::smallSvd<S>(detail::SmallMat<S>(J), u, sig, v);
    dim = int(J.cols()) - int(sig.size());
    for (const S& x : sig)
      if (!(x > S(64) * Tolerance<S>::rank() * sig[0])) ++dim;
    return DgVector<S>(v.col(v.cols() - 1));
  };
  int dim = 0;
  DgVector<S> dir = kernel(th, dim);
  out.kernelDimension = dim;
  if (dim != 1) return out;
  const S tol = Tolerance<S>::identity(1024);
  out.closed = true;
  for (int k = 0; k < steps; ++k) {
    int d = 0;
    DgVector<S> kv = kernel(th, d);
    if (kv.dot(dir) < S(0)) kv = -kv;
    dir = kv;
    th += stepLength * dir;
    S res = S(0);
    for (int it = 0; it < 30; ++it) {  // Gauss–Newton on log ρ(θ) = 0 (spatial Jacobian)
      const Vec6<S> r = geo.forward(th).log().coeffs();
      res = r.template lpNorm<Eigen::Infinity>();
      if (res <= tol) break;
      const ScrewMatrix<S> J = geo.screws(th);
      const DgMatrix<S> JJ = J * J.transpose() + Tolerance<S>::sqrtEpsilon() * Tolerance<S>::sqrtEpsilon() * DgMatrix<S>::Identity(6, 6);
      th -= J.transpose() * JJ.ldlt().solve(DgMatrix<S>(r));
    }
    out.maxResidual = std::max<S>(out.maxResidual, res);
    if (!(res <= tol)) out.closed = false;
    out.path.push_back(th);
  }
  return out;
}

#define SOMA_INSTANTIATE_MOBILITY(S)                                                                      \
  template int screwSystemDimension<S>(const std::vector<Vec6<S>>&);                              \
  template int infinitesimalMobility<S>(const std::vector<Vec6<S>>&);                             \
  template ScrewMatrix<S> completionAlgebra<S>(const std::vector<Vec6<S>>&);                      \
  template int completionMobility<S>(const std::vector<Vec6<S>>&);                                \
  template bool isSubalgebra<S>(const std::vector<Vec6<S>>&);                                     \
  template S subalgebraDefect<S>(const std::vector<Vec6<S>>&);                                    \
  template std::vector<SubalgebraRow<S>> table15_1<S>(const S&);                                  \
  template std::vector<Vec6<S>> bennettLoop<S>(const S&, const S&, const S&, const S&);           \
  template S loopResidual<S>(const std::vector<Vec6<S>>&, const DgVector<S>&);                    \
  template LoopTrace<S> traceLoop<S>(const std::vector<Vec6<S>>&, const S&, int);

}  // namespace soma
