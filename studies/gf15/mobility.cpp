// Studies of GF §15.2 (in the asked scalar; the two derived figures in double, soma::render): mobility of single loops — Kutzbach–Grübler, the completion group,
// the subalgebra (totally geodesic) criterion, Table 15.1, the Bennett loop as the paradoxical
// exception, the flat 4-bar, and the self-motions of a singular robot (erratum E15.13 is OCR).
#include "gf15/common.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/render/render.hpp"

#include <Eigen/SVD>

#include <array>

namespace soma::studies::gf15::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using draws::maxOf;  // soma/studies/scalar_draws.hpp

/// A line screw (pitch 0) through r along w, both given in S: w normalised in S.
template <class S> Vec6<S> lineIn(Vec3<S> w, const Vec3<S>& r) {
  using std::sqrt;
  w /= S(sqrt(S(w.squaredNorm())));
  return (Vec6<S>() << w, Vec3<S>(r.cross(w))).finished();
}
template <class S> Vec3<S> v3(const S& x, const S& y, const S& z) { return Vec3<S>(x, y, z); }
template <class S> std::vector<Vec6<S>> planar4R() {
  const Vec3<S> z = Vec3<S>::UnitZ();
  return {lineIn<S>(z, v3<S>(0, 0, 0)), lineIn<S>(z, v3<S>(1, 0, 0)), lineIn<S>(z, v3<S>(1, 2, 0)), lineIn<S>(z, v3<S>(-1, 1, 0))};
}
template <class S> std::vector<Vec6<S>> spherical4R() {  // four axes through the origin
  const Vec3<S> o = Vec3<S>::Zero();
  return {lineIn<S>(v3<S>(1, 0, 0), o), lineIn<S>(v3<S>(0, 1, 0), o), lineIn<S>(v3<S>(0, frac<S>(3, 5), frac<S>(4, 5)), o),
          lineIn<S>(v3<S>(frac<S>(12, 25), frac<S>(3, 5), frac<S>(16, 25)), o)};
}
/// The smallest nonzero singular value of the joint screws at θ (rank decided as traceLoop does).
template <class S> S sigmaMinNonzero(const JointSpaceGeometry<S>& geo, const DgVector<S>& th) {
  const std::vector<S> sv = detail::smallSingularValues<S>(detail::SmallMat<S>(geo.screws(th)));
  S hi = S(0), lo = S(0);
  for (const S& x : sv) hi = std::max<S>(hi, x);
  for (const S& x : sv)
    if (x > S(64) * Tolerance<S>::rank() * hi && (lo == S(0) || x < lo)) lo = x;
  return lo;
}

// traceLoop's corrector stops at |log ρ(θ)| ≤ 1024 ε (mobility_impl.hpp): the residual checks take that
// bound (2.3e-13 in double; 1e-12 before).
template <class S> void definitions(Context& ctx) {
  // the flat 4-bar: links 1, 1, 1 along x and the ground 3 — all joints on the x-axis
  const Vec3<S> z = Vec3<S>::UnitZ();
  const std::vector<Vec6<S>> flat = {lineIn<S>(z, v3<S>(0, 0, 0)), lineIn<S>(z, v3<S>(1, 0, 0)), lineIn<S>(z, v3<S>(2, 0, 0)),
                                     lineIn<S>(z, v3<S>(3, 0, 0))};
  ctx.checkEqual("joint screws (planar: (1, 0, −x_i)) span a 2-system", 2, screwSystemDimension(flat));
  ctx.checkEqual("infinitesimal mobility of the flat 4-bar", 2, infinitesimalMobility(flat));
  // configuration space: crank angle φ at joint 1 (ground from (0,0) to (3,0)); the coupler must join
  // (cos φ, sin φ) to the rocker of length 1 about (3, 0): |P − (3,0)| ≤ 2 is needed. At φ = 0 the distance
  // is 2 exactly; at |φ| ≥ 10⁻³ it is 2 + 3φ²/4 ≥ 2 + 7.5e-7, above 2 + 4 ε in every scalar (float: 9.5e-7
  // would not be; 4 ε = 4.8e-7 is)
  int feasible = 0;
  for (int k = -1000; k <= 1000; ++k) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const S phi = frac<S>(k, 1000);
    const S cx = cos(phi) - S(3), sy = sin(phi);
    const S d = sqrt(S(cx * cx + sy * sy));
    if (d <= S(2) + tol<S>(4)) ++feasible;
  }
  ctx.checkEqual("crank angles in [−1, 1] rad (step 1e-3) at which the loop closes: only φ = 0", 1, feasible);
  const LoopTrace<S> t = traceLoop<S>(flat, frac<S>(1, 20), 5);
  ctx.checkEqual("kernel dimension 2 at the flat configuration (no 1-dim solution curve to trace)", 2, t.kernelDimension);
  ctx.note("Global dimension 0 (a single real point) with infinitesimal mobility 2: infinitesimal mobility is only an upper bound.");
}

template <class S> void kutzbach(Context& ctx) {
  auto g = std::mt19937_64(1521);
  ctx.checkEqual("single loop, n = 7 joints: m = n − 6", 1, kutzbachGrubler(7, 7, 7));
  ctx.checkEqual("single loop, n = 5: m = −1", -1, kutzbachGrubler(5, 5, 5));
  const auto s7 = randomScrewsS<S>(g, 7);
  const LoopTrace<S> t7 = traceLoop<S>(s7, frac<S>(1, 20), 30);
  ctx.checkEqual("random 7R loop: kernel of Σθ̇_is_i = 0 at θ = 0", 1, t7.kernelDimension);
  ctx.checkResidual("the 7R loop traced for 1.5 rad of arc: max |log ρ(θ)| (the corrector's 1024 ε)", t7.maxResidual, tol<S>(1024));
  ctx.checkEqual("and every corrector converged", 1, t7.closed ? 1 : 0);
  const auto s5 = randomScrewsS<S>(g, 5);
  ctx.checkEqual("random 5R loop: kernel dimension 0 (rigid, local mobility 0)", 0, traceLoop<S>(s5, frac<S>(1, 20), 3).kernelDimension);
}

