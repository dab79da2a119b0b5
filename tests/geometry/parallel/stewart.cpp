// Forward kinematics of the general Stewart–Gough platform (GF §11.5.4): all 40 complex
// solutions by homotopy continuation, the real ones polished in the working scalar.
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/parallel/stewart_numeric.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/study_parameters.hpp"
#include "support/scalars.hpp"

#include <cstdlib>
#include <string>
#include <vector>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

/// A random general platform (base radius ~1, platform ~0.6, not planar) and a posture above it.
template <class S> StewartPlatform<S> randomPlatform(std::mt19937_64& g, SE3<S>* pose) {
  StewartPlatform<S> P;
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<S>(test::uniform<S>(g), test::uniform<S>(g), test::uniform<S>(g, -0.2, 0.2));
    P.platform[i] = Vec3<S>(test::uniform<S>(g, -0.6, 0.6), test::uniform<S>(g, -0.6, 0.6), test::uniform<S>(g, -0.1, 0.1));
  }
  Vec6<S> xi;
  xi << test::uniform<S>(g, -0.3, 0.3), test::uniform<S>(g, -0.3, 0.3), test::uniform<S>(g, -0.3, 0.3),
      test::uniform<S>(g, -0.2, 0.2), test::uniform<S>(g, -0.2, 0.2), test::uniform<S>(g, 0.8, 1.2);
  *pose = SE3Tangent<S>(xi).exp();
  P.legs = stewartLegLengths<S>(P, *pose);
  return P;
}

/// Distance from g to the nearest posture of the solution (Frobenius norm of the 4×4 difference).
template <class S> S nearest(const StewartForwardSolution<S>& s, const SE3<S>& g) {
  S best = S(-1);
  for (const auto& h : s.postures) {
    const S d = (h.matrix() - g.matrix()).norm();
    if (best < S(0) || d < best) best = d;
  }
  return best;
}

template <class S> void checkConjugatePairs(const StewartForwardSolution<S>& s) {
  int nonReal = 0;
  for (const auto& x : s.complex_solutions) {
    S im = S(0);
    for (const auto& z : x) {
      using std::abs;
      im = std::max(im, abs(z.imag()));
    }
    if (im <= Tolerance<S>::input()) continue;
    ++nonReal;
    CHECK(containsConjugate<S>(s.complex_solutions, x, Tolerance<S>::input()));
  }
  CHECK(nonReal % 2 == 0);
  CHECK(s.real_count % 2 == 0);
  CHECK(nonReal + s.real_count == s.complexCount());
}

}  // namespace

TEMPLATE_TEST_CASE("Stewart leg quadric vanishes at the posture that defines the lengths", "[stewart]",
                   SOMA_TEST_SCALARS) {
  // GF §11.5.4, GF-11.5.4-stewart-leg-quadric: u·u − L² a·a = 0 with u = a q + 2c − p a.
  using S = TestType;
  auto& g = test::rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    SE3<S> pose;
    const StewartPlatform<S> P = randomPlatform<S>(g, &pose);
    const Vec8<S> v = StudyParameters<S>::fromSE3(pose).coeffs();
    StudyPointC<S> x;
    for (int k = 0; k < 8; ++k) x[k] = std::complex<S>(v(k));
    const auto f = stewartSystem<S>(stewartComplexPlatform<S>(P), x);
    for (int k = 0; k < 7; ++k) CHECK(std::abs(toDouble(f[k].real())) <= toDouble(Tolerance<S>::identity(256)));
    // A wrong length leaves a residual of the size of the change (the check can fail).
    StewartPlatform<S> Q = P;
    Q.legs[2] += S(1) / S(10);
    const auto f2 = stewartSystem<S>(stewartComplexPlatform<S>(Q), x);
    CHECK(std::abs(toDouble(f2[3].real())) > 0.01);
    CHECK(stewartResidual<S>(P, pose) <= Tolerance<S>::identity(64));
  }
}

