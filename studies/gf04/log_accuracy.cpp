// GF-4.4-log-accuracy: how many ulps does soma's SE(3) log lose over θ ∈ (0, π], in the scalar
// asked for (--scalar, --bits), against an mpfr reference (GF §4.4.2, where the book's
// polynomial log loses up to eps/θ² — see GF-4.4.2-se3-log-4x4)? Plus the figure: error (ulps)
// vs θ on a log axis, drawn with soma::render as a 2-D plot.
#include "gf04/common.hpp"

#include "soma/algebra/log_accuracy.hpp"

#include "soma/render/render.hpp"

#include <cmath>
#include <cstdio>

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

struct Sample {
  double theta, delta, ulps;  // θ, π − θ, max(rotation, translation) normwise error in ulps
  bool nearPi;                // from the π − δ sweep (plotted against δ)
};

/// Reference log of (q, t) in mpfr at the current precision, independent of SE3::log:
/// ω = 2 atan2(|q_v|, q_w) q_v/|q_v|, v = Jl(ω)⁻¹ t with Jl = Σ ad(ω)^k/(k+1)! (power series).
// GF §4.4.2, GF-4.4.2-se3-log-4x4; GF §4.5.3, GF-4.5.3-so3-dexp-and-inverse
void referenceLog(Quat<mpreal> q, const Vec3<mpreal>& t, Vec3<mpreal>& w, Vec3<mpreal>& v) {
  q.coeffs() /= sqrt(q.coeffs().squaredNorm());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const mpreal n = sqrt(q.vec().squaredNorm());
  const mpreal theta = 2 * atan2(n, q.w());
  w = n == 0 ? Vec3<mpreal>(Vec3<mpreal>::Zero()) : Vec3<mpreal>(q.vec() * (theta / n));
  const SO3Tangent<mpreal> wt(w);
  v = dexpSeries(wt, 400).fullPivLu().solve(t);
}

/// Errors of SE3<S>::log at the given angles (random axes and translations, fixed seed).
template <class S> std::vector<Sample> sweep(const std::vector<double>& deltas, const std::vector<double>& thetas) {
  const int oldBits = mpfrBits();
  const int bits = std::max(320, 2 * digits<S>() + 64);
  const S eps = Tolerance<S>::epsilon();
  auto g = rng(4404);
  std::vector<Sample> out;
  auto one = [&](const S& theta, double thetaD, double deltaD, bool nearPi) {
    const Vec3<S> axis = randomUnit<S>(g), t = randomVec<S, 3>(g);
    const SE3<S> X(SO3Tangent<S>(Vec3<S>(axis * theta)).exp(), t);
    const SE3Tangent<S> s = X.log();
    setMpfrBits(bits);
    Quat<mpreal> q;
    q.coeffs() << scalarCast<mpreal>(X.quaternion().x()), scalarCast<mpreal>(X.quaternion().y()),
        scalarCast<mpreal>(X.quaternion().z()), scalarCast<mpreal>(X.quaternion().w());
    Vec3<mpreal> tr;
    for (int k = 0; k < 3; ++k) tr(k) = scalarCast<mpreal>(X.translation()(k));
    Vec3<mpreal> wr, vr;
    referenceLog(q, tr, wr, vr);
    mpreal dw = 0, dv = 0;
    for (int k = 0; k < 3; ++k) {
      const mpreal a = abs(scalarCast<mpreal>(s.coeffs()(k)) - wr(k));
      const mpreal b = abs(scalarCast<mpreal>(s.coeffs()(k + 3)) - vr(k));
      if (a > dw) dw = a;
      if (b > dv) dv = b;
    }
    const mpreal e = scalarCast<mpreal>(eps);
    const double ew = (dw / (e * wr.cwiseAbs().maxCoeff())).toDouble();
    const double ev = (dv / (e * vr.cwiseAbs().maxCoeff())).toDouble();
    setMpfrBits(oldBits);
    out.push_back({thetaD, deltaD, std::max(ew, ev), nearPi});
  };
  for (const double th : thetas) one(scalarCast<S>(th), th, 3.14159265358979323846 - th, false);
  for (const double d : deltas) one(pi<S>() - scalarCast<S>(d), 3.14159265358979323846 - d, d, true);
  one(pi<S>(), 3.14159265358979323846, 0.0, true);
  return out;
}

