#pragma once
// Gripping and friction: GF §12.5–12.6.
#include "soma/geometry/statics/grasp.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <cmath>
#include <limits>

namespace soma {
namespace {
template <class S> using MatD = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> using VecD = Eigen::Matrix<S, Eigen::Dynamic, 1>;

template <class S> void checkSet(const WrenchSet<S>& W, const char* who) {
  if (W.rows() != 6 && W.rows() != 3)
    throw InvalidInput(std::string(who) + ": a wrench set has 6 rows (space) or 3 (plane), got " +
                       std::to_string(W.rows()));
  if (W.cols() == 0) throw InvalidInput(std::string(who) + ": the wrench set is empty");
  if (!allFinite(W)) throw InvalidInput(std::string(who) + ": a wrench has a NaN or infinite entry");
}
template <class S> void checkUnit(const Vec3<S>& n, const char* who) {
  using std::abs;
  if (!allFinite(n) || !(abs(n.squaredNorm() - S(1)) <= Tolerance<S>::input()))
    throw InvalidInput(std::string(who) + ": the contact normal is not a unit vector");
}
/// Columns scaled to unit norm (positive spanning is invariant under positive scaling).
template <class S> MatD<S> normalisedColumns(const WrenchSet<S>& W, const char* who) {
  using std::sqrt;
  MatD<S> N = W;
  for (Eigen::Index j = 0; j < N.cols(); ++j) {
    const S nn = N.col(j).squaredNorm();
    if (!(nn > S(0))) throw InvalidInput(std::string(who) + ": wrench " + std::to_string(j + 1) + " is zero");
    N.col(j) /= sqrt(nn);
  }
  return N;
}
template <class S> int rankOf(const MatD<S>& W) { return detail::smallNumericalRank<S>(W); }
}  // namespace

// GF §12.5, GF-12.5-force-closure-frictionless: 𝒩 = (p × n, n).
template <class S> Wrench<S> contactNormalWrench(const Vec3<S>& point, const Vec3<S>& normal) {
  checkUnit(normal, "contactNormalWrench");
  if (!allFinite(point)) throw InvalidInput("contactNormalWrench: the contact point has a NaN or infinite entry");
  return Wrench<S>::ofForce(point, normal);
}
template <class S> WrenchSet<S> contactNormalWrenches(const std::vector<Vec3<S>>& points,
                                                      const std::vector<Vec3<S>>& normals) {
  if (points.size() != normals.size())
    throw InvalidInput("contactNormalWrenches: " + std::to_string(points.size()) + " points but " +
                       std::to_string(normals.size()) + " normals");
  WrenchSet<S> W(6, Eigen::Index(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) W.col(Eigen::Index(i)) = contactNormalWrench<S>(points[i], normals[i]).coeffs();
  return W;
}

// GF §12.5, GF-12.5-ungrippable-surfaces: rank and the screws every wrench annihilates.
template <class S> WrenchSpan<S> wrenchSpan(const WrenchSet<S>& W) {
  checkSet(W, "wrenchSpan");
  MatD<S> u, v;
  std::vector<S> sig;
  detail::smallSvd<S>(MatD<S>(W.transpose()), u, sig, v);
  WrenchSpan<S> out;
  const S smax = sig.empty() ? S(0) : sig[0];
  for (std::size_t k = 0; k < sig.size(); ++k) {
    if (smax > S(0) && sig[k] > Tolerance<S>::rank() * smax) ++out.rank;
    else out.annihilatedScrews.push_back(v.col(Eigen::Index(k)));
  }
  out.singularValues = sig;
  return out;
}

// GF §12.5, GF-12.5-positive-grasp-seven: max t s.t. W w = 0, Σ w = 1, w_i ≥ t.
template <class S> PositiveSpan<S> positiveSpan(const WrenchSet<S>& W) {
  checkSet(W, "positiveSpan");
  const MatD<S> N = normalisedColumns(W, "positiveSpan");
  const Eigen::Index d = N.rows(), m = N.cols(), nv = 2 * m + 1;
  MatD<S> A = MatD<S>::Zero(d + 1 + m, nv);
  VecD<S> b = VecD<S>::Zero(d + 1 + m), c = VecD<S>::Zero(nv);
  A.block(0, 0, d, m) = N;
  A.block(d, 0, 1, m).setOnes();
  b(d) = S(1);
  for (Eigen::Index i = 0; i < m; ++i) {
    A(d + 1 + i, i) = S(1);
    A(d + 1 + i, m) = S(-1);
    A(d + 1 + i, m + 1 + i) = S(-1);
  }
  c(m) = S(-1);
  PositiveSpan<S> out;
  out.rank = rankOf<S>(N);
  const auto lp = minimiseLinearProgram<S>(c, A, b);
  if (lp.status == LinearProgramResult<S>::Status::Optimal) out.margin = lp.x(m);
  out.spans = out.rank == int(d) && out.margin > Tolerance<S>::rank();
  if (!out.spans) out.margin = S(0);
  return out;
}

// GF §12.5, GF-12.5-form-closure: max Σ 𝒲_i(s) over {𝒲_i(s) ≥ 0, |s_j| ≤ 1}.
template <class S> FormClosure<S> formClosure(const WrenchSet<S>& W) {
  checkSet(W, "formClosure");
  const MatD<S> N = normalisedColumns(W, "formClosure");
  const Eigen::Index d = N.rows(), m = N.cols(), nv = 4 * d + m;
  // x = [s⁺ (d), s⁻ (d), u⁺ (d), u⁻ (d), e (m)]
  MatD<S> A = MatD<S>::Zero(m + 2 * d, nv);
  VecD<S> b = VecD<S>::Zero(m + 2 * d), c = VecD<S>::Zero(nv);
  A.block(0, 0, m, d) = N.transpose();
  A.block(0, d, m, d) = -N.transpose();
  A.block(0, 4 * d, m, m) = -MatD<S>::Identity(m, m);
  for (Eigen::Index j = 0; j < 2 * d; ++j) {
    A(m + j, j) = S(1);
    A(m + j, 2 * d + j) = S(1);
    b(m + j) = S(1);
  }
  c.tail(m).setConstant(S(-1));
  FormClosure<S> out;
  out.rank = rankOf<S>(N);
  const auto lp = minimiseLinearProgram<S>(c, A, b);
  out.escapeValue = -lp.value;
  out.escape = lp.x.head(d) - lp.x.segment(d, d);
  // Rank < d: a screw annihilated by every contact is feasible in both directions.
  if (out.rank < int(d) && !(out.escapeValue > Tolerance<S>::rank() * S(m))) {
    const auto span = wrenchSpan<S>(W);
    out.escape = span.annihilatedScrews.front();
  }
  out.closed = out.rank == int(d) && !(out.escapeValue > Tolerance<S>::rank() * S(m));
  return out;
}

// GF §12.6, GF-12.6-friction-cone: inscribed pyramid of the cone of semi-angle atan μ.
template <class S> WrenchSet<S> frictionConeEdges(const Vec3<S>& point, const Vec3<S>& normal,
                                                  const S& mu, int k) {
  using std::abs;
  using std::cos;
  using std::sin;
  checkUnit(normal, "frictionConeEdges");
  if (!allFinite(point)) throw InvalidInput("frictionConeEdges: the contact point has a NaN or infinite entry");
  if (!isFinite(mu) || mu < S(0))
    throw InvalidInput("frictionConeEdges: friction coefficient μ = " + toString(mu) + " is not a finite number ≥ 0");
  if (k < 3) throw InvalidInput("frictionConeEdges: a linearised cone needs k ≥ 3 edges, got " + std::to_string(k));
  // Tangent basis: cross with the axis least aligned with n.
  Vec3<S> e = Vec3<S>::UnitX();
  if (abs(normal.y()) < abs(normal.x()) && abs(normal.y()) <= abs(normal.z())) e = Vec3<S>::UnitY();
  else if (abs(normal.z()) < abs(normal.x()) && abs(normal.z()) < abs(normal.y())) e = Vec3<S>::UnitZ();
  const Vec3<S> t1 = normal.cross(e).normalized(), t2 = normal.cross(t1);
  WrenchSet<S> W(6, k);
  for (int j = 0; j < k; ++j) {
    const S th = S(2) * pi<S>() * S(j) / S(k);
    const Vec3<S> f = normal + mu * (cos(th) * t1 + sin(th) * t2);
    W.col(j) = Wrench<S>::ofForce(point, f).coeffs();
  }
  return W;
}

// GF §12.6, GF-12.6-friction-cone (standard form).
template <class S> Wrench<S> standardFrictionWrench(const S& F, const S& gamma, const S& theta) {
  using std::cos;
  using std::sin;
  if (!isFinite(F) || F < S(0)) throw InvalidInput("standardFrictionWrench: normal force F = " + toString(F) + " is not ≥ 0 (fingers push)");
  if (!isFinite(gamma) || gamma < S(0)) throw InvalidInput("standardFrictionWrench: γ = " + toString(gamma) + " is not ≥ 0");
  return Wrench<S>(Vec3<S>::Zero(), Vec3<S>(gamma * F * cos(theta), gamma * F * sin(theta), F));
}

// GF §12.6, GF-12.6-dual-friction-cone (corrected, erratum E12.2): ω free, v_z ≥ μ |v_t|.
template <class S> bool inDualFrictionCone(const SE3Tangent<S>& s, const S& mu) {
  if (!isFinite(mu) || mu < S(0)) throw InvalidInput("inDualFrictionCone: μ = " + toString(mu) + " is not a finite number ≥ 0");
  const Vec3<S> v = s.lin();
  return v.z() >= S(0) && v.z() * v.z() >= mu * mu * (v.x() * v.x() + v.y() * v.y());
}

template <class S> Vec3<S> planarWrench(const Vec2<S>& p, const Vec2<S>& f) {
  return Vec3<S>(p.x() * f.y() - p.y() * f.x(), f.x(), f.y());
}
template <class S> WrenchSet<S> planarFrictionConeEdges(const Vec2<S>& point, const Vec2<S>& normal,
                                                        const S& mu) {
  using std::abs;
  if (!allFinite(normal) || !(abs(normal.squaredNorm() - S(1)) <= Tolerance<S>::input()))
    throw InvalidInput("planarFrictionConeEdges: the contact normal is not a unit vector");
  if (!isFinite(mu) || mu < S(0)) throw InvalidInput("planarFrictionConeEdges: μ = " + toString(mu) + " is not a finite number ≥ 0");
  const Vec2<S> t(-normal.y(), normal.x());
  WrenchSet<S> W(3, 2);
  const Vec3<S> w0 = planarWrench<S>(point, Vec2<S>(normal + mu * t)),
                w1 = planarWrench<S>(point, Vec2<S>(normal - mu * t));
  for (int i = 0; i < 3; ++i) W(i, 0) = w0(i), W(i, 1) = w1(i);  // element-wise: GCC 12 -Warray-bounds on Vec3<float>
  return W;
}

// GF §12.6, GF-12.6-planar-two-finger-grasp: the joining segment strictly inside both cones,
// cones pointing towards each other or both away.
template <class S> bool planarTwoFingerForceClosure(const Vec2<S>& p1, const Vec2<S>& n1,
                                                    const Vec2<S>& p2, const Vec2<S>& n2, const S& mu) {
  using std::abs;
  for (const auto* n : {&n1, &n2})
    if (!allFinite(*n) || !(abs(n->squaredNorm() - S(1)) <= Tolerance<S>::input()))
      throw InvalidInput("planarTwoFingerForceClosure: a contact normal is not a unit vector");
  if (!isFinite(mu) || mu < S(0)) throw InvalidInput("planarTwoFingerForceClosure: μ = " + toString(mu) + " is not a finite number ≥ 0");
  const Vec2<S> d = p2 - p1;
  const S dd = d.squaredNorm();
  if (!(dd > S(0))) throw InvalidInput("planarTwoFingerForceClosure: the two contacts coincide");
  const S a = n1.dot(d), b = n2.dot(d), k = S(1) + mu * mu;
  // (n·d)² (1 + μ²) > |d|²  ⟺  the angle between n and ±d is below atan μ.
  return a * a * k > dd && b * b * k > dd && ((a > S(0) && b < S(0)) || (a < S(0) && b > S(0)));
}

// GF §12.5, GF-12.5-second-order-contact (printed form verified).
template <class S> S secondOrderContactForm(const S& kx, const S& ky, const SE3Tangent<S>& s) {
  const Vec3<S> w = s.ang(), v = s.lin();
  return kx * v.x() * v.x() + ky * v.y() * v.y() - w.x() * v.y() + w.y() * v.x();
}

// GF §12.5, GF-12.5-curved-feasible-regions (corrected, erratum E12.3): f(ε) = 2 v_z ε + ε² q + O(ε³).
template <class S> ContactMotion classifyObjectMotion(const S& kx, const S& ky, const SE3Tangent<S>& s) {
  using std::abs;
  using std::sqrt;
  if (!allFinite(s.coeffs()) || !isFinite(kx) || !isFinite(ky))
    throw InvalidInput("classifyObjectMotion: NaN or infinite curvature or screw");
  const S vn = sqrt(s.lin().squaredNorm()), wn = sqrt(s.ang().squaredNorm());
  if (!(vn + wn > S(0))) throw InvalidInput("classifyObjectMotion: the zero screw is not a motion");
  const S vz = s.lin().z();
  if (abs(vz) > Tolerance<S>::rank() * (vn + wn))
    return vz < S(0) ? ContactMotion::Separates : ContactMotion::Penetrates;
  const S q = secondOrderContactForm<S>(kx, ky, s);
  const S qs = (abs(kx) + abs(ky)) * vn * vn + wn * vn;
  if (abs(q) > Tolerance<S>::rank() * qs) return q < S(0) ? ContactMotion::Separates : ContactMotion::Penetrates;
  return ContactMotion::ThirdOrder;
}

#define SOMA_STATICS_GRASP_INST(S)                                                                       \
  template Wrench<S> contactNormalWrench<S>(const Vec3<S>&, const Vec3<S>&);                              \
  template WrenchSet<S> contactNormalWrenches<S>(const std::vector<Vec3<S>>&, const std::vector<Vec3<S>>&); \
  template WrenchSpan<S> wrenchSpan<S>(const WrenchSet<S>&);                                              \
  template PositiveSpan<S> positiveSpan<S>(const WrenchSet<S>&);                                          \
  template FormClosure<S> formClosure<S>(const WrenchSet<S>&);                                            \
  template WrenchSet<S> frictionConeEdges<S>(const Vec3<S>&, const Vec3<S>&, const S&, int);              \
  template Wrench<S> standardFrictionWrench<S>(const S&, const S&, const S&);                             \
  template bool inDualFrictionCone<S>(const SE3Tangent<S>&, const S&);                                    \
  template Vec3<S> planarWrench<S>(const Vec2<S>&, const Vec2<S>&);                                       \
  template WrenchSet<S> planarFrictionConeEdges<S>(const Vec2<S>&, const Vec2<S>&, const S&);             \
  template bool planarTwoFingerForceClosure<S>(const Vec2<S>&, const Vec2<S>&, const Vec2<S>&,           \
                                               const Vec2<S>&, const S&);                                 \
  template S secondOrderContactForm<S>(const S&, const S&, const SE3Tangent<S>&);                         \
  template ContactMotion classifyObjectMotion<S>(const S&, const S&, const SE3Tangent<S>&);

}  // namespace soma
