// The singular set of a 3R arm in joint space: Fourier series of det J, roots along lines,
// continuation tracing, image reversals (the second cusp count), aspects. Double only.
#include "soma/geometry/cuspidal/singular_set.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/polynomial.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace soma {

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrapPi(double x) { return std::atan2(std::sin(x), std::cos(x)); }

std::array<double, 5> basis(double t) {
  return {1.0, std::cos(t), std::sin(t), std::cos(2 * t), std::sin(2 * t)};
}
std::array<double, 5> basisDerivative(double t) {
  return {0.0, -std::sin(t), std::cos(t), -2 * std::sin(2 * t), 2 * std::cos(2 * t)};
}

/// Real roots in [−π, π) of α0 + α1 cos θ + α2 sin θ + α3 cos 2θ + α4 sin 2θ (sorted).
std::vector<double> trigQuadraticRoots(const std::array<double, 5>& al, double scale) {
  double amax = 0;
  for (double a : al) amax = std::max(amax, std::abs(a));
  if (amax <= Tolerance<double>::rank() * scale) return {};
  auto f = [&](double t) {
    const auto e = basis(t);
    double v = 0;
    for (int k = 0; k < 5; ++k) v += al[k] * e[k];
    return v;
  };
  // θ = φ0 + ψ, t = tan(ψ/2): pick φ0 so that ψ = π (t = ∞) is far from a root.
  double phi0 = 0, best = -1;
  for (int j = 0; j < 8; ++j) {
    const double ph = 2 * kPi * j / 8;
    const double v = std::abs(f(ph + kPi));
    if (v > best) best = v, phi0 = ph;
  }
  const double c1 = std::cos(phi0), s1 = std::sin(phi0), c2 = std::cos(2 * phi0), s2 = std::sin(2 * phi0);
  const double b0 = al[0], b1 = al[1] * c1 + al[2] * s1, b2 = al[2] * c1 - al[1] * s1;
  const double b3 = al[3] * c2 + al[4] * s2, b4 = al[4] * c2 - al[3] * s2;
  // Numerators over (1 + t²)²: 1 → 1 + 2t² + t⁴, cos → 1 − t⁴, sin → 2t + 2t³,
  // cos 2 → 1 − 6t² + t⁴, sin 2 → 4t − 4t³.
  const std::array<double, 5> c = {b0 + b1 + b3, 2 * b2 + 4 * b4, 2 * b0 - 6 * b3, 2 * b2 - 4 * b4,
                                    b0 - b1 + b3};
  std::vector<double> out;
  for (double t : quarticRealRoots<double>(c)) out.push_back(wrapPi(phi0 + 2 * std::atan(t)));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

double DetJSeries::value(double t2, double t3) const {
  const auto a = basis(t2), b = basis(t3);
  double v = 0;
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) v += C(j, k) * a[j] * b[k];
  return v;
}

Eigen::Vector2d DetJSeries::gradient(double t2, double t3) const {
  const auto a = basis(t2), b = basis(t3), da = basisDerivative(t2), db = basisDerivative(t3);
  Eigen::Vector2d g(0, 0);
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) {
      g(0) += C(j, k) * da[j] * b[k];
      g(1) += C(j, k) * a[j] * db[k];
    }
  return g;
}

std::vector<double> DetJSeries::rootsInTheta2(double t3) const {
  const auto b = basis(t3);
  std::array<double, 5> al{};
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) al[j] += C(j, k) * b[k];
  return trigQuadraticRoots(al, scale);
}

std::vector<double> DetJSeries::rootsInTheta3(double t2) const {
  const auto a = basis(t2);
  std::array<double, 5> al{};
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) al[k] += C(j, k) * a[j];
  return trigQuadraticRoots(al, scale);
}

bool DetJSeries::vanishesAlongTheta2(double t3) const {
  const auto b = basis(t3);
  for (int j = 0; j < 5; ++j) {
    double a = 0;
    for (int k = 0; k < 5; ++k) a += C(j, k) * b[k];
    if (std::abs(a) > Tolerance<double>::rank() * scale) return false;
  }
  return true;
}

