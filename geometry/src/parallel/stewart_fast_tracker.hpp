#pragma once
// The fast path of the Stewart forward kinematics (GF §11.5.4, GF-11.5.4-stewart-forty): the same
// parameter homotopy as stewart_impl.hpp's general tracker (start platform, γ, chart h·x = 1, the
// leg quadrics and the Study quadric), its 40 paths tracked in double by a tracker written for
// speed only:
//   - four paths at a time, one per lane of a pack of four doubles, in lockstep
//     (stewart_fast_lanes.hpp; compiled twice, for AVX2 + FMA and for the default instruction set,
//     the first taken when the CPU has both: stewart_fast_tracker.cpp),
//   - hand-written complex arithmetic (std::complex<double>'s product follows C99 Annex G: it tests
//     its result for NaN and may call __muldc3; its quotient calls __divdc3),
//   - fixed-size storage, the platform at τ formed once per τ (not once per evaluation),
//   - ONE LU per step and no other: the Newton iterations after the first reuse the first's LU
//     (simplified Newton), the tangent dx/dτ = −J⁻¹ ∂H/∂τ at the accepted point comes from that LU
//     refined once with the last Jacobian, and the predictor is the Hermite interpolant through the
//     last three accepted points and their tangents (degree 5, local error O(h⁶)), extrapolated to
//     τ + h; the general tracker's RK4 factors four more Jacobians per step (and each Newton one).
// It is double only (that is its purpose: the ≤ 1 ms median of issue 21); every other scalar, and
// double whenever this tracker is in doubt (a path that fails, ends singular or at infinity, or two
// endpoints that coincide), uses the general tracker, and solveStewartForward says so in its notes.
#include "soma/algebra/tolerance.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace soma::stewart_fast {

/// A complex number of the homotopy's data (the kernel's arithmetic is on packs of them).
struct Cx {
  double re, im;
};
inline Cx cx(const std::complex<double>& z) { return {z.real(), z.imag()}; }

using V8 = std::array<Cx, 8>;

/// The parameter homotopy P(τ) = P0 + φ(τ) (P1 − P0), φ(τ) = τ / (τ + γ(1 − τ)), of
/// stewart_detail::ParameterHomotopy, with the chart row h·x − 1 as row 7. Per leg, the
/// difference d = q − p and sum s = q + p of its joints and L², each affine in φ.
struct Homotopy {
  struct Leg {
    Cx d0[3], s0[3], l0, dd[3], ds[3], dl;
  };
  std::array<Leg, 6> leg;
  Cx gamma;
  V8 h;
};

/// How one path ended.
struct Path {
  V8 x;
  bool finite = false;  ///< reached τ = 1 and Newton converged there to the rounding floor
  double pivotRatio = 0;
  int steps = 0, lus = 0;
};

/// Step control of the fast tracker (relative to max(1, |x|∞)), chosen on the 32 platforms of
/// bench/stewart.cpp (papers/benchmarks/stewart.md: 64 steps a path at target 2.5e-3 and three
/// simplified Newton iterations, 53.6 at 5.8e-3 with the fourth and the refactoring; accepting
/// after one Newton step, or at 1.2e-4, lost paths; with the lanes, 2026-12-04: 58.5 steps at
/// 2.5e-3 against 55.1 at 5.8e-3, the former ~4 % faster — a step costs the most Newton iterations
/// of its lanes):
struct Settings {
  /// the predictor's target error (the first Newton correction): eps^(1/6) ≈ 2.5e-3;
  double predErr = Tolerance<double>::precision(5);
  /// a step is accepted when a Newton correction falls below this (the point is then exact to
  /// ~ its square: 1e-12 and below): eps^(1/3) ≈ 6e-6;
  double accept = Tolerance<double>::precision(2);
  /// a step is rejected when the first correction exceeds this multiple of predErr (the
  /// prediction left the path's neighbourhood: Newton might converge to another path);
  double rejectFactor = 8;
  /// Newton iterations a step at most; from the third on, the Jacobian is factored afresh when the
  /// last iteration contracted by less than this factor (the simplified Newton converges linearly,
  /// at a rate ~ cond · first: with the predictor's target above ~2e-3 it alone did not reach
  /// `accept` in three iterations on many steps, which were then rejected). With the lanes, three
  /// iterations (64 steps a path) against four (58.7): the same time — a lockstep step runs as many
  /// iterations as its slowest lane — and fewer platforms handed to the general tracker
  /// (SOMA-11.5.4-stewart-speed-accuracy: 2 of 1000 against 6; 3 of 500 of the tests' kind against 6);
  int maxIterations = 3;
  double refactorRate = 1.0 / 16;
  /// the LU's threshold pivoting while tracking (stewart_fast_lanes.hpp's factor): a diagonal pivot
  /// is kept unless below this fraction of its column's largest entry (growth ≤ 11 a column; the
  /// endpoints' Newton polish pivots partially, its pivot ratio deciding "singular");
  double pivotThreshold = 0.1;
  double hmax = 0.25, hstart = 0.05;
  int maxSteps = 2000;
};

/// Four paths at a time (stewart_fast_lanes.hpp; eight in the AVX-512 kernel).
inline constexpr int kLanes = 4;

/// The kernel stewartFastKernel() names: the widest this CPU has, capped by SOMA_STEWART_KERNEL.
enum class Kernel { Portable, Avx2, Avx512 };
Kernel kernel();
const char* kernelName(Kernel k);

/// Tracks every path from its start (τ = 0) to τ = 1 and polishes its endpoint there by Newton to the
/// rounding floor, with kernel(); out[i] is the path from starts[i] (finite = false: it did not get there).
void trackAll(const Homotopy& H, const std::vector<V8>& starts, const Settings& o, std::vector<Path>& out);

}  // namespace soma::stewart_fast