TEST_CASE("Stewart start platform: 40 finite solutions, reproduced by an independent total-degree run",
          "[stewart]") {
  // GF §11.5.4, GF-11.5.4-stewart-forty: a random complex 6-6 platform has 40 solutions.
  const auto& start = stewartStartSolutions<double>();
  REQUIRE(start.size() == 40);
  const auto P = stewartStartPlatform<double>();
  for (const auto& x : start) {
    const auto f = stewartSystem<double>(P, x);
    double fx = 0, xn = 0;
    for (const auto& z : f) fx = std::max(fx, std::abs(z));
    for (const auto& z : x) xn = std::max(xn, std::abs(z));
    CHECK(fx <= Tolerance<double>::identity(4096) * xn * xn);
  }
  // Another seed (other gammas) finds the same 40 points.
  const auto again = stewartTotalDegreeSolve(P, 7);
  REQUIRE(again.size() == 40);
  for (const auto& x : again) {
    bool found = false;
    for (const auto& y : start) {
      double d = 0;
      for (int k = 0; k < 8; ++k) d = std::max(d, std::abs(x[k] - y[k]));
      found = found || d <= 1e-9;
    }
    CHECK(found);
  }
}

TEST_CASE("Stewart forward kinematics in double: 40 on random platforms, the defining posture returned",
          "[stewart]") {
  auto& g = test::rng(2026);
  int platforms = 0;
  for (int trial = 0; trial < 8; ++trial) {
    SE3<double> pose;
    const auto P = randomPlatform<double>(g, &pose);
    const auto s = solveStewartForward<double>(P);
    INFO("trial " << trial);
    CHECK(s.complexCount() == 40);
    CHECK(s.count() >= 1);
    CHECK(nearest<double>(s, pose) <= 1e-10);
    CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
    checkConjugatePairs<double>(s);
    ++platforms;
  }
  CHECK(platforms == 8);
}

// Issue 21: the fast double tracker (geometry/src/parallel/stewart_fast_tracker.hpp) against the
// general tracker, two independent trackers (Hermite predictor + simplified Newton vs RK4 + Newton)
// on the same homotopy; both endpoints polished by Newton at τ = 1 to the rounding floor. Every kernel
// of the fast tracker this CPU runs (stewart_fast_lanes.hpp: portable, and AVX2 / AVX-512 where the
// CPU has them), each on the same 12 platforms.
TEST_CASE("Stewart fast double tracker: 40 distinct, the defining posture, the general tracker's solution set",
          "[stewart]") {
  using namespace soma;
  std::vector<std::string> kernels{"portable"};
#if defined(__x86_64__)
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                      __builtin_cpu_supports("avx512vl");
  if (avx2) kernels.push_back("avx2");
  CHECK(std::string(stewartFastKernel()) == (avx512 ? "avx512" : avx2 ? "avx2" : "portable"));  // the widest
#endif
  const std::size_t widest = kernels.size();
  auto& g = test::rng(2121);
  for (int trial = 0; trial < 12; ++trial) {
    SE3<double> pose;
    const auto P = randomPlatform<double>(g, &pose);
    const auto ref = solveStewartForward<double>(P, StewartTracking::General);
    for (std::size_t kk = 0; kk <= widest; ++kk) {
      // The capped kernels, then (kk == widest) the one Auto takes uncapped.
      if (kk < widest) setenv("SOMA_STEWART_KERNEL", kernels[kk].c_str(), 1);
      else unsetenv("SOMA_STEWART_KERNEL");
      if (kk < widest) CHECK(std::string(stewartFastKernel()) == kernels[kk]);
      const auto s = solveStewartForward<double>(P);
      INFO("trial " << trial << ", kernel " << stewartFastKernel());
      CHECK(s.tracker == "fast");
      CHECK(ref.tracker == "general");
      CHECK(s.notes.size() == ref.notes.size());  // no fallback note
      REQUIRE(s.distinctCount() == 40);
      CHECK(s.complexCount() == 40);
      CHECK(s.paths_tracked == 40);
      // Finite, and pairwise apart: the smallest distance between two of the 40 (each scaled so that
      // its largest coordinate is 1) is far above the matching tolerance below.
      double sep = 1e300;
      for (std::size_t i = 0; i < 40; ++i) {
        for (const auto& z : s.complex_solutions[i]) CHECK((std::isfinite(z.real()) && std::isfinite(z.imag())));
        for (std::size_t j = i + 1; j < 40; ++j) {
          double d = 0;
          for (int k = 0; k < 8; ++k) d = std::max(d, std::abs(s.complex_solutions[i][k] - s.complex_solutions[j][k]));
          sep = std::min(sep, d);
        }
      }
      CHECK(sep > 1e-4);
      // The same 40 as the general tracker, one to one: both are Newton-polished at τ = 1 to
      // ~64 eps · cond, so they agree to far below √eps (checked) and far below the separation.
      std::vector<bool> used(40, false);
      double worst = 0;
      for (const auto& x : s.complex_solutions) {
        int best = -1;
        double bd = 1e300;
        for (std::size_t j = 0; j < ref.complex_solutions.size(); ++j) {
          double d = 0;
          for (int k = 0; k < 8; ++k) d = std::max(d, std::abs(x[k] - ref.complex_solutions[j][k]));
          if (d < bd) bd = d, best = static_cast<int>(j);
        }
        REQUIRE(best >= 0);
        CHECK(!used[static_cast<std::size_t>(best)]);
        used[static_cast<std::size_t>(best)] = true;
        worst = std::max(worst, bd);
      }
      CHECK(worst <= Tolerance<double>::sqrtEpsilon());
      CHECK(s.real_count == ref.real_count);
      REQUIRE(s.count() == ref.count());
      for (std::size_t k = 0; k < s.count(); ++k)
        CHECK((s.postures[k].matrix() - ref.postures[k].matrix()).norm() <= Tolerance<double>::sqrtEpsilon());
      CHECK(nearest<double>(s, pose) <= 1e-10);
      CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
      checkConjugatePairs<double>(s);
    }
  }
}

