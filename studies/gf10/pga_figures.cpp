// GF chapter 10 figure (Fig. 10.1, a plane n·r = d) rendered with soma::render, with the sign of
// the shuffle p ∨ π shaded on both sides (documents erratum E10.10), and the cross-check of
// pga::Line against a Plücker 6-vector computed directly from two points (in the scalar asked for;
// the figure in double, as soma::render draws).
#include "soma/geometry/pga/distance.hpp"
#include "soma/geometry/pga/join.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"

#include <random>

namespace soma::studies::gf10::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace soma::pga;
namespace rd = soma::render;
using V3 = Eigen::Vector3d;
constexpr const char* kChapter = "GF 10 — Points, lines, planes; Pieper robots";

// GF §10.1.1, GF-10.1.1-fig10.1-plane (with erratum E10.10).
void planeFigure(Context& c) {
  const V3 n = V3(0.25, 0.35, 1.0).normalized();
  const double d = 1.2;
  const Plane<double> pi(n, d);
  const V3 foot = d * n;
  const V3 a = n.cross(V3(1, 0, 0)).normalized(), b = n.cross(a);
  // Sample points on a grid through the plane, coloured by the sign of p ∨ π = d − x·n.
  std::mt19937_64 g(1011);
  std::uniform_real_distribution<double> u(-1.6, 1.6), h(-1.1, 1.1);
  rd::Points neg, pos;
  neg.c = rd::palette::vermillion;
  pos.c = rd::palette::blue;
  neg.radius = pos.radius = 0.03;
  int negNormalSide = 0, posOtherSide = 0, total = 0;
  for (int k = 0; k < 150; ++k) {
    double off = h(g);
    if (std::abs(off) < 0.15) continue;
    const V3 x = foot + u(g) * a + u(g) * b + off * n;
    const double s = shuffle(Point<double>(x), pi);
    ++total;
    if (s < 0) {
      neg.p.push_back(x);
      negNormalSide += n.dot(x) > d;
    } else {
      pos.p.push_back(x);
      posOtherSide += n.dot(x) < d;
    }
  }
  c.checkEqual("sample points with p ∨ π < 0 that lie on the normal's side (n·x > d)", (long long)neg.p.size(), negNormalSide);
  c.checkEqual("sample points with p ∨ π > 0 that lie on the other side", (long long)pos.p.size(), posOtherSide);
  c.checkEqual("all samples classified", total, (long long)(neg.p.size() + pos.p.size()));
  if (!c.makeFigures()) return;
  rd::Scene scene;
  scene.title = "Fig. 10.1: the plane n·r = d, π = n + d e; the sign of p ∨ π (E10.10)";
  rd::Mesh quad;
  const double R = 1.9;
  for (const auto& [s, t] : std::vector<std::pair<double, double>>{{-R, -R}, {R, -R}, {R, R}, {-R, R}}) {
    quad.v.push_back(foot + s * a + t * b);
    quad.n.push_back(n);
  }
  quad.tri = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3)};
  quad.c = rd::palette::skyBlue.withAlpha(0.45f);
  scene.add(quad);
  rd::Polyline edge;
  edge.p = quad.v;
  edge.closed = true;
  edge.c = rd::palette::blue.darker(0.3f);
  edge.width = 2;
  scene.add(edge);
  scene.add(neg);
  scene.add(pos);
  rd::Polyline dist;
  dist.p = {V3::Zero(), foot};
  dist.dashed = true;
  dist.width = 3;
  dist.c = rd::palette::darkGrey;
  scene.add(dist);
  scene.add(rd::Points{{V3::Zero()}, rd::palette::black, 0.05});
  scene.add(rd::Arrow{foot, V3(foot + 0.9 * n), rd::palette::black, 0.025});
  auto label = [&](const V3& at, const std::string& text, Eigen::Vector2d off = {8, -8},
                   rd::HAlign ha = rd::HAlign::Left, rd::Color col = rd::palette::black) {
    rd::Label l;
    l.at = at;
    l.text = text;
    l.pixelHeight = 24;
    l.offset = off;
    l.hAlign = ha;
    l.c = col;
    scene.add(l);
  };
  label(V3::Zero(), "origin O", {-10, 8}, rd::HAlign::Right);
  label(0.5 * foot, "d = 1.2", {10, 0});
  label(V3(foot + 0.9 * n), "unit normal n", {14, 4});
  label(V3(foot + 1.3 * n - 1.2 * b), "p ∨ π < 0: the side n points to", {0, -14}, rd::HAlign::Center, rd::palette::vermillion);
  label(V3(foot - 1.3 * n + 1.2 * b), "p ∨ π = d − x·n > 0: the origin's side", {0, 80}, rd::HAlign::Center, rd::palette::blue);
  label(V3(foot + R * a - R * b), "π: n·r = d", {8, 8});
  const std::string file = "GF-10.1.1-fig10.1-plane.png";
  rd::renderPng(scene, V3(-(a * 1.0 + n * 0.42 - b * 0.55)).normalized(), {1200, 950}, c.figurePath(file));
  c.figure(file,
           "A plane π = n + d e (n·r = d, d = 1.2) with its unit normal n and the distance d from the origin "
           "(GF Fig. 10.1). Random points are coloured by the sign of the shuffle p ∨ π = d − x·n: vermillion "
           "where it is negative — on the side the normal points to, opposite to the book's statement (E10.10) — "
           "and blue where it is positive.");
}