template <class S> void completion(Context& ctx) {
  const auto p = planar4R<S>(), s = spherical4R<S>();
  ctx.checkEqual("planar 4R: dim Δ∞ (se(2))", 3, int(completionAlgebra(p).cols()));
  ctx.checkEqual("planar 4R: m = n − dim Δ∞", 1, completionMobility(p));
  const LoopTrace<S> tp = traceLoop<S>(p, frac<S>(1, 20), 40);
  ctx.checkEqual("planar 4R traced (2 rad of arc) and closed", 1, (tp.kernelDimension == 1 && tp.closed) ? 1 : 0);
  ctx.checkEqual("spherical 4R: dim Δ∞ (so(3))", 3, int(completionAlgebra(s).cols()));
  ctx.checkEqual("spherical 4R: m = n − dim Δ∞", 1, completionMobility(s));
  const LoopTrace<S> ts = traceLoop<S>(s, frac<S>(1, 20), 40);
  ctx.checkEqual("spherical 4R traced and closed", 1, (ts.kernelDimension == 1 && ts.closed) ? 1 : 0);
  const auto b = bennettLoop<S>(S(1), frac<S>(1, 2), frac<S>(11, 10), frac<S>(7, 10));
  ctx.checkEqual("Bennett 4R: dim Δ∞ = 6 (the completion group is SE(3))", 6, int(completionAlgebra(b).cols()));
  ctx.checkEqual("Bennett 4R: n − dim Δ∞", -2, completionMobility(b));
  const LoopTrace<S> tb = traceLoop<S>(b, frac<S>(1, 20), 60);
  ctx.checkEqual("Bennett 4R: kernel dimension at θ = 0", 1, tb.kernelDimension);
  ctx.checkResidual("Bennett 4R traced for 3 rad of arc: max |log ρ(θ)| (mobility 1, the paradoxical exception; the corrector's 1024 ε)",
                    tb.maxResidual, tol<S>(1024));
  ctx.checkEqual("every corrector converged", 1, tb.closed ? 1 : 0);
  // the traced Bennett path obeys Bennett's relation θ₃ = −θ₁, θ₄ = −θ₂ relative to the home pose; a point
  // with |log ρ| ≤ 1024 ε lies within 1024 ε/σ of the curve (σ the smallest nonzero singular value of the
  // joint screws along the path), and the relations are sums of two angles: bound 2 · 1024 ε / min σ
  const JointSpaceGeometry<S> geo(b);
  S rel = 0, sig = S(0);
  bool first = true;
  for (const DgVector<S>& th : tb.path) {
    rel = maxOf(rel, maxOf(S(abs(S(th(2) + th(0)))), S(abs(S(th(3) + th(1))))));
    const S sg = sigmaMinNonzero(geo, th);
    sig = first || sg < sig ? sg : sig;
    first = false;
  }
  ctx.checkResidual("along the trace θ₃ = −θ₁ and θ₄ = −θ₂ (Bennett's joint relations; 2 · 1024 ε / min σ)", rel, S(tol<S>(2048) / sig));
  auto bent = b;
  bent[3](2) += frac<S>(1, 20);
  bent[3].template head<3>().normalize();
  // the rank decision at θ = 0 takes σ_min/σ_max > 64·1024 ε (traceLoop's threshold, 7.8e-3 in float)
  {
    ScrewMatrix<S> Jb(6, 4);
    for (int i = 0; i < 4; ++i) Jb.col(i) = bent[std::size_t(i)];
    const std::vector<S> sv = detail::smallSingularValues<S>(detail::SmallMat<S>(Jb));
    S lo = sv[0], hi = sv[0];
    for (const S& x : sv) {
      lo = std::min<S>(lo, x);
      hi = std::max<S>(hi, x);
    }
    const S ratio = lo / hi, threshold = S(64) * Tolerance<S>::rank();
    if (ratio > threshold)
      ctx.checkEqual("one twist perturbed by 0.05: rigid (kernel 0), as Kutzbach says", 0,
                     traceLoop<S>(bent, frac<S>(1, 20), 3).kernelDimension);
    else
      ctx.note("Perturbed Bennett (one twist moved by 0.05): σ_min/σ_max = " + toString(toDouble(ratio), 3) +
               " is below the rank threshold 64·1024 ε = " + toString(toDouble(threshold), 3) +
               " of this scalar, which cannot tell the rigid loop from a mobile one: check skipped.");
  }
  using std::sin;
  ctx.note("Bennett a = 1, α = 0.5, β = 1.1 (b = a sin β / sin α = " + toString(toDouble(S(sin(frac<S>(11, 10)) / sin(frac<S>(1, 2)))), 4) +
           "), closed at θ₁ = 0.7 by tan(θ₁/2)tan(θ₂/2) = sin((β+α)/2)/sin((β−α)/2); min σ along the trace " + toString(toDouble(sig), 3) + ".");
}

/// An orthonormal basis of the span of the columns of M, all of them (M has full column rank: three
/// independent joints). No rank decision: at one of the draws σ₃/σ₁ = 3.1e-3 (the parallel axes nearly in
/// one plane), below float's rank threshold 64·1024 ε = 7.8e-3, and a rank-2 basis would put ∇_UV 0.11 off it.
template <class S> DgMatrix<S> spanOf(const DgMatrix<S>& M) {
  detail::SmallMat<S> u, v;
  std::vector<S> sig;
  detail::smallSvd<S>(detail::SmallMat<S>(M), u, sig, v);
  return DgMatrix<S>(u.leftCols(M.cols()));
}

template <class S> void totallyGeodesic(Context& ctx) {
  using V6S = Vec6<S>;
  auto g = std::mt19937_64(1523);
  // Δ₁ a subalgebra (se(2): three parallel revolutes): ρ's image is the subgroup; ∇_UV stays in Δ₁
  const Vec3<S> z = Vec3<S>::UnitZ();
  const std::vector<V6S> se2 = {lineIn<S>(z, v3<S>(0, 0, 0)), lineIn<S>(z, v3<S>(1, frac<S>(1, 2), 0)), lineIn<S>(z, v3<S>(frac<S>(-3, 10), 1, 0))};
  const std::vector<V6S> skew = {lineIn<S>(v3<S>(1, 0, 0), v3<S>(0, 0, 0)), lineIn<S>(v3<S>(0, 1, 0), v3<S>(0, 0, 1)),
                                 lineIn<S>(v3<S>(0, 0, 1), v3<S>(1, 0, 0))};
  auto outOfSpan = [&](const std::vector<V6S>& s) {
    const JointSpaceGeometry<S> geo(s);
    S worst = 0, logWorst = 0;
    DgMatrix<S> M(6, 3);
    for (int i = 0; i < 3; ++i) M.col(i) = s[std::size_t(i)];
    const DgMatrix<S> span0 = spanOf<S>(M);
    for (int t = 0; t < 10; ++t) {
      const DgVector<S> th = rvecS<S>(g, 3), td = rvecS<S>(g, 3), pd = rvecS<S>(g, 3), pdd = rvecS<S>(g, 3);
      const V6S nab = geo.covariantDerivative(th, td, pd, pdd);
      const DgMatrix<S> U = spanOf<S>(DgMatrix<S>(geo.screws(th)));
      worst = maxOf(worst, S((nab - U * (U.transpose() * nab)).norm()));
      const V6S l = geo.forward(th).log().coeffs();
      logWorst = maxOf(logWorst, S((l - span0 * (span0.transpose() * l)).norm()));
    }
    return std::pair<S, S>(worst, logWorst);
  };
  // a projection off an orthonormal basis of O(1) screws (and the log of a product of three exponentials):
  // 64 ε (1.4e-14 in double; 1e-13 before)
  const auto [n1, l1] = outOfSpan(se2);
  ctx.checkEqual("three parallel revolutes: Δ₁ is a subalgebra", 1, isSubalgebra(se2) ? 1 : 0);
  ctx.checkResidual("∇_UV is tangent to the image (distance from the tangent space, 10 random U, V; 64 ε)", n1, tol<S>(64));
  ctx.checkResidual("log ρ(θ) ∈ Δ₁ (BCH: the image is the subgroup; 64 ε)", l1, tol<S>(64));
  const auto [n2, l2] = outOfSpan(skew);
  (void)l2;
  ctx.checkEqual("three mutually skew revolutes: not a subalgebra", 0, isSubalgebra(skew) ? 1 : 0);
  ctx.checkPrintedFails("control: ∇_UV tangent for a non-subalgebra", "— control", n2, tol<S>(64));
  // the proof's ∇_UV at line 9674 equals the §15.1 formula (relabelled); E15.13 (θ̇^1 for θ̇_1) is OCR
  const JointSpaceGeometry<S> geo(randomScrewsS<S>(g, 4));
  const DgVector<S> th = rvecS<S>(g, 4), td = rvecS<S>(g, 4), pd = rvecS<S>(g, 4), pdd = rvecS<S>(g, 4);
  const ScrewMatrix<S> J = geo.screws(th);
  V6S line9674 = J * pdd;
  for (int i = 0; i < 4; ++i)
    for (int k = i + 1; k < 4; ++k)
      line9674 += (td(i) * pd(k) + td(k) * pd(i)) / S(2) * brS<S>(V6S(J.col(i)), V6S(J.col(k)));
  // the same sum in another order: 64 ε (1.4e-14 in double; 1e-14 before)
  ctx.checkResidual("line 9674, ½Σ_{i<k}(θ̇_iφ̇_k + θ̇_kφ̇_i)[s_i, s_k], equals the §15.1 ∇_UV (relabelled k < i sum; 64 ε)",
                    mx<S>(V6S(line9674 - geo.covariantDerivative(th, td, pd, pdd))), tol<S>(64));
  ctx.note("E15.13 (θ̇^1 for θ̇_1 at line 9674) is an OCR superscript with no numerical content: the formula with θ̇_1 is "
           "the one checked here. The necessity argument holds: the coefficients of [s_i, s_k] are arbitrary, so [s_i, s_k] ∈ Δ₁.");
}