TEMPLATE_TEST_CASE("Stewart forward kinematics in every scalar", "[stewart]", float, long double, __float128,
                   mpfr::mpreal) {
  using S = TestType;
  // mpfr at 128 bits (the tracking is done to √eps of double in every scalar; the precision
  // shows in the Newton-polished endpoints): 256 bits would only make the case slower.
  const int bits = mpfrBits();
  if constexpr (std::is_same_v<S, mpfr::mpreal>) setMpfrBits(128);
  auto& g = test::rng(77);
  SE3<S> pose;
  const auto P = randomPlatform<S>(g, &pose);
  const auto s = solveStewartForward<S>(P);
  CHECK(s.complexCount() == 40);
  CHECK(s.tracker == "general");  // the fast tracker is double only
  const S near = nearest<S>(s, pose);
  CHECK(near >= S(0));
  CHECK(near <= Tolerance<S>::sqrtEpsilon());
  CHECK(s.worstResidual() <= Tolerance<S>::identity(256));
  checkConjugatePairs<S>(s);
  setMpfrBits(bits);
}

// ×1e±200 (issue 24): the squared spreads overflow or underflow double; the validation and the
// scale are norms (safeNorm), so the platform is the same problem at every size.
TEST_CASE("Stewart forward kinematics is scale-free: lengths ×1e-8, ×1e8, ×1e-200 and ×1e200", "[stewart][hostile]") {
  auto& g = test::rng(5);
  SE3<double> pose;
  const auto P = randomPlatform<double>(g, &pose);
  const auto ref = solveStewartForward<double>(P);
  REQUIRE(ref.complexCount() == 40);
  for (double k : {1e-8, 1e8, 1e-200, 1e200}) {
    StewartPlatform<double> Q = P;
    for (int i = 0; i < 6; ++i) {
      Q.base[i] *= k;
      Q.platform[i] *= k;
      Q.legs[i] *= k;
    }
    const auto s = solveStewartForward<double>(Q);
    INFO("scale " << k);
    CHECK(s.complexCount() == 40);
    REQUIRE(s.count() == ref.count());
    CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
    for (std::size_t j = 0; j < s.count(); ++j) {
      CHECK((s.postures[j].rotation() - ref.postures[j].rotation()).norm() <= 1e-12);
      CHECK((s.postures[j].translation() / k - ref.postures[j].translation()).norm() <= 1e-12);
    }
  }
}