// ---- the figure: two log-axis panels drawn as polylines in the z = 0 plane ---------------------
namespace rd = soma::render;
struct Panel {
  double x0, width, height;  // world placement
  double lo, hi;             // log10 range on the x axis
  double yMax;               // ulps at the top
  Eigen::Vector3d at(double logx, double ulps) const {
    return {x0 + width * (logx - lo) / (hi - lo), height * std::min(ulps, yMax) / yMax, 0};
  }
};
void axes(rd::Scene& scene, const Panel& p, const std::string& xlabel, int yTicks) {
  rd::Polyline frame;
  frame.p = {p.at(p.lo, p.yMax), p.at(p.lo, 0), p.at(p.hi, 0)};
  frame.c = rd::palette::black;
  frame.width = 2;
  scene.add(frame);
  for (int e = int(std::ceil(p.lo)); e <= int(std::floor(p.hi)); e += 2) {
    rd::Polyline tick;
    tick.p = {p.at(e, 0), p.at(e, 0) - Eigen::Vector3d(0, 0.08, 0)};
    tick.width = 2;
    scene.add(tick);
    rd::Label l;
    l.at = p.at(e, 0) - Eigen::Vector3d(0, 0.1, 0);
    l.text = e == 0 ? "1" : "1e" + std::to_string(e);
    l.hAlign = rd::HAlign::Center;
    l.vAlign = rd::VAlign::Top;
    l.offset = {0, 2};
    l.pixelHeight = 18;
    scene.add(l);
  }
  for (int k = 0; k <= yTicks; ++k) {
    const double u = p.yMax * k / yTicks;
    rd::Polyline tick;
    tick.p = {p.at(p.lo, u), p.at(p.lo, u) - Eigen::Vector3d(0.08, 0, 0)};
    tick.width = 2;
    scene.add(tick);
    rd::Polyline grid;
    grid.p = {p.at(p.lo, u), p.at(p.hi, u)};
    grid.c = rd::palette::lightGrey;
    grid.width = 1;
    if (k > 0) scene.add(grid);
    rd::Label l;
    l.at = p.at(p.lo, u) - Eigen::Vector3d(0.1, 0, 0);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%g", u);
    l.text = buf;
    l.hAlign = rd::HAlign::Right;
    l.vAlign = rd::VAlign::Middle;
    l.offset = {-2, 0};
    l.pixelHeight = 18;
    scene.add(l);
  }
  rd::Label xl;
  xl.at = p.at(0.5 * (p.lo + p.hi), 0) - Eigen::Vector3d(0, 0.55, 0);
  xl.text = xlabel;
  xl.hAlign = rd::HAlign::Center;
  xl.vAlign = rd::VAlign::Top;
  xl.offset = {0, 0};
  xl.pixelHeight = 22;
  scene.add(xl);
}
void series(rd::Scene& scene, const Panel& p, const std::vector<Sample>& s, bool byDelta, rd::Color col) {
  rd::Polyline line;
  line.c = col;
  line.width = 2;
  rd::Points pts;
  pts.c = col;
  pts.radius = 0.035;
  for (const Sample& x : s) {
    const double v = byDelta ? x.delta : x.theta;
    if (v <= 0) continue;
    const double lx = std::log10(v);
    if (byDelta != x.nearPi || lx < p.lo || lx > p.hi) continue;
    line.p.push_back(p.at(lx, x.ulps));
    pts.p.push_back(p.at(lx, x.ulps));
  }
  scene.add(line);
  scene.add(pts);
}

