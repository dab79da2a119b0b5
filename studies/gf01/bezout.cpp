// Study of GF §1.3 (degree and Bézout's theorem): random plane curves of degrees d₁, d₂ meet in
// d₁d₂ points (conics 4, conic and cubic 6, two cubics 9 — the count behind the Burmester points,
// GF-5.3.5), counted twice: by the resultant in y (its degree in x, and each root lifted to a common
// point of both curves) and by PHCpack (Debian's homotopy-continuation solver); a tangency counts
// twice; points at infinity are lost unless one homogenises; three surfaces of PR³ meet in
// d₁d₂d₃ points (PHCpack). Double: PHCpack and Eigen's complex eigensolver work in double.
#include "soma/studies/phc_runner.hpp"
#include "soma/studies/study.hpp"
#include "soma/algebra/polynomial.hpp"
#include "soma/algebra/tolerance.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <array>
#include <complex>
#include <functional>
#include <random>

namespace soma::studies::gf01bezout::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 1 — Introduction";
constexpr const char* kWhyDouble = "PHCpack (the independent solver) and Eigen's complex eigensolver work in double";
using C = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

/// A plane curve f(x, y) = 0 of total degree d in the affine chart z = 1: its coefficients
/// c(i, j) of xⁱyʲ (i + j ≤ d).
struct Curve {
  int d = 0;
  Eigen::MatrixXd c;
  C operator()(C x, C y) const {
    C v = 0;
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j) v += c(i, j) * std::pow(x, i) * std::pow(y, j);
    return v;
  }
  /// Coefficients of y ↦ f(x, y), ascending.
  Eigen::VectorXcd inY(C x) const {
    Eigen::VectorXcd a = Eigen::VectorXcd::Zero(d + 1);
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j) a(j) += c(i, j) * std::pow(x, i);
    return a;
  }
  double scale() const { return c.cwiseAbs().maxCoeff(); }
  /// PHCpack's text of the polynomial in x, y.
  std::string phc() const {
    std::string s;
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j)
        if (c(i, j) != 0) s += fmt::format(" {}*x^{}*y^{}", phcNumber(c(i, j)), i, j);
    return s + ";";
  }
};
Curve randomCurve(std::mt19937_64& g, int d) {
  std::uniform_real_distribution<double> u(-1, 1);
  Curve f;
  f.d = d;
  f.c = Eigen::MatrixXd::Zero(d + 1, d + 1);
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) f.c(i, j) = u(g);
  return f;
}
/// Sylvester matrix of two polynomials in y (ascending coefficients); det = Res_y.
C resultantAt(const Curve& f, const Curve& g, C x) {
  const Eigen::VectorXcd a = f.inY(x), b = g.inY(x);
  const int m = f.d, n = g.d;
  Eigen::MatrixXcd S = Eigen::MatrixXcd::Zero(m + n, m + n);
  for (int r = 0; r < n; ++r)
    for (int k = 0; k <= m; ++k) S(r, r + k) = a(m - k);
  for (int r = 0; r < m; ++r)
    for (int k = 0; k <= n; ++k) S(n + r, r + k) = b(n - k);
  return S.partialPivLu().determinant();
}
struct Eliminant {
  std::vector<double> coeffs;  ///< R(x) ascending, truncated at its numerical degree
  int degree = 0;
  double tail = 0;  ///< largest |coefficient| above the degree, relative (DFT rounding)
};
/// R(x) = Res_y(f, g) by its values at N roots of unity (an exact DFT for degree < N).
Eliminant eliminant(const Curve& f, const Curve& g) {
  const int N = 2 * (f.d * g.d + 1);
  std::vector<C> vals(N);
  for (int k = 0; k < N; ++k) vals[std::size_t(k)] = resultantAt(f, g, std::polar(1.0, 2 * kPi * k / N));
  std::vector<double> r(N);
  double big = 0;
  for (int m = 0; m < N; ++m) {
    C s = 0;
    for (int k = 0; k < N; ++k) s += vals[std::size_t(k)] * std::polar(1.0, -2 * kPi * k * m / N);
    r[std::size_t(m)] = (s / double(N)).real();
    big = std::max(big, std::abs(r[std::size_t(m)]));
  }
  // Coefficients of random data are O(1) relative to the largest; the DFT leaves N·ε·max.
  Eliminant e;
  const double cut = 1e-8 * big;
  for (int m = 0; m < N; ++m)
    if (std::abs(r[std::size_t(m)]) > cut) e.degree = m;
  for (int m = e.degree + 1; m < N; ++m) e.tail = std::max(e.tail, std::abs(r[std::size_t(m)]) / big);
  e.coeffs.assign(r.begin(), r.begin() + e.degree + 1);
  return e;
}
/// Roots of a complex polynomial (ascending) as the eigenvalues of its companion matrix.
std::vector<C> complexRoots(const Eigen::VectorXcd& a) {
  int n = int(a.size()) - 1;
  while (n > 0 && std::abs(a(n)) <= 1e-14 * a.cwiseAbs().maxCoeff()) --n;
  Eigen::MatrixXcd M = Eigen::MatrixXcd::Zero(n, n);
  for (int i = 1; i < n; ++i) M(i, i - 1) = 1;
  for (int i = 0; i < n; ++i) M(i, n - 1) = -a(i) / a(n);
  const Eigen::VectorXcd ev = Eigen::ComplexEigenSolver<Eigen::MatrixXcd>(M, false).eigenvalues();
  return std::vector<C>(ev.data(), ev.data() + ev.size());
}
struct Point2 {
  C x, y;
  double residual = 0;
};
/// Every root x₀ of the eliminant lifted to the common root y₀ of f(x₀, ·) and g(x₀, ·).
std::vector<Point2> intersect(const Curve& f, const Curve& g, const Eliminant& e) {
  std::vector<Point2> pts;
  for (const auto& x0 : polynomialRoots<double>(e.coeffs)) {
    Point2 best{x0, 0, 1e300};
    for (const C& y0 : complexRoots(f.inY(x0))) {
      const double r = std::max(std::abs(f(x0, y0)) / f.scale(), std::abs(g(x0, y0)) / g.scale()) /
                       std::pow(std::max({1.0, std::abs(x0), std::abs(y0)}), std::max(f.d, g.d));
      if (r < best.residual) best = {x0, y0, r};
    }
    pts.push_back(best);
  }
  return pts;
}
double separation(const std::vector<Point2>& p) {
  double s = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) s = std::min(s, std::abs(p[i].x - p[j].x) + std::abs(p[i].y - p[j].y));
  return s;
}
/// PHCpack's regular finite solutions of f = g = 0.
std::vector<Point2> phcIntersect(const Curve& f, const Curve& g, const std::string& tag, PhcResult* raw = nullptr) {
  const PhcResult run = solveWithPhc({f.phc(), g.phc()}, {"x", "y"}, tag);
  if (raw) *raw = run;
  std::vector<Point2> pts;
  for (const auto& s : run.solutions)
    if (s.regular) pts.push_back({s.x(0), s.x(1), 0});
  return pts;
}

