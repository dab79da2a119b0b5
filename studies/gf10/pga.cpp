// Studies of GF chapter 10, §10.1–10.2: points, lines and planes in the Clifford algebra
// Cl(0,3,1) — the elements and their motions, incidence, meets (exterior product), joins (the
// book's shuffle product), perpendiculars, angles and distances (contraction), the common
// perpendicular; errata E10.1, E10.10, E10.11. Double only (scalarGeneric = false): the library
// is instantiated and tested for all five scalars in tests/geometry/pga.
#include "soma/geometry/pga/angle.hpp"
#include "soma/geometry/pga/common_perpendicular.hpp"
#include "soma/geometry/pga/distance.hpp"
#include "soma/geometry/pga/incidence.hpp"
#include "soma/geometry/pga/motor.hpp"
#include "soma/geometry/pga/projection.hpp"
#include "soma/geometry/pga/reflection.hpp"
#include "soma/studies/study.hpp"

#include <Eigen/LU>
#include <random>

namespace soma::studies::gf10::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace soma::pga;
using S = double;
using V3 = Vec3<S>;
constexpr const char* kChapter = "GF 10 — Points, lines, planes; Pieper robots";

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
V3 rvec(std::mt19937_64& g, double r = 1) { return V3(uni(g, -r, r), uni(g, -r, r), uni(g, -r, r)); }
V3 runit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  V3 v;
  do v = V3(n(g), n(g), n(g));
  while (v.squaredNorm() < 1e-6);
  return v.normalized();
}
double md(const V3& a, const V3& b) { return (a - b).cwiseAbs().maxCoeff(); }
template <clifford::GradeMask A, clifford::GradeMask B>
double md(const clifford::Multivector<Cl031, S, A>& a, const clifford::Multivector<Cl031, S, B>& b) {
  return clifford::maxAbsDiff(a, b);
}
double tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }
/// Runs f over `n` random trials and returns the largest value it reports.
template <class F> double worst(int n, F&& f) {
  double w = 0;
  for (int i = 0; i < n; ++i) w = std::max(w, f(i));
  return w;
}
SE3<S> randomMotion(std::mt19937_64& g, double r = 2) { return SE3<S>(SO3<S>::Random(g), rvec(g, r)); }

// ---- §10.1 the elements -----------------------------------------------------------------------

SOMA_STUDY_DOUBLE("GF-10.1.1-planes", "Planes π = n + d𝐞: ππ* = 1, the motion law n' = Rn, d' = d + Rn·t", "GF §10.1.1",
           [](Context& c) {
             auto g = rng(101);
             c.checkResidual("ππ* = |n|² (20 random (n, d))", worst(20, [&](int) {
                               const V3 n = rvec(g);
                               return std::abs(Plane<S>(n, uni(g)).normSquared() - n.squaredNorm());
                             }), tol());
             double law = 0, expl = 0, hstar = 0;
             for (int i = 0; i < 20; ++i) {
               const double big = i % 5 == 4 ? 1e6 : 1;  // large |t| too
               const SE3<S> m(SO3<S>::Random(g), rvec(g, 2 * big));
               const Motor<S> h = Motor<S>::fromSE3(m);
               const Plane<S> pi(runit(g), uni(g));
               const Plane<S> p2 = h(pi);
               const V3 Rn = m.rotation() * pi.normal();
               law = std::max(law, std::max(md(p2.normal(), Rn),
                                            std::abs(p2.distance() - (pi.distance() + Rn.dot(m.translation()))) / big));
               // The book's explicit form g n g* + (d − ½(gng*t + tgng*))𝐞, computed in the algebra.
               const Quat<S>& q = m.quaternion();
               EvenElement<S> gg(q.w());
               setBookCoeff(gg, basis::e23, q.x());
               setBookCoeff(gg, basis::e31, q.y());
               setBookCoeff(gg, basis::e12, q.z());
               const Grade1<S> n(Plane<S>(pi.normal(), 0).element()), t(Plane<S>(m.translation(), 0).element());
               const auto gng = (gg * n * gg.conjugate()).grade<1>();
               const auto E = Grade1<S>::basisBlade(basis::e.mask);
               const auto dd = (t * gng + gng * t).scalarPart();
               const Grade1<S> book(gng + Grade1<S>(E * (pi.distance() - dd / 2)));
               expl = std::max(expl, md(book, p2.element()) / big);
               // h* = g* + ½𝐞g*t (GF §10.1.1).
               const EvenElement<S> hs(gg.conjugate() + EvenElement<S>((E * gg.conjugate() * t) * 0.5));
               hstar = std::max(hstar, md(hs, h.conjugate().element()) / big);
             }
             c.checkResidual("hπh*: n' = Rn, d' = d + (Rn)·t (20 motions, |t| up to 2e6, relative)", law, tol());
             c.checkResidual("hπh* = gng* + (d − ½(gng*t + tgng*))𝐞 (the book's expansion)", expl, tol());
             c.checkResidual("h* = g* + ½𝐞g*t", hstar, tol());
             c.checkEqual("the plane at infinity 𝐞 cannot be normalised", "InvalidInput", [] {
               try {
                 (void)Plane<S>::atInfinity().normalized();
                 return std::string("normalised");
               } catch (const InvalidInput&) { return std::string("InvalidInput"); }
             }());
             c.checkResidual("d = 0 (plane through the origin) moves to d' = Rn·t",
                             [&] {
                               const SE3<S> m = randomMotion(g);
                               const Plane<S> p(V3(0, 0, 1), 0);
                               return std::abs(Motor<S>::fromSE3(m)(p).distance() - (m.rotation() * V3(0, 0, 1)).dot(m.translation()));
                             }(),
                             tol());
           });