TEST_CASE("Stewart forward kinematics: impossible leg lengths give no posture and say so", "[stewart]") {
  auto& g = test::rng(9);
  SE3<double> pose;
  StewartPlatform<double> P = randomPlatform<double>(g, &pose);
  // Base points ~2 apart, platform points ≤ 1.7 apart, legs 0.05: no assembly exists.
  for (int i = 0; i < 6; ++i) {
    P.base[i] *= 3.0;
    P.legs[i] = 0.05;
  }
  const auto s = solveStewartForward<double>(P);
  CHECK(s.complexCount() == 40);
  CHECK(s.count() == 0);
  bool said = false;
  for (const auto& n : s.notes) said = said || n.find("no real posture") != std::string::npos;
  CHECK(said);
}

TEST_CASE("Stewart platform validation names the defect", "[stewart]") {
  auto& g = test::rng(3);
  SE3<double> pose;
  const auto P = randomPlatform<double>(g, &pose);
  auto Q = P;
  Q.legs[4] = -1;
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), Catch::Contains("leg length 5 is negative"));
  Q = P;
  Q.base[1](2) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), Catch::Contains("base point 2 is not finite"));
  Q = P;
  for (auto& q : Q.platform) q = P.platform[0];
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), Catch::Contains("platform points coincide"));
  // A base point 1e200 away (issue 24: the squared spread overflowed, and the message blamed the
  // base): against a base that wide the platform is one point, and the message says so.
  Q = P;
  Q.base[0] = Vec3<double>(1e200, 0, 0);
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), Catch::Contains("platform points coincide (they lie within ") &&
                                                        Catch::Contains("of the platform's size 1e+200)"));
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), !Catch::Contains("base points coincide"));
  // Base points farther apart than double holds (1e308 and −1e308): said so, not "coincide".
  Q = P;
  Q.base[0] = Vec3<double>(1e308, 0, 0);
  Q.base[1] = Vec3<double>(-1e308, 0, 0);
  CHECK_THROWS_WITH(solveStewartForward<double>(Q), Catch::Contains("base points lie farther apart than double holds"));
}

TEST_CASE("Stewart 6-3 platform: 16 postures, the other 24 paths end at singular points", "[stewart]") {
  // GF §11.5.2, GF-11.5.2-6-3-stewart-sixteen: platform joints coincide in pairs, (2σ₄)³ = 16.
  auto& g = test::rng(63);
  for (int trial = 0; trial < 2; ++trial) {
    SE3<double> pose;
    StewartPlatform<double> P = randomPlatform<double>(g, &pose);
    const std::array<Vec3<double>, 3> t3{P.platform[0], P.platform[2], P.platform[4]};
    for (int i = 0; i < 6; ++i) P.platform[i] = t3[((i + 1) / 2) % 3];  // pairs (6,1) (2,3) (4,5)
    P.legs = stewartLegLengths<double>(P, pose);
    const auto s = solveStewartForward<double>(P);
    CHECK(s.expected_count == 16);
    CHECK(s.complexCount() == 16);
    CHECK(s.tracker == "general");  // not a general 6-6 platform: the fast tracker is not tried
    CHECK(s.paths_failed == 0);
    CHECK(s.paths_singular == 24);
    CHECK(nearest<double>(s, pose) <= 1e-10);
    CHECK(s.worstResidual() <= Tolerance<double>::identity(64));
    checkConjugatePairs<double>(s);
  }
}