// GF §1.3, GF-1.3-bezout-degree
void bezoutDegree(Context& c) {
  std::mt19937_64 gen(1304);
  // A lifted root is a common point when its relative residual is at rounding level; the roots of
  // a degree-9 eliminant carry its condition (≈ 1e3 here), hence 1e-9.
  const double tolPoint = 1e-9;
  for (const auto& [d1, d2] : std::vector<std::pair<int, int>>{{2, 2}, {2, 3}, {3, 3}}) {
    const Curve f = randomCurve(gen, d1), g = randomCurve(gen, d2);
    const Eliminant e = eliminant(f, g);
    const std::string what = fmt::format("random curves of degrees {} and {}", d1, d2);
    c.checkEqual(what + ": degree of the resultant Res_y(f, g) in x = d₁d₂", d1 * d2, e.degree);
    c.checkResidual(what + ": … its coefficients above d₁d₂ vanish (relative, DFT rounding N·ε)", e.tail, 1e-12);
    const auto pts = intersect(f, g, e);
    int common = 0;
    double worst = 0;
    for (const auto& p : pts) {
      common += p.residual <= tolPoint;
      worst = std::max(worst, p.residual);
    }
    c.checkEqual(what + ": roots x₀ of the resultant that lift to a common point (x₀, y₀) of both curves", d1 * d2, common);
    c.recordIn(what + ": … and the points are distinct (smallest separation)", "> 1e-3", fmt::format("{:.3g}", separation(pts)),
               separation(pts), 1e-3, separation(pts) > 1e-3);
    const auto ph = phcIntersect(f, g, fmt::format("bezout{}{}", d1, d2));
    c.checkEqual(what + ": PHCpack's regular finite solutions", d1 * d2, static_cast<long long>(ph.size()));
    double farthest = 0;
    for (const auto& q : ph) {
      double best = 1e300;
      for (const auto& p : pts) best = std::min(best, std::abs(p.x - q.x) + std::abs(p.y - q.y));
      farthest = std::max(farthest, best);
    }
    c.checkResidual(what + ": every PHCpack point is one of the resultant's (|Δx| + |Δy|)", farthest, 1e-8);
  }
  // Multiplicity: a circle and an ellipse tangent at one point meet in 4 points counted with
  // multiplicity, 3 distinct (the eliminant has a double root). Coordinates turned by a generic
  // angle so that no two points share x.
  {
    const double th = 0.37, ct = std::cos(th), st = std::sin(th);
    auto rotate = [&](const std::function<double(double, double)>& h, int d) {
      // coefficients of h(ct·x + st·y, −st·x + ct·y) by exact interpolation on a (d+1)² grid
      Curve f;
      f.d = d;
      const int n = d + 1;
      Eigen::MatrixXd V(n * n, n * n), rhs(n * n, 1);
      int row = 0;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b, ++row) {
          const double x = a - 1.0, y = b - 1.0;
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) V(row, i * n + j) = std::pow(x, i) * std::pow(y, j);
          rhs(row, 0) = h(ct * x + st * y, -st * x + ct * y);
        }
      const Eigen::VectorXd k = V.fullPivLu().solve(rhs);
      f.c = Eigen::MatrixXd::Zero(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) f.c(i, j) = k(i * n + j);
      return f;
    };
    // circle x² + y² = 1 and ellipse ((x − 1.5)/0.5)² + (y/0.8)² = 1, tangent at (1, 0)
    const Curve f = rotate([](double x, double y) { return x * x + y * y - 1; }, 2);
    const Curve g = rotate([](double x, double y) { return (x - 1.5) * (x - 1.5) / 0.25 + y * y / 0.64 - 1; }, 2);
    const Eliminant e = eliminant(f, g);
    const auto pts = intersect(f, g, e);
    int clusters = 0;
    std::vector<bool> used(pts.size(), false);
    double pairGap = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (used[i]) continue;
      ++clusters;
      for (std::size_t j = i + 1; j < pts.size(); ++j)
        if (std::abs(pts[i].x - pts[j].x) < 1e-6) used[j] = true, pairGap = std::abs(pts[i].x - pts[j].x);
    }
    c.checkEqual("tangent conics: degree of the resultant (points with multiplicity)", 4, e.degree);
    c.checkEqual("… distinct intersection points (roots closer than 1e-6 merged: a double root splits by ~√ε)", 3, clusters);
    c.recordIn("… the double root's two copies (its split under rounding is O(√ε))", "< 1e-6", fmt::format("{:.2g}", pairGap),
               pairGap, 1e-6, pairGap < 1e-6);
  }
  // Points at infinity: two circles share the circular points (1 : ±i : 0). In the chart z = 1 the
  // resultant has degree 2 and PHCpack's 4 paths end in 2 finite solutions; in a generic chart
  // (x, y, z) = (X, Y, 1 + aX + bY), which puts the line z = 0 at finite distance, all 4.
  {
    Curve f, g;
    f.d = g.d = 2;
    f.c = Eigen::MatrixXd::Zero(3, 3);
    g.c = Eigen::MatrixXd::Zero(3, 3);
    f.c(2, 0) = f.c(0, 2) = 1, f.c(0, 0) = -1;                       // x² + y² − 1
    g.c(2, 0) = g.c(0, 2) = 1, g.c(1, 0) = 1, g.c(0, 1) = 0.3, g.c(0, 0) = -2;  // x² + y² + x + 0.3y − 2
    c.checkEqual("two circles, chart z = 1: degree of the resultant (2 of the 4 points are at infinity)", 2, eliminant(f, g).degree);
    PhcResult raw;
    const auto ph = phcIntersect(f, g, "circles", &raw);
    c.checkEqual("… PHCpack: regular finite solutions (of 4 paths, the others diverge)", 2, static_cast<long long>(ph.size()));
    c.checkEqual("… PHCpack's path count = the Bézout number 2·2", 4, raw.paths);
    // Homogenise: F(X, Y, Z) = Z²f(X/Z, Y/Z) with Z = 1 + aX + bY.
    const double a = 0.61, b = -0.43;
    auto chart = [&](const Curve& h) {
      Curve k;
      k.d = 2;
      k.c = Eigen::MatrixXd::Zero(3, 3);
      // Z² f(X/Z, Y/Z) = c20 X² + c02 Y² + c11 XY + (c10 X + c01 Y) Z + c00 Z²
      const auto& q = h.c;
      k.c(2, 0) = q(2, 0) + q(1, 0) * a + q(0, 0) * a * a;
      k.c(0, 2) = q(0, 2) + q(0, 1) * b + q(0, 0) * b * b;
      k.c(1, 1) = q(1, 1) + q(1, 0) * b + q(0, 1) * a + 2 * q(0, 0) * a * b;
      k.c(1, 0) = q(1, 0) + 2 * q(0, 0) * a;
      k.c(0, 1) = q(0, 1) + 2 * q(0, 0) * b;
      k.c(0, 0) = q(0, 0);
      return k;
    };
    const Curve F = chart(f), G = chart(g);
    const Eliminant e = eliminant(F, G);
    c.checkEqual("… in a generic chart: degree of the resultant = 4 (the circular points now finite)", 4, e.degree);
    int circular = 0;
    for (const auto& p : intersect(F, G, e)) {
      const C z = 1.0 + a * p.x + b * p.y;  // back to (x : y : z); circular points have z = 0, y = ±ix
      if (std::abs(z) < 1e-8 * (std::abs(p.x) + 1) && std::abs(p.y * p.y + p.x * p.x) < 1e-8 * std::norm(p.x)) ++circular;
    }
    c.checkEqual("… two of them are the circular points (1 : ±i : 0)", 2, circular);
  }
  // A complete intersection of three surfaces of PR³: degree d₁d₂d₃ (PHCpack, affine chart
  // w·X = 1 of random w, so that no solution is at infinity).
  for (const auto& degs : std::vector<std::array<int, 3>>{{2, 2, 2}, {2, 2, 3}}) {
    std::uniform_real_distribution<double> u(-1, 1);
    const std::vector<std::string> names = {"x0", "x1", "x2", "x3"};
    std::vector<std::string> eqs;
    std::vector<std::function<double(const Eigen::VectorXcd&)>> evals;
    for (int d : degs) {
      // a random form of degree d in 4 variables: Σ over monomials x^α, |α| = d
      std::vector<std::pair<std::array<int, 4>, double>> terms;
      for (int i = 0; i <= d; ++i)
        for (int j = 0; i + j <= d; ++j)
          for (int k = 0; i + j + k <= d; ++k) terms.push_back({{i, j, k, d - i - j - k}, u(gen)});
      std::string s;
      for (const auto& [al, co] : terms)
        s += fmt::format(" {}*x0^{}*x1^{}*x2^{}*x3^{}", phcNumber(co), al[0], al[1], al[2], al[3]);
      eqs.push_back(s + ";");
      evals.push_back([terms, d](const Eigen::VectorXcd& x) {
        C v = 0;
        for (const auto& [al, co] : terms) v += co * std::pow(x(0), al[0]) * std::pow(x(1), al[1]) * std::pow(x(2), al[2]) * std::pow(x(3), al[3]);
        return std::abs(v) / std::pow(x.cwiseAbs().maxCoeff(), d);
      });
    }
    Eigen::Vector4d w(u(gen), u(gen), u(gen), u(gen));
    eqs.push_back(fmt::format(" {}*x0 {}*x1 {}*x2 {}*x3 - 1;", phcNumber(w(0)), phcNumber(w(1)), phcNumber(w(2)), phcNumber(w(3))));
    const PhcResult run = solveWithPhc(eqs, names, fmt::format("surf{}{}{}", degs[0], degs[1], degs[2]));
    int regular = 0;
    double worst = 0;
    for (const auto& s : run.solutions) {
      if (!s.regular) continue;
      ++regular;
      for (const auto& f : evals) worst = std::max(worst, f(s.x));
    }
    const int bez = degs[0] * degs[1] * degs[2];
    c.checkEqual(fmt::format("surfaces of degrees {}, {}, {} in PR³: PHCpack's regular solutions = {}·{}·{}", degs[0], degs[1],
                             degs[2], degs[0], degs[1], degs[2]),
                 bez, regular);
    c.checkResidual("… soma's evaluation of the three forms at them (relative to |x|^d)", worst, 1e-10);
  }
  c.note("The plane counts are checked twice: the resultant's degree with each root lifted to a common point, "
         "and PHCpack's homotopy (phc -b -0, total degree) matching those points one to one.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-1.3-bezout-degree", "Bézout: curves of degrees d₁, d₂ meet in d₁d₂ points (4, 6, 9); surfaces of PR³ in d₁d₂d₃",
                  "GF §1.3", bezoutDegree);

}  // namespace soma::studies::gf01bezout::SOMA_UNITY_ID
