// SOMA-screw-identification-speed-accuracy: the identification of a screw system's Gibson–Hunt
// type from generators (GF ch. 8, identifyScrewSystem) on every rung of the scalar ladder. A
// fixed-seed family of generator sets, each a posed and mixed normal form of a known type built in
// mpfr (≥ 512 bits) at a distance δ = 2^-k from the boundary with a more special type (k from 1 to
// 330), then rounded to the rung: the time per identification, the fraction identified as the
// construction's type, and the error of the invariants (pitches, principal axes) against the
// construction's exact ones.
#include "soma/geometry/screws/identification.hpp"
#include "soma/studies/mpfr_bits.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using T = ScrewSystemType;

/// A type whose parameter δ = 2^-k puts it at that distance from `boundary`; `reciprocal`: the
/// generators span the reciprocal (a 4- or 5-system), identified through its 2- or 1-system.
struct Family {
  T type, boundary;
  bool reciprocal;
  const char* what;  ///< the δ that separates the two
};

const Family kFamilies[] = {
    {T::Screw, T::Line, false, "screw, pitch δ (line at δ = 0)"},
    {T::IIBp_2, T::IIB0_2, false, "IIB, pitch δ (IIB(p=0) at δ = 0)"},
    {T::IBp_2, T::IB0sup_2, false, "IB, p = δ (IB⁰ at δ = 0)"},
    {T::IA_2, T::IIAp_2, false, "IA, p_a − p_b = δ (IIA(p) at δ = 0)"},
    {T::ICp_3, T::IC0_3, false, "IC, p = δ (IC⁰ at δ = 0)"},
    {T::IB3_3, T::IIB_3, false, "IB₃, p_a − p_b = δ (IIB at δ = 0)"},
    {T::IA1_3, T::IA2_3, false, "IA₁, p_b − p_c = δ (IA₂ at δ = 0)"},
    {T::IA_2, T::IIAp_2, true, "4-system reciprocal to IA, p_a − p_b = δ"},
    {T::Screw, T::Line, true, "5-system reciprocal to a screw of pitch δ"},
};
constexpr int kExponents[] = {1, 3, 6, 10, 14, 18, 22, 26, 30, 36, 42, 48, 54, 60, 70, 80, 100, 120, 160, 200, 240, 280, 330};
constexpr int kSeedsPerCell = 2;

/// One generator set: built in mpfr at the construction's precision; its exact invariants.
struct Sample {
  int family = 0;
  int exponent = 0;           ///< δ = 2^-exponent
  ScrewMatX<mpreal> gen;      ///< 6 × n generators Ad(g)·N·A
  std::array<mpreal, 3> p{};  ///< the construction's parameters
  int parameterCount = 0;
  Mat3<mpreal> axes;          ///< the frame's rotation R_g (principal axes: its columns)
  std::array<double, 3> gap{};  ///< per axis column: the pitch gap of that axis (0: not compared)
  double lBound = 1;          ///< 1 + max|p| + |d|: bounds the identification's length scale L
};

