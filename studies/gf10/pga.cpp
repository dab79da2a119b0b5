// Studies of GF chapter 10, §10.1–10.2: points, lines and planes in the Clifford algebra
// Cl(0,3,1) — the elements and their motions, incidence, meets (exterior product), joins (the
// book's shuffle product), perpendiculars, angles and distances (contraction), the common
// perpendicular; errata E10.1, E10.10, E10.11. Every study runs in the scalar asked for (--scalar);
// the library is also tested for all five scalars in tests/geometry/pga.
#include "soma/geometry/pga/angle.hpp"
#include "soma/geometry/pga/common_perpendicular.hpp"
#include "soma/geometry/pga/distance.hpp"
#include "soma/geometry/pga/incidence.hpp"
#include "soma/geometry/pga/motor.hpp"
#include "soma/geometry/pga/projection.hpp"
#include "soma/geometry/pga/reflection.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <Eigen/LU>
#include <random>

namespace soma::studies::gf10::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace soma::pga;
constexpr const char* kChapter = "GF 10 — Points, lines, planes; Pieper robots";
using std::abs;
using std::atan2;
using std::ldexp;
using std::sqrt;

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
using draws::frac;
using draws::uni;  // soma/studies/scalar_draws.hpp
template <class S> Vec3<S> rvec(std::mt19937_64& g, double r = 1) {
  const S x = uni<S>(g, -r, r), y = uni<S>(g, -r, r), z = uni<S>(g, -r, r);
  return Vec3<S>(x, y, z);
}
template <class S> Vec3<S> runit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  Eigen::Vector3d v;
  do {
    const double x = n(g), y = n(g), z = n(g);
    v = Eigen::Vector3d(x, y, z);
  } while (v.squaredNorm() < 1e-6);
  const Vec3<S> w = castMatrix<S>(v);
  return w / sqrt(w.squaredNorm());
}
template <class S> S md(const Vec3<S>& a, const Vec3<S>& b) { return (a - b).cwiseAbs().maxCoeff(); }
template <class S, clifford::GradeMask A, clifford::GradeMask B>
S md(const clifford::Multivector<Cl031, S, A>& a, const clifford::Multivector<Cl031, S, B>& b) {
  return clifford::maxAbsDiff(a, b);
}
template <class S> S tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }
/// Runs f over `n` random trials and returns the largest value it reports.
template <class S, class F> S worst(int n, F&& f) {
  S w(0);
  for (int i = 0; i < n; ++i) w = std::max(w, S(f(i)));
  return w;
}
template <class S> SE3<S> randomMotion(std::mt19937_64& g, double r = 2) { return SE3<S>(SO3<S>::Random(g), rvec<S>(g, r)); }

// ---- §10.1 the elements -----------------------------------------------------------------------