template <class S> void table(Context& ctx) {
  const auto rows = table15_1<S>(frac<S>(3, 2));
  ctx.checkEqual("rows of Table 15.1", 10, int(rows.size()));
  int closed = 0;
  std::string list;
  for (const auto& r : rows) {
    const bool ok = isSubalgebra(r.basis) && int(completionAlgebra(r.basis).cols()) == int(r.basis.size());
    closed += ok ? 1 : 0;
    list += r.group + " (" + r.huntType + ", dim " + std::to_string(r.basis.size()) + "); ";
  }
  ctx.checkEqual("rows closed under the bracket with Δ = Δ∞ (p = 3/2)", 10, closed);
  S worst = 0;
  for (const auto& r : rows) worst = maxOf(worst, subalgebraDefect(r.basis));
  // unit basis screws with entries 0, 1, p: brackets and projections off them, 4 ε (8.9e-16 in double; 1e-15 before)
  ctx.checkResidual("max distance of a bracket [s_i, s_k] from Δ over all rows (4 ε)", worst, tol<S>(4));
  ctx.note(list);
  // the subalgebra of a row, placed anywhere (random rigid motion), remains closed: Ad is an automorphism
  auto g = std::mt19937_64(1525);
  int moved = 0;
  for (const auto& r : rows) {
    const Mat6<S> A = SE3<S>::Random(g).adjoint();  // double draws, the rotation normalised in S (a cast double
    // rotation is orthogonal only to 1e-16, and the conjugated rows then miss isSubalgebra's 1024 ε in wider scalars)
    std::vector<Vec6<S>> b;
    for (const auto& s : r.basis) b.push_back(A * s);
    moved += isSubalgebra(b) ? 1 : 0;
  }
  ctx.checkEqual("the ten rows conjugated by a random rigid motion stay subalgebras", 10, moved);
}

template <class S> void singularRobot(Context& ctx) {
  // a 6R with a spherical wrist: s₄, s₅, s₆ through the wrist centre w; at θ₅ = 0 the axes 4 and 6 coincide
  const Vec3<S> w(frac<S>(3, 5), frac<S>(1, 10), frac<S>(4, 5));
  const std::vector<Vec6<S>> s = {lineIn<S>(v3<S>(0, 0, 1), v3<S>(0, 0, 0)), lineIn<S>(v3<S>(0, 1, 0), v3<S>(0, 0, frac<S>(1, 2))),
                                  lineIn<S>(v3<S>(0, 1, 0), v3<S>(frac<S>(1, 2), 0, frac<S>(7, 10))), lineIn<S>(v3<S>(1, 0, 0), w),
                                  lineIn<S>(v3<S>(0, 1, 0), w), lineIn<S>(v3<S>(1, 0, 0), w)};
  ctx.checkEqual("wrist singular (s₄ = s₆): kernel dimension of J with the end effector held", 1, infinitesimalMobility(s));
  const JointSpaceGeometry<S> geo(s);
  // the self-motion θ₄ = t, θ₆ = −t keeps the end effector exactly still: a finite (mobility-1) motion
  S worst = 0;
  for (int k = -10; k <= 10; ++k) {
    DgVector<S> th = DgVector<S>::Zero(6);
    th(3) = frac<S>(k, 10);
    th(5) = -th(3);
    worst = maxOf(worst, mx<S>(Mat4<S>(geo.forward(th).matrix() - Mat4<S>::Identity())));
  }
  // two exponentials about the same line and their product with |w| ≈ 1: 8 ε (1.8e-15 in double; 1e-15 before)
  ctx.checkResidual("self-motion θ₄ = −θ₆ ∈ [−1, 1]: max |ρ(θ) − I| (8 ε)", worst, tol<S>(8));
  // a doubly singular pose: also s₁ through w parallel to s₄ ... here: s₂ moved onto s₅'s line as well
  auto s2 = s;
  s2[1] = s[4];
  ctx.checkEqual("with s₂ = s₅ too: kernel dimension 2 (harder for a controller)", 2, infinitesimalMobility(s2));
}

// ---- derived figures (catalogue ch. 15 "Figures worth reproducing" (b), (c)) ----------------------