SOMA_STUDY_DOUBLE("GF-10.1.2-points-and-free-vectors", "Points e1e2e3 + x e2e3𝐞 + …: pp* = 1, hph* = point(Rx + t), free vectors rotate",
           "GF §10.1.2", [](Context& c) {
             auto g = rng(102);
             double conj = 0, norm = 0, act = 0, freev = 0, neg = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 x = rvec(g, 3);
               const Point<S> p(x);
               conj = std::max(conj, md(p.element().conjugate(), p.element()));
               norm = std::max(norm, std::abs(p.normSquared() - 1));
               const SE3<S> m = randomMotion(g);
               const Motor<S> h = Motor<S>::fromSE3(m);
               act = std::max(act, md(h(p).position(), m.act(x)));
               const Point<S> f = h(Point<S>::freeVector(x));
               freev = std::max(freev, md(f.bulk(), V3(m.rotation() * x)) + std::abs(f.weight()));
               // Negative points: weight −1 stays −1 and the place moves like a point.
               const Point<S> n2 = h(-p);
               neg = std::max(neg, std::abs(n2.weight() + 1) + md(n2.position(), m.act(x)));
             }
             c.checkResidual("p* = p", conj, 0.0);
             c.checkResidual("pp* = 1", norm, tol());
             c.checkResidual("hph* = point(R x + t) (SE3::act, 20 random)", act, tol());
             c.checkResidual("hfh* = gfg* (free vectors: rotation only, weight stays 0)", freev, tol());
             c.checkResidual("negative points (weight −1) keep their weight and move like points", neg, tol());
             // Sorted-blade storage: e3e1𝐞 = −e1e3𝐞.
             const Point<S> py(V3(0, 1, 0));
             c.checkNear("coefficient of the sorted blade e1e3𝐞 for y = 1 is −1 (e3e1𝐞 = −e1e3𝐞)", -1.0,
                         py.element().coeff(basis::e31e.mask), 0.0);
           });

SOMA_STUDY_DOUBLE("GF-10.1.3-lines", "Lines v·(e2e3, e3e1, e1e2) + u·(e1𝐞, e2𝐞, e3𝐞): ℓℓ* = |v|² − 2(v·u)e1e2e3𝐞; hℓh*",
           "GF §10.1.3", [](Context& c) {
             auto g = rng(103);
             double cj = 0, nn = 0, act = 0, rev = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 v = rvec(g), u = rvec(g);
               const Line<S> l(v, u);
               cj = std::max(cj, md(l.element().conjugate(), Grade2<S>(-l.element())));
               const auto [n0, n4] = l.normSquared();
               nn = std::max(nn, std::abs(n0 - v.squaredNorm()) + std::abs(n4 + 2 * v.dot(u)));
               const V3 q = rvec(g), d = runit(g);
               const SE3<S> m = randomMotion(g);
               const Line<S> moved = Motor<S>::fromSE3(m)(Line<S>::throughPoint(q, d));
               act = std::max(act, md(moved.element(), Line<S>::throughPoint(m.act(q), V3(m.rotation() * d)).element()));
               rev = std::max(rev, md((-Line<S>::throughPoint(q, d)).element(), Line<S>::throughPoint(q, V3(-d)).element()));
             }
             c.checkResidual("ℓ* = −ℓ", cj, 0.0);
             c.checkResidual("ℓℓ* = |v|² − 2(v·u) e1e2e3𝐞 (so ℓℓ* = 1 ⇔ |v| = 1 and v·u = 0)", nn, tol());
             c.checkResidual("hℓh* = line(Rq + t, Rv)", act, tol());
             c.checkResidual("−ℓ is the line with the opposite direction", rev, 0.0);
             const Line<S> screw(V3(0, 0, 1), V3(0.5, 0, 0.3));
             c.checkNear("a grade-2 element with v·u ≠ 0 is a screw: pitch v·u/|v|²", 0.3, screw.pitch(), tol());
             c.checkEqual("… and fails the Klein condition", "screw", screw.isLine() ? "line" : "screw");
             // The motion of a screw is the adjoint action.
             const SE3<S> m = randomMotion(g);
             const SE3Tangent<S> xi(Vec6<S>::Random());
             c.checkResidual("hsh* = Ad(g) s for a screw s (SE3::adjoint)",
                             (Motor<S>::fromSE3(m)(Line<S>::fromTwist(xi)).toTwist().coeffs() - m.adjoint() * xi.coeffs())
                                 .cwiseAbs()
                                 .maxCoeff(),
                             tol());
           });

// ---- §10.2.1 incidence ------------------------------------------------------------------------

SOMA_STUDY_DOUBLE("GF-10.2.1-incidence-plane-point", "π ∧ p = ½(πp − pπ) = (x·n − d)e1e2e3𝐞", "GF §10.2.1", [](Context& c) {
  auto g = rng(211);
  c.checkResidual("π ∧ p = ½(πp − pπ) = (x·n − d) e1e2e3𝐞 (20 random)", worst(20, [&](int) {
                    const Plane<S> pi(rvec(g), uni(g));
                    const V3 x = rvec(g);
                    const Point<S> p(x);
                    const auto w = pi.element() ^ p.element();
                    const auto comm = (pi.element() * p.element() - p.element() * pi.element()) * 0.5;
                    return md(w, comm) + std::abs(bookCoeff(w, basis::e123e) - (x.dot(pi.normal()) - pi.distance()));
                  }), tol());
  const Plane<S> pi(runit(g), 0.4);
  const V3 on = pi.normal() * 0.4 + pi.normal().cross(rvec(g));
  c.checkResidual("a point built on the plane: |π ∧ p| (scale-free)", incidenceResidual(Point<S>(on), pi), tol(16));
  const V3 far = on * 1e8 + pi.normal() * (0.4 - 0.4 * 1e8);  // on the plane, 1e8 away
  c.checkResidual("a point on the plane 1e8 from the origin (scale-free residual)", incidenceResidual(Point<S>(far), pi), tol(16));
  const double r = Tolerance<S>::rank(), sc = on.norm() + 0.4;
  c.checkEqual("off by 2·rank·scale along n: not incident", "not incident",
               incident(Point<S>(V3(on + pi.normal() * (2 * r * sc))), pi) ? "incident" : "not incident");
  c.checkEqual("off by rank/4·scale: incident", "incident",
               incident(Point<S>(V3(on + pi.normal() * (r / 4 * sc))), pi) ? "incident" : "not incident");
});

