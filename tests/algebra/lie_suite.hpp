#pragma once
// One generic, manif-style property suite for the Lie groups SO3<S> and SE3<S> (DESIGN §7):
// the same checks run at the identity, at Random()·1e-8, at random elements and at the edge
// angles 0, 1e-8, π − 1e-8, π, on both sides of every Taylor switch, for all five scalars.
// Helpers only; the TEST_CASEs live in so3*.cpp / se3*.cpp.
#include "soma/algebra/lie_algebra.hpp"
#include "soma/algebra/log_accuracy.hpp"
#include "soma/algebra/se3.hpp"
#include "support/scalars.hpp"

#include <string>
#include <vector>

namespace soma::test::lie {

template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) { return m.cwiseAbs().maxCoeff(); }

/// RAII: run a block at another default mpfr precision (for reference values).
struct MpfrBits {
  int old;
  explicit MpfrBits(int bits) : old(mpfrBits()) { setMpfrBits(bits); }
  ~MpfrBits() { setMpfrBits(old); }
  MpfrBits(const MpfrBits&) = delete;
  MpfrBits& operator=(const MpfrBits&) = delete;
};

constexpr int kRefBits = 512;

/// x as a kRefBits mpreal (exact: every rung has at most 256 bits).
template <class S> mpreal ref(const S& x) { return detail::logacc::exact(x, kRefBits); }
template <class Derived> auto refMat(const Eigen::MatrixBase<Derived>& m) {
  using S = typename Derived::Scalar;
  return m.unaryExpr([](const S& x) { return ref(x); }).eval();
}

template <class G> using Tan = typename G::Tangent;
template <class G> using Scal = typename G::Scalar;
template <class G> using TanVec = typename Tan<G>::DataType;
template <class G> using AdMat = Eigen::Matrix<Scal<G>, G::DoF, G::DoF>;
template <class G> constexpr bool kIsSE3 = G::DoF == 6;

/// A tangent with rotation angle θ about `axis` (unit) and, for SE(3), linear part v.
template <class G>
Tan<G> tangentOf(const Vec3<Scal<G>>& axis, const Scal<G>& theta, const Vec3<Scal<G>>& v) {
  using S = Scal<G>;
  if constexpr (kIsSE3<G>) {
    return Tan<G>(Vec3<S>(axis * theta), v);
  } else {
    (void)v;
    return Tan<G>(Vec3<S>(axis * theta));
  }
}

/// Rotation angle of a tangent.
template <class G> Scal<G> angleOf(const Tan<G>& t) {
  using std::sqrt;
  return sqrt(t.coeffs().template head<3>().squaredNorm());
}

/// True when θ < π exactly (judged in mpfr): log(exp(ξ)) = ξ is only expected then.
template <class S> bool belowPi(const S& theta) {
  MpfrBits bits(kRefBits);
  return ref(theta) < mpfr::const_pi();
}

template <class G> struct Sample {
  Tan<G> xi;
  std::string label;
};

/// The Taylor switches of so3.hpp / se3.hpp, as rotation angles:
///  precision(3): SO3 exp k, Jacobian coefficients B, C, inverse coefficient D;
///  2·asin(precision(3)): SO3 log (switch on |q_v|² = sin²(θ/2));
///  precision(5): se3QBlock; 1: detail::thetaMinusSin.
template <class S> std::vector<std::pair<S, std::string>> taylorSwitches() {
  using std::asin;
  using std::sqrt;
  const S p3 = sqrt(detail::taylorSwitch2<S>(3)), p5 = sqrt(detail::taylorSwitch2<S>(5));
  return {{p3, "precision(3)"},
          {S(2) * asin(p3), "2 asin(precision(3)) (log)"},
          {p5, "precision(5) (Q block)"},
          {S(1), "1 (thetaMinusSin)"}};
}