/// One pose of the Bennett 4R: DH frames F₀ = I, F_{i+1} = F_i Rz(θ_i) Tx(a_i) Rx(α_i) (F₄ = I when closed).
struct BennettPose {
  std::array<double, 4> th{};
  std::array<SE3<double>, 5> F;
};
SE3<double> dhLink(double th, double a, double al) {
  return SE3<double>(SO3<double>::fromAxisAngle(V3::UnitZ(), th), V3::Zero())
      .compose(SE3<double>(SO3<double>::fromAxisAngle(V3::UnitX(), al), V3(a, 0, 0)));
}
BennettPose chainPose(const std::array<double, 4>& th, const std::array<double, 4>& len, const std::array<double, 4>& tw) {
  BennettPose p;
  p.th = th;
  p.F[0] = SE3<double>::Identity();
  for (int i = 0; i < 4; ++i) p.F[std::size_t(i + 1)] = p.F[std::size_t(i)].compose(dhLink(th[std::size_t(i)], len[std::size_t(i)], tw[std::size_t(i)]));
  return p;
}
/// Bennett's joint relation: tan(θ₁/2) tan(θ₂/2) = sin((β+α)/2)/sin((β−α)/2), θ₃ = −θ₁, θ₄ = −θ₂ (Bennett 1903).
std::array<double, 4> bennettAngles(double al, double be, double th1) {
  const double K = std::sin((be + al) / 2) / std::sin((be - al) / 2);
  const double th2 = 2 * std::atan(K / std::tan(th1 / 2));
  return {th1, th2, -th1, -th2};
}
double closureError(const BennettPose& p) { return (p.F[4].matrix() - Mat4<double>::Identity()).cwiseAbs().maxCoeff(); }
std::vector<V6> poseScrews(const BennettPose& p) {
  std::vector<V6> s;
  for (int i = 0; i < 4; ++i) s.push_back(lineScrew(p.F[std::size_t(i)].rotation().col(2), p.F[std::size_t(i)].translation()));
  return s;
}
/// Common normal of the lines (p, u) and (q, v): length, twist angle and the foot on each line.
struct CommonNormal {
  double length, twist;
  V3 footOnFirst, footOnSecond;
};
CommonNormal commonNormal(const V3& p, const V3& u, const V3& q, const V3& v) {
  const V3 n = u.cross(v);
  const double uv = u.dot(v), den = n.squaredNorm();  // > 0: consecutive Bennett axes are never parallel
  const V3 d = q - p;
  const double s = (d.dot(u) - uv * d.dot(v)) / den, t = (uv * d.dot(u) - d.dot(v)) / den;
  const V3 f1 = p + s * u, f2 = q + t * v;
  return {(f2 - f1).norm(), std::atan2(n.norm(), uv), f1, f2};
}
/// Smallest |log F₄(θ)| reachable from θ₀ by Levenberg–Marquardt on the open chain (forward-difference Jacobian).
std::pair<double, std::array<double, 4>> closestClosure(const std::array<double, 4>& th0, const std::array<double, 4>& len,
                                                       const std::array<double, 4>& tw) {
  auto res = [&](const Eigen::Vector4d& t) {
    return V6(chainPose({t(0), t(1), t(2), t(3)}, len, tw).F[4].log().coeffs());
  };
  Eigen::Vector4d t(th0[0], th0[1], th0[2], th0[3]);
  double lambda = 1e-3;
  V6 r = res(t);
  for (int it = 0; it < 200; ++it) {
    Eigen::Matrix<double, 6, 4> J;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector4d h = t;
      h(k) += 1e-7;
      J.col(k) = (res(h) - r) / 1e-7;
    }
    const Eigen::Matrix4d A = J.transpose() * J + lambda * Eigen::Matrix4d::Identity();
    const Eigen::Vector4d step = -A.ldlt().solve(J.transpose() * r);
    const V6 r2 = res(t + step);
    if (r2.squaredNorm() < r.squaredNorm()) {
      t += step;
      r = r2;
      lambda = std::max(lambda / 10, 1e-12);
    } else {
      lambda *= 10;
    }
  }
  return {r.lpNorm<Eigen::Infinity>(), {t(0), t(1), t(2), t(3)}};
}
/// The second-order obstruction of a loop at θ = 0 (BCH): a kernel velocity θ̇ extends to a curve only if
/// Q(θ̇) = Σ_{i<k} θ̇_iθ̇_k[s_i, s_k] lies in Span(s_i). B is Q's polarisation projected off the span.
V6 obstruction(const std::vector<V6>& s, const DV& x, const DV& y) {
  V6 q = V6::Zero();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t k = i + 1; k < s.size(); ++k)
      q += 0.5 * (x(Eigen::Index(i)) * y(Eigen::Index(k)) + y(Eigen::Index(i)) * x(Eigen::Index(k))) * br(s[i], s[k]);
  DM M(6, Eigen::Index(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i) M.col(Eigen::Index(i)) = s[i];
  Eigen::JacobiSVD<DM> svd(M, Eigen::ComputeThinU);
  const int r = screwSystemDimension(s);
  const DM U = svd.matrixU().leftCols(r);
  return q - U * (U.transpose() * q);
}
/// The 2×2 form n·B(k_a, k_b) on a 2-dim kernel {u, w} when B's values are parallel (to n); its determinant
/// decides: > 0 definite (no real curve through the point), < 0 two real branches.
double obstructionDeterminant(const std::vector<V6>& s, const DV& u, const DV& w, double& offLine) {
  const V6 uu = obstruction(s, u, u), uw = obstruction(s, u, w), ww = obstruction(s, w, w);
  V6 n = uu.norm() >= ww.norm() ? uu : ww;
  if (uw.norm() > n.norm()) n = uw;
  n.normalize();
  offLine = std::max({(uu - uu.dot(n) * n).norm(), (uw - uw.dot(n) * n).norm(), (ww - ww.dot(n) * n).norm()});
  return uu.dot(n) * ww.dot(n) - uw.dot(n) * uw.dot(n);
}

namespace rd = soma::render;
constexpr const char* kWhyDoubleFigure = "a figure: soma::render draws double geometry";
void addLabel(rd::Scene& s, const V3& at, const std::string& text, Eigen::Vector2d off = {8, -8}, double px = 24,
              rd::Color col = rd::palette::black, rd::HAlign h = rd::HAlign::Left) {
  rd::Label l;
  l.at = at;
  l.text = text;
  l.offset = off;
  l.pixelHeight = px;
  l.c = col;
  l.hAlign = h;
  s.add(l);
}
void addTube(rd::Scene& s, std::vector<V3> p, double r, rd::Color c) {
  rd::Tube t;
  t.p = std::move(p);
  t.radius = r;
  t.c = c;
  s.add(t);
}
/// A revolute joint: a short cylinder of the given half-length about the axis (p, u).
void addJoint(rd::Scene& s, const V3& p, const V3& u, double halfLength, double r, rd::Color c) {
  addTube(s, {V3(p - halfLength * u), V3(p + halfLength * u)}, r, c);
}
void renderFigure(Context& ctx, const rd::Scene& sc, const V3& view, int w, int h, const std::string& file, const std::string& caption,
                  bool ortho = false, const V3& up = V3::UnitZ()) {
  rd::FitOptions fo;
  fo.width = w;
  fo.height = h;
  fo.orthographic = ortho;
  fo.up = up;
  rd::renderPng(sc, view, fo, ctx.figurePath(file));
  ctx.figure(file, caption);
}