SOMA_STUDY_DOUBLE("GF-10.2.1-incidence-plane-line", "π ∧ ℓ = ½(πℓ + ℓπ) = (n·v)e1e2e3 + (n × u + d v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞) (E10.1)",
           "GF §10.2.1", [](Context& c) {
             auto g = rng(212);
             double sym = 0, corrected = 0, printed = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 n = rvec(g), v = rvec(g), u = rvec(g);
               const double d = uni(g);
               const auto pi = Plane<S>(n, d).element();
               const auto l = Line<S>(v, u).element();
               const auto w = pi ^ l;
               sym = std::max(sym, md(w, (pi * l + l * pi) * 0.5));
               const double e12e = bookCoeff(w, basis::e12e);
               corrected = std::max(corrected, std::abs(bookCoeff(w, basis::e123) - n.dot(v)) +
                                                   std::abs(bookCoeff(w, basis::e23e) - (n.y() * u.z() - n.z() * u.y() + d * v.x())) +
                                                   std::abs(bookCoeff(w, basis::e31e) - (n.z() * u.x() - n.x() * u.z() + d * v.y())) +
                                                   std::abs(e12e - (n.x() * u.y() - n.y() * u.x() + d * v.z())));
               printed = std::max(printed, std::abs(e12e - (n.x() * u.y() - n.y() * u.x() + d * v.x())));
             }
             c.checkResidual("π ∧ ℓ = ½(πℓ + ℓπ)", sym, tol());
             c.checkResidual("coefficients with the e1e2𝐞 term n_x u_y − n_y u_x + d v_z (corrected)", corrected, tol());
             c.checkPrintedFails("e1e2𝐞 coefficient n_x u_y − n_y u_x + d v_x", "E10.1", printed, tol());
             const Plane<S> z0(V3(0, 0, 1), 0);
             const Line<S> inside = Line<S>::throughPoint(V3(1, 2, 0), V3(1, -1, 0));
             c.checkResidual("a line inside the plane: π ∧ ℓ = 0", incidenceResidual(inside, z0), tol(16));
             const auto par = z0.element() ^ Line<S>::throughPoint(V3(1, 2, 0.5), V3(1, -1, 0)).element();
             c.checkResidual("parallel but off the plane: the e1e2e3 part vanishes", std::abs(bookCoeff(par, basis::e123)), 0.0);
             c.checkNear("… while the 𝐞-parts do not (|n × u + d v| = 0.5·|v|)", 0.5 * std::sqrt(2.0),
                         Point<S>(par).bulk().norm(), tol());
           });

SOMA_STUDY_DOUBLE("GF-10.2.1-incidence-point-line", "pℓ* + ℓp* = 2(u − p × v)·(e2e3𝐞, e3e1𝐞, e1e2𝐞); ℓ ∧ p ≡ 0", "GF §10.2.1",
           [](Context& c) {
             auto g = rng(213);
             double form = 0, wedge0 = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 x = rvec(g), v = rvec(g), u = rvec(g);
               const auto p = Point<S>(x).element();
               const auto l = Line<S>(v, u).element();
               const auto r = (p * l.conjugate() + l * p.conjugate()).grade<3>();
               form = std::max(form, md(Point<S>(r).bulk(), V3(2 * (u - x.cross(v)))) + std::abs(Point<S>(r).weight()));
               wedge0 = std::max(wedge0, DenseElement<S>(l ^ p).maxAbs());
             }
             c.checkResidual("pℓ* + ℓp* = 2(z v_y − y v_z + u_x) e2e3𝐞 + … (20 random)", form, tol());
             c.checkResidual("ℓ ∧ p = 0 for all lines and points (grades add past 4)", wedge0, 0.0);
             const V3 q = rvec(g), d = runit(g);
             c.checkResidual("a point on the line: p × v = u", incidenceResidual(Point<S>(V3(q + 0.7 * d)), Line<S>::throughPoint(q, d)), tol(16));
           });

// ---- §10.2.2 meets ----------------------------------------------------------------------------

SOMA_STUDY_DOUBLE("GF-10.2.2-meet-two-planes", "ℓ = π1 ∧ π2/√((π1∧π2)(π1∧π2)*); parallel planes meet at infinity", "GF §10.2.2",
           [](Context& c) {
             auto g = rng(221);
             double scal = 0, book = 0, inc = 0, dir = 0;
             for (int i = 0; i < 20; ++i) {
               const Plane<S> a(runit(g), uni(g)), b(runit(g), uni(g));
               const auto w = a.element() ^ b.element();
               const auto ww = w * w.conjugate();
               scal = std::max(scal, std::abs(bookCoeff(ww, basis::e123e)) + DenseElement<S>(ww.grades<0b11110>()).maxAbs());
               const auto p1 = a.element(), p2 = b.element();
               const auto rhs = (DenseElement<S>(S(2)) - DenseElement<S>(p2 * p1 * p2 * p1) - DenseElement<S>(p1 * p2 * p1 * p2)) * 0.25;
               book = std::max(book, md(DenseElement<S>(ww), rhs));
               const Line<S> l = meet(a, b);
               inc = std::max(inc, std::max(incidenceResidual(l, a), incidenceResidual(l, b)));
               dir = std::max(dir, md(l.direction(), V3(a.normal().cross(b.normal()).normalized())));
             }
             c.checkResidual("(π1∧π2)(π1∧π2)* is a scalar (no grade 2, 3, 4 part)", scal, tol());
             c.checkResidual("… = ¼(2 − π2π1π2π1 − π1π2π1π2) for unit planes", book, tol());
             c.checkResidual("π_i ∧ ℓ = 0: the meet lies in both planes (scale-free)", inc, tol());
             c.checkResidual("direction n1 × n2/|n1 × n2|", dir, tol());
             const double r = Tolerance<S>::rank();
             const Plane<S> z0(V3(0, 0, 1), 0);
             auto tilt = [](double s) { return V3(s, 0, std::sqrt(1 - s * s)); };
             const Line<S> l2 = meet(z0, Plane<S>(tilt(2 * r), 1));
             c.checkEqual("nearly parallel, sin∠ = 2·rank: a finite line", "finite", l2.isAtInfinity() ? "at infinity" : "finite");
             c.checkResidual("… lying in both planes", std::max(incidenceResidual(l2, z0), incidenceResidual(l2, Plane<S>(tilt(2 * r), 1))), tol());
             const Line<S> lh = meet(z0, Plane<S>(tilt(r / 2), 1));
             c.checkEqual("sin∠ = rank/2: the line at infinity (v = 0, no division by ~0)", "at infinity",
                          lh.isAtInfinity() ? "at infinity" : "finite");
             c.checkEqual("parallel planes z = 0, z = 3: the line at infinity", "at infinity",
                          meet(z0, Plane<S>(V3(0, 0, 1), 3)).isAtInfinity() ? "at infinity" : "finite");
             c.checkEqual("coincident planes: no line", "InvalidInput", [&] {
               try {
                 (void)meet(z0, Plane<S>(V3(0, 0, -2), 0));
                 return std::string("a line");
               } catch (const InvalidInput&) { return std::string("InvalidInput"); }
             }());
             c.note("The book's remark that the grade-4 terms cancel (seed 6147) prints e_ke_je_ie_j for e_ke_le_ie_j (typo).");
           });