/// Identity, Random·1e-8, the edge angles 0, 1e-8, 0.3, 1, 2, π − 1e-8, π, both sides
/// (relative 2^-10) of each Taylor switch, then `nRandom` random tangents (angle in [0, π)).
template <class G> std::vector<Sample<G>> samples(std::mt19937_64& g, int nRandom) {
  using S = Scal<G>;
  std::vector<Sample<G>> out;
  out.push_back({Tan<G>::Zero(), "identity"});
  auto axis = [&] { return unitVec3<S>(g); };
  auto lin = [&] { return uniformVec<S, 3>(g); };
  {
    Tan<G> r = tangentOf<G>(axis(), uniform<S>(g, 0, 3.14), lin());
    out.push_back({r * S(1e-8), "Random*1e-8"});
  }
  const S p = pi<S>();
  const std::pair<S, const char*> edges[] = {
      {S(0), "0"},          {S(1e-8), "1e-8"},     {S(3) / S(10), "0.3"}, {S(1), "1"},
      {S(2), "2"},          {p - S(1e-8), "pi-1e-8"}, {p, "pi"}};
  for (const auto& [th, name] : edges) out.push_back({tangentOf<G>(axis(), th, lin()), name});
  const S rel = S(1) / S(1024);
  for (const auto& [sw, name] : taylorSwitches<S>()) {
    out.push_back({tangentOf<G>(axis(), sw * (S(1) - rel), lin()), "below " + name});
    out.push_back({tangentOf<G>(axis(), sw * (S(1) + rel), lin()), "above " + name});
  }
  if constexpr (kIsSE3<G>) {  // lengths 1e8 and 1e-8 (DESIGN §8)
    out.push_back({tangentOf<G>(axis(), S(1), Vec3<S>(lin() * S(1e8))), "|v| ~ 1e8"});
    out.push_back({tangentOf<G>(axis(), p - S(1e-8), Vec3<S>(lin() * S(1e8))), "pi-1e-8, |v| ~ 1e8"});
    out.push_back({tangentOf<G>(axis(), S(1), Vec3<S>(lin() * S(1e-8))), "|v| ~ 1e-8"});
  }
  for (int i = 0; i < nRandom; ++i)
    out.push_back({tangentOf<G>(axis(), uniform<S>(g, 0, 3.14159), lin()), "random"});
  return out;
}

/// Homogeneous action through matrix(): R p (SO3) or (M (p; 1)).head(3) (SE3).
template <class G> Vec3<Scal<G>> actByMatrix(const G& x, const Vec3<Scal<G>>& p) {
  using S = Scal<G>;
  if constexpr (kIsSE3<G>) {
    const Vec4<S> h = x.matrix() * Vec4<S>(p(0), p(1), p(2), S(1));
    return h.template head<3>();
  } else {
    return x.matrix() * p;
  }
}

/// Scale of an element for absolute tolerances: 1 + |t|∞.
template <class G> Scal<G> scaleOf(const G& x) {
  if constexpr (kIsSE3<G>) return Scal<G>(1) + x.translation().cwiseAbs().maxCoeff();
  else return Scal<G>(1);
}