SOMA_STUDY({.id = "GF-10.1.1-fig10.1-plane",
            .title = "Fig. 10.1: a plane n·r = d, with the sign of p ∨ π on both sides (E10.10)",
            .source = "GF §10.1.1",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = planeFigure,
            .whyDouble = "a figure: soma::render draws double geometry"});

// pga::Line (the Clifford-algebra form) against the Plücker 6-vector (v; u) = (x2 − x1; x1 × x2)
// of two points computed directly, including far points and nearly coincident ones.
template <class S> void pluckerCrossCheck(Context& c) {
  using std::abs;
  std::mt19937_64 g(1012);
  std::uniform_real_distribution<double> u(-1, 1);
  // Draws in double (the same inputs on every rung), cast to S.
  auto draw = [&](double scale) {
    const double x = u(g) * scale, y = u(g) * scale, z = u(g) * scale;
    return Vec3<S>(scalarCast<S>(x), scalarCast<S>(y), scalarCast<S>(z));
  };
  S worst(0), klein(0), recip(0);
  for (int k = 0; k < 200; ++k) {
    const double scaleD = k % 4 == 3 ? 1e6 : 1;
    const S scale = scalarCast<S>(scaleD);
    const Vec3<S> x1 = draw(scaleD), x2 = draw(scaleD);
    const Vec3<S> y1 = draw(1), y2 = draw(1);
    Vec6<S> p, q;
    p << x2 - x1, x1.cross(x2);
    q << y2 - y1, y1.cross(y2);
    const Line<S> l = shuffle(Point<S>(x1), Point<S>(x2));
    const Line<S> m = shuffle(Point<S>(y1), Point<S>(y2));
    Vec6<S> lp;
    lp << l.direction(), l.moment();
    worst = std::max(worst, S((lp - p).cwiseAbs().maxCoeff() / (scale * scale)));
    klein = std::max(klein, S(abs(l.kleinForm() - p.template head<3>().dot(p.template tail<3>())) / (scale * scale * scale)));
    // ℓ1 ∨ ℓ2 is the reciprocal product of the 6-vectors; for joins of points it is ±6·volume.
    Mat3<S> M;
    M.col(0) = x2 - x1, M.col(1) = y1 - x1, M.col(2) = y2 - x1;
    const S rp = p.template head<3>().dot(q.template tail<3>()) + p.template tail<3>().dot(q.template head<3>());
    recip = std::max(recip, S((abs(shuffle(l, m) - rp) + abs(abs(rp) - abs(M.determinant()))) / (scale * scale * (1 + scale))));
  }
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("p1 ∨ p2 = Plücker (x2 − x1; x1 × x2), 200 pairs, |x| up to 1e6 (relative)", worst, tol);
  c.checkResidual("Klein form v·u of the join = that of the 6-vector (= 0 up to rounding)", klein, tol);
  c.checkResidual("ℓ1 ∨ ℓ2 = reciprocal product = ±det(x2 − x1, y1 − x1, y2 − x1)", recip, tol);
}

SOMA_STUDY_SCALAR("soma-pga-plucker-crosscheck",
                  "pga::Line from two points = the Plücker 6-vector (x2 − x1; x1 × x2); ∨ = reciprocal product",
                  "GF §6.2, §10.2.3", pluckerCrossCheck);

}  // namespace
}  // namespace soma::studies::gf10::SOMA_UNITY_ID