TEST_CASE("Stewart planar base and platform: 40, real postures in mirror pairs", "[stewart]") {
  // Base in z = 0, platform in its z = 0: reflecting a posture in the base plane (and the
  // platform in its own plane, which fixes its joints) gives another posture M g M.
  auto& g = test::rng(41);
  SE3<double> pose;
  StewartPlatform<double> P = randomPlatform<double>(g, &pose);
  for (int i = 0; i < 6; ++i) P.base[i](2) = P.platform[i](2) = 0;
  P.legs = stewartLegLengths<double>(P, pose);
  const auto s = solveStewartForward<double>(P);
  CHECK(s.expected_count == 40);
  CHECK(s.complexCount() == 40);
  CHECK(nearest<double>(s, pose) <= 1e-10);
  const Mat3<double> Mz = Vec3<double>(1, 1, -1).asDiagonal();
  REQUIRE(s.count() >= 2);
  for (const auto& h : s.postures) {
    Mat4<double> m = Mat4<double>::Identity();
    m.topLeftCorner<3, 3>() = Mz * h.rotation() * Mz;
    m.topRightCorner<3, 1>() = Mz * h.translation();
    double best = 1e300;
    for (const auto& k : s.postures) best = std::min(best, (k.matrix() - m).norm());
    CHECK(best <= 1e-10);
  }
}

// ---- The multi-start methods (stewart_numeric.hpp) ------------------------------------------------

TEST_CASE("Stewart ceres and nlopt: real postures only, each one of the homotopy's, the defining one found",
          "[stewart][numeric]") {
  auto& g = test::rng(1158);
  StewartOptions ceres, nlopt;
  ceres.method = StewartMethod::Ceres;
  nlopt.method = StewartMethod::Nlopt;
  for (int trial = 0; trial < 3; ++trial) {
    SE3<double> pose;
    const auto P = randomPlatform<double>(g, &pose);
    const auto h = solveStewart<double>(P);
    REQUIRE(h.complexCount() == 40);
    CHECK(h.certified);
    for (const auto& sol : {solveStewart(P, ceres), solveStewart(P, nlopt)}) {
      INFO(sol.method << ", platform " << trial << ": " << sol.count() << " postures, homotopy " << h.count());
      CHECK_FALSE(sol.certified);
      CHECK(sol.count() >= 1);
      CHECK(sol.count() <= h.count());
      CHECK(nearest(sol, pose) <= Tolerance<double>::sqrtEpsilon());
      for (std::size_t j = 0; j < sol.count(); ++j) {
        CHECK(sol.residuals[j] <= Tolerance<double>::identity(64));
        CHECK(nearest(h, sol.postures[j]) <= Tolerance<double>::sqrtEpsilon());  // no posture outside the set
      }
      CHECK_FALSE(sol.notes.empty());  // says it is not certified
    }
  }
}

TEST_CASE("Stewart ceres: impossible leg lengths give no posture and a note — bad input is rejected",
          "[stewart][numeric]") {
  auto& g = test::rng(1159);
  SE3<double> pose;
  auto P = randomPlatform<double>(g, &pose);
  auto far = P;
  for (auto& L : far.legs) L *= 40;  // legs far longer than the base and platform allow together
  far.legs[0] = 1e-3;
  const auto s = solveStewartForwardCeres(far);
  CHECK(s.count() == 0);
  CHECK(s.notes.size() == 2);
  auto bad = P;
  bad.legs[2] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(solveStewartForwardNlopt(bad), InvalidInput);
  StewartNumericOptions none;
  none.starts = 0;
  CHECK_THROWS_AS(solveStewartForwardCeres(P, none), InvalidInput);
}

TEMPLATE_TEST_CASE("Stewart Newton polish reaches the rounding floor of the scalar from a nearby posture",
                   "[stewart][numeric]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng(1160);
  SE3<S> pose;
  const auto P = randomPlatform<S>(g, &pose);
  Vec6<S> xi;
  for (int k = 0; k < 6; ++k) xi(k) = test::uniform<S>(g, -1e-3, 1e-3);
  bool converged = false;
  const SE3<S> h = polishStewartPosture<S>(P, pose * SE3Tangent<S>(xi).exp(), &converged);
  CHECK(converged);
  CHECK(stewartResidual<S>(P, h) <= Tolerance<S>::identity(64));
  CHECK((h.matrix() - pose.matrix()).norm() <= Tolerance<S>::identity(1u << 12));
}

// ---- The entry point (solve_stewart.hpp) -----------------------------------------------------------