/// The family's samples: random frame g (SE3::Random, in mpfr), random basis change A (entries
/// in [−0.5, 0.5] plus 2 on the diagonal, well conditioned), random pitches |p| ∈ [0.2, 2].
std::vector<Sample> buildSamples(std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  auto mag = [&] { return 0.2 + 1.8 * u(g); };
  auto sgn = [&] { return u(g) < 0.5 ? -1.0 : 1.0; };
  std::vector<Sample> out;
  for (int f = 0; f < int(std::size(kFamilies)); ++f)
    for (int k : kExponents)
      for (int s = 0; s < kSeedsPerCell; ++s) {
        const Family& fam = kFamilies[f];
        Sample x;
        x.family = f;
        x.exponent = k;
        const mpreal delta = mpfr::ldexp(mpreal(1), -k);
        std::array<mpreal, 3> p{mpreal(0), mpreal(0), mpreal(0)};
        x.gap = {0, 0, 0};
        switch (fam.type) {
          case T::Screw: case T::IIBp_2: case T::IBp_2: case T::ICp_3:
            p[0] = delta;  // the ω direction (axis 0) is fixed by the rotational part: gap 1
            x.gap[0] = 1;
            break;
          case T::IA_2: case T::IB3_3: {
            const double b = sgn() * mag();
            p = {mpreal(b) + delta, mpreal(b), mpreal(0)};
            x.gap = {std::ldexp(1.0, -k), std::ldexp(1.0, -k), 0};
            break;
          }
          case T::IA1_3: {
            const double a = sgn() * mag(), d = mag();
            p = {mpreal(a), mpreal(a - d), mpreal(a - d) - delta};
            x.gap = {d, std::ldexp(1.0, -k), std::ldexp(1.0, -k)};
            break;
          }
          default: break;
        }
        x.p = p;
        x.parameterCount = screwSystemTypeParameterCount(fam.type);
        const SE3<mpreal> pose = SE3<mpreal>::Random(g);
        ScrewMatX<mpreal> nf = screwSystemNormalForm<mpreal>(fam.type, p);
        if (fam.reciprocal) nf = ScrewSystem<mpreal>(nf).reciprocal().basis();
        const int n = int(nf.cols());
        ScrewMatX<mpreal> a(n, n);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) a(i, j) = mpreal(u(g) - 0.5 + (i == j ? 2.0 : 0.0));
        x.gen = ScrewMatX<mpreal>(pose.adjoint() * nf) * a;
        x.axes = pose.rotation();
        double pmax = 0;
        for (const auto& v : p) pmax = std::max(pmax, std::abs(toDouble(v)));
        x.lBound = 1 + pmax + toDouble(mpreal(pose.translation().norm()));
        out.push_back(std::move(x));
      }
  return out;
}

/// The generators rounded to the rung (mpfr: to the rung's precision, mpfrBits()).
template <class S> ScrewMatX<S> toRung(const ScrewMatX<mpreal>& m) {
  ScrewMatX<S> r(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if constexpr (std::is_same_v<S, mpreal>) {
        mpreal y(m(i, j));
        y.setPrecision(mpfrBits());  // rounds to nearest
        r(i, j) = y;
      } else {
        r(i, j) = scalarCast<S>(m(i, j));
      }
    }
  return r;
}

struct Measured {
  TradeRung rung;
  std::size_t resolved = 0, resolvedRight = 0;      ///< δ ≥ 16 · 1024 ε L: must be the construction's type
  std::size_t unresolved = 0, unresolvedSpecial = 0;  ///< δ ≤ 16 ε: must be the boundary type
  std::size_t right = 0;
  double worstRatio = 0;  ///< worst invariant error / (1024 ε L) over the resolved samples
  std::string worstWhere;
  int smallestResolvedExponent = 0;  ///< the largest k of a correct identification in every family
  double eps = 0;  ///< ε of the rung
};