SOMA_STUDY_DOUBLE("GF-10.2.2-meet-line-plane", "p = ℓ ∧ π/±√((ℓ∧π)(ℓ∧π)*), sign making the e1e2e3 coefficient +1", "GF §10.2.2",
           [](Context& c) {
             auto g = rng(222);
             double on = 0, ref = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 q = rvec(g), v = runit(g);
               const Line<S> l = Line<S>::throughPoint(q, v);
               const Plane<S> pi(runit(g), uni(g));
               const Point<S> p = meet(l, pi);
               on = std::max(on, std::max(incidenceResidual(p, l), incidenceResidual(p, pi)) + std::abs(p.weight() - 1));
               const double s = (pi.distance() - pi.normal().dot(q)) / pi.normal().dot(v);
               ref = std::max(ref, md(p.position(), V3(q + s * v)) * std::abs(pi.normal().dot(v)) / (1 + std::abs(s)));
             }
             c.checkResidual("the meet lies on ℓ (p × v = u) and on π, weight +1 (20 random)", on, tol());
             c.checkResidual("= q + s v with s = (d − n·q)/(n·v) (conditioning-scaled)", ref, tol());
             const double r = Tolerance<S>::rank();
             const Plane<S> z0(V3(0, 0, 1), 0);
             const Point<S> f = meet(Line<S>::throughPoint(V3(0, 0, 1), V3(std::sqrt(1 - r * r / 4), 0, r / 2)), z0);
             c.checkEqual("line at angle rank/2 to the plane: the point at infinity (free vector ±v)", "at infinity",
                          f.isAtInfinity() ? "at infinity" : "finite");
             const Point<S> p2 = meet(Line<S>::throughPoint(V3(0, 0, 1), V3(std::sqrt(1 - 4 * r * r), 0, 2 * r)), z0);
             c.checkNear("angle 2·rank: a finite point at x = −cot∠ ≈ −1/(2·rank) (2.2e12)", -std::sqrt(1 - 4 * r * r) / (2 * r), p2.position().x(),
                         Tolerance<S>::rank() / (2 * r));
           });

SOMA_STUDY_DOUBLE("GF-10.2.2-meet-three-planes", "p = π1 ∧ π2 ∧ π3/±√(…) against a 3×3 linear solve", "GF §10.2.2", [](Context& c) {
  auto g = rng(223);
  double err = 0;
  for (int i = 0; i < 50; ++i) {
    const Plane<S> a(runit(g), uni(g)), b(runit(g), uni(g)), d(runit(g), uni(g));
    Mat3<S> N;
    N.row(0) = a.normal().transpose(), N.row(1) = b.normal().transpose(), N.row(2) = d.normal().transpose();
    const V3 x = N.fullPivLu().solve(V3(a.distance(), b.distance(), d.distance()));
    const double cond = N.norm() * N.inverse().norm();
    err = std::max(err, md(meet(a, b, d).position(), x) / (cond * (1 + x.norm())));
  }
  c.checkResidual("meet of 3 planes = solution of [n1 n2 n3]ᵀx = d (50 random, relative to cond·|x|)", err, tol(64));
  const Plane<S> z0(V3(0, 0, 1), 0), x0(V3(1, 0, 0), 0);
  const Point<S> prism = meet(z0, x0, Plane<S>(V3(1, 0, 1).normalized(), 1));
  c.checkEqual("a prism (normals coplanar, no common line): point at infinity", "at infinity",
               prism.isAtInfinity() ? "at infinity" : "finite");
  c.checkNear("… in the direction of its edges (±e_y)", 1.0, std::abs(prism.bulk().y()), tol());
  c.checkEqual("three planes through one line: no point", "InvalidInput", [&] {
    try {
      (void)meet(z0, x0, Plane<S>(V3(1, 0, 1).normalized(), 0));
      return std::string("a point");
    } catch (const InvalidInput&) { return std::string("InvalidInput"); }
  }());
});

// ---- §10.2.3 joins: the shuffle product -------------------------------------------------------

/// The book's shuffle formula read with n = `n` (the printed text says "n the dimension of the
/// algebra", i.e. 16; E10.11): the coefficient of blade(a) ∨ blade(b), 0 when j + k < n.
int shuffleWithN(Blade a, Blade b, int n) {
  const int j = std::popcount(a), k = std::popcount(b);
  if (j + k < n) return 0;
  return shuffleCoefficient(a, b);  // for n = 4 the corrected formula (shuffle.hpp)
}