/// The group identities of the suite at one sample X = exp(ξ), with random partners.
template <class G> void checkGroupProperties(const Sample<G>& smp, std::mt19937_64& g) {
  using S = Scal<G>;
  using std::abs;
  const S eps = Tolerance<S>::epsilon();
  const Tan<G>& xi = smp.xi;
  INFO("sample " << smp.label << ", theta = " << toString(angleOf<G>(xi), 20));
  const G X = xi.exp();
  const G Y = G::Random(g), Z = G::Random(g);
  const Tan<G> eta = tangentOf<G>(unitVec3<S>(g), uniform<S>(g, 0, 3), uniformVec<S, 3>(g));
  const S sc = scaleOf(X) * scaleOf(Y) * scaleOf(Z);
  const S tol = S(32) * eps * sc;

  // exp∘log and log∘exp (principal branch: θ < π exactly).
  CHECK(X.log().exp().isApprox(X, tol));
  const S th = angleOf<G>(xi);
  if (belowPi(th)) {
    CHECK(X.log().isApprox(xi, tol * (S(1) + th)));
  } else {  // θ = pi<S>() ≥ π: the log is the other half-turn, still of angle ≤ π
    CHECK(angleOf<G>(X.log()) <= pi<S>() * (S(1) + S(4) * eps));
  }
  // Inverse, identity, associativity.
  CHECK((X * X.inverse()).isApprox(G::Identity(), tol));
  CHECK((X.inverse() * X).isApprox(G::Identity(), tol));
  CHECK(X.inverse().inverse().isApprox(X, tol));
  CHECK((X * G::Identity()).isApprox(X, S(2) * eps));
  CHECK(((X * Y) * Z).isApprox(X * (Y * Z), tol));
  // The action agrees with matrix() and is a group action (A1), (A2) of GF §2.4.
  const Vec3<S> p = uniformVec<S, 3>(g, -2, 2);
  CHECK(maxAbs(Vec3<S>(X.act(p) - actByMatrix(X, p))) <= S(4) * tol);
  CHECK(maxAbs(Vec3<S>(X.act(Y.act(p)) - (X * Y).act(p))) <= S(4) * tol);
  CHECK(maxAbs(Vec3<S>(G::Identity().act(p) - p)) == S(0));
  CHECK(maxAbs(typename G::Transformation((X * Y).matrix() - X.matrix() * Y.matrix())) <= tol);
  // Rotation block is orthogonal with det +1.
  const Mat3<S> R = X.matrix().template topLeftCorner<3, 3>();
  CHECK(maxAbs(Mat3<S>(R.transpose() * R - Mat3<S>::Identity())) <= S(8) * eps);
  CHECK(abs(R.determinant() - S(1)) <= S(8) * eps);
  // Adjoint: Ad(X) η = vee(X hat(η) X⁻¹) (GF-4.2-adjoint-SO3/SE3), homomorphism, and
  // exp(Ad(X) η) = X exp(η) X⁻¹.
  const TanVec<G> adEta = X.adjoint() * eta.coeffs();
  const TanVec<G> conj =
      Tan<G>::vee(X.matrix() * eta.hat() * X.inverse().matrix()).coeffs();
  CHECK(maxAbs(TanVec<G>(conj - adEta)) <= S(4) * tol);
  CHECK(maxAbs(AdMat<G>((X * Y).adjoint() - X.adjoint() * Y.adjoint())) <= S(4) * tol);
  CHECK(Tan<G>(adEta).exp().isApprox(X * eta.exp() * X.inverse(), S(8) * tol));
  // rplus/rminus and lplus/lminus are inverse to each other.
  CHECK(X.rplus(Y.rminus(X)).isApprox(Y, S(4) * tol));
  CHECK(X.lplus(Y.lminus(X)).isApprox(Y, S(4) * tol));
  CHECK(X.rplus(eta).rminus(X).isApprox(eta, S(4) * tol));
  CHECK(X.between(Y).isApprox(X.inverse() * Y, tol));
  // Geodesic interpolation: endpoints and the midpoint M with (X⁻¹M)² = X⁻¹Y.
  CHECK(G::interpolate(X, Y, S(0)).isApprox(X, tol));
  CHECK(G::interpolate(X, Y, S(1)).isApprox(Y, S(4) * tol));
  const G M = G::interpolate(X, Y, S(1) / S(2));
  const G h = X.inverse() * M;
  CHECK((h * h).isApprox(X.inverse() * Y, S(8) * tol));
  // Casting up to mpfr and back keeps the element.
  CHECK(X.template cast<mpreal>().template cast<S>().isApprox(X, S(2) * eps * sc));
}