template <class S> void planes(Context& c) {
  auto g = rng(101);
  c.checkResidual("ππ* = |n|² (20 random (n, d))", worst<S>(20, [&](int) {
                    const Vec3<S> n = rvec<S>(g);
                    return abs(Plane<S>(n, uni<S>(g)).normSquared() - n.squaredNorm());
                  }), tol<S>());
  S law = 0, expl = 0, hstar = 0;
  for (int i = 0; i < 20; ++i) {
    const S big = i % 5 == 4 ? S(1000000) : S(1);  // large |t| too
    const SE3<S> m(SO3<S>::Random(g), rvec<S>(g, i % 5 == 4 ? 2000000.0 : 2.0));
    const Motor<S> h = Motor<S>::fromSE3(m);
    const Plane<S> pi(runit<S>(g), uni<S>(g));
    const Plane<S> p2 = h(pi);
    const Vec3<S> Rn = m.rotation() * pi.normal();
    law = std::max(law, std::max(md(p2.normal(), Rn),
                                 abs(p2.distance() - (pi.distance() + Rn.dot(m.translation()))) / big));
    // The book's explicit form g n g* + (d − ½(gng*t + tgng*))𝐞, computed in the algebra.
    const Quat<S>& q = m.quaternion();
    EvenElement<S> gg(q.w());
    setBookCoeff(gg, basis::e23, q.x());
    setBookCoeff(gg, basis::e31, q.y());
    setBookCoeff(gg, basis::e12, q.z());
    const Grade1<S> n(Plane<S>(pi.normal(), 0).element()), t(Plane<S>(m.translation(), 0).element());
    const auto gng = (gg * n * gg.conjugate()).template grade<1>();
    const auto E = Grade1<S>::basisBlade(basis::e.mask);
    const auto dd = (t * gng + gng * t).scalarPart();
    const Grade1<S> book(gng + Grade1<S>(E * (pi.distance() - dd / 2)));
    expl = std::max(expl, md(book, p2.element()) / big);
    // h* = g* + ½𝐞g*t (GF §10.1.1).
    const EvenElement<S> hs(gg.conjugate() + EvenElement<S>((E * gg.conjugate() * t) * frac<S>(1, 2)));
    hstar = std::max(hstar, md(hs, h.conjugate().element()) / big);
  }
  c.checkResidual("hπh*: n' = Rn, d' = d + (Rn)·t (20 motions, |t| up to 2e6, relative)", law, tol<S>());
  c.checkResidual("hπh* = gng* + (d − ½(gng*t + tgng*))𝐞 (the book's expansion)", expl, tol<S>());
  c.checkResidual("h* = g* + ½𝐞g*t", hstar, tol<S>());
  c.checkEqual("the plane at infinity 𝐞 cannot be normalised", "InvalidInput", [] {
    try {
      (void)Plane<S>::atInfinity().normalized();
      return std::string("normalised");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
  c.checkResidual("d = 0 (plane through the origin) moves to d' = Rn·t",
                  [&] {
                    const SE3<S> m = randomMotion<S>(g);
                    const Plane<S> p(Vec3<S>(0, 0, 1), 0);
                    return abs(Motor<S>::fromSE3(m)(p).distance() - (m.rotation() * Vec3<S>(0, 0, 1)).dot(m.translation()));
                  }(),
                  tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.1.1-planes", "Planes π = n + d𝐞: ππ* = 1, the motion law n' = Rn, d' = d + Rn·t", "GF §10.1.1",
                  planes);

template <class S> void pointsFreeVectors(Context& c) {
  auto g = rng(102);
  S conj = 0, norm = 0, act = 0, freev = 0, neg = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> x = rvec<S>(g, 3);
    const Point<S> p(x);
    conj = std::max(conj, md(p.element().conjugate(), p.element()));
    norm = std::max(norm, abs(p.normSquared() - 1));
    const SE3<S> m = randomMotion<S>(g);
    const Motor<S> h = Motor<S>::fromSE3(m);
    act = std::max(act, md(h(p).position(), m.act(x)));
    const Point<S> f = h(Point<S>::freeVector(x));
    freev = std::max(freev, md(f.bulk(), Vec3<S>(m.rotation() * x)) + abs(f.weight()));
    // Negative points: weight −1 stays −1 and the place moves like a point.
    const Point<S> n2 = h(-p);
    neg = std::max(neg, abs(n2.weight() + 1) + md(n2.position(), m.act(x)));
  }
  c.checkResidual("p* = p", conj, S(0));
  c.checkResidual("pp* = 1", norm, tol<S>());
  c.checkResidual("hph* = point(R x + t) (SE3::act, 20 random)", act, tol<S>());
  c.checkResidual("hfh* = gfg* (free vectors: rotation only, weight stays 0)", freev, tol<S>());
  c.checkResidual("negative points (weight −1) keep their weight and move like points", neg, tol<S>());
  // Sorted-blade storage: e3e1𝐞 = −e1e3𝐞.
  const Point<S> py(Vec3<S>(0, 1, 0));
  c.checkNear("coefficient of the sorted blade e1e3𝐞 for y = 1 is −1 (e3e1𝐞 = −e1e3𝐞)", S(-1),
              py.element().coeff(basis::e31e.mask), S(0));
}
SOMA_STUDY_SCALAR("GF-10.1.2-points-and-free-vectors", "Points e1e2e3 + x e2e3𝐞 + …: pp* = 1, hph* = point(Rx + t), free vectors rotate",
           "GF §10.1.2",
                  pointsFreeVectors);

template <class S> void lines(Context& c) {
  auto g = rng(103);
  S cj = 0, nn = 0, act = 0, rev = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> v = rvec<S>(g), u = rvec<S>(g);
    const Line<S> l(v, u);
    cj = std::max(cj, md(l.element().conjugate(), Grade2<S>(-l.element())));
    const auto [n0, n4] = l.normSquared();
    nn = std::max(nn, abs(n0 - v.squaredNorm()) + abs(n4 + 2 * v.dot(u)));
    const Vec3<S> q = rvec<S>(g), d = runit<S>(g);
    const SE3<S> m = randomMotion<S>(g);
    const Line<S> moved = Motor<S>::fromSE3(m)(Line<S>::throughPoint(q, d));
    act = std::max(act, md(moved.element(), Line<S>::throughPoint(m.act(q), Vec3<S>(m.rotation() * d)).element()));
    rev = std::max(rev, md((-Line<S>::throughPoint(q, d)).element(), Line<S>::throughPoint(q, Vec3<S>(-d)).element()));
  }
  c.checkResidual("ℓ* = −ℓ", cj, S(0));
  c.checkResidual("ℓℓ* = |v|² − 2(v·u) e1e2e3𝐞 (so ℓℓ* = 1 ⇔ |v| = 1 and v·u = 0)", nn, tol<S>());
  c.checkResidual("hℓh* = line(Rq + t, Rv)", act, tol<S>());
  c.checkResidual("−ℓ is the line with the opposite direction", rev, S(0));
  const Line<S> screw(Vec3<S>(0, 0, 1), Vec3<S>(frac<S>(1, 2), 0, frac<S>(3, 10)));
  c.checkNear("a grade-2 element with v·u ≠ 0 is a screw: pitch v·u/|v|²", frac<S>(3, 10), screw.pitch(), tol<S>());
  c.checkEqual("… and fails the Klein condition", "screw", screw.isLine() ? "line" : "screw");
  // The motion of a screw is the adjoint action.
  const SE3<S> m = randomMotion<S>(g);
  const SE3Tangent<S> xi(Vec6<S>::Random());
  c.checkResidual("hsh* = Ad(g) s for a screw s (SE3::adjoint)",
                  (Motor<S>::fromSE3(m)(Line<S>::fromTwist(xi)).toTwist().coeffs() - m.adjoint() * xi.coeffs())
                      .cwiseAbs()
                      .maxCoeff(),
                  tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.1.3-lines", "Lines v·(e2e3, e3e1, e1e2) + u·(e1𝐞, e2𝐞, e3𝐞): ℓℓ* = |v|² − 2(v·u)e1e2e3𝐞; hℓh*",
           "GF §10.1.3",
                  lines);

// ---- §10.2.1 incidence ------------------------------------------------------------------------

template <class S> void incidencePlanePoint(Context& c) {
  auto g = rng(211);
  c.checkResidual("π ∧ p = ½(πp − pπ) = (x·n − d) e1e2e3𝐞 (20 random)", worst<S>(20, [&](int) {
                    const Plane<S> pi(rvec<S>(g), uni<S>(g));
                    const Vec3<S> x = rvec<S>(g);
                    const Point<S> p(x);
                    const auto w = pi.element() ^ p.element();
                    const auto comm = (pi.element() * p.element() - p.element() * pi.element()) * frac<S>(1, 2);
                    return md(w, comm) + abs(bookCoeff(w, basis::e123e) - (x.dot(pi.normal()) - pi.distance()));
                  }), tol<S>());
  const Plane<S> pi(runit<S>(g), frac<S>(2, 5));
  const Vec3<S> on = pi.normal() * frac<S>(2, 5) + pi.normal().cross(rvec<S>(g));
  c.checkResidual("a point built on the plane: |π ∧ p| (scale-free)", incidenceResidual(Point<S>(on), pi), tol<S>(16));
  const S e8(100000000);
  const Vec3<S> far = on * e8 + pi.normal() * (frac<S>(2, 5) - frac<S>(2, 5) * e8);  // on the plane, 1e8 away
  c.checkResidual("a point on the plane 1e8 from the origin (scale-free residual)", incidenceResidual(Point<S>(far), pi), tol<S>(16));
  const S r = Tolerance<S>::rank(), sc = on.norm() + frac<S>(2, 5);
  c.checkEqual("off by 2·rank·scale along n: not incident", "not incident",
               incident(Point<S>(Vec3<S>(on + pi.normal() * (2 * r * sc))), pi) ? "incident" : "not incident");
  c.checkEqual("off by rank/4·scale: incident", "incident",
               incident(Point<S>(Vec3<S>(on + pi.normal() * (r / 4 * sc))), pi) ? "incident" : "not incident");
}
SOMA_STUDY_SCALAR("GF-10.2.1-incidence-plane-point", "π ∧ p = ½(πp − pπ) = (x·n − d)e1e2e3𝐞", "GF §10.2.1",
                  incidencePlanePoint);

template <class S> void incidencePlaneLine(Context& c) {
  auto g = rng(212);
  S sym = 0, corrected = 0, printed = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> n = rvec<S>(g), v = rvec<S>(g), u = rvec<S>(g);
    const S d = uni<S>(g);
    const auto pi = Plane<S>(n, d).element();
    const auto l = Line<S>(v, u).element();
    const auto w = pi ^ l;
    sym = std::max(sym, md(w, (pi * l + l * pi) * frac<S>(1, 2)));
    const S e12e = bookCoeff(w, basis::e12e);
    corrected = std::max(corrected, abs(bookCoeff(w, basis::e123) - n.dot(v)) +
                                        abs(bookCoeff(w, basis::e23e) - (n.y() * u.z() - n.z() * u.y() + d * v.x())) +
                                        abs(bookCoeff(w, basis::e31e) - (n.z() * u.x() - n.x() * u.z() + d * v.y())) +
                                        abs(e12e - (n.x() * u.y() - n.y() * u.x() + d * v.z())));
    printed = std::max(printed, abs(e12e - (n.x() * u.y() - n.y() * u.x() + d * v.x())));
  }
  c.checkResidual("π ∧ ℓ = ½(πℓ + ℓπ)", sym, tol<S>());
  c.checkResidual("coefficients with the e1e2𝐞 term n_x u_y − n_y u_x + d v_z (corrected)", corrected, tol<S>());
  c.checkPrintedFails("e1e2𝐞 coefficient n_x u_y − n_y u_x + d v_x", "E10.1", printed, tol<S>());
  const Plane<S> z0(Vec3<S>(0, 0, 1), 0);
  const Line<S> inside = Line<S>::throughPoint(Vec3<S>(1, 2, 0), Vec3<S>(1, -1, 0));
  c.checkResidual("a line inside the plane: π ∧ ℓ = 0", incidenceResidual(inside, z0), tol<S>(16));
  const auto par = z0.element() ^ Line<S>::throughPoint(Vec3<S>(1, 2, frac<S>(1, 2)), Vec3<S>(1, -1, 0)).element();
  c.checkResidual("parallel but off the plane: the e1e2e3 part vanishes", abs(bookCoeff(par, basis::e123)), S(0));
  c.checkNear("… while the 𝐞-parts do not (|n × u + d v| = 0.5·|v|)", frac<S>(1, 2) * sqrt(S(2)),
              Point<S>(par).bulk().norm(), tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.1-incidence-plane-line", "π ∧ ℓ = ½(πℓ + ℓπ) = (n·v)e1e2e3 + (n × u + d v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞) (E10.1)",
           "GF §10.2.1",
                  incidencePlaneLine);

template <class S> void incidencePointLine(Context& c) {
  auto g = rng(213);
  S form = 0, wedge0 = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> x = rvec<S>(g), v = rvec<S>(g), u = rvec<S>(g);
    const auto p = Point<S>(x).element();
    const auto l = Line<S>(v, u).element();
    const auto r = (p * l.conjugate() + l * p.conjugate()).template grade<3>();
    form = std::max(form, md(Point<S>(r).bulk(), Vec3<S>(2 * (u - x.cross(v)))) + abs(Point<S>(r).weight()));
    wedge0 = std::max(wedge0, DenseElement<S>(l ^ p).maxAbs());
  }
  c.checkResidual("pℓ* + ℓp* = 2(z v_y − y v_z + u_x) e2e3𝐞 + … (20 random)", form, tol<S>());
  c.checkResidual("ℓ ∧ p = 0 for all lines and points (grades add past 4)", wedge0, S(0));
  const Vec3<S> q = rvec<S>(g), d = runit<S>(g);
  c.checkResidual("a point on the line: p × v = u", incidenceResidual(Point<S>(Vec3<S>(q + frac<S>(7, 10) * d)), Line<S>::throughPoint(q, d)), tol<S>(16));
}
SOMA_STUDY_SCALAR("GF-10.2.1-incidence-point-line", "pℓ* + ℓp* = 2(u − p × v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞); ℓ ∧ p ≡ 0", "GF §10.2.1",
                  incidencePointLine);

// ---- §10.2.2 meets ----------------------------------------------------------------------------

template <class S> void meetTwoPlanes(Context& c) {
  auto g = rng(221);
  S scal = 0, book = 0, inc = 0, dir = 0;
  for (int i = 0; i < 20; ++i) {
    const Plane<S> a(runit<S>(g), uni<S>(g)), b(runit<S>(g), uni<S>(g));
    const auto w = a.element() ^ b.element();
    const auto ww = w * w.conjugate();
    scal = std::max(scal, abs(bookCoeff(ww, basis::e123e)) + DenseElement<S>(ww.template grades<0b11110>()).maxAbs());
    const auto p1 = a.element(), p2 = b.element();
    const auto rhs = (DenseElement<S>(S(2)) - DenseElement<S>(p2 * p1 * p2 * p1) - DenseElement<S>(p1 * p2 * p1 * p2)) * frac<S>(1, 4);
    book = std::max(book, md(DenseElement<S>(ww), rhs));
    const Line<S> l = meet(a, b);
    inc = std::max(inc, std::max(incidenceResidual(l, a), incidenceResidual(l, b)));
    dir = std::max(dir, md(l.direction(), Vec3<S>(a.normal().cross(b.normal()).normalized())));
  }
  c.checkResidual("(π1∧π2)(π1∧π2)* is a scalar (no grade 2, 3, 4 part)", scal, tol<S>());
  c.checkResidual("… = ¼(2 − π2π1π2π1 − π1π2π1π2) for unit planes", book, tol<S>());
  c.checkResidual("π_i ∧ ℓ = 0: the meet lies in both planes (scale-free)", inc, tol<S>());
  c.checkResidual("direction n1 × n2/|n1 × n2|", dir, tol<S>());
  const S r = Tolerance<S>::rank();
  const Plane<S> z0(Vec3<S>(0, 0, 1), 0);
  auto tilt = [](S s) { return Vec3<S>(s, 0, sqrt(1 - s * s)); };
  const Line<S> l2 = meet(z0, Plane<S>(tilt(2 * r), 1));
  c.checkEqual("nearly parallel, sin∠ = 2·rank: a finite line", "finite", l2.isAtInfinity() ? "at infinity" : "finite");
  c.checkResidual("… lying in both planes", std::max(incidenceResidual(l2, z0), incidenceResidual(l2, Plane<S>(tilt(2 * r), 1))), tol<S>());
  const Line<S> lh = meet(z0, Plane<S>(tilt(r / 2), 1));
  c.checkEqual("sin∠ = rank/2: the line at infinity (v = 0, no division by ~0)", "at infinity",
               lh.isAtInfinity() ? "at infinity" : "finite");
  c.checkEqual("parallel planes z = 0, z = 3: the line at infinity", "at infinity",
               meet(z0, Plane<S>(Vec3<S>(0, 0, 1), 3)).isAtInfinity() ? "at infinity" : "finite");
  c.checkEqual("coincident planes: no line", "InvalidInput", [&] {
    try {
      (void)meet(z0, Plane<S>(Vec3<S>(0, 0, -2), 0));
      return std::string("a line");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
  c.note("The book's remark that the grade-4 terms cancel (seed 6147) prints e_ke_je_ie_j for e_ke_le_ie_j (typo).");
}
SOMA_STUDY_SCALAR("GF-10.2.2-meet-two-planes", "ℓ = π1 ∧ π2/√((π1∧π2)(π1∧π2)*); parallel planes meet at infinity", "GF §10.2.2",
                  meetTwoPlanes);

template <class S> void meetLinePlane(Context& c) {
  auto g = rng(222);
  S on = 0, ref = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> q = rvec<S>(g), v = runit<S>(g);
    const Line<S> l = Line<S>::throughPoint(q, v);
    const Plane<S> pi(runit<S>(g), uni<S>(g));
    const Point<S> p = meet(l, pi);
    on = std::max(on, std::max(incidenceResidual(p, l), incidenceResidual(p, pi)) + abs(p.weight() - 1));
    const S s = (pi.distance() - pi.normal().dot(q)) / pi.normal().dot(v);
    ref = std::max(ref, md(p.position(), Vec3<S>(q + s * v)) * abs(pi.normal().dot(v)) / (1 + abs(s)));
  }
  c.checkResidual("the meet lies on ℓ (p × v = u) and on π, weight +1 (20 random)", on, tol<S>());
  c.checkResidual("= q + s v with s = (d − n·q)/(n·v) (conditioning-scaled)", ref, tol<S>());
  const S r = Tolerance<S>::rank();
  const Plane<S> z0(Vec3<S>(0, 0, 1), 0);
  const Point<S> f = meet(Line<S>::throughPoint(Vec3<S>(0, 0, 1), Vec3<S>(sqrt(1 - r * r / 4), 0, r / 2)), z0);
  c.checkEqual("line at angle rank/2 to the plane: the point at infinity (free vector ±v)", "at infinity",
               f.isAtInfinity() ? "at infinity" : "finite");
  const Point<S> p2 = meet(Line<S>::throughPoint(Vec3<S>(0, 0, 1), Vec3<S>(sqrt(1 - 4 * r * r), 0, 2 * r)), z0);
  c.checkNear("angle 2·rank: a finite point at x = −cot∠ ≈ −1/(2·rank) (2.2e12 in double)", -sqrt(1 - 4 * r * r) / (2 * r), p2.position().x(),
              Tolerance<S>::rank() / (2 * r));
}
SOMA_STUDY_SCALAR("GF-10.2.2-meet-line-plane", "p = ℓ ∧ π/±√((ℓ∧π)(ℓ∧π)*), sign making the e1e2e3 coefficient +1", "GF §10.2.2",
                  meetLinePlane);

template <class S> void meetThreePlanes(Context& c) {
  auto g = rng(223);
  S err = 0;
  for (int i = 0; i < 50; ++i) {
    const Plane<S> a(runit<S>(g), uni<S>(g)), b(runit<S>(g), uni<S>(g)), d(runit<S>(g), uni<S>(g));
    Mat3<S> N;
    N.row(0) = a.normal().transpose(), N.row(1) = b.normal().transpose(), N.row(2) = d.normal().transpose();
    const Vec3<S> x = N.fullPivLu().solve(Vec3<S>(a.distance(), b.distance(), d.distance()));
    const S cond = N.norm() * N.inverse().norm();
    err = std::max(err, md(meet(a, b, d).position(), x) / (cond * (1 + x.norm())));
  }
  c.checkResidual("meet of 3 planes = solution of [n1 n2 n3]ᵀx = d (50 random, relative to cond·|x|)", err, tol<S>(64));
  const Plane<S> z0(Vec3<S>(0, 0, 1), 0), x0(Vec3<S>(1, 0, 0), 0);
  const Point<S> prism = meet(z0, x0, Plane<S>(Vec3<S>(1, 0, 1).normalized(), 1));
  c.checkEqual("a prism (normals coplanar, no common line): point at infinity", "at infinity",
               prism.isAtInfinity() ? "at infinity" : "finite");
  c.checkNear("… in the direction of its edges (±e_y)", S(1), abs(prism.bulk().y()), tol<S>());
  c.checkEqual("three planes through one line: no point", "InvalidInput", [&] {
    try {
      (void)meet(z0, x0, Plane<S>(Vec3<S>(1, 0, 1).normalized(), 0));
      return std::string("a point");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
}
SOMA_STUDY_SCALAR("GF-10.2.2-meet-three-planes", "p = π1 ∧ π2 ∧ π3/±√(…) against a 3×3 linear solve", "GF §10.2.2",
                  meetThreePlanes);

// ---- §10.2.3 joins: the shuffle product -------------------------------------------------------

/// The book's shuffle formula read with n = `n` (the printed text says "n the dimension of the
/// algebra", i.e. 16; E10.11): the coefficient of blade(a) ∨ blade(b), 0 when j + k < n.
int shuffleWithN(Blade a, Blade b, int n) {
  const int j = std::popcount(a), k = std::popcount(b);
  if (j + k < n) return 0;
  return shuffleCoefficient(a, b);  // for n = 4 the corrected formula (shuffle.hpp)
}

template <class S> void shuffleDefinition(Context& c) {
  c.checkEqual("e1e2e3 ∨ e2e3𝐞 (book's worked example): coefficient of e2e3", 1, shuffleCoefficient(7, 14));
  int agree = 0, nonzero = 0;
  for (Blade a = 0; a < 16; ++a)
    for (Blade b = 0; b < 16; ++b) {
      agree += shuffleCoefficient(a, b) == Cl031::regressiveSign(a, b);
      nonzero += shuffleCoefficient(a, b) != 0;
    }
  c.checkEqual("blade pairs where the permutation formula equals multivector.hpp's regressive product", 256, agree);
  c.checkEqual("non-zero blade pairs (a | b = e1e2e3𝐞: Σ C(4,j)2^j)", 81, nonzero);
  auto g = rng(231);
  c.checkResidual("a ∨ b (permutation formula) = a & b (Poincaré duality) on 20 random dense pairs", worst<S>(20, [&](int) {
                    DenseElement<S> a, b;
                    for (int i = 0; i < a.size; ++i) a[i] = uni<S>(g), b[i] = uni<S>(g);
                    return md(shuffle(a, b), a & b);
                  }), tol<S>(64));
  int printedNonzero = 0;
  for (Blade a = 0; a < 16; ++a)
    for (Blade b = 0; b < 16; ++b) printedNonzero += shuffleWithN(a, b, 16) != 0;
  c.checkPrintedFails("n = \"the dimension of the algebra\" = 16: j + k ≥ n never holds, so every shuffle is 0 and "
                 "e1e2e3 ∨ e2e3𝐞 = e2e3 is lost (|1 − coefficient|)", "E10.11",
              abs(S(1) - shuffleWithN(7, 14, 16)), S(0));
  c.checkEqual("… non-zero pairs with n = 16", 0, printedNonzero);
  c.note("E10.11: n is the dimension of the generator space (4), the index a_σ(4−k+1) should read "
         "a_σ(n−k+1) (the same for n = 4) and the last determinant column is b_ki, not b_σ(k)i. "
         "The sum over σ ∈ S_j counts each split (n−k)!(j+k−n)! times, hence the prefactor: the "
         "coefficients come out in {−1, 0, 1} (asserted when the table is built).");
}
SOMA_STUDY_SCALAR("GF-10.2.3-shuffle-definition",
           "The shuffle product by the book's permutation formula (E10.11) = the regressive product; e1e2e3 ∨ e2e3𝐞 = e2e3",
           "GF §10.2.3",
                  shuffleDefinition);

template <class S> void joinTwoPoints(Context& c) {
  auto g = rng(232);
  S form = 0, unit = 0, onl = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> x1 = rvec<S>(g), x2 = rvec<S>(g);
    const Line<S> j = shuffle(Point<S>(x1), Point<S>(x2));
    form = std::max(form, md(j.direction(), Vec3<S>(x2 - x1)) + md(j.moment(), Vec3<S>(x1.cross(x2))));
    const Line<S> l = join(Point<S>(x1), Point<S>(x2));
    unit = std::max(unit, abs(l.normSquared().first - 1) + abs(l.normSquared().second));
    onl = std::max(onl, std::max(incidenceResidual(Point<S>(x1), l), incidenceResidual(Point<S>(x2), l)));
  }
  c.checkResidual("the book's coordinates: direction x2 − x1, moment x1 × x2 (= x1 × (x2 − x1), u = r × v)", form, tol<S>());
  c.checkResidual("ℓ = p1∨p2/√(…) is a unit line (ℓℓ* = 1)", unit, tol<S>());
  c.checkResidual("both points lie on it", onl, tol<S>());
  // Far points 1 apart, R = 2^min(⌊p/2⌋, p − 16) from the origin (p = significand bits: 6.7e7 in double,
  // 256 in float, where 1e8 + 1 = 1e8 and 1/R must stay above join's rank threshold 1024 ε): R² and
  // R(R + 1) are exact, so the join is exact and the residual is the normalisation's rounding. (With an R
  // that is not a power of 2, x1 × x2 loses ε·R² to cancellation, a relative ε·R on the moment.)
  const S R = ldexp(S(1), std::min(digits<S>() / 2, digits<S>() - 16));
  const Vec3<S> a(R, -R, R), b(R + 1, -R, R);
  const Line<S> far = join(Point<S>(a), Point<S>(b));
  c.checkResidual("far points (2^min(⌊p/2⌋, p − 16) from the origin, 1 apart): both on the line (scale-free)",
                  std::max(incidenceResidual(Point<S>(a), far), incidenceResidual(Point<S>(b), far)), tol<S>());
  c.checkEqual("coincident points: no line", "InvalidInput", [&] {
    try {
      (void)join(Point<S>(a), Point<S>(a));
      return std::string("a line");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
}
SOMA_STUDY_SCALAR("GF-10.2.3-join-two-points", "p1 ∨ p2 = (x2 − x1)·(e2e3, e3e1, e1e2) + (x1 × x2)·(e1𝐞, e2𝐞, e3𝐞)", "GF §10.2.3",
                  joinTwoPoints);

template <class S> void joinPointLine(Context& c) {
  auto g = rng(233);
  S form = 0, contains = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> x = rvec<S>(g), q = rvec<S>(g), v = runit<S>(g);
    const Line<S> l = Line<S>::throughPoint(q, v);
    const Plane<S> j = shuffle(Point<S>(x), l);
    form = std::max(form, md(j.normal(), Vec3<S>(l.moment() - x.cross(v))) + abs(j.distance() - x.dot(l.moment())));
    const Plane<S> pi = join(Point<S>(x), l);
    contains = std::max(contains, std::max(incidenceResidual(Point<S>(x), pi), incidenceResidual(l, pi)));
  }
  c.checkResidual("normal u − x × v = (r − x) × v, distance x·u (book formula, 20 random)", form, tol<S>());
  c.checkResidual("the normalised plane contains p and ℓ", contains, tol<S>(1024));
  const Line<S> l = Line<S>::throughPoint(Vec3<S>(1, 2, 3), Vec3<S>(0, 0, 1));
  c.checkResidual("p on ℓ: p ∨ ℓ = 0 (another incidence test)", shuffle(Point<S>(Vec3<S>(1, 2, 7)), l).element().maxAbs(), S(0));
}
SOMA_STUDY_SCALAR("GF-10.2.3-join-point-line", "p ∨ ℓ = (x·u)𝐞 + (u − x × v)·(e1, e2, e3): the plane of p and ℓ", "GF §10.2.3",
                  joinPointLine);

template <class S> void planeThreePoints(Context& c) {
  auto g = rng(234);
  S contains = 0, orient = 0;
  for (int i = 0; i < 20; ++i) {
    const Vec3<S> x1 = rvec<S>(g), x2 = rvec<S>(g), x3 = rvec<S>(g);
    const Plane<S> pi = join(Point<S>(x1), Point<S>(x2), Point<S>(x3));
    for (const Vec3<S>& x : {x1, x2, x3}) contains = std::max(contains, incidenceResidual(Point<S>(x), pi));
    orient = std::max(orient, md(pi.normal(), Vec3<S>((x2 - x1).cross(x3 - x1).normalized())));
  }
  c.checkResidual("the plane contains the three points (20 random)", contains, tol<S>(64));
  c.checkResidual("unit normal along (x2 − x1) × (x3 − x1)", orient, tol<S>(1024));
  const Vec3<S> a(1, 2, 3), d(frac<S>(3, 10), frac<S>(-1, 5), frac<S>(1, 2));
  c.checkResidual("collinear points: |p1 ∨ p2 ∨ p3| = 0",
                  shuffle(shuffle(Point<S>(a).element(), Point<S>(Vec3<S>(a + d)).element()), Point<S>(Vec3<S>(a - 2 * d)).element()).maxAbs(),
                  tol<S>(16));
}
SOMA_STUDY_SCALAR("GF-10.2.3-plane-three-points", "π = p1 ∨ p2 ∨ p3/√(…); collinear ⇔ p1 ∨ p2 ∨ p3 = 0", "GF §10.2.3",
                  planeThreePoints);

template <class S> void pointPlaneCoplanarity(Context& c) {
  auto g = rng(235);
  c.checkResidual("p ∨ π = d − x·n (a scalar, 20 random)", worst<S>(20, [&](int) {
                    const Vec3<S> x = rvec<S>(g), n = rvec<S>(g);
                    const S d = uni<S>(g);
                    return abs(shuffle(Point<S>(x), Plane<S>(n, d)) - (d - x.dot(n)));
                  }), tol<S>());
  const Plane<S> pi(runit<S>(g), frac<S>(3, 10));
  auto on = [&] { return Point<S>(Vec3<S>(pi.normal() * frac<S>(3, 10) + pi.normal().cross(rvec<S>(g)))); };
  const Point<S> a = on(), b = on(), d = on(), e = on();
  c.checkResidual("four points of one plane: p1 ∨ p2 ∨ p3 ∨ p4 = 0 (scale-free)", coplanarityResidual(a, b, d, e), tol<S>(16));
  const Vec3<S> x = rvec<S>(g);
  Mat3<S> M;
  M.col(0) = b.position() - a.position(), M.col(1) = d.position() - a.position(), M.col(2) = x - a.position();
  const S four = shuffle(shuffle(shuffle(a.element(), b.element()), d.element()), Point<S>(x).element()).scalarPart();
  c.checkNear("a random fourth point: |p1 ∨ p2 ∨ p3 ∨ p4| = |det(x2 − x1, x3 − x1, x4 − x1)| ≠ 0",
              abs(M.determinant()), abs(four), tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.3-point-plane-and-coplanarity", "p ∨ π = d − x·n; four points coplanar ⇔ p1 ∨ p2 ∨ p3 ∨ p4 = 0",
           "GF §10.2.3",
                  pointPlaneCoplanarity);

template <class S> void lineLineShuffle(Context& c) {
  auto g = rng(236);
  c.checkResidual("ℓ1 ∨ ℓ2 = v·μ + u·w (= Q0 of the 6-vectors, 20 random)", worst<S>(20, [&](int) {
                    const Vec3<S> v = rvec<S>(g), u = rvec<S>(g), w = rvec<S>(g), mu = rvec<S>(g);
                    return abs(shuffle(Line<S>(v, u), Line<S>(w, mu)) - (v.dot(mu) + u.dot(w)));
                  }), tol<S>());
  c.checkResidual("= −(distance)·sin∠ for unit lines (skew lines 0.75 apart at 60°)",
                  abs(abs(shuffle(Line<S>::throughPoint(Vec3<S>(0, 0, 0), Vec3<S>(1, 0, 0)),
                                            Line<S>::throughPoint(Vec3<S>(0, 0, frac<S>(3, 4)), Vec3<S>(frac<S>(1, 2), sqrt(S(3)) / 2, 0)))) -
                           frac<S>(3, 4) * sqrt(S(3)) / 2),
                  tol<S>());
  const Vec3<S> o = rvec<S>(g);
  c.checkResidual("two lines through one point: ℓ1 ∨ ℓ2 = 0 (coplanar)",
                  coplanarityResidual(Line<S>::throughPoint(o, runit<S>(g)), Line<S>::throughPoint(o, runit<S>(g))), tol<S>(16));
  c.note("OCR: the printed ℓ1, ℓ2 drop the '+' before u_z e3𝐞 and μ_z e3𝐞 (seed 6238–6240).");
}
SOMA_STUDY_SCALAR("GF-10.2.3-line-line-shuffle", "ℓ1 ∨ ℓ2 = v·μ + u·w, the reciprocal product; coplanar ⇔ 0", "GF §10.2.3",
                  lineLineShuffle);

// ---- §10.2.4 perpendicularity: the contraction ------------------------------------------------

template <class S> void contractionDefinition(Context& c) {
  auto g = rng(241);
  S def = 0, split = 0, deriv = 0, assoc = 0;
  for (int i = 0; i < 20; ++i) {
    DenseElement<S> c1, c2, c3;
    for (int k = 0; k < c1.size; ++k) c1[k] = uni<S>(g), c2[k] = uni<S>(g), c3[k] = uni<S>(g);
    const DenseElement<S> x(Plane<S>(rvec<S>(g), uni<S>(g)).element());
    def = std::max(def, md(DenseElement<S>(x | c1), DenseElement<S>((x * c1 - c1.involute() * x) * frac<S>(1, 2))));
    split = std::max(split, md(DenseElement<S>(x * c1), DenseElement<S>((x ^ c1) + (x | c1))));
    deriv = std::max(deriv, md(DenseElement<S>(x | (c1 ^ c2)),
                               DenseElement<S>(((x | c1) ^ c2) + (c1.involute() ^ (x | c2)))));
    assoc = std::max(assoc, md(DenseElement<S>((c1 ^ c2) | c3), DenseElement<S>(c1 | (c2 | c3))));
  }
  c.checkResidual("x⌋c = ½(xc − α(c)x) for vectors x (clifford::leftContraction, 20 random c)", def, tol<S>());
  c.checkResidual("xc = x ∧ c + x⌋c", split, tol<S>());
  c.checkResidual("x⌋(c1 ∧ c2) = (x⌋c1) ∧ c2 + α(c1) ∧ (x⌋c2)", deriv, tol<S>());
  c.checkResidual("(c1 ∧ c2)⌋c3 = c1⌋(c2⌋c3)", assoc, tol<S>());
  c.note("OCR: seed 6284–6285 renders ⌋ as 'ightharpoonup' inside a broken 'egin' environment.");
}
SOMA_STUDY_SCALAR("GF-10.2.4-contraction-definition", "x⌋c = ½(xc − α(c)x); xc = x ∧ c + x⌋c; the derivation rule; (c1 ∧ c2)⌋c3 = c1⌋(c2⌋c3)",
           "GF §10.2.4",
                  contractionDefinition);

template <class S> void planePlaneAngle(Context& c) {
  auto g = rng(242);
  S form = 0, ang = 0;
  for (int i = 0; i < 20; ++i) {
    const Plane<S> a(runit<S>(g), uni<S>(g)), b(runit<S>(g), uni<S>(g));
    form = std::max(form, abs((a.element() | b.element()).scalarPart() + a.normal().dot(b.normal())));
    const S ref = atan2(a.normal().cross(b.normal()).norm(), a.normal().dot(b.normal()));
    ang = std::max(ang, abs(angle(a, b) - ref));
  }
  c.checkResidual("π1⌋π2 = −(n_x m_x + n_y m_y + n_z m_z) (20 random)", form, tol<S>());
  c.checkResidual("angle = atan2(|π1 ∧ π2| direction, −π1⌋π2) = the angle of the normals", ang, tol<S>());
  c.checkResidual("perpendicular planes: π1⌋π2 = 0",
                  abs((Plane<S>(Vec3<S>(1, 0, 0), 2).element() | Plane<S>(Vec3<S>(0, 1, 0), -1).element()).scalarPart()), S(0));
}
SOMA_STUDY_SCALAR("GF-10.2.4-plane-plane-angle", "π1⌋π2 = −n·m = −cos∠; perpendicular ⇔ 0", "GF §10.2.4",
                  planePlaneAngle);

template <class S> void planeLinePerpendicularPlane(Context& c) {
  auto g = rng(243);
  S form = 0, geo = 0;
  for (int i = 0; i < 20; ++i) {
    const Plane<S> pi(runit<S>(g), uni<S>(g));
    const Line<S> l = Line<S>::throughPoint(rvec<S>(g), runit<S>(g));
    const Plane<S> raw((pi.element() | l.element()).template grade<1>());
    form = std::max(form, md(raw.normal(), Vec3<S>(pi.normal().cross(l.direction()))) +
                              abs(raw.distance() + pi.normal().dot(l.moment())));
    const Plane<S> pp = perpendicularPlane(pi, l);
    const S sn = pi.normal().cross(l.direction()).norm();
    geo = std::max(geo, (incidenceResidual(l, pp) + abs(pp.normal().dot(pi.normal()))) * sn);
  }
  c.checkResidual("π⌋ℓ coordinates (20 random)", form, tol<S>());
  c.checkResidual("the normalised π⊥ contains ℓ and is ⟂ π (scaled by sin∠)", geo, tol<S>());
  c.checkEqual("ℓ ⟂ π: π⌋ℓ = 0, no unique plane", "InvalidInput", [&] {
    try {
      (void)perpendicularPlane(Plane<S>(Vec3<S>(0, 0, 1), 0), Line<S>::throughPoint(Vec3<S>(1, 1, 1), Vec3<S>(0, 0, 1)));
      return std::string("a plane");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
}
SOMA_STUDY_SCALAR("GF-10.2.4-plane-line-perpendicular-plane", "π⌋ℓ = (n × v)·(e1, e2, e3) − (n·u)𝐞: the plane through ℓ perpendicular to π",
           "GF §10.2.4",
                  planeLinePerpendicularPlane);

template <class S> void planePointPerpendicularLine(Context& c) {
  auto g = rng(244);
  c.checkResidual("π⌋p = the line through p with direction −n, unit without normalising (20 random)", worst<S>(20, [&](int) {
                    const Plane<S> pi(runit<S>(g), uni<S>(g));
                    const Vec3<S> x = rvec<S>(g, 2);
                    const Line<S> l((pi.element() | Point<S>(x).element()).template grade<2>());
                    return md(l.element(), Line<S>::throughPoint(x, Vec3<S>(-pi.normal())).element()) +
                           abs(l.normSquared().first - 1);
                  }), tol<S>());
  const Plane<S> pi(runit<S>(g), frac<S>(1, 2));
  const Vec3<S> x = rvec<S>(g);
  c.checkResidual("perpendicularLine (divided by −1) meets π at the foot x − (n·x − d)n",
                  md(meet(perpendicularLine(pi, Point<S>(x)), pi).position(), Vec3<S>(x - pi.normal() * (pi.normal().dot(x) - frac<S>(1, 2)))),
                  tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.4-plane-point-perpendicular-line", "π⌋p = −n·(e2e3, …) − (x × n)·(e1𝐞, …) = line(p, −n)", "GF §10.2.4",
                  planePointPerpendicularLine);

template <class S> void lineLineAngle(Context& c) {
  auto g = rng(245);
  S form = 0, ang = 0;
  for (int i = 0; i < 20; ++i) {
    const Line<S> a(rvec<S>(g), rvec<S>(g)), b(rvec<S>(g), rvec<S>(g));
    form = std::max(form, abs((a.element() | b.element()).scalarPart() + a.direction().dot(b.direction())));
    ang = std::max(ang, abs(angle(a, b) - atan2(a.direction().cross(b.direction()).norm(), a.direction().dot(b.direction()))));
  }
  c.checkResidual("ℓ1⌋ℓ2 = −(v_x w_x + v_y w_y + v_z w_z), a scalar (20 random)", form, tol<S>());
  c.checkResidual("angle from −ℓ1⌋ℓ2 and ½[ℓ1, ℓ2] by atan2", ang, tol<S>());
  c.checkResidual("perpendicular skew lines: ℓ1⌋ℓ2 = 0",
                  abs((Line<S>::throughPoint(Vec3<S>(0, 0, 0), Vec3<S>(1, 0, 0)).element() |
                            Line<S>::throughPoint(Vec3<S>(0, 0, 3), Vec3<S>(0, 1, 0)).element()).scalarPart()),
                  S(0));
}
SOMA_STUDY_SCALAR("GF-10.2.4-line-line-angle", "ℓ1⌋ℓ2 = −v·w (the Killing form); perpendicular ⇔ 0", "GF §10.2.4",
                  lineLineAngle);

template <class S> void linePointPerpendicularPlane(Context& c) {
  auto g = rng(246);
  c.checkResidual("ℓ⌋p coordinates (20 random)", worst<S>(20, [&](int) {
                    const Line<S> l = Line<S>::throughPoint(rvec<S>(g), runit<S>(g));
                    const Vec3<S> x = rvec<S>(g);
                    const Plane<S> p((l.element() | Point<S>(x).element()).template grade<1>());
                    return md(p.normal(), Vec3<S>(-l.direction())) + abs(p.distance() + x.dot(l.direction()));
                  }), tol<S>());
  const Line<S> l = Line<S>::throughPoint(rvec<S>(g), runit<S>(g));
  const Vec3<S> x = rvec<S>(g);
  const Plane<S> pp = perpendicularPlane(l, Point<S>(x));
  c.checkResidual("it passes through p and its normal is ±v (|v × n| = 0)",
                  incidenceResidual(Point<S>(x), pp) + pp.normal().cross(l.direction()).norm(), tol<S>());
  const Vec3<S> q = l.pointNearestOrigin(), v = l.direction();
  c.checkResidual("ℓ ∧ (plane) = the foot of the perpendicular q + v(v·(x − q))",
                  md(project(Point<S>(x), l).position(), Vec3<S>(q + v * v.dot(x - q))), tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.4-line-point-perpendicular-plane", "ℓ⌋p = −v·(e1, e2, e3) − (x·v)𝐞: the plane through p ⟂ ℓ", "GF §10.2.4",
                  linePointPerpendicularPlane);

template <class S> void distances(Context& c) {
  auto g = rng(247);
  S pl = 0, pli = 0, pp = 0, one = 0;
  for (int i = 0; i < 20; ++i) {
    const Plane<S> pi(runit<S>(g), uni<S>(g));
    const Vec3<S> x = rvec<S>(g, 2), y = rvec<S>(g, 2);
    pl = std::max(pl, abs(abs(shuffle(Point<S>(x), pi)) - abs(pi.normal().dot(x) - pi.distance())));
    const Line<S> l = Line<S>::throughPoint(rvec<S>(g), runit<S>(g));
    const S d2 = shuffle(Point<S>(x), l).normSquared();
    pli = std::max(pli, abs(d2 - (x - l.pointNearestOrigin()).cross(l.direction()).squaredNorm()));
    const auto j = shuffle(Point<S>(x).element(), Point<S>(y).element());
    pp = std::max(pp, abs(-(j | j).scalarPart() - (x - y).squaredNorm()));
    one = std::max(one, abs((Point<S>(x).element() | Point<S>(y).element()).scalarPart() - 1));
  }
  c.checkResidual("|p ∨ π| = |n·x − d| (20 random)", pl, tol<S>());
  c.checkResidual("(p ∨ ℓ)(p ∨ ℓ)* = squared point–line distance", pli, tol<S>());
  c.checkResidual("−(p1 ∨ p2)⌋(p1 ∨ p2) = |x1 − x2|²", pp, tol<S>());
  c.checkResidual("p1⌋p2 = 1 (says nothing)", one, tol<S>());
  // The sign: a point δ = 0.25 along +n from the plane.
  const Plane<S> pi(runit<S>(g), frac<S>(3, 5));
  const Vec3<S> x = pi.normal() * (frac<S>(3, 5) + frac<S>(1, 4));
  const S pv = shuffle(Point<S>(x), pi);
  c.checkPrintedFails("p ∨ π is positive when p is on the side the normal points to (p ∨ π + 0.25)", "E10.10",
              abs(pv - frac<S>(1, 4)), tol<S>());
  c.checkNear("p ∨ π = d − x·n = −0.25 there (corrected: negative on the normal's side)", frac<S>(-1, 4), pv, tol<S>());
  c.checkNear("signedDistance(p, π) = n·x − d = +0.25", frac<S>(1, 4), signedDistance(Point<S>(x), pi), tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.4-distances", "Signed point–plane distance p ∨ π (E10.10), point–line (p∨ℓ)(p∨ℓ)*, point–point −(p1∨p2)⌋(p1∨p2)",
           "GF §10.2.4",
                  distances);

template <class S> void commonPerpendicular(Context& c) {
  auto g = rng(248);
  S cond = 0, meets = 0, pitch = 0, sI = 0, closest = 0;
  for (int i = 0; i < 30; ++i) {
    const Line<S> a = Line<S>::throughPoint(rvec<S>(g), runit<S>(g)), b = Line<S>::throughPoint(rvec<S>(g), runit<S>(g));
    const Line<S> s = commutator(a, b);
    // s satisfies the equations; its pitch (s ∨ s)/(−2 s⌋s) is Line::pitch.
    cond = std::max(cond, abs((s.element() | a.element()).scalarPart()) + abs(shuffle(s, a)) +
                              abs((s.element() | b.element()).scalarPart()) + abs(shuffle(s, b)));
    const S ss = (s.element() | s.element()).scalarPart();
    pitch = std::max(pitch, abs(shuffle(s, s) / (-2 * ss) - s.pitch()));
    const auto I = Grade4<S>::basisBlade(basis::e123e.mask);
    const Line<S> si((s.element() | I).template grade<2>());
    sI = std::max(sI, md(si.element(), Line<S>(Vec3<S>::Zero(), Vec3<S>(-s.direction())).element()));
    const Line<S> l = commonPerpendicular(a, b);
    const S sn = a.direction().cross(b.direction()).norm();
    meets = std::max(meets, (abs((l.element() | a.element()).scalarPart()) + abs(shuffle(l, a)) +
                             abs((l.element() | b.element()).scalarPart()) + abs(shuffle(l, b)) +
                             abs(l.normSquared().first - 1) + abs(l.normSquared().second)) * sn * sn);
    // Closest points by coordinates lie on ℓ.
    const Vec3<S> r1 = a.pointNearestOrigin(), r2 = b.pointNearestOrigin(), v1 = a.direction(), v2 = b.direction();
    const S k = v1.dot(v2), e1 = v1.dot(r2 - r1), e2 = v2.dot(r2 - r1);
    const Vec3<S> c1 = r1 + v1 * ((e1 - k * e2) / (1 - k * k)), c2 = r2 + v2 * ((k * e1 - e2) / (1 - k * k));
    closest = std::max(closest, (incidenceResidual(Point<S>(c1), l) + incidenceResidual(Point<S>(c2), l)) * sn * sn);
  }
  c.checkResidual("s = ℓ1ℓ2 − ℓ2ℓ1: s⌋ℓi = 0 and s ∨ ℓi = 0 (30 random pairs)", cond, tol<S>());
  c.checkResidual("pitch h = (s ∨ s)/(−2 s⌋s) = v·u/|v|² of s", pitch, tol<S>());
  c.checkResidual("s⌋e1e2e3𝐞 = −(v_x e1𝐞 + v_y e2𝐞 + v_z e3𝐞)", sI, tol<S>());
  c.checkResidual("ℓ = λ/√(λλ*): unit line, ⟂ and meeting both (× sin²∠)", meets, tol<S>(1024));
  c.checkResidual("the closest points of ℓ1, ℓ2 (coordinates) lie on ℓ (× sin²∠)", closest, tol<S>(1024));
  c.checkEqual("parallel lines: s⌋s = s ∨ s = 0, no unique perpendicular", "InvalidInput", [&] {
    try {
      (void)commonPerpendicular(Line<S>::throughPoint(Vec3<S>(0, 0, 0), Vec3<S>(1, 0, 0)), Line<S>::throughPoint(Vec3<S>(0, 1, 0), Vec3<S>(1, 0, 0)));
      return std::string("a line");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
  const Line<S> cross = commonPerpendicular(Line<S>::throughPoint(Vec3<S>(1, 2, 3), Vec3<S>(1, 0, 0)),
                                            Line<S>::throughPoint(Vec3<S>(1, 2, 3), Vec3<S>(0, 1, 0)));
  c.checkResidual("intersecting lines (h = 0): the normal line through the intersection",
                  md(cross.element(), Line<S>::throughPoint(Vec3<S>(1, 2, 3), Vec3<S>(0, 0, 1)).element()), tol<S>());
}
SOMA_STUDY_SCALAR("GF-10.2.4-common-perpendicular", "λ = −2(s⌋s)s + (s⌋e1e2e3𝐞)(s ∨ s), s = [ℓ1, ℓ2]: the common perpendicular",
           "GF §10.2.4",
                  commonPerpendicular);

}  // namespace
}  // namespace soma::studies::gf10::SOMA_UNITY_ID