SOMA_STUDY_DOUBLE("GF-10.2.3-shuffle-definition",
           "The shuffle product by the book's permutation formula (E10.11) = the regressive product; e1e2e3 ∨ e2e3𝐞 = e2e3",
           "GF §10.2.3", [](Context& c) {
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
             c.checkResidual("a ∨ b (permutation formula) = a & b (Poincaré duality) on 20 random dense pairs", worst(20, [&](int) {
                               DenseElement<S> a, b;
                               for (int i = 0; i < a.size; ++i) a[i] = uni(g), b[i] = uni(g);
                               return md(shuffle(a, b), a & b);
                             }), tol(64));
             int printedNonzero = 0;
             for (Blade a = 0; a < 16; ++a)
               for (Blade b = 0; b < 16; ++b) printedNonzero += shuffleWithN(a, b, 16) != 0;
             c.checkPrintedFails("n = \"the dimension of the algebra\" = 16: j + k ≥ n never holds, so every shuffle is 0 and "
                            "e1e2e3 ∨ e2e3𝐞 = e2e3 is lost (|1 − coefficient|)", "E10.11",
                         std::abs(1.0 - shuffleWithN(7, 14, 16)), 0.0);
             c.checkEqual("… non-zero pairs with n = 16", 0, printedNonzero);
             c.note("E10.11: n is the dimension of the generator space (4), the index a_σ(4−k+1) should read "
                    "a_σ(n−k+1) (the same for n = 4) and the last determinant column is b_ki, not b_σ(k)i. "
                    "The sum over σ ∈ S_j counts each split (n−k)!(j+k−n)! times, hence the prefactor: the "
                    "coefficients come out in {−1, 0, 1} (asserted when the table is built).");
           });

SOMA_STUDY_DOUBLE("GF-10.2.3-join-two-points", "p1 ∨ p2 = (x2 − x1)·(e2e3, e3e1, e1e2) + (x1 × x2)·(e1𝐞, e2𝐞, e3𝐞)", "GF §10.2.3",
           [](Context& c) {
             auto g = rng(232);
             double form = 0, unit = 0, onl = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 x1 = rvec(g), x2 = rvec(g);
               const Line<S> j = shuffle(Point<S>(x1), Point<S>(x2));
               form = std::max(form, md(j.direction(), V3(x2 - x1)) + md(j.moment(), V3(x1.cross(x2))));
               const Line<S> l = join(Point<S>(x1), Point<S>(x2));
               unit = std::max(unit, std::abs(l.normSquared().first - 1) + std::abs(l.normSquared().second));
               onl = std::max(onl, std::max(incidenceResidual(Point<S>(x1), l), incidenceResidual(Point<S>(x2), l)));
             }
             c.checkResidual("the book's coordinates: direction x2 − x1, moment x1 × x2 (= x1 × (x2 − x1), u = r × v)", form, tol());
             c.checkResidual("ℓ = p1∨p2/√(…) is a unit line (ℓℓ* = 1)", unit, tol());
             c.checkResidual("both points lie on it", onl, tol());
             const V3 a(1e8, -1e8, 1e8), b(1e8 + 1, -1e8, 1e8);
             const Line<S> far = join(Point<S>(a), Point<S>(b));
             c.checkResidual("far points (1e8 from the origin, 1 apart): both on the line (scale-free)",
                             std::max(incidenceResidual(Point<S>(a), far), incidenceResidual(Point<S>(b), far)), tol());
             c.checkEqual("coincident points: no line", "InvalidInput", [&] {
               try {
                 (void)join(Point<S>(a), Point<S>(a));
                 return std::string("a line");
               } catch (const InvalidInput&) { return std::string("InvalidInput"); }
             }());
           });

SOMA_STUDY_DOUBLE("GF-10.2.3-join-point-line", "p ∨ ℓ = (x·u)𝐞 + (u − x × v)·(e1, e2, e3): the plane of p and ℓ", "GF §10.2.3",
           [](Context& c) {
             auto g = rng(233);
             double form = 0, contains = 0;
             for (int i = 0; i < 20; ++i) {
               const V3 x = rvec(g), q = rvec(g), v = runit(g);
               const Line<S> l = Line<S>::throughPoint(q, v);
               const Plane<S> j = shuffle(Point<S>(x), l);
               form = std::max(form, md(j.normal(), V3(l.moment() - x.cross(v))) + std::abs(j.distance() - x.dot(l.moment())));
               const Plane<S> pi = join(Point<S>(x), l);
               contains = std::max(contains, std::max(incidenceResidual(Point<S>(x), pi), incidenceResidual(l, pi)));
             }
             c.checkResidual("normal u − x × v = (r − x) × v, distance x·u (book formula, 20 random)", form, tol());
             c.checkResidual("the normalised plane contains p and ℓ", contains, tol(1024));
             const Line<S> l = Line<S>::throughPoint(V3(1, 2, 3), V3(0, 0, 1));
             c.checkResidual("p on ℓ: p ∨ ℓ = 0 (another incidence test)", shuffle(Point<S>(V3(1, 2, 7)), l).element().maxAbs(), 0.0);
           });

SOMA_STUDY_DOUBLE("GF-10.2.3-plane-three-points", "π = p1 ∨ p2 ∨ p3/√(…); collinear ⇔ p1 ∨ p2 ∨ p3 = 0", "GF §10.2.3", [](Context& c) {
  auto g = rng(234);
  double contains = 0, orient = 0;
  for (int i = 0; i < 20; ++i) {
    const V3 x1 = rvec(g), x2 = rvec(g), x3 = rvec(g);
    const Plane<S> pi = join(Point<S>(x1), Point<S>(x2), Point<S>(x3));
    for (const V3& x : {x1, x2, x3}) contains = std::max(contains, incidenceResidual(Point<S>(x), pi));
    orient = std::max(orient, md(pi.normal(), V3((x2 - x1).cross(x3 - x1).normalized())));
  }
  c.checkResidual("the plane contains the three points (20 random)", contains, tol(64));
  c.checkResidual("unit normal along (x2 − x1) × (x3 − x1)", orient, tol(1024));
  const V3 a(1, 2, 3), d(0.3, -0.2, 0.5);
  c.checkResidual("collinear points: |p1 ∨ p2 ∨ p3| = 0",
                  shuffle(shuffle(Point<S>(a).element(), Point<S>(V3(a + d)).element()), Point<S>(V3(a - 2 * d)).element()).maxAbs(),
                  tol(16));
});