/// Identify every sample in S; the invariant errors against the construction, computed in mpfr
/// at `refBits`.
template <class S> Measured measure(const std::vector<Sample>& samples, int refBits) {
  using std::abs;
  Measured m;
  TradeRung& r = m.rung;
  const int bits = mpfrBits();
  r.scalar = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) r.scalar += " (" + std::to_string(bits) + " bits)";
  const double eps = toDouble(Tolerance<S>::epsilon());
  m.eps = eps;
  const double tolRank = toDouble(Tolerance<S>::rank());  // the identification's decision threshold / L
  std::vector<double> times;
  double worstPitch = 0, worstAxis = 0;
  std::vector<int> lastRight(std::size(kFamilies), 0);
  for (const Sample& x : samples) {
    const Family& fam = kFamilies[x.family];
    const ScrewMatX<S> gen = toRung<S>(x.gen);
    ScrewSystemIdentification<S> id;
    double best = 0;
    for (int rep = 0; rep < 3; ++rep) {  // the least of three runs: the machine is shared
      const auto t0 = std::chrono::steady_clock::now();
      id = identifyScrewSystem<S>(gen);
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = rep == 0 ? dt : std::min(best, dt);
    }
    times.push_back(best);
    const bool right = id.type == fam.type && id.viaReciprocal == fam.reciprocal;
    const bool special = id.type == fam.boundary && id.viaReciprocal == fam.reciprocal;
    const double delta = std::ldexp(1.0, -x.exponent);
    // Resolved: δ exceeds the decision threshold 1024 ε L (L ≤ lBound) 16-fold, and the threshold
    // is far above the rounding of the generators (a few ε · L: relative ε per entry, a basis
    // change of condition ≤ 3); unresolved: δ below 16 ε, which that rounding swamps, so the data
    // are of the boundary type to within the rung's precision.
    const bool isResolved = delta >= 16 * tolRank * x.lBound, isUnresolved = delta <= 16 * eps;
    m.right += right;
    if (right) lastRight[std::size_t(x.family)] = std::max(lastRight[std::size_t(x.family)], x.exponent);
    if (isResolved) {
      ++m.resolved;
      m.resolvedRight += right;
    }
    if (isUnresolved) {
      ++m.unresolved;
      m.unresolvedSpecial += special;
    }
    if (!right) continue;
    // The invariants against the construction's, in mpfr at refBits.
    setMpfrBits(refBits);
    double ep = 0, ea = 0;
    for (int i = 0; i < x.parameterCount; ++i)
      ep = std::max(ep, toDouble(mpreal(abs(scalarCast<mpreal>(id.parameters[std::size_t(i)]) - x.p[std::size_t(i)]))));
    const Mat3<S> rot = id.frame.rotation();
    for (int j = 0; j < 3; ++j) {
      if (x.gap[std::size_t(j)] == 0) continue;
      Vec3<mpreal> a, b = x.axes.col(j);
      for (int i = 0; i < 3; ++i) a(i) = scalarCast<mpreal>(rot(i, j));
      const mpreal sine = mpreal(a.cross(b).norm()) / mpreal(a.norm() * b.norm());
      // Davis–Kahan: sin θ ≤ ‖δM‖ / gap, so sin θ × gap is the comparable size of the error.
      ea = std::max(ea, toDouble(sine) * x.gap[std::size_t(j)]);
    }
    setMpfrBits(bits);
    worstPitch = std::max(worstPitch, ep);
    worstAxis = std::max(worstAxis, ea);
    if (isResolved) {
      const double ratio = std::max(ep, ea) / (1024 * eps * x.lBound);
      if (ratio > m.worstRatio) {
        m.worstRatio = ratio;
        m.worstWhere = fmt::format("{}, δ = 2^-{}", fam.what, x.exponent);
      }
    }
  }
  m.smallestResolvedExponent = *std::min_element(lastRight.begin(), lastRight.end());
  r.samples = samples.size();
  timeQuantiles(times, r.medianSeconds, r.p95Seconds);
  r.worstError = std::max(worstPitch, worstAxis);
  r.worstErrorText = io::numberText(r.worstError);  // measured in double (a difference of the rung's values)
  r.comment = fmt::format("type right on {} of {} ({:.1f} %), in every family down to δ = 2^-{} at least; pitch "
                          "error {:.3g}, axis error {:.3g} (sin θ × gap)",
                          m.right, samples.size(), 100.0 * double(m.right) / double(samples.size()),
                          m.smallestResolvedExponent, worstPitch, worstAxis);
  return m;
}