/// studies/platforms/general.json (an irregular, non-planar 6-6 platform).
template <class S> StewartPlatform<S> generalPlatform() {
  const double base[6][3] = {{0.854648, 0.248159, 0.002365},  {0.806715, 0.596192, -0.055343},
                             {-0.668405, 0.732368, 0.056675}, {-0.954569, 0.316566, 0.053623},
                             {-0.19489, -0.936848, -0.052013}, {0.304459, -1.079584, 0.063352}};
  const double plat[6][3] = {{0.48443, 0.136726, 0.018518},   {-0.142747, 0.423322, -0.024849},
                             {-0.24425, 0.452013, 0.030514},  {-0.241091, -0.381148, -0.042368},
                             {-0.196986, -0.460494, -0.020788}, {0.485676, -0.026128, 0.020398}};
  const double legs[6] = {1.042060141, 1.415693982, 1.051051562, 1.443082953, 0.974698497, 1.427782454};
  StewartPlatform<S> P;
  for (int i = 0; i < 6; ++i) {
    P.base[i] = Vec3<S>(scalarCast<S>(base[i][0]), scalarCast<S>(base[i][1]), scalarCast<S>(base[i][2]));
    P.platform[i] = Vec3<S>(scalarCast<S>(plat[i][0]), scalarCast<S>(plat[i][1]), scalarCast<S>(plat[i][2]));
    P.legs[i] = scalarCast<S>(legs[i]);
  }
  return P;
}

TEMPLATE_TEST_CASE("StewartPlatform::cast: to a wider scalar and back is exact", "[stewart][cast]", long double,
                   __float128, mpfr::mpreal) {
  auto& g = test::rng(1836);
  SE3<double> pose;
  const auto P = randomPlatform<double>(g, &pose);
  const StewartPlatform<double> back = P.template cast<TestType>().template cast<double>();
  for (int i = 0; i < 6; ++i) {
    CHECK(back.base[i] == P.base[i]);
    CHECK(back.platform[i] == P.platform[i]);
    CHECK(back.legs[i] == P.legs[i]);
  }
  // To float: each coordinate rounded once.
  const StewartPlatform<float> f = P.template cast<float>();
  for (int i = 0; i < 6; ++i) {
    CHECK(f.legs[i] == static_cast<float>(P.legs[i]));
    CHECK(f.base[i](2) == static_cast<float>(P.base[i](2)));
  }
}

TEST_CASE("solveStewart: general 6-6 platform, 40 complex by homotopy — ceres and nlopt find a subset, polished in "
          "long double", "[stewart][entry]") {
  const auto P = generalPlatform<double>();
  const StewartSolution<double> h = solveStewart(P);
  CHECK(h.method == "homotopy");
  CHECK(h.certified);
  CHECK(h.complexCount() == 40);
  CHECK(h.expected_count == 40);
  CHECK(h.count() % 2 == 0);
  for (const auto& r : h.residuals) CHECK(r <= Tolerance<double>::identity(64));
  bool said = false;
  for (const auto& n : h.notes) said = said || n.find("start system") != std::string::npos;
  CHECK(said);
  const auto Pl = P.cast<long double>();
  for (StewartMethod m : {StewartMethod::Ceres, StewartMethod::Nlopt}) {
    StewartOptions o;
    o.method = m;
    const StewartSolution<long double> s = solveStewart(Pl, o);
    INFO(s.method << ": " << s.count() << " postures, homotopy " << h.count());
    CHECK(s.method == stewartMethodName(m));
    CHECK_FALSE(s.certified);
    CHECK(s.count() >= 1);
    CHECK(s.count() <= h.count());
    for (std::size_t j = 0; j < s.count(); ++j) {
      CHECK(s.residuals[j] <= Tolerance<long double>::identity(64));  // polished in long double
      CHECK(nearest(h, s.postures[j].template cast<double>()) <= Tolerance<double>::sqrtEpsilon());
    }
  }
  CHECK(parseStewartMethod("auto") == StewartMethod::Homotopy);
  CHECK_FALSE(parseStewartMethod("newton"));
}

}  // namespace SOMA_UNITY_ID