double toolPointJacobianDet(const SerialRobot<double>& robot, const JointVector<double>& q) {
  const JacobianMatrix<double> Js = robot.spatialJacobian(q);
  const Vec3<double> p = robot.fk(q).translation();
  Mat3<double> Jp;
  for (int i = 0; i < 3; ++i) {
    const Vec3<double> w = Js.block<3, 1>(0, i), v = Js.block<3, 1>(3, i);
    Jp.col(i) = v + w.cross(p);  // velocity of the point p: v + ω × p
  }
  return Jp.determinant();
}

DetJSeries detJSeries(const SerialRobot<double>& robot) {
  (void)arm3RFrame(robot);  // validates: exactly three revolute joints
  constexpr int N = 6;
  Eigen::Matrix<double, N, N> D;
  std::array<std::array<double, 5>, N> w{};
  for (int a = 0; a < N; ++a) {
    const double t = 2 * kPi * a / N;
    const auto e = basis(t);
    w[a] = {e[0] / N, 2 * e[1] / N, 2 * e[2] / N, 2 * e[3] / N, 2 * e[4] / N};
  }
  DetJSeries s;
  s.scale = 0;
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b) {
      JointVector<double> q(3);
      q << 0, 2 * kPi * a / N, 2 * kPi * b / N;
      D(a, b) = toolPointJacobianDet(robot, q);
      s.scale = std::max(s.scale, std::abs(D(a, b)));
    }
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) {
      double c = 0;
      for (int a = 0; a < N; ++a)
        for (int b = 0; b < N; ++b) c += w[a][j] * w[b][k] * D(a, b);
      s.C(j, k) = c;
    }
  if (!(s.scale > 0)) s.scale = 1;  // det J ≡ 0: a degenerate arm (every posture singular)
  return s;
}

namespace {

/// The lines θ3 = c along which det J vanishes identically (orthogonal arms with r3 = 0 and a3 > a2
/// have two, θ3 = ±c): the roots of θ3 ↦ det J(θ2*, θ3) at a θ2* of no special value where every
/// θ2-coefficient of det J vanishes too.
std::vector<double> vanishingLines(const DetJSeries& dj) {
  std::vector<double> lines;
  for (double c : dj.rootsInTheta3(0.7390851332151607))  // the fixed point of cos: no special angle
    if (dj.vanishesAlongTheta2(c) && (lines.empty() || std::abs(wrapPi(c - lines.back())) > Tolerance<double>::sqrtEpsilon()))
      lines.push_back(c);
  return lines;
}

/// det J = (cos(θ3 − m) − cos δ) · R(θ2, θ3) for two lines θ3 = m ± δ of det J ≡ 0: R's series,
/// exactly (R has degree 1 in θ3). In φ = θ3 − m a row a0 + a1 cos φ + b1 sin φ + a2 cos 2φ +
/// b2 sin 2φ equals (cos φ − cos δ)(p0 + p1 cos φ + q1 sin φ) with p1 = 2 a2, q1 = 2 b2,
/// p0 = a1 + cos δ · p1 (the constant and sin φ terms then agree: det J vanishes on both lines).
DetJSeries divideByLines(const DetJSeries& dj, double c1, double c2) {
  const double m = (c1 + c2) / 2, cd = std::cos((c1 - c2) / 2);
  const double cm = std::cos(m), sm = std::sin(m), c2m = std::cos(2 * m), s2m = std::sin(2 * m);
  DetJSeries r;
  for (int j = 0; j < 5; ++j) {
    // The row in φ: a frequency-k pair (cos kθ3, sin kθ3) turns by k·m.
    const double a1 = dj.C(j, 1) * cm + dj.C(j, 2) * sm, a2 = dj.C(j, 3) * c2m + dj.C(j, 4) * s2m;
    const double b2 = -dj.C(j, 3) * s2m + dj.C(j, 4) * c2m;
    const double p1 = 2 * a2, q1 = 2 * b2, p0 = a1 + cd * p1;
    // Back to θ3: p1 cos φ + q1 sin φ = (p1 cos m − q1 sin m) cos θ3 + (p1 sin m + q1 cos m) sin θ3.
    r.C(j, 0) = p0;
    r.C(j, 1) = p1 * cm - q1 * sm;
    r.C(j, 2) = p1 * sm + q1 * cm;
  }
  r.scale = 0;
  for (int a = 0; a < 12; ++a)
    for (int b = 0; b < 12; ++b) r.scale = std::max(r.scale, std::abs(r.value(2 * kPi * a / 12, 2 * kPi * b / 12)));
  return r;
}

}  // namespace

