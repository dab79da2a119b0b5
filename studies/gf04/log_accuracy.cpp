// GF-4.4-log-accuracy: how many ulps does soma's SE(3) log lose over θ ∈ (0, π], in the scalar
// asked for (--scalar, --bits), against an mpfr reference (GF §4.4.2, where the book's
// polynomial log loses up to eps/θ² — see GF-4.4.2-se3-log-4x4)? Plus the figure: error (ulps)
// vs θ on a log axis, drawn with soma::render as a 2-D plot.
#include "gf04/common.hpp"

#include "soma/algebra/log_accuracy.hpp"

#include "soma/render/render.hpp"
#include "soma/render/svg.hpp"

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
template <class S> std::vector<Sample> sweep(const std::vector<double>& deltas, const std::vector<double>& thetas,
                                             double* referenceResidual = nullptr) {
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
    // widened exactly to the reference's bits (an mpreal keeps its own precision: for S = mpreal a
    // plain copy would leave the whole reference at S's bits — the check below caught that)
    using detail::logacc::exact;
    q.coeffs() << exact(X.quaternion().x(), bits), exact(X.quaternion().y(), bits), exact(X.quaternion().z(), bits),
        exact(X.quaternion().w(), bits);
    Vec3<mpreal> tr;
    for (int k = 0; k < 3; ++k) tr(k) = exact(X.translation()(k), bits);
    Vec3<mpreal> wr, vr;
    referenceLog(q, tr, wr, vr);
    if (referenceResidual) {  // |exp(ref) − X| / (1 + |t|) in units of 2^−bits (exp by expSeries, common.hpp)
      Mat4<mpreal> X4 = Mat4<mpreal>::Identity();
      Quat<mpreal> qn = q;
      qn.coeffs() /= sqrt(qn.coeffs().squaredNorm());
      X4.topLeftCorner<3, 3>() = qn.toRotationMatrix();
      X4.topRightCorner<3, 1>() = tr;
      const mpreal r = Mat4<mpreal>(expSeries(Mat4<mpreal>(SE3Tangent<mpreal>(wr, vr).hat())) - X4).cwiseAbs().maxCoeff() /
                       (1 + tr.cwiseAbs().maxCoeff()) / pow(mpreal(2), -bits);
      *referenceResidual = std::max(*referenceResidual, r.toDouble());
    }
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
/// One scalar's samples as a plot series against θ (byDelta false) or π − θ (true).
void addSeries(rd::Plot& plot, const std::vector<Sample>& s, bool byDelta, const std::string& name, rd::Color col) {
  std::vector<double> xs, ys;
  for (const Sample& x : s) {
    if (byDelta != x.nearPi) continue;
    const double v = byDelta ? x.delta : x.theta;
    if (v <= 0) continue;
    xs.push_back(v);
    ys.push_back(x.ulps);
  }
  auto& sr = plot.add(name, xs, ys, col);
  sr.markers = true;
  sr.markerRadius = 4;
  sr.width = 2;
}

// Runs in the asked scalar S (--scalar; mpfr at --bits, the reference at ≥ 2·bits + 64); double,
// the default, also draws the float128 sweep for comparison. SOMA-log-speed-accuracy measures
// every rung in one run.
template <class S> void logAccuracy(Context& c) {
  std::vector<double> thetas, deltas;
  for (int k = 0; k <= 32; ++k) thetas.push_back(std::pow(10.0, -8.0 + 8.0 * k / 32));  // 1e-8 … 1
  for (int k = 0; k < 24; ++k) thetas.push_back(1.0 + 2.0 * (k + 0.5) / 24);            // 1 … 3
  for (int k = 0; k <= 32; ++k) deltas.push_back(std::pow(10.0, -15.0 + 15.0 * k / 32) * 0.9);  // π − δ
  double refResidual = 0;
  const auto own = sweep<S>(deltas, thetas, &refResidual);
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
  // The reference checked by an independent method: exp of the reference log by the Taylor series
  // with scaling and squaring (expSeries, gf04/common.hpp: no atan2, no Jl⁻¹), compared with X in
  // mpfr. The series is summed to ε² = 2^−2·bits and each of the ≤ 3 squarings of a 4×4 product adds
  // ≈ 4·2^−bits relative: the residual stays below 2^−(bits−10)(1 + |t|), i.e. ≤ 1024 units of 2^−bits.
  // At π − δ the log's condition 1/δ ≤ 1.1e15 keeps the reference's forward error ≤ 2^−(bits−60), far
  // below an ulp of every rung (bits ≥ 2p + 64).
  c.checkResidual("mpfr reference log verified independently: |exp(ref) − X| / (1 + |t|) over the sweep, "
                  "in units of 2^−bits (Taylor series with scaling and squaring; ≤ 2^10)",
                  refResidual, 1024.0);
  // Cross-check with the library's own sweep (algebra/log_accuracy.hpp): another sampling and another
  // seed, but the SAME reference formula (atan2 angle, Jl⁻¹ by its series) — not an independent method.
  const LogAccuracy lib = worstLogError<S>(std::is_same_v<S, mpreal> ? 100 : 300);
  c.record("soma::worstLogError<" + name + ">(" + std::to_string(lib.samples) + ") (algebra/'s sweep: other samples, same reference formula)",
           "≤ 4 ulps", toString(lib.worstUlps, 3) + " ulps at θ = " + toString(lib.worstTheta, 3), lib.worstUlps, 4.0,
           lib.worstUlps <= 4.0);
  std::vector<Sample> f128;
  if constexpr (std::is_same_v<S, double>) f128 = sweep<__float128>(deltas, thetas);
  c.note("Method: X = (exp(θâ), t) built in the scalar type, SE3::log in that type, reference in mpfr (≥ 320 bits) "
         "from the same quaternion and translation: ω = 2 atan2(|q_v|, q_w) q_v/|q_v|, v = Jl(ω)⁻¹t with Jl by its "
         "power series. Error = max(‖Δω‖∞/‖ω‖∞, ‖Δv‖∞/‖v‖∞)/ε.");
  if (!c.makeFigures()) return;
  // Two plots against θ ∈ [1e-8, 3] and against π − θ near π: the asked scalar, and in double (the
  // default run) also float, long double and float128 beside it (the figure's four scalars).
  std::vector<std::pair<std::string, std::vector<Sample>>> drawn;
  drawn.emplace_back(name, own);
  if constexpr (std::is_same_v<S, double>) {
    drawn.emplace_back("float", sweep<float>(deltas, thetas));
    drawn.emplace_back("long double", sweep<long double>(deltas, thetas));
    drawn.emplace_back("float128", f128);
  }
  std::string names;
  for (std::size_t k = 0; k < drawn.size(); ++k) names += (k ? ", " : "") + drawn[k].first;
  for (const bool byDelta : {false, true}) {
    rd::Plot plot;
    plot.title = byDelta ? "SE(3) log near π: error in ulps vs π − θ" : "SE(3) log: error in ulps vs θ";
    plot.x.label = byDelta ? "π − θ (log scale)" : "θ (log scale)";
    plot.x.scale = rd::AxisScale::Log10;
    plot.y.label = "normwise error (ulps of the scalar)";
    plot.y.min = 0;
    for (std::size_t k = 0; k < drawn.size(); ++k) addSeries(plot, drawn[k].second, byDelta, drawn[k].first, rd::palette::cycle(k));
    const std::string file = byDelta ? "GF-4.4-log-accuracy-near-pi.png" : "GF-4.4-log-accuracy.png";
    rd::renderPlotPngAndSvg(plot, c.figurePath(file), 1200, 760);
    c.figure(file, "Normwise error of soma's SE3::log in ulps of each scalar type (" + names +
                       ") against an mpfr reference, for random axes and translations, " +
                       (byDelta ? "against π − θ for θ near π." : "against θ ∈ [1e-8, 3]."));
  }
}

}  // namespace

SOMA_STUDY({.id = "GF-4.4-log-accuracy",
            .title = "Worst SE(3) log error over θ ∈ (0, π] in the asked scalar (vs mpfr at ≥ 2p + 64 bits)",
            .source = "GF §4.4.2",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { logAccuracy<S>(c); }); }});

}  // namespace soma::studies::gf04::SOMA_UNITY_ID