SOMA_STUDY_DOUBLE("GF-10.2.3-point-plane-and-coplanarity", "p ∨ π = d − x·n; four points coplanar ⇔ p1 ∨ p2 ∨ p3 ∨ p4 = 0",
           "GF §10.2.3", [](Context& c) {
             auto g = rng(235);
             c.checkResidual("p ∨ π = d − x·n (a scalar, 20 random)", worst(20, [&](int) {
                               const V3 x = rvec(g), n = rvec(g);
                               const double d = uni(g);
                               return std::abs(shuffle(Point<S>(x), Plane<S>(n, d)) - (d - x.dot(n)));
                             }), tol());
             const Plane<S> pi(runit(g), 0.3);
             auto on = [&] { return Point<S>(V3(pi.normal() * 0.3 + pi.normal().cross(rvec(g)))); };
             const Point<S> a = on(), b = on(), d = on(), e = on();
             c.checkResidual("four points of one plane: p1 ∨ p2 ∨ p3 ∨ p4 = 0 (scale-free)", coplanarityResidual(a, b, d, e), tol(16));
             const V3 x = rvec(g);
             Mat3<S> M;
             M.col(0) = b.position() - a.position(), M.col(1) = d.position() - a.position(), M.col(2) = x - a.position();
             const double four = shuffle(shuffle(shuffle(a.element(), b.element()), d.element()), Point<S>(x).element()).scalarPart();
             c.checkNear("a random fourth point: |p1 ∨ p2 ∨ p3 ∨ p4| = |det(x2 − x1, x3 − x1, x4 − x1)| ≠ 0",
                         std::abs(M.determinant()), std::abs(four), tol());
           });

SOMA_STUDY_DOUBLE("GF-10.2.3-line-line-shuffle", "ℓ1 ∨ ℓ2 = v·μ + u·w, the reciprocal product; coplanar ⇔ 0", "GF §10.2.3",
           [](Context& c) {
             auto g = rng(236);
             c.checkResidual("ℓ1 ∨ ℓ2 = v·μ + u·w (= Q0 of the 6-vectors, 20 random)", worst(20, [&](int) {
                               const V3 v = rvec(g), u = rvec(g), w = rvec(g), mu = rvec(g);
                               return std::abs(shuffle(Line<S>(v, u), Line<S>(w, mu)) - (v.dot(mu) + u.dot(w)));
                             }), tol());
             c.checkResidual("= −(distance)·sin∠ for unit lines (skew lines 0.75 apart at 60°)",
                             std::abs(std::abs(shuffle(Line<S>::throughPoint(V3(0, 0, 0), V3(1, 0, 0)),
                                                       Line<S>::throughPoint(V3(0, 0, 0.75), V3(0.5, std::sqrt(3.0) / 2, 0)))) -
                                      0.75 * std::sqrt(3.0) / 2),
                             tol());
             const V3 o = rvec(g);
             c.checkResidual("two lines through one point: ℓ1 ∨ ℓ2 = 0 (coplanar)",
                             coplanarityResidual(Line<S>::throughPoint(o, runit(g)), Line<S>::throughPoint(o, runit(g))), tol(16));
             c.note("OCR: the printed ℓ1, ℓ2 drop the '+' before u_z e3𝐞 and μ_z e3𝐞 (seed 6238–6240).");
           });

// ---- §10.2.4 perpendicularity: the contraction ------------------------------------------------

SOMA_STUDY_DOUBLE("GF-10.2.4-contraction-definition", "x⌋c = ½(xc − α(c)x); xc = x ∧ c + x⌋c; the derivation rule; (c1 ∧ c2)⌋c3 = c1⌋(c2⌋c3)",
           "GF §10.2.4", [](Context& c) {
             auto g = rng(241);
             double def = 0, split = 0, deriv = 0, assoc = 0;
             for (int i = 0; i < 20; ++i) {
               DenseElement<S> c1, c2, c3;
               for (int k = 0; k < c1.size; ++k) c1[k] = uni(g), c2[k] = uni(g), c3[k] = uni(g);
               const DenseElement<S> x(Plane<S>(rvec(g), uni(g)).element());
               def = std::max(def, md(DenseElement<S>(x | c1), DenseElement<S>((x * c1 - c1.involute() * x) * 0.5)));
               split = std::max(split, md(DenseElement<S>(x * c1), DenseElement<S>((x ^ c1) + (x | c1))));
               deriv = std::max(deriv, md(DenseElement<S>(x | (c1 ^ c2)),
                                          DenseElement<S>(((x | c1) ^ c2) + (c1.involute() ^ (x | c2)))));
               assoc = std::max(assoc, md(DenseElement<S>((c1 ^ c2) | c3), DenseElement<S>(c1 | (c2 | c3))));
             }
             c.checkResidual("x⌋c = ½(xc − α(c)x) for vectors x (clifford::leftContraction, 20 random c)", def, tol());
             c.checkResidual("xc = x ∧ c + x⌋c", split, tol());
             c.checkResidual("x⌋(c1 ∧ c2) = (x⌋c1) ∧ c2 + α(c1) ∧ (x⌋c2)", deriv, tol());
             c.checkResidual("(c1 ∧ c2)⌋c3 = c1⌋(c2⌋c3)", assoc, tol());
             c.note("OCR: seed 6284–6285 renders ⌋ as 'ightharpoonup' inside a broken 'egin' environment.");
           });

SOMA_STUDY_DOUBLE("GF-10.2.4-plane-plane-angle", "π1⌋π2 = −n·m = −cos∠; perpendicular ⇔ 0", "GF §10.2.4", [](Context& c) {
  auto g = rng(242);
  double form = 0, ang = 0;
  for (int i = 0; i < 20; ++i) {
    const Plane<S> a(runit(g), uni(g)), b(runit(g), uni(g));
    form = std::max(form, std::abs((a.element() | b.element()).scalarPart() + a.normal().dot(b.normal())));
    const double ref = std::atan2(a.normal().cross(b.normal()).norm(), a.normal().dot(b.normal()));
    ang = std::max(ang, std::abs(angle(a, b) - ref));
  }
  c.checkResidual("π1⌋π2 = −(n_x m_x + n_y m_y + n_z m_z) (20 random)", form, tol());
  c.checkResidual("angle = atan2(|π1 ∧ π2| direction, −π1⌋π2) = the angle of the normals", ang, tol());
  c.checkResidual("perpendicular planes: π1⌋π2 = 0",
                  std::abs((Plane<S>(V3(1, 0, 0), 2).element() | Plane<S>(V3(0, 1, 0), -1).element()).scalarPart()), 0.0);
});