// GF §15.2 lines 9647, 9682: GF-15.2-mobility-definitions (flat 4-bar), GF-15.2-completion-group-mobility (Bennett)
void bennettFigure(Context& ctx) {
  const double a = 1, al = 0.6, be = 1.3, b = a * std::sin(be) / std::sin(al);
  const std::array<double, 4> len{a, b, a, b}, tw{al, be, al, be};
  const std::vector<double> th1s = {0.5, 0.9, 1.4, 2.0, 2.6};
  std::vector<BennettPose> poses;
  double closeWorst = 0, bennettWorst = 0, offsetWorst = 0, libWorst = 0;
  int rank3 = 0, mob1 = 0;
  for (double t1 : th1s) {
    poses.push_back(chainPose(bennettAngles(al, be, t1), len, tw));
    const BennettPose& p = poses.back();
    closeWorst = std::max(closeWorst, closureError(p));
    // the link lengths and twists measured from the drawn axes (common normals of consecutive axes)
    std::array<CommonNormal, 4> cn;
    for (int i = 0; i < 4; ++i) {
      const SE3<double>& A = p.F[std::size_t(i)];
      const SE3<double>& B = p.F[std::size_t((i + 1) % 4)];
      cn[std::size_t(i)] = commonNormal(A.translation(), A.rotation().col(2), B.translation(), B.rotation().col(2));
    }
    bennettWorst = std::max({bennettWorst, abs(cn[0].length - cn[2].length), abs(cn[1].length - cn[3].length),
                             abs(cn[0].twist - cn[2].twist), abs(cn[1].twist - cn[3].twist),
                             abs(cn[0].length * std::sin(cn[1].twist) - cn[1].length * std::sin(cn[0].twist))});
    for (int i = 0; i < 4; ++i)  // offset d_i: the two normals meet axis i at the same point
      offsetWorst = std::max(offsetWorst, (cn[std::size_t(i)].footOnFirst - cn[std::size_t((i + 3) % 4)].footOnSecond).norm());
    const auto s = poseScrews(p);
    rank3 += screwSystemDimension(s) == 3 ? 1 : 0;
    mob1 += infinitesimalMobility(s) == 1 ? 1 : 0;
    const auto lib = bennettLoop<double>(a, al, be, t1);
    for (int i = 0; i < 4; ++i) libWorst = std::max(libWorst, (lib[std::size_t(i)] - s[std::size_t(i)]).cwiseAbs().maxCoeff());
  }
  const int nPose = int(th1s.size());
  ctx.checkResidual("Bennett a = 1, α = 0.6, β = 1.3, five drawn poses θ₁ = 0.5 … 2.6: max |F₄ − I| (loop closes)", closeWorst, 1e-14);
  ctx.checkResidual("measured from the drawn axes: a₁ = a₃, a₂ = a₄, α₁ = α₃, α₂ = α₄, a₁ sin α₂ = a₂ sin α₁ (max deviation)",
                    bennettWorst, 1e-13);
  ctx.checkResidual("offsets d_i = 0: the common normals to axes i−1 and i+1 meet axis i at one point (max gap)", offsetWorst, 1e-13);
  ctx.checkResidual("the drawn joint screws equal bennettLoop()'s (library construction)", libWorst, 1e-14);
  ctx.checkEqual("poses at which the four joint screws span a 3-system", nPose, rank3);
  ctx.checkEqual("poses with loop mobility (kernel of Σθ̇_is_i = 0) = 1 — Kutzbach predicts 4 − 6 = −2", nPose, mob1);
  // controls: the Bennett condition broken. (i) a₂ 5 % long, a₄ = b: no closure near the drawn pose
  const std::array<double, 4> lenOne{a, 1.05 * b, a, b}, lenBoth{a, 1.05 * b, a, 1.05 * b};
  const auto sBad = poseScrews(chainPose(bennettAngles(al, be, 1.4), lenOne, tw));
  ctx.checkEqual("control, a₂ = 1.05 b: the four axes at the drawn angles span a 4-system", 4, screwSystemDimension(sBad));
  const double lmGood = closestClosure({1.45, poses[2].th[1] + 0.05, -1.35, -poses[2].th[1] - 0.04}, len, tw).first;
  const double lmOne = closestClosure(poses[2].th, lenOne, tw).first;
  ctx.checkResidual("positive control: Levenberg–Marquardt from a perturbed θ closes the Bennett loop, min |log F₄|", lmGood, 1e-12);
  ctx.record("control, a₂ = 1.05 b (a₄ = b): min |log F₄| reached by Levenberg–Marquardt from the pose (cannot close)", "> 1e-3",
             toString(lmOne, 4), lmOne, 1e-3, lmOne > 1e-3);
  // (ii) a₂ = a₄ = 1.05 b (opposite sides still equal, a/sin α ≠ b/sin β): closes, but only at an isolated pose
  const auto [lmBoth, thBoth] = closestClosure(poses[2].th, lenBoth, tw);
  ctx.checkResidual("control, a₂ = a₄ = 1.05 b: Levenberg–Marquardt finds a closed pose, |log F₄|", lmBoth, 1e-12);
  ctx.checkEqual("… at which the joint screws span a 4-system: loop mobility 0 (rigid, as Kutzbach says)", 0,
                 infinitesimalMobility(poseScrews(chainPose(thBoth, lenBoth, tw))));
  // the flat 4-bar: joints on the x-axis at 0, 1, 2, 3 (links 1, 1, 1, ground 3)
  const V3 z = V3::UnitZ();
  const std::vector<double> xs = {0, 1, 2, 3};
  std::vector<V6> flat;
  for (double x : xs) flat.push_back(lineScrew(z, V3(x, 0, 0)));
  ctx.checkEqual("flat 4-bar: rank of the joint screws", 2, screwSystemDimension(flat));
  ctx.checkEqual("flat 4-bar: infinitesimal mobility 4 − 2", 2, infinitesimalMobility(flat));
  DV u(4), w(4);
  u << 1, -2, 1, 0;  // J₃ held (θ̇₄ = 0): J₂ moves
  w << 0, 1, -2, 1;  // J₂ held (θ̇₁ = 0): J₃ moves
  SM Jf(6, 4);
  for (int i = 0; i < 4; ++i) Jf.col(i) = flat[std::size_t(i)];
  ctx.checkResidual("the drawn infinitesimal motions (1, −2, 1, 0), (0, 1, −2, 1) are in the kernel: max |Σθ̇_is_i|",
                    std::max(maxAbs(DV(Jf * u)), maxAbs(DV(Jf * w))), 1e-15);
  double offLine = 0;
  const double detFlat = obstructionDeterminant(flat, u, w, offLine);
  ctx.checkNear("second-order obstruction Q(θ̇) = Σ_{i<k}θ̇_iθ̇_k[s_i, s_k] off the span, on the kernel: det (definite ⇒ isolated point, "
                "mobility 0)", 3.0, detFlat, 1e-13);
  ctx.checkResidual("(its values all lie on one line: the x-translations)", offLine, 1e-14);
  // control: the folded rhombus (links 1, 1, 1, 1; joints at 0, 1, 0, 1) has the same kernel dimension but moves
  std::vector<V6> rhombus;
  for (double x : {0.0, 1.0, 0.0, 1.0}) rhombus.push_back(lineScrew(z, V3(x, 0, 0)));
  DV ur(4), wr(4);
  ur << 1, 0, -1, 0;
  wr << 0, 1, 0, -1;
  double offR = 0;
  const double detR = obstructionDeterminant(rhombus, ur, wr, offR);
  ctx.checkEqual("control, folded rhombus 1, 1, 1, 1: infinitesimal mobility", 2, infinitesimalMobility(rhombus));
  ctx.checkNear("control, folded rhombus: det of the obstruction form (indefinite ⇒ two real branches cross)", -1.0, detR, 1e-13);
  // the configuration space picture: the crank circle |J₂| = 1 touches the reach |J₂ − J₄| ≤ 2 of rocker + coupler only at J₂ = (1, 0)
  ctx.note("Bennett linkage a = 1, α = 0.6, β = 1.3, b = a sin β / sin α = " + toString(b, 6) +
           "; control min |log F₄| with a₂ = 1.05 b: " + toString(lmOne, 4) + "; closed pose with a₂ = a₄ = 1.05 b at θ = (" +
           toString(thBoth[0], 4) + ", " + toString(thBoth[1], 4) + ", " + toString(thBoth[2], 4) + ", " + toString(thBoth[3], 4) + ").");
  if (!ctx.makeFigures()) return;

  // ---- Bennett figure ----
  {
    rd::Scene sc;
    sc.title = "Bennett's 4R loop (GF §15.2): overconstrained, yet it moves";
    const rd::Color ground = rd::palette::darkGrey;
    const double jr = 0.055, jh = 0.22, lr = 0.03;
    // the fixed link 4 (J₄ → J₁) and the fixed axes 1 and 4
    const V3 p1 = poses[0].F[0].translation(), u1 = poses[0].F[0].rotation().col(2);
    const V3 p4 = poses[0].F[3].translation(), u4 = poses[0].F[3].rotation().col(2);
    addTube(sc, {p4, p1}, 1.4 * lr, ground);
    addJoint(sc, p1, u1, jh, jr, ground);
    addJoint(sc, p4, u4, jh, jr, ground);
    for (const auto& [p, uu] : {std::pair(p1, u1), std::pair(p4, u4)}) {
      rd::Polyline ax;
      ax.p = {V3(p - 0.9 * uu), V3(p + 0.9 * uu)};
      ax.c = rd::palette::grey;
      ax.dashed = true;
      sc.add(ax);
    }
    // the paths of J₂ (circle about axis 1) and J₃ (circle about axis 4) over the whole motion
    rd::Polyline c2, c3;
    for (int k = 1; k < 200; ++k) {
      const BennettPose q = chainPose(bennettAngles(al, be, pi<double>() * k / 200), len, tw);
      c2.p.push_back(q.F[1].translation());
      c3.p.push_back(q.F[2].translation());
    }
    c2.c = c3.c = rd::palette::grey;
    c2.width = c3.width = 1.5;
    sc.add(c2);
    sc.add(c3);
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const rd::Color col = rd::colorMap(0.85 * double(k) / double(poses.size() - 1));
      const BennettPose& p = poses[k];
      const V3 j2 = p.F[1].translation(), j3 = p.F[2].translation();
      addTube(sc, {p1, j2}, lr, col);
      addTube(sc, {j2, j3}, lr, col);
      addTube(sc, {j3, p4}, lr, col);
      addJoint(sc, j2, p.F[1].rotation().col(2), jh, jr, col);
      addJoint(sc, j3, p.F[2].rotation().col(2), jh, jr, col);
      addLabel(sc, j2, "θ₁ = " + toString(th1s[k], 2), {10, -6}, 20, col.darker(0.2f));
    }
    addLabel(sc, V3(p1 + 0.9 * u1), "fixed axis 1", {8, 0}, 22, ground);
    addLabel(sc, V3(p4 + 0.9 * u4), "fixed axis 4", {8, 0}, 22, ground);
    renderFigure(ctx, sc, V3(-0.3, -0.8, -0.9), 1200, 950, "gf15_bennett.png",
                 "Bennett's 4R loop, a = 1, α = 0.6, β = 1.3, b = a sin β/sin α = " + toString(b, 4) +
                     ", offsets 0, at five positions θ₁ = 0.5 … 2.6 (dark to light; θ₂ from tan(θ₁/2)tan(θ₂/2) = "
                     "sin((β+α)/2)/sin((β−α)/2), θ₃ = −θ₁, θ₄ = −θ₂). Link 4 and axes 1, 4 are fixed (grey); the moving joints 2 and 3 "
                     "travel on circles about axes 1 and 4 (thin grey). At each pose F₄ = I to " + toString(closeWorst, 2) +
                     " and the four joint screws span a 3-system: mobility 1 where Kutzbach–Grübler gives −2.");
  }
  // ---- flat 4-bar figure (top view) ----
  {
    rd::Scene sc;
    sc.title = "The flat 4-bar: one configuration, infinitesimal mobility 2";
    const rd::Color lc = rd::palette::blue;
    std::vector<V3> J;
    for (double x : xs) J.push_back(V3(x, 0, 0));
    // the crank circle of J₂ about J₁ and the boundary of the reach of J₂ through rocker and coupler (|J₂ − J₄| ≤ 2)
    rd::Polyline crank, reach;
    for (int k = 0; k <= 240; ++k) {
      const double t = 2 * pi<double>() * k / 240;
      crank.p.push_back(V3(std::cos(t), std::sin(t), -0.02));
      reach.p.push_back(V3(3 + 2 * std::cos(t), 2 * std::sin(t), -0.02));
    }
    crank.c = rd::palette::bluishGreen;
    reach.c = rd::palette::orange;
    crank.width = reach.width = 2.5;
    reach.dashed = true;
    sc.add(crank);
    sc.add(reach);
    addTube(sc, {J[0], J[3]}, 0.03, rd::palette::darkGrey);  // ground, drawn below the links
    for (int i = 0; i < 3; ++i) addTube(sc, {V3(J[std::size_t(i)] + V3(0, 0, 0.08)), V3(J[std::size_t(i + 1)] + V3(0, 0, 0.08))}, 0.035, lc);
    for (int i = 0; i < 4; ++i) {
      addJoint(sc, V3(J[std::size_t(i)] + V3(0, 0, 0.04)), z, 0.08, 0.075, i == 0 || i == 3 ? rd::palette::darkGrey : lc);
      addLabel(sc, J[std::size_t(i)], "J" + std::string(i == 0 ? "₁" : i == 1 ? "₂" : i == 2 ? "₃" : "₄"), {0, 18}, 24,
               rd::palette::black, rd::HAlign::Center);
      sc.labels.back().vAlign = rd::VAlign::Top;
    }
    // the two independent infinitesimal motions: velocities of J₂ and J₃ from the kernel vectors u, w
    auto vel = [&](const DV& td, int joint) {  // twist of the link ending at J_{joint+1} (links from the ground through J₁)
      V6 t = V6::Zero();
      for (int i = 0; i < joint; ++i) t += td(i) * flat[std::size_t(i)];
      const V3 p = J[std::size_t(joint)];
      return V3(t.tail<3>() + t.head<3>().cross(p));
    };
    const double sc8 = 0.45;
    sc.add(rd::Arrow{V3(J[1] + V3(0, 0, 0.1)), V3(J[1] + V3(0, 0, 0.1) + sc8 * vel(u, 1)), rd::palette::vermillion, 0.025});
    sc.add(rd::Arrow{V3(J[2] + V3(0, 0, 0.1)), V3(J[2] + V3(0, 0, 0.1) + sc8 * vel(w, 2)), rd::palette::reddishPurple, 0.025});
    addLabel(sc, V3(J[1] + sc8 * vel(u, 1)), "δθ = (1, −2, 1, 0): J₂ moves", {-8, -4}, 22, rd::palette::vermillion, rd::HAlign::Right);
    addLabel(sc, V3(J[2] + sc8 * vel(w, 2)), "δθ = (0, 1, −2, 1): J₃ moves", {8, -4}, 22, rd::palette::reddishPurple);
    addLabel(sc, V3(0, -1, 0), "crank circle |J₂ − J₁| = 1", {0, 8}, 22, rd::palette::bluishGreen, rd::HAlign::Center);
    sc.labels.back().vAlign = rd::VAlign::Top;
    addLabel(sc, V3(3.3, -1.2, 0), "J₂ reachable via J₃: |J₂ − J₄| ≤ 2", {0, 0}, 22, rd::palette::orange, rd::HAlign::Center);
    renderFigure(ctx, sc, V3(0, 0, -1), 1200, 800, "gf15_flat_4bar.png",
                 "The flat 4-bar (links 1, 1, 1 on the ground 3, all joints on one line), seen from above. The crank circle of J₂ "
                 "(green) touches the region J₂ can reach through rocker and coupler (inside the dashed circle) only at J₂ = (1, 0): "
                 "the configuration space is one point, mobility 0. The joint screws span only a 2-system, so Σθ̇_is_i = 0 has a "
                 "2-dimensional kernel: J₂ and J₃ can start to move independently (arrows), infinitesimal mobility 2. The "
                 "second-order term Σθ̇_iθ̇_k[s_i, s_k] is definite on that kernel (det 3), so no real motion follows.",
                 true, V3::UnitY());
  }
}