/// Jacobian identities that hold in every rung: Jr Jr⁻¹ = I, Jl Jl⁻¹ = I, Jl = Ad(exp ξ) Jr,
/// Jr(ξ) = Jl(−ξ), ljac = Σ ad^k/(k+1)! (GF-4.5.2-dexp-hausdorff), J_out of exp/log equal
/// rjac/rjacinv, inverse/compose/act J_out in closed form.
template <class G> void checkJacobianIdentities(const Sample<G>& smp) {
  using S = Scal<G>;
  using M = AdMat<G>;
  const S eps = Tolerance<S>::epsilon();
  const Tan<G>& xi = smp.xi;
  INFO("sample " << smp.label << ", theta = " << toString(angleOf<G>(xi), 20));
  const S sc = S(1) + maxAbs(xi.coeffs());
  const S tol = S(64) * eps * sc;  // entries of the Q blocks grow like |v|
  const M I = M::Identity();
  const M Jr = xi.rjac(), Jl = xi.ljac(), Jri = xi.rjacinv(), Jli = xi.ljacinv();
  CHECK(maxAbs(M(Jr * Jri - I)) <= tol);
  CHECK(maxAbs(M(Jl * Jli - I)) <= tol);
  CHECK(maxAbs(M(Jl - xi.exp().adjoint() * Jr)) <= tol);
  CHECK(maxAbs(M(Jr - (-xi).ljac())) == S(0));
  CHECK(maxAbs(M(Jl - dexpSeries(xi, 120))) <= tol);
  CHECK(maxAbs(M(Jr - dexpSeries(xi, 120, true))) <= tol);
  M J;
  const G X = xi.exp(&J);
  CHECK(maxAbs(M(J - Jr)) == S(0));
  const Tan<G> l = X.log(&J);
  CHECK(maxAbs(M(J - l.rjacinv())) == S(0));
  X.inverse(&J);
  CHECK(maxAbs(M(J + X.adjoint())) == S(0));
}

/// Central difference on the manifold of f: G → G at X (columns: (f(X⊕he_i) ⊖ f(X⊕−he_i))/2h,
/// both minus taken at f(X)).
template <class G, class F> AdMat<G> numericJacobian(const G& X, F f, const Scal<G>& h) {
  using S = Scal<G>;
  AdMat<G> J;
  const auto fx = f(X);
  for (int i = 0; i < G::DoF; ++i) {
    TanVec<G> e = TanVec<G>::Zero();
    e(i) = h;
    const TanVec<G> dp = f(X.rplus(Tan<G>(e))).rminus(fx).coeffs();
    const TanVec<G> dm = f(X.rplus(Tan<G>(TanVec<G>(-e)))).rminus(fx).coeffs();
    J.col(i) = (dp - dm) / (S(2) * h);
  }
  return J;
}