SOMA_STUDY_DOUBLE("GF-10.2.4-plane-line-perpendicular-plane", "π⌋ℓ = (n × v)·(e1, e2, e3) − (n·u)𝐞: the plane through ℓ perpendicular to π",
           "GF §10.2.4", [](Context& c) {
             auto g = rng(243);
             double form = 0, geo = 0;
             for (int i = 0; i < 20; ++i) {
               const Plane<S> pi(runit(g), uni(g));
               const Line<S> l = Line<S>::throughPoint(rvec(g), runit(g));
               const Plane<S> raw((pi.element() | l.element()).grade<1>());
               form = std::max(form, md(raw.normal(), V3(pi.normal().cross(l.direction()))) +
                                         std::abs(raw.distance() + pi.normal().dot(l.moment())));
               const Plane<S> pp = perpendicularPlane(pi, l);
               const double sn = pi.normal().cross(l.direction()).norm();
               geo = std::max(geo, (incidenceResidual(l, pp) + std::abs(pp.normal().dot(pi.normal()))) * sn);
             }
             c.checkResidual("π⌋ℓ coordinates (20 random)", form, tol());
             c.checkResidual("the normalised π⊥ contains ℓ and is ⟂ π (scaled by sin∠)", geo, tol());
             c.checkEqual("ℓ ⟂ π: π⌋ℓ = 0, no unique plane", "InvalidInput", [&] {
               try {
                 (void)perpendicularPlane(Plane<S>(V3(0, 0, 1), 0), Line<S>::throughPoint(V3(1, 1, 1), V3(0, 0, 1)));
                 return std::string("a plane");
               } catch (const InvalidInput&) { return std::string("InvalidInput"); }
             }());
           });

SOMA_STUDY_DOUBLE("GF-10.2.4-plane-point-perpendicular-line", "π⌋p = −n·(e2e3, …) − (x × n)·(e1𝐞, …) = line(p, −n)", "GF §10.2.4",
           [](Context& c) {
             auto g = rng(244);
             c.checkResidual("π⌋p = the line through p with direction −n, unit without normalising (20 random)", worst(20, [&](int) {
                               const Plane<S> pi(runit(g), uni(g));
                               const V3 x = rvec(g, 2);
                               const Line<S> l((pi.element() | Point<S>(x).element()).grade<2>());
                               return md(l.element(), Line<S>::throughPoint(x, V3(-pi.normal())).element()) +
                                      std::abs(l.normSquared().first - 1);
                             }), tol());
             const Plane<S> pi(runit(g), 0.5);
             const V3 x = rvec(g);
             c.checkResidual("perpendicularLine (divided by −1) meets π at the foot x − (n·x − d)n",
                             md(meet(perpendicularLine(pi, Point<S>(x)), pi).position(), V3(x - pi.normal() * (pi.normal().dot(x) - 0.5))),
                             tol());
           });

SOMA_STUDY_DOUBLE("GF-10.2.4-line-line-angle", "ℓ1⌋ℓ2 = −v·w (the Killing form); perpendicular ⇔ 0", "GF §10.2.4", [](Context& c) {
  auto g = rng(245);
  double form = 0, ang = 0;
  for (int i = 0; i < 20; ++i) {
    const Line<S> a(rvec(g), rvec(g)), b(rvec(g), rvec(g));
    form = std::max(form, std::abs((a.element() | b.element()).scalarPart() + a.direction().dot(b.direction())));
    ang = std::max(ang, std::abs(angle(a, b) - std::atan2(a.direction().cross(b.direction()).norm(), a.direction().dot(b.direction()))));
  }
  c.checkResidual("ℓ1⌋ℓ2 = −(v_x w_x + v_y w_y + v_z w_z), a scalar (20 random)", form, tol());
  c.checkResidual("angle from −ℓ1⌋ℓ2 and ½[ℓ1, ℓ2] by atan2", ang, tol());
  c.checkResidual("perpendicular skew lines: ℓ1⌋ℓ2 = 0",
                  std::abs((Line<S>::throughPoint(V3(0, 0, 0), V3(1, 0, 0)).element() |
                            Line<S>::throughPoint(V3(0, 0, 3), V3(0, 1, 0)).element()).scalarPart()),
                  0.0);
});

SOMA_STUDY_DOUBLE("GF-10.2.4-line-point-perpendicular-plane", "ℓ⌋p = −v·(e1, e2, e3) − (x·v)𝐞: the plane through p ⟂ ℓ", "GF §10.2.4",
           [](Context& c) {
             auto g = rng(246);
             c.checkResidual("ℓ⌋p coordinates (20 random)", worst(20, [&](int) {
                               const Line<S> l = Line<S>::throughPoint(rvec(g), runit(g));
                               const V3 x = rvec(g);
                               const Plane<S> p((l.element() | Point<S>(x).element()).grade<1>());
                               return md(p.normal(), V3(-l.direction())) + std::abs(p.distance() + x.dot(l.direction()));
                             }), tol());
             const Line<S> l = Line<S>::throughPoint(rvec(g), runit(g));
             const V3 x = rvec(g);
             const Plane<S> pp = perpendicularPlane(l, Point<S>(x));
             c.checkResidual("it passes through p and its normal is ±v (|v × n| = 0)",
                             incidenceResidual(Point<S>(x), pp) + pp.normal().cross(l.direction()).norm(), tol());
             const V3 q = l.pointNearestOrigin(), v = l.direction();
             c.checkResidual("ℓ ∧ (plane) = the foot of the perpendicular q + v(v·(x − q))",
                             md(project(Point<S>(x), l).position(), V3(q + v * v.dot(x - q))), tol());
           });