std::vector<SingularBranch> traceSingularCurves(const SerialRobot<double>& robot, const DetJSeries& dj,
                                                double step, int seedLines) {
  if (!(step > 0) || seedLines < 1) throw InvalidInput("traceSingularCurves: step > 0 and seedLines ≥ 1 required");
  const Arm3RFrame<double> frame = arm3RFrame(robot);
  // Two lines θ3 = c of det J ≡ 0 cross the other branches at nodes, where a continuation can turn
  // onto the line and follow it for its whole step budget (measured on orthogonal arms with r3 = 0:
  // (1, 0.4, 0.45, 1, 0) with a corrector across the tangent, (1, 1.2, 1.85, 1, 0) with one along
  // ∇det J; thousands of false image reversals). So the other branches are traced on the quotient
  // R = det J / (cos(θ3 − m) − cos δ), which has no such node, and the lines are added as branches.
  const std::vector<double> lines = vanishingLines(dj);
  const DetJSeries reduced = lines.size() == 2 ? divideByLines(dj, lines[0], lines[1]) : dj;
  const DetJSeries& f = reduced;
  // Occupancy of the torus by traced points (cells of about 2 steps).
  const int M = std::max(16, int(2 * kPi / (2 * step)));
  std::vector<char> occ(std::size_t(M) * M, 0);
  auto cell = [&](double x) {
    int i = int(std::floor((wrapPi(x) + kPi) / (2 * kPi) * M));
    return std::clamp(i, 0, M - 1);
  };
  auto mark = [&](const Eigen::Vector2d& x) {
    const int i = cell(x(0)), j = cell(x(1));
    for (int di = -1; di <= 1; ++di)
      for (int dk = -1; dk <= 1; ++dk) occ[std::size_t((j + dk + M) % M) * M + (i + di + M) % M] = 1;
  };
  auto occupied = [&](const Eigen::Vector2d& x) { return occ[std::size_t(cell(x(1))) * M + cell(x(0))] != 0; };
  const double tolD = Tolerance<double>::identity() * f.scale;
  auto correct = [&](Eigen::Vector2d& y) {
    for (int it = 0; it < 12; ++it) {
      const double d = f.value(y(0), y(1));
      if (std::abs(d) <= tolD) return true;
      const Eigen::Vector2d g = f.gradient(y(0), y(1));
      const double g2 = g.squaredNorm();
      if (!(g2 > 0)) return false;
      y -= (d / g2) * g;
    }
    return std::abs(f.value(y(0), y(1))) <= Tolerance<double>::sqrtEpsilon() * f.scale;
  };
  // The corrector of a step: Newton along n, the normal of the branch's current tangent (pseudo-
  // arclength continuation): across n the branch is O(h²) away from the predictor, a curve crossing
  // it at a node O(h), where a corrector along ∇f can land on the other curve.
  auto correctAcross = [&](Eigen::Vector2d& y, const Eigen::Vector2d& n) {
    for (int it = 0; it < 12; ++it) {
      const double d = f.value(y(0), y(1));
      if (std::abs(d) <= tolD) return true;
      const double gn = f.gradient(y(0), y(1)).dot(n);
      if (!(std::abs(gn) > 0)) return false;
      y -= (d / gn) * n;
    }
    return std::abs(f.value(y(0), y(1))) <= Tolerance<double>::sqrtEpsilon() * f.scale;
  };
  auto tangent = [&](const Eigen::Vector2d& y) {
    const Eigen::Vector2d g = f.gradient(y(0), y(1));
    Eigen::Vector2d t(-g(1), g(0));
    const double n = t.norm();
    return n > 0 ? Eigen::Vector2d(t / n) : Eigen::Vector2d(0, 0);
  };
  auto wrappedDistance = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::hypot(wrapPi(a(0) - b(0)), wrapPi(a(1) - b(1)));
  };
  std::vector<Eigen::Vector2d> seeds;
  for (int l = 0; l < seedLines; ++l) {
    const double c = -kPi + 2 * kPi * (l + 0.5) / seedLines;
    if (!f.vanishesAlongTheta2(c))
      for (double r : f.rootsInTheta2(c)) seeds.emplace_back(r, c);
    for (double r : f.rootsInTheta3(c)) seeds.emplace_back(c, r);
  }
  std::vector<SingularBranch> out;
  // |∇det J| and the section's (ρ, z) at each point of a traced branch, then the branch kept.
  auto finish = [&](SingularBranch& br) {
    br.section.reserve(br.joints.size());
    for (const auto& p : br.joints) br.gradient.push_back(dj.gradient(p(0), p(1)).norm());
    for (const auto& p : br.joints) {
      JointVector<double> q(3);
      q << 0, p(0), p(1);
      br.section.push_back(workspaceSection(frame, robot, q));
    }
    out.push_back(std::move(br));
  };
  const int maxSteps = int(40 * kPi / step);
  for (const auto& s0 : seeds) {
    if (occupied(s0)) continue;
    Eigen::Vector2d x = s0;
    if (!correct(x)) continue;
    SingularBranch br;
    br.joints.push_back(x);
    Eigen::Vector2d t = tangent(x);
    if (t.squaredNorm() == 0) continue;
    double travelled = 0;
    for (int k = 0; k < maxSteps; ++k) {
      double h = step;
      Eigen::Vector2d y;
      bool ok = false;
      for (int tries = 0; tries < 7 && !ok; ++tries, h /= 2) {
        y = x + h * t;
        ok = correctAcross(y, Eigen::Vector2d(-t(1), t(0))) && (y - x).norm() < 3 * h;
      }
      if (!ok) break;
      Eigen::Vector2d tn = tangent(y);
      if (tn.squaredNorm() == 0) tn = t;  // through a node: keep going straight
      if (tn.dot(t) < 0) tn = -tn;
      travelled += (y - x).norm();
      x = y;
      t = tn;
      br.joints.push_back(x);
      if (travelled > 8 * step && wrappedDistance(x, s0) < 0.75 * step) {
        br.closed = true;
        // Stepped past the start: drop the point so the closing chord runs forward.
        const Eigen::Vector2d back(wrapPi(s0(0) - x(0)), wrapPi(s0(1) - x(1)));
        if (back.dot(t) < 0) br.joints.pop_back();
        break;
      }
    }
    for (const auto& p : br.joints) mark(p);
    finish(br);
  }
  // The lines themselves (traced on the quotient above, they are not among its branches): θ2 once
  // round at the tracing step; each maps to one point of the section.
  if (lines.size() == 2)
    for (double c : lines) {
      SingularBranch br;
      const int n = std::max(8, int(std::ceil(2 * kPi / step)));
      for (int k = 0; k < n; ++k) br.joints.emplace_back(-kPi + 2 * kPi * k / n, c);
      br.closed = true;
      finish(br);
    }
  return out;
}