// Runs in the asked scalar S (--scalar; mpfr at --bits, the reference at ≥ 2·bits + 64); double,
// the default, also draws the float128 sweep for comparison. SOMA-log-speed-accuracy measures
// every rung in one run.
template <class S> void logAccuracy(Context& c) {
  std::vector<double> thetas, deltas;
  for (int k = 0; k <= 32; ++k) thetas.push_back(std::pow(10.0, -8.0 + 8.0 * k / 32));  // 1e-8 … 1
  for (int k = 0; k < 24; ++k) thetas.push_back(1.0 + 2.0 * (k + 0.5) / 24);            // 1 … 3
  for (int k = 0; k <= 32; ++k) deltas.push_back(std::pow(10.0, -15.0 + 15.0 * k / 32) * 0.9);  // π − δ
  const auto own = sweep<S>(deltas, thetas);
  auto worst = [](const std::vector<Sample>& s) {
    Sample w{0, 0, -1, false};
    for (const Sample& x : s)
      if (x.ulps > w.ulps) w = x;
    return w;
  };
  std::string name(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) name += " (" + std::to_string(mpfrBits()) + " bits)";
  {
    const Sample w = worst(own);
    c.record("worst SE(3) log error in " + name + " over θ ∈ (0, π] (" + std::to_string(own.size()) +
                 " angles, ulps of the normwise error; goal: a few ulps, ≤ 4)",
             "≤ 4 ulps", toString(w.ulps, 3) + " ulps at θ = " + (w.theta > 1.5 ? "π − " + toString(w.delta, 2) : toString(w.theta, 3)),
             w.ulps, 4.0, w.ulps <= 4.0);
  }
  // Cross-check with the library's own sweep (algebra/log_accuracy.hpp, another sampling and
  // another seed): the two independent measurements must agree that the error is a few ulps.
  const LogAccuracy lib = worstLogError<S>(std::is_same_v<S, mpreal> ? 100 : 300);
  c.record("soma::worstLogError<" + name + ">(" + std::to_string(lib.samples) + ") (independent sweep in algebra/)",
           "≤ 4 ulps", toString(lib.worstUlps, 3) + " ulps at θ = " + toString(lib.worstTheta, 3), lib.worstUlps, 4.0,
           lib.worstUlps <= 4.0);
  std::vector<Sample> f128;
  if constexpr (std::is_same_v<S, double>) f128 = sweep<__float128>(deltas, thetas);
  const auto& dbl = own;
  c.note("Method: X = (exp(θâ), t) built in the scalar type, SE3::log in that type, reference in mpfr (≥ 320 bits) "
         "from the same quaternion and translation: ω = 2 atan2(|q_v|, q_w) q_v/|q_v|, v = Jl(ω)⁻¹t with Jl by its "
         "power series. Error = max(‖Δω‖∞/‖ω‖∞, ‖Δv‖∞/‖v‖∞)/ε.");
  if (!c.makeFigures()) return;
  rd::Scene scene;
  scene.title = "SE(3) log: error in ulps vs θ (left) and vs π − θ (right)";
  const Panel left{0, 6, 4, -8, 0, 0}, right{7.2, 6, 4, -15, 0, 0};
  double yMax = 0;
  const std::vector<Sample>* both[2] = {&dbl, &f128};
  for (const auto* s : both)
    for (const Sample& x : *s) yMax = std::max(yMax, x.ulps);
  const int keys = f128.empty() ? 1 : 2;
  yMax = std::max(1.0, std::ceil(yMax));
  Panel l = left, r = right;
  l.yMax = r.yMax = yMax;
  const int yTicks = int(yMax) <= 8 ? int(yMax) : 4;
  axes(scene, l, "θ (log scale)", yTicks);
  axes(scene, r, "π − θ (log scale)", yTicks);
  series(scene, l, dbl, false, rd::palette::blue);
  series(scene, l, f128, false, rd::palette::vermillion);
  series(scene, r, dbl, true, rd::palette::blue);
  series(scene, r, f128, true, rd::palette::vermillion);
  rd::Label ylab;
  ylab.at = l.at(l.lo, yMax) + Eigen::Vector3d(0, 0.25, 0);
  ylab.text = "error (ulps)";
  ylab.hAlign = rd::HAlign::Center;
  ylab.pixelHeight = 22;
  scene.add(ylab);
  for (int k = 0; k < keys; ++k) {
    rd::Label key;
    key.at = r.at(r.hi, yMax) + Eigen::Vector3d(-2.3, -0.35 - 0.4 * k, 0);
    key.text = k == 0 ? "● " + name : "● float128";
    key.c = k == 0 ? rd::palette::blue : rd::palette::vermillion;
    key.pixelHeight = 22;
    key.vAlign = rd::VAlign::Middle;
    scene.add(key);
  }
  rd::RenderOptions opt;
  opt.width = 1400;
  opt.height = 700;
  const Eigen::Vector3d centre(6.5, 1.75, 0);
  opt.camera = rd::Camera::ortho(centre + Eigen::Vector3d(0, 0, 10), centre, Eigen::Vector3d(0, 1, 0), 7.4);
  const std::string file = "GF-4.4-log-accuracy.png";
  rd::renderPng(scene, opt, c.figurePath(file));
  c.figure(file, "Normwise error of soma's SE3::log in ulps of the scalar type (" + name + " blue" +
                     (f128.empty() ? std::string() : ", float128 vermillion") +
                     ") against an mpfr reference, for random axes and translations: left vs θ ∈ [1e-8, 1], right "
                     "vs π − θ.");
}

}  // namespace

SOMA_STUDY({.id = "GF-4.4-log-accuracy",
            .title = "Worst SE(3) log error over θ ∈ (0, π] in the asked scalar (vs mpfr at ≥ 2p + 64 bits)",
            .source = "GF §4.4.2",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { logAccuracy<S>(c); }); }});

}  // namespace soma::studies::gf04::SOMA_UNITY_ID