/// A joint of a Table 15.1 joint set: revolute, prismatic or helical about the line (point, dir).
struct DrawnJoint {
  char kind;  // 'R', 'P', 'H'
  V3 dir, at;
  V6 screw(double p) const {
    if (kind == 'P') {
      V6 s;
      s << V3::Zero(), dir;
      return s;
    }
    return lineScrew(dir, at, kind == 'H' ? p : 0.0);
  }
};
/// A closed box (12 triangles) centred at c with half-extents h along the orthonormal axes e0, e1, e2.
rd::Mesh box(const V3& c, const V3& e0, const V3& e1, const V3& e2, const V3& h, rd::Color col) {
  rd::Mesh m;
  for (int k = 0; k < 8; ++k)
    m.v.push_back(V3(c + ((k & 1) ? h(0) : -h(0)) * e0 + ((k & 2) ? h(1) : -h(1)) * e1 + ((k & 4) ? h(2) : -h(2)) * e2));
  const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : f) {
    m.tri.emplace_back(q[0], q[1], q[2]);
    m.tri.emplace_back(q[0], q[2], q[3]);
  }
  m.c = col;
  return m;
}
void drawJoint(rd::Scene& sc, const DrawnJoint& j, const V3& centre, double p) {
  const V3 a = centre + j.at, u = j.dir.normalized();
  const V3 e1 = (abs(u.z()) < 0.9 ? u.cross(V3::UnitZ()) : u.cross(V3::UnitX())).normalized(), e2 = u.cross(e1);
  rd::Polyline ax;
  ax.p = {V3(a - 0.75 * u), V3(a + 0.75 * u)};
  ax.c = rd::palette::grey;
  ax.dashed = true;
  ax.dashLength = 6;
  ax.width = 1.5;
  if (j.kind == 'R') {
    sc.add(ax);
    addJoint(sc, a, u, 0.3, 0.1, rd::palette::blue);
  } else if (j.kind == 'P') {
    addTube(sc, {V3(a - 0.6 * u), V3(a + 0.6 * u)}, 0.025, rd::palette::darkGrey);
    sc.add(box(a, u, e1, e2, V3(0.17, 0.1, 0.1), rd::palette::vermillion));
  } else {
    sc.add(ax);
    addTube(sc, {V3(a - 0.55 * u), V3(a + 0.55 * u)}, 0.03, rd::palette::darkGrey);
    std::vector<V3> hx;
    const double turns = 1.1 / (2 * pi<double>() * p);  // axial length 1.1 at p per radian
    for (int k = 0; k <= 400; ++k) {
      const double t = 2 * pi<double>() * turns * (k / 400.0 - 0.5);
      hx.push_back(V3(a + p * t * u + 0.13 * (std::cos(t) * e1 + std::sin(t) * e2)));
    }
    addTube(sc, hx, 0.025, rd::palette::bluishGreen);
  }
}