/// Every analytic Jacobian against central differences on the manifold (double, long double):
/// exp, log, inverse, compose (both), act (both), rjac, ljac, rjacinv, ljacinv.
template <class G> void checkJacobiansNumerically(const Sample<G>& smp, std::mt19937_64& g) {
  using S = Scal<G>;
  using M = AdMat<G>;
  using std::cbrt;
  const S eps = Tolerance<S>::epsilon();
  const S h = cbrt(eps);            // balances truncation h² against rounding ε/h
  const Tan<G>& xi = smp.xi;
  const S tol = S(64) * h * h * (S(1) + maxAbs(xi.coeffs()));  // ≈ 64 ε^(2/3), relative to |ξ|
  const S th = angleOf<G>(xi);
  INFO("sample " << smp.label << ", theta = " << toString(th, 20));
  const G X = xi.exp();
  const G Y = G::Random(g);
  auto fdTangent = [&](auto f) {  // f: tangent → G; columns (f(ξ+he_i) ⊖ f(ξ−he_i))/2h at f(ξ)
    M J;
    const G f0 = f(xi);
    for (int i = 0; i < G::DoF; ++i) {
      TanVec<G> e = TanVec<G>::Zero();
      e(i) = h;
      J.col(i) = (f(xi + Tan<G>(e)).rminus(f0).coeffs() - f(xi - Tan<G>(e)).rminus(f0).coeffs()) /
                 (S(2) * h);
    }
    return J;
  };
  // exp: J_out = Jr.
  M J;
  xi.exp(&J);
  CHECK(maxAbs(M(J - fdTangent([](const Tan<G>& t) { return t.exp(); }))) <= tol);
  // ljac: exp(ξ + δ) = exp(Jl δ) exp(ξ), i.e. the left minus.
  {
    M Jn;
    const G f0 = xi.exp();
    for (int i = 0; i < G::DoF; ++i) {
      TanVec<G> e = TanVec<G>::Zero();
      e(i) = h;
      Jn.col(i) = ((xi + Tan<G>(e)).exp().lminus(f0).coeffs() -
                   (xi - Tan<G>(e)).exp().lminus(f0).coeffs()) / (S(2) * h);
    }
    CHECK(maxAbs(M(xi.ljac() - Jn)) <= tol);
  }
  // log: J_out = Jr⁻¹(log X) (log is discontinuous across θ = π: skip there).
  if (th < pi<S>() - S(1) / S(1000)) {
    const Tan<G> l = X.log(&J);
    M Jn;
    for (int i = 0; i < G::DoF; ++i) {
      TanVec<G> e = TanVec<G>::Zero();
      e(i) = h;
      Jn.col(i) = (X.rplus(Tan<G>(e)).log().coeffs() - X.rplus(Tan<G>(TanVec<G>(-e))).log().coeffs()) /
                  (S(2) * h);
    }
    CHECK(maxAbs(M(J - Jn)) <= tol);
    CHECK(maxAbs(M(l.rjacinv() - Jn)) <= tol);
    // ljacinv: log(exp(δ) X) = log X + Jl⁻¹ δ.
    for (int i = 0; i < G::DoF; ++i) {
      TanVec<G> e = TanVec<G>::Zero();
      e(i) = h;
      Jn.col(i) = (X.lplus(Tan<G>(e)).log().coeffs() - X.lplus(Tan<G>(TanVec<G>(-e))).log().coeffs()) /
                  (S(2) * h);
    }
    CHECK(maxAbs(M(l.ljacinv() - Jn)) <= tol);
  }
  // inverse: J_out = −Ad(X).
  X.inverse(&J);
  CHECK(maxAbs(M(J - numericJacobian(X, [](const G& a) { return a.inverse(); }, h))) <= tol);
  // compose: J_out_self = Ad(Y)⁻¹, J_out_b = I.
  M Ja, Jb;
  X.compose(Y, &Ja, &Jb);
  CHECK(maxAbs(M(Ja - numericJacobian(X, [&](const G& a) { return a.compose(Y); }, h))) <= tol);
  CHECK(maxAbs(M(Jb - numericJacobian(Y, [&](const G& b) { return X.compose(b); }, h))) <= tol);
  // act: J_out_self (3×DoF) and J_out_p (3×3).
  const Vec3<S> p = uniformVec<S, 3>(g, -2, 2);
  Eigen::Matrix<S, 3, G::DoF> Jx, Jxn;
  Mat3<S> Jp, Jpn;
  X.act(p, &Jx, &Jp);
  for (int i = 0; i < G::DoF; ++i) {
    TanVec<G> e = TanVec<G>::Zero();
    e(i) = h;
    Jxn.col(i) = (X.rplus(Tan<G>(e)).act(p) - X.rplus(Tan<G>(TanVec<G>(-e))).act(p)) / (S(2) * h);
  }
  for (int i = 0; i < 3; ++i) {
    Vec3<S> e = Vec3<S>::Zero();
    e(i) = h;
    Jpn.col(i) = (X.act(Vec3<S>(p + e)) - X.act(Vec3<S>(p - e))) / (S(2) * h);
  }
  CHECK(maxAbs(Eigen::Matrix<S, 3, G::DoF>(Jx - Jxn)) <= S(4) * tol);
  CHECK(maxAbs(Mat3<S>(Jp - Jpn)) <= tol);
}