// GF §8.2–8.4 (identifyScrewSystem); SOMA-screw-identification-speed-accuracy
void screwIdentificationTrade(Context& c) {
  const MpfrBitsRestore restore;  // the rung's precision, restored on any exit
  const int bits = restore.bits();
  const int refBits = std::max(512, 2 * bits + 64);
  setMpfrBits(refBits);
  const std::vector<Sample> samples = buildSamples(822026);
  setMpfrBits(bits);
  std::vector<Measured> ms;
  ms.push_back(measure<float>(samples, refBits));
  ms.push_back(measure<double>(samples, refBits));
  ms.push_back(measure<long double>(samples, refBits));
  ms.push_back(measure<__float128>(samples, refBits));
  ms.push_back(measure<mpreal>(samples, refBits));
  TradeTable t;
  t.solver = "Screw-system identification (GF ch. 8)";
  t.sample = "generator set";
  t.errorLabel = "worst invariant error";
  for (const Measured& m : ms) {
    const std::string& s = m.rung.scalar;
    c.checkEqual(fmt::format("{}: generator sets at δ ≥ 16 × 1024 ε L from the boundary identified as the "
                             "construction's type (of {})", s, m.resolved),
                 (long long)m.resolved, (long long)m.resolvedRight);
    c.checkEqual(fmt::format("{}: generator sets at δ ≤ 16 ε (below the rounding of the data) identified as the "
                             "boundary type (of {})", s, m.unresolved),
                 (long long)m.unresolved, (long long)m.unresolvedSpecial);
    // Weyl (pitches) and Davis–Kahan (axes × gap) bound both errors by ‖δM‖, the perturbation of
    // the symmetric pitch matrix by rounding, which the identification assumes below its decision
    // threshold 1024 ε L (Tolerance::rank() × L).
    c.record(fmt::format("{}: worst invariant error (pitch; axis sin θ × gap) of the resolved sets ≤ 1024 ε L "
                         "(Weyl, Davis–Kahan)", s),
             "≤ 1", fmt::format("{:.3g} × 1024 ε L ({})", m.worstRatio, m.worstWhere), m.worstRatio, 1.0,
             m.worstRatio <= 1.0);
    t.rungs.push_back(m.rung);
  }
  // The resolution grows with the rung: each rung identifies at least the sets the previous one did.
  for (std::size_t i = 1; i < ms.size(); ++i)
    if (ms[i].eps < ms[i - 1].eps)  // (mpfr below 113 bits is not a wider rung than float128)
      c.checkEqual(fmt::format("{} identifies at least as many sets right as {}", ms[i].rung.scalar, ms[i - 1].rung.scalar),
                   "yes", ms[i].right >= ms[i - 1].right ? "yes" : "no");
  c.note(fmt::format(
      "{} generator sets: {} families × {} distances δ = 2^-k (k = 1 … 330) × {} seeds, each Ad(g)·N·A with N the "
      "normal form (GF Tables 8.1, 8.2), g a random frame and A a random well-conditioned basis change, built in mpfr "
      "at {} bits and rounded to the rung. A set is 'right' when identifyScrewSystem returns the construction's type; "
      "below the rung's resolution (about 1024 ε L) it returns the more special boundary type, as it should for the "
      "data it is given. Invariant errors: the pitches and the principal axes (frame columns of simple pitch) against "
      "the construction's, computed in mpfr; an axis error is sin θ × its pitch gap. identifyScrewSystem has no "
      "escalation: every rung solves in itself. Time: the least of three runs per set (the machine is shared); the "
      "float, long double, float128 and mpfr instantiations of the library are compiled at -O1, double at -O3 "
      "(cmake/SomaInstantiate.cmake), which is why float is slower than double. Double's p95 is the two reciprocal "
      "families: in this binary they run an -O0 copy of smallComplement<double> that a study compiled at -O0 "
      "instantiates and the linker keeps (~100 µs per set here, 5.8 µs linked into a program of its own; "
      "papers/selig-2005/ch08.md).",
      samples.size(), std::size(kFamilies), std::size(kExponents), kSeedsPerCell, refBits));
  c.trade(std::move(t), "SOMA-screw-identification-speed-accuracy.png",
          "Screw-system identification: median time per generator set (point; bar to the p95) against the worst "
          "invariant error, one point per scalar (log–log).");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-screw-identification-speed-accuracy",
            .title = "Screw-system identification on every scalar: time per generator set, types right, invariant error",
            .source = "GF ch. 8",
            .chapter = "soma — speed vs accuracy",
            .scalarGeneric = false,
            .run = [](Context& c) { screwIdentificationTrade(c); },
            .ladder = true});

}  // namespace soma::studies::SOMA_UNITY_ID