// GF §15.2 lines 9688–9704, GF-15.2-table-15.1: the ten subgroups as the joint sets that generate them
void tableFigure(Context& ctx) {
  const double p = 0.1;
  const auto rows = table15_1<double>(p);
  const V3 X = V3::UnitX(), Y = V3::UnitY(), Z = V3::UnitZ(), O = V3::Zero();
  const V3 q1(0, 0.5, 0.35), q2(0, -0.5, 0.35), q3(0, 0, -0.45);  // three parallel axes of the planar sets
  struct Panel {
    std::string name;
    std::vector<DrawnJoint> joints;
  };
  const std::vector<Panel> panels = {
      {"ℝ (IIB): P", {{'P', X, O}}},
      {"Hₚ (IA, p ≠ 0): H", {{'H', X, O}}},
      {"SO(2) (IA, p = 0): R", {{'R', X, O}}},
      {"ℝ² (IIC): PP", {{'P', X, V3(0, 0, 0.3)}, {'P', Y, V3(0, 0, -0.35)}}},
      {"SO(2) × ℝ (IB₀): C = RP", {{'R', X, V3(-0.4, 0, 0)}, {'P', X, V3(0.45, 0, 0)}}},
      {"ℝ³ (IID): PPP", {{'P', X, V3(0, 0, 0.45)}, {'P', Y, V3(0, 0, 0)}, {'P', Z, V3(0.55, 0, 0)}}},
      {"SO(3) (IIA): 3R concurrent", {{'R', X, O}, {'R', Y, O}, {'R', Z, O}}},
      {"SE(2) (IIC, p = 0): 3R ∥", {{'R', X, q1}, {'R', X, q2}, {'R', X, q3}}},
      {"Hₚ ⋉ ℝ² (IIC, p ≠ 0): 3H ∥", {{'H', X, q1}, {'H', X, q2}, {'H', X, q3}}},
      {"SE(2) × ℝ (IIC‾): 3R ∥ + P", {{'R', X, q1}, {'R', X, q2}, {'R', X, q3}, {'P', X, V3(0, 0, -0.95)}}}};
  auto g = std::mt19937_64(1527);
  int sameSpan = 0, closed = 0;
  double defect = 0, logOff = 0;
  auto span = [](const std::vector<V6>& s) {
    DM M(6, Eigen::Index(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) M.col(Eigen::Index(i)) = s[i];
    Eigen::JacobiSVD<DM> svd(M, Eigen::ComputeThinU);
    return DM(svd.matrixU().leftCols(screwSystemDimension(s)));
  };
  auto product = [](const std::vector<V6>& s, const DV& th) {
    SE3<double> r = SE3<double>::Identity();
    for (std::size_t i = 0; i < s.size(); ++i) r = r.compose(SE3Tangent<double>(V6(th(Eigen::Index(i)) * s[i])).exp());
    return r;
  };
  for (std::size_t k = 0; k < panels.size(); ++k) {
    std::vector<V6> s;
    for (const auto& j : panels[k].joints) s.push_back(j.screw(p));
    std::vector<V6> both = s;
    both.insert(both.end(), rows[k].basis.begin(), rows[k].basis.end());
    const int d = int(rows[k].basis.size());
    sameSpan += (screwSystemDimension(s) == d && screwSystemDimension(both) == d) ? 1 : 0;
    closed += isSubalgebra(s) ? 1 : 0;
    defect = std::max(defect, subalgebraDefect(s));
    const DM U = span(s);
    for (int t = 0; t < 10; ++t) {  // the joint set moves only inside its subgroup: log ρ(θ) ∈ Span(s_i)
      const V6 l = product(s, rvec(g, int(s.size()))).log().coeffs();
      logOff = std::max(logOff, (l - U * (U.transpose() * l)).norm());
    }
  }
  ctx.checkEqual("drawn joint sets whose screws span exactly the row's normal form (p = 0.1)", 10, sameSpan);
  ctx.checkEqual("drawn joint sets closed under the bracket", 10, closed);
  ctx.checkResidual("max distance of a bracket of drawn screws from their span", defect, 1e-15);
  ctx.checkResidual("10 random θ ∈ [−1, 1]ⁿ per set: max distance of log(e^{θ₁s₁}···e^{θₙsₙ}) from the span", logOff, 1e-13);
  // control: the SE(2) set with its third axis tilted by 0.1 rad about y — no longer a subalgebra
  std::vector<V6> tilted;
  for (const auto& j : panels[7].joints) tilted.push_back(j.screw(p));
  tilted[2] = lineScrew(V3(std::cos(0.1), 0, std::sin(0.1)), q3);
  ctx.checkEqual("control: SE(2) set with one axis tilted by 0.1 rad is not a subalgebra", 0, isSubalgebra(tilted) ? 1 : 0);
  ctx.checkEqual("… its completion algebra is all of se(3) (dim Δ∞)", 6, int(completionAlgebra(tilted).cols()));
  double tiltOff = 0;
  const DM Ut = span(tilted);
  for (int t = 0; t < 10; ++t) {
    const V6 l = product(tilted, rvec(g, 3)).log().coeffs();
    tiltOff = std::max(tiltOff, (l - Ut * (Ut.transpose() * l)).norm());
  }
  ctx.record("control: tilted set, max distance of log ρ(θ) from the span (leaves it)", "> 1e-3", toString(tiltOff, 4), tiltOff, 1e-3,
             tiltOff > 1e-3);
  if (!ctx.makeFigures()) return;
  rd::Scene sc;
  sc.title = "Table 15.1: joint sets whose screws form a subalgebra (full-cycle mobility)";
  const V3 view = V3(0.55, 1, -0.45).normalized();
  const V3 right = view.cross(Z).normalized(), up = right.cross(view);
  const double dx = 2.7, dy = 2.55;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const int col = int(k % 5), row = int(k / 5);
    const V3 c = (col - 2) * dx * right - row * dy * up;
    for (const auto& j : panels[k].joints) drawJoint(sc, j, c, p);
    if (k == 6) sc.add(rd::sphere(c, 0.16, rd::palette::lightGrey.darker(0.2f)));
    addLabel(sc, V3(c + 1.15 * up), panels[k].name, {0, 0}, 21, rd::palette::black, rd::HAlign::Center);
    sc.labels.back().vAlign = rd::VAlign::Middle;
  }
  renderFigure(ctx, sc, view, 1500, 760, "gf15_table15_1.png",
               "The ten rows of Table 15.1 drawn as joint sets (p = 0.1 m/rad): revolute R (blue cylinder), prismatic P "
               "(vermillion slider on a rail), helical H (green helix); the first seven are the normal forms themselves, "
               "SE(2) is drawn as three parallel revolutes (a planar 3R), Hₚ ⋉ ℝ² as three parallel helicals of equal pitch, "
               "SE(2) × ℝ as a planar 3R with a prismatic joint along the axes (Schoenflies). Each set's screws span the "
               "row's normal form and are closed under the bracket, so a loop built from them keeps its mobility over the whole cycle.",
               true);
}

}  // namespace