/// exp, log, rjac, ljac, rjacinv, ljacinv at one sample against kRefBits mpfr references:
/// exp by the power series of hat(ξ), log by the independent reference of log_accuracy.hpp,
/// Jacobians by Σ (±ad)^k/(k+1)! and their LU inverses. Errors normwise, ≤ `ulps`·ε.
template <class G> void checkAgainstReference(const Sample<G>& smp, int ulps) {
  using S = Scal<G>;
  using GM = typename G::Transformation;
  using GMr = Eigen::Matrix<mpreal, GM::RowsAtCompileTime, GM::ColsAtCompileTime>;
  using M = AdMat<G>;
  using Mr = Eigen::Matrix<mpreal, G::DoF, G::DoF>;
  const S eps = Tolerance<S>::epsilon();
  const Tan<G>& xi = smp.xi;
  INFO("sample " << smp.label << ", theta = " << toString(angleOf<G>(xi), 20));
  const G X = xi.exp();
  const GM E = X.matrix();
  const Tan<G> L = X.log();
  const M Jr = xi.rjac(), Jl = xi.ljac(), Jri = xi.rjacinv(), Jli = xi.ljacinv();
  GMr Eref;
  TanVec<G> dLog;
  M dJr, dJl, dJri, dJli;
  S nJ;
  {
    MpfrBits bits(kRefBits);
    const auto xr = xi.template cast<mpreal>();  // exact: default precision is kRefBits here
    // exp: Σ hat^k/k!, |hat| ≤ π + |v|.
    const GMr H = xr.hat();
    GMr term = GMr::Identity();
    Eref = GMr::Identity();
    const mpreal tiny = pow(mpreal(2), -kRefBits - 8);
    for (int k = 1; k < 4000; ++k) {
      term = (term * H / mpreal(k)).eval();
      Eref += term;
      if (term.cwiseAbs().maxCoeff() < tiny) break;
    }
    // log of the S element (exact input), independent of the library's log.
    Vec3<mpreal> w, v;
    Quat<mpreal> q;
    q.coeffs() = refMat(X.quaternion().coeffs());
    Vec3<mpreal> t = Vec3<mpreal>::Zero();
    if constexpr (kIsSE3<G>) t = refMat(X.translation());
    detail::logacc::referenceLog(q, t, w, v);
    Eigen::Matrix<mpreal, G::DoF, 1> lr;
    if constexpr (kIsSE3<G>) lr << w, v;
    else lr = w;
    dLog = castMatrix<S>(Eigen::Matrix<mpreal, G::DoF, 1>(refMat(L.coeffs()) - lr));
    // Jacobians: series of ±ad at 512 bits.
    const Mr Al = dexpSeries(xr, 200), Ar = dexpSeries(xr, 200, true);
    dJl = castMatrix<S>(Mr(refMat(Jl) - Al));
    dJr = castMatrix<S>(Mr(refMat(Jr) - Ar));
    dJli = castMatrix<S>(Mr(refMat(Jli) - Mr(Al.fullPivLu().inverse())));
    dJri = castMatrix<S>(Mr(refMat(Jri) - Mr(Ar.fullPivLu().inverse())));
    nJ = scalarCast<S>(mpreal(Al.cwiseAbs().maxCoeff()));
  }
  const S tolE = S(ulps) * eps * scaleOf(X);
  CHECK(maxAbs(GM(E - castMatrix<S>(Eref))) <= tolE);
  CHECK(maxAbs(dLog) <= S(ulps) * eps * (S(1) + maxAbs(L.coeffs())));
  const S tolJ = S(ulps) * eps * nJ;
  CHECK(maxAbs(dJl) <= tolJ);
  CHECK(maxAbs(dJr) <= tolJ);
  CHECK(maxAbs(dJli) <= tolJ);
  CHECK(maxAbs(dJri) <= tolJ);
}

}  // namespace soma::test::lie