// GF §5.2.3 (a cusp of the section is where the image of the singular curve turns back)
std::vector<Eigen::Vector2d> imageReversals(const std::vector<SingularBranch>& branches) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& br : branches) {
    const std::size_t n = br.section.size();
    if (n < 3) continue;
    auto F = [&](std::size_t i) {
      const auto& s = br.section[i % n];
      return Eigen::Vector2d(s(0) * s(0), s(1));
    };
    const std::size_t last = br.closed ? n : n - 2;
    // A branch whose image is one point (a line θ3 = const along which the tool point sits on axis
    // 2, so turning θ2 does not move it: orthogonal arms with r3 = 0 and a3 > a2) has no cusp; its
    // chords are round-off, and their "reversals" are noise.
    double extent = 0, size = 0;
    for (std::size_t i = 0; i < n; ++i) {
      extent = std::max(extent, (F(i) - F(0)).norm());
      size = std::max(size, F(i).norm());
    }
    const double noise = Tolerance<double>::sqrtEpsilon() * (1 + size);
    if (extent <= noise) continue;
    std::vector<double> gs = br.gradient;
    std::nth_element(gs.begin(), gs.begin() + gs.size() / 2, gs.end());
    const double median = gs[gs.size() / 2];
    auto nearNode = [&](std::size_t k) {
      for (std::size_t i = k + n - 3; i <= k + n + 3; ++i)
        if (!br.closed && (i < n || i >= 2 * n)) continue;
        else if (br.gradient[i % n] < 0.02 * median) return true;
      return false;
    };
    std::size_t prevHit = std::size_t(-1);
    for (std::size_t k = 0; k < last; ++k) {
      const Eigen::Vector2d d0 = F(k + 1) - F(k), d1 = F(k + 2) - F(k + 1);
      if (d0.dot(d1) < 0 && !nearNode(k + 1)) {
        // A cusp makes one reversal; round-off at a near-stationary chord could make a pair of
        // adjacent ones: merge reversals within 4 steps.
        if (prevHit != std::size_t(-1) && k - prevHit <= 4) continue;
        prevHit = k;
        out.push_back(br.section[(k + 1) % n]);
      }
    }
  }
  return out;
}