SOMA_STUDY_SCALAR("GF-15.2-mobility-definitions", "Mobility vs infinitesimal mobility: the flat 4-bar (0 vs 2)", "GF §15.2", definitions);
SOMA_STUDY_SCALAR("GF-15.2-loop-equation-kutzbach", "Loop equation and Kutzbach–Grübler m = n − 6 (7R mobile, 5R rigid)", "GF §15.2", kutzbach);
SOMA_STUDY_SCALAR("GF-15.2-completion-group-mobility", "m = n − dim Δ∞: planar and spherical 4R; Bennett the exception", "GF §15.2", completion);
SOMA_STUDY_SCALAR("GF-15.2-totally-geodesic-subalgebra", "Subalgebra ⟺ totally geodesic image (line 9674, erratum E15.13)", "GF §15.2", totallyGeodesic);
SOMA_STUDY_SCALAR("GF-15.2-table-15.1", "Table 15.1: the ten screw systems guaranteeing full-cycle mobility are subalgebras", "GF §15.2", table);
SOMA_STUDY_SCALAR("GF-15.2-singular-robot-mobility", "A 6R held at its end effector: singular iff infinitesimally mobile; self-motions", "GF §15.2", singularRobot);
// the two figures stay in double: soma::render draws double geometry
SOMA_STUDY({.id = "GF-15-fig-bennett",
            .title = "Derived figure: Bennett's overconstrained 4R in motion; the flat 4-bar (mobility 0, infinitesimal 2)",
            .source = "GF §15.2", .chapter = kChapter, .scalarGeneric = false, .run = bennettFigure, .whyDouble = kWhyDoubleFigure});
SOMA_STUDY({.id = "GF-15-fig-table-15.1", .title = "Derived figure: the ten subgroups of Table 15.1 drawn as their joint sets",
            .source = "GF §15.2", .chapter = kChapter, .scalarGeneric = false, .run = tableFigure, .whyDouble = kWhyDoubleFigure});

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