SOMA_STUDY_DOUBLE("GF-10.2.4-distances", "Signed point–plane distance p ∨ π (E10.10), point–line (p∨ℓ)(p∨ℓ)*, point–point −(p1∨p2)⌋(p1∨p2)",
           "GF §10.2.4", [](Context& c) {
             auto g = rng(247);
             double pl = 0, pli = 0, pp = 0, one = 0;
             for (int i = 0; i < 20; ++i) {
               const Plane<S> pi(runit(g), uni(g));
               const V3 x = rvec(g, 2), y = rvec(g, 2);
               pl = std::max(pl, std::abs(std::abs(shuffle(Point<S>(x), pi)) - std::abs(pi.normal().dot(x) - pi.distance())));
               const Line<S> l = Line<S>::throughPoint(rvec(g), runit(g));
               const double d2 = shuffle(Point<S>(x), l).normSquared();
               pli = std::max(pli, std::abs(d2 - (x - l.pointNearestOrigin()).cross(l.direction()).squaredNorm()));
               const auto j = shuffle(Point<S>(x).element(), Point<S>(y).element());
               pp = std::max(pp, std::abs(-(j | j).scalarPart() - (x - y).squaredNorm()));
               one = std::max(one, std::abs((Point<S>(x).element() | Point<S>(y).element()).scalarPart() - 1));
             }
             c.checkResidual("|p ∨ π| = |n·x − d| (20 random)", pl, tol());
             c.checkResidual("(p ∨ ℓ)(p ∨ ℓ)* = squared point–line distance", pli, tol());
             c.checkResidual("−(p1 ∨ p2)⌋(p1 ∨ p2) = |x1 − x2|²", pp, tol());
             c.checkResidual("p1⌋p2 = 1 (says nothing)", one, tol());
             // The sign: a point δ = 0.25 along +n from the plane.
             const Plane<S> pi(runit(g), 0.6);
             const V3 x = pi.normal() * (0.6 + 0.25);
             const double pv = shuffle(Point<S>(x), pi);
             c.checkPrintedFails("p ∨ π is positive when p is on the side the normal points to (p ∨ π + 0.25)", "E10.10",
                         std::abs(pv - 0.25), tol());
             c.checkNear("p ∨ π = d − x·n = −0.25 there (corrected: negative on the normal's side)", -0.25, pv, tol());
             c.checkNear("signedDistance(p, π) = n·x − d = +0.25", 0.25, signedDistance(Point<S>(x), pi), tol());
           });

SOMA_STUDY_DOUBLE("GF-10.2.4-common-perpendicular", "λ = −2(s⌋s)s + (s⌋e1e2e3𝐞)(s ∨ s), s = [ℓ1, ℓ2]: the common perpendicular",
           "GF §10.2.4", [](Context& c) {
             auto g = rng(248);
             double cond = 0, meets = 0, pitch = 0, sI = 0, closest = 0;
             for (int i = 0; i < 30; ++i) {
               const Line<S> a = Line<S>::throughPoint(rvec(g), runit(g)), b = Line<S>::throughPoint(rvec(g), runit(g));
               const Line<S> s = commutator(a, b);
               // s satisfies the equations; its pitch (s ∨ s)/(−2 s⌋s) is Line::pitch.
               cond = std::max(cond, std::abs((s.element() | a.element()).scalarPart()) + std::abs(shuffle(s, a)) +
                                         std::abs((s.element() | b.element()).scalarPart()) + std::abs(shuffle(s, b)));
               const double ss = (s.element() | s.element()).scalarPart();
               pitch = std::max(pitch, std::abs(shuffle(s, s) / (-2 * ss) - s.pitch()));
               const auto I = Grade4<S>::basisBlade(basis::e123e.mask);
               const Line<S> si((s.element() | I).grade<2>());
               sI = std::max(sI, md(si.element(), Line<S>(V3::Zero(), V3(-s.direction())).element()));
               const Line<S> l = commonPerpendicular(a, b);
               const double sn = a.direction().cross(b.direction()).norm();
               meets = std::max(meets, (std::abs((l.element() | a.element()).scalarPart()) + std::abs(shuffle(l, a)) +
                                        std::abs((l.element() | b.element()).scalarPart()) + std::abs(shuffle(l, b)) +
                                        std::abs(l.normSquared().first - 1) + std::abs(l.normSquared().second)) * sn * sn);
               // Closest points by coordinates lie on ℓ.
               const V3 r1 = a.pointNearestOrigin(), r2 = b.pointNearestOrigin(), v1 = a.direction(), v2 = b.direction();
               const double k = v1.dot(v2), e1 = v1.dot(r2 - r1), e2 = v2.dot(r2 - r1);
               const V3 c1 = r1 + v1 * ((e1 - k * e2) / (1 - k * k)), c2 = r2 + v2 * ((k * e1 - e2) / (1 - k * k));
               closest = std::max(closest, (incidenceResidual(Point<S>(c1), l) + incidenceResidual(Point<S>(c2), l)) * sn * sn);
             }
             c.checkResidual("s = ℓ1ℓ2 − ℓ2ℓ1: s⌋ℓi = 0 and s ∨ ℓi = 0 (30 random pairs)", cond, tol());
             c.checkResidual("pitch h = (s ∨ s)/(−2 s⌋s) = v·u/|v|² of s", pitch, tol());
             c.checkResidual("s⌋e1e2e3𝐞 = −(v_x e1𝐞 + v_y e2𝐞 + v_z e3𝐞)", sI, tol());
             c.checkResidual("ℓ = λ/√(λλ*): unit line, ⟂ and meeting both (× sin²∠)", meets, tol(1024));
             c.checkResidual("the closest points of ℓ1, ℓ2 (coordinates) lie on ℓ (× sin²∠)", closest, tol(1024));
             c.checkEqual("parallel lines: s⌋s = s ∨ s = 0, no unique perpendicular", "InvalidInput", [&] {
               try {
                 (void)commonPerpendicular(Line<S>::throughPoint(V3(0, 0, 0), V3(1, 0, 0)), Line<S>::throughPoint(V3(0, 1, 0), V3(1, 0, 0)));
                 return std::string("a line");
               } catch (const InvalidInput&) { return std::string("InvalidInput"); }
             }());
             const Line<S> cross = commonPerpendicular(Line<S>::throughPoint(V3(1, 2, 3), V3(1, 0, 0)),
                                                       Line<S>::throughPoint(V3(1, 2, 3), V3(0, 1, 0)));
             c.checkResidual("intersecting lines (h = 0): the normal line through the intersection",
                             md(cross.element(), Line<S>::throughPoint(V3(1, 2, 3), V3(0, 0, 1)).element()), tol());
           });

}  // namespace
}  // namespace soma::studies::gf10::SOMA_UNITY_ID