double AspectMap::theta(int i) const { return -kPi + 2 * kPi * (i + 0.5) / n; }

AspectMap aspects(const DetJSeries& dj, int n) {
  if (n < 8) throw InvalidInput("aspects: grid size n must be at least 8");
  AspectMap m;
  m.n = n;
  std::vector<double> th(n);
  for (int i = 0; i < n; ++i) th[i] = m.theta(i);
  std::vector<int> parent(std::size_t(n) * n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  auto unite = [&](int a, int b) { parent[find(a)] = find(b); };
  std::vector<int> sgn(std::size_t(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double v = dj.value(th[i], th[j]);
      sgn[std::size_t(j) * n + i] = v > 0 ? 1 : (v < 0 ? -1 : 0);
    }
  // An edge from a to b (b = a + 2π/n, wrapping) is free when no root lies in [a, b].
  auto freeEdge = [&](const std::vector<double>& roots, double a, double b) {
    for (double r : roots) {
      double d = r - a;
      while (d < 0) d += 2 * kPi;
      while (d >= 2 * kPi) d -= 2 * kPi;
      double len = b - a;
      while (len < 0) len += 2 * kPi;
      if (d <= len) return false;
    }
    return true;
  };
  for (int j = 0; j < n; ++j) {  // rows: θ3 = th[j], edges along θ2
    if (dj.vanishesAlongTheta2(th[j])) {
      for (int i = 0; i < n; ++i) sgn[std::size_t(j) * n + i] = 0;
      continue;
    }
    const auto roots = dj.rootsInTheta2(th[j]);
    for (int i = 0; i < n; ++i) {
      const int a = j * n + i, b = j * n + (i + 1) % n;
      if (sgn[a] != 0 && sgn[a] == sgn[b] && freeEdge(roots, th[i], th[(i + 1) % n])) unite(a, b);
    }
  }
  for (int i = 0; i < n; ++i) {  // columns: θ2 = th[i], edges along θ3
    const auto roots = dj.rootsInTheta3(th[i]);
    for (int j = 0; j < n; ++j) {
      const int a = j * n + i, b = ((j + 1) % n) * n + i;
      if (sgn[a] != 0 && sgn[a] == sgn[b] && freeEdge(roots, th[j], th[(j + 1) % n])) unite(a, b);
    }
  }
  m.label.assign(std::size_t(n) * n, -1);
  std::vector<int> rootLabel(std::size_t(n) * n, -1);
  for (int a = 0; a < n * n; ++a) {
    if (sgn[a] == 0) continue;
    const int r = find(a);
    if (rootLabel[r] < 0) {
      rootLabel[r] = m.count();
      m.sign.push_back(sgn[a]);
    }
    m.label[a] = rootLabel[r];
  }
  return m;
}

int AspectMap::aspectOf(const DetJSeries& dj, double t2, double t3) const {
  const double h = 2 * kPi / n;
  const int i0 = int(std::floor((wrapPi(t2) + kPi) / h - 0.5));
  const int j0 = int(std::floor((wrapPi(t3) + kPi) / h - 0.5));
  const double s0 = dj.value(t2, t3);
  for (int di = 0; di <= 1; ++di)
    for (int dk = 0; dk <= 1; ++dk) {
      const int i = ((i0 + di) % n + n) % n, j = ((j0 + dk) % n + n) % n;
      const int lab = label[std::size_t(j) * n + i];
      if (lab < 0) continue;
      const double a2 = t2 + wrapPi(theta(i) - t2), a3 = t3 + wrapPi(theta(j) - t3);
      bool clear = true;
      for (int k = 0; k <= 32 && clear; ++k) {
        const double u = k / 32.0;
        const double v = dj.value(t2 + u * (a2 - t2), t3 + u * (a3 - t3));
        clear = (v > 0) == (s0 > 0) && v != 0;
      }
      if (clear) return lab;
    }
  return -1;
}

}  // namespace soma

#include "soma/geometry/cuspidal/witness.hpp"

namespace soma {

PathCheck checkPathSign(const DetJSeries& dj, const std::vector<Eigen::Vector3d>& path, int sign,
                        double spacing) {
  PathCheck pc;
  if (path.empty() || !(spacing > 0)) return pc;
  // |D(x) − D(y)| ≤ Lip · max(|Δθ2|, |Δθ3|), Lip = Σ |C_jk| (ω_j + ω_k), ω = (0, 1, 1, 2, 2).
  const double w[5] = {0, 1, 1, 2, 2};
  double lip = 0;
  for (int j = 0; j < 5; ++j)
    for (int k = 0; k < 5; ++k) lip += std::abs(dj.C(j, k)) * (w[j] + w[k]);
  pc.minSignedDet = std::numeric_limits<double>::infinity();
  pc.certified = true;
  double prev = sign * dj.value(path[0](1), path[0](2));
  pc.minSignedDet = prev;
  pc.points = 1;
  for (std::size_t s = 0; s + 1 < path.size(); ++s) {
    Eigen::Vector3d d;
    for (int i = 0; i < 3; ++i) d(i) = wrapPi(path[s + 1](i) - path[s](i));
    const double len = std::max(std::abs(d(1)), std::abs(d(2)));
    const int m = std::max(1, int(std::ceil(len / spacing)));
    const double h = len / m;
    for (int k = 1; k <= m; ++k) {
      const Eigen::Vector3d x = path[s] + d * (double(k) / m);
      const double v = sign * dj.value(x(1), x(2));
      pc.minSignedDet = std::min(pc.minSignedDet, v);
      if (!(std::min(prev, v) > lip * h / 2)) pc.certified = false;
      prev = v;
      ++pc.points;
    }
  }
  if (!(pc.minSignedDet > 0)) pc.certified = false;
  return pc;
}

}  // namespace soma
