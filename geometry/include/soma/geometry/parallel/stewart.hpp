#pragma once
// Forward kinematics of the general Stewart–Gough (6-6) platform: every posture of the platform
// for six given leg lengths, found as ALL the complex solutions of the leg equations in Study
// parameters and then the real ones kept (GF §11.5.4, GF-11.5.4-stewart-forty: at most 40).
//
// Formulation (GF §11.5.4, GF-11.5.4-stewart-leg-quadric). A posture p ↦ R p + t is the point
// x = (a : c) of PR⁷ with c = ½ t a (the book's convention, study_parameters.hpp). With
// u_i = a q_i + 2c − p_i a (quaternion products, q_i the platform point in platform coordinates,
// p_i the base point), |R q_i + t − p_i|² = u_i·u_i / a·a, so leg i is the quadric
//     u_i·u_i − L_i² a·a = 0,
// and the system is: the Study quadric a·c = 0, the six leg quadrics, and an affine chart
// h·x = 1 (h a fixed random complex vector). Its isolated solutions are the finite postures; the
// conic a = 0, c·c = 0 at infinity lies on every leg quadric (GF-11.5.3-SS-quadric-at-infinity)
// and is never one of them.
//
// Method: homotopy continuation. (a) Once per process, a total-degree homotopy (2⁷ = 128 paths)
// solves the system for a fixed random COMPLEX "start platform"; the 40 finite nonsingular
// endpoints are kept (the others end on the conic at infinity). (b) For a user platform, a
// parameter homotopy with the gamma trick carries those 40 solutions to the target platform's
// 40 (predictor RK4, Newton corrector, adaptive step, complex arithmetic of the working scalar),
// then the real ones are polished by Newton in real arithmetic. Paths that fail or collide
// (path jumping) are re-tracked with a smaller step, then with another gamma, then in a wider
// scalar; every such step is written in `notes`. The user platform is centred and scaled to unit
// size first (lengths 1e-8 … 1e8 are the same problem).
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"

#include <array>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

namespace soma {

/// A Stewart–Gough platform with leg lengths: base joint centres p_i (base frame), platform
/// joint centres q_i (platform frame), leg i from p_i to q_i of length L_i.
template <class S> struct StewartPlatform {
  std::array<Vec3<S>, 6> base;
  std::array<Vec3<S>, 6> platform;
  std::array<S, 6> legs;

  /// The same platform in scalar T (each coordinate and length converted once).
  template <class T> StewartPlatform<T> cast() const {
    StewartPlatform<T> P;
    for (int i = 0; i < 6; ++i) {
      P.base[i] = castMatrix<T>(base[i]);
      P.platform[i] = castMatrix<T>(platform[i]);
      P.legs[i] = scalarCast<T>(legs[i]);
    }
    return P;
  }
};

/// A point of CP⁷ (a0..a3, c0..c3).
template <class S> using StudyPointC = std::array<std::complex<S>, 8>;

/// Complex parameters of the leg system (base points, platform points, squared lengths).
template <class S> struct StewartComplexPlatform {
  std::array<std::array<std::complex<S>, 3>, 6> p;
  std::array<std::array<std::complex<S>, 3>, 6> q;
  std::array<std::complex<S>, 6> L2;
};

/// A complex solution in the user's frame (platform frame → base frame, p ↦ R q + t with R the
/// sandwich a q ā): the rotation quaternion a = (w, x, y, z) scaled so that a·a = 1 (the bilinear
/// square, not |a|²; of the two signs, the one whose largest-modulus coordinate has a positive real
/// part), the translation t, the Study parameters (a, c = ½ t a) and the multiplicity of the root.
template <class S> struct StewartComplexPosture {
  std::array<std::complex<S>, 4> rotation;
  std::array<std::complex<S>, 3> translation;
  StudyPointC<S> study;
  bool real = false;
  int multiplicity = 1;
};

/// The answer of the forward kinematics (DESIGN §3).
template <class S> struct StewartForwardSolution {
  /// Real postures p ↦ R p + t of the platform (platform frame → base frame).
  std::vector<SE3<S>> postures;
  /// Per posture: max_i | |R q_i + t − p_i| − L_i | / scale, scale = the platform's size
  /// (largest of |p_i − p̄|, |q_i − q̄|, L_i).
  std::vector<S> residuals;
  /// Every finite complex solution found (distinct points of CP⁷, each scaled so that its
  /// largest coordinate is 1), in the centred and scaled coordinates of the solve.
  std::vector<StudyPointC<S>> complex_solutions;
  /// Multiplicity of each complex solution (1 but at a double root, e.g. a posture on the boundary of
  /// the assembly space where two real postures merge: 2). complexCount() counts with multiplicity.
  std::vector<int> multiplicity;
  /// Multiplicity of each real posture (as multiplicity).
  std::vector<int> posture_multiplicity;
  /// complex_solutions in the user's frame (stewartComplexPosture), filled by solveStewartForward.
  std::vector<StewartComplexPosture<S>> complex_postures;
  /// The platform's class (stewart_class.hpp: "6-6", "6-3", …) and its leg–joint pattern.
  std::string platform_class, pattern;
  /// How many of complex_solutions are real (= postures.size() unless a real one failed the
  /// real polish, which a note reports).
  int real_count = 0;
  /// The number of complex postures of the platform's class (40 for a general 6-6 platform, GF
  /// §11.5.4, GF-11.5.4-stewart-forty; stewart_class.hpp for the others); 0 when the class has no
  /// tabulated count (the solve is then not certified).
  int expected_count = 40;
  /// Paths tracked in total (40 on the plain path; more when some were re-tracked).
  int paths_tracked = 0;
  /// Predictor–corrector steps over all paths tracked (accepted and rejected).
  int steps = 0;
  /// Paths that did not reach a finite nonsingular endpoint on the last attempt.
  int paths_failed = 0;
  /// Paths tracked again in a wider scalar (0 when none; a note says which and why): float's failed
  /// paths re-tracked one by one in double, and the failed or singular paths of a solve short of
  /// its count, for which the whole platform is re-solved (float → double, double and long double →
  /// float128).
  int paths_escalated = 0;
  /// Paths whose endpoint lies on the exceptional plane a = 0 (degenerate platforms).
  int paths_at_infinity = 0;
  /// Paths that end at a singular point (the step collapses just before τ = 1, or Newton is not
  /// quadratic there): a multiple solution of a degenerate platform (6-3: 24 of 40), or two
  /// solutions too close together for the scalar.
  int paths_singular = 0;
  double seconds = 0;
  std::string method = "homotopy";
  /// Which tracker gave the answer: "fast" (double, general 6-6 platform: stewart_fast_tracker.hpp)
  /// or "general" (every other case, and double when the fast tracker was in doubt; a note says so).
  std::string tracker = "general";
  std::vector<std::string> notes;

  std::size_t count() const { return postures.size(); }
  /// Complex solutions counted with multiplicity.
  int complexCount() const {
    int n = 0;
    for (std::size_t k = 0; k < complex_solutions.size(); ++k) n += k < multiplicity.size() ? multiplicity[k] : 1;
    return n;
  }
  /// Distinct complex solutions.
  int distinctCount() const { return static_cast<int>(complex_solutions.size()); }
  S worstResidual() const {
    S w = S(0);
    for (const auto& r : residuals)
      if (r > w) w = r;
    return w;
  }
};

/// Throws InvalidInput when a coordinate is not finite, a leg length is negative or not
/// finite, or the base or the platform points are all the same point.
template <class S> void validateStewartPlatform(const StewartPlatform<S>& P);

/// Inverse kinematics: the six leg lengths |R q_i + t − p_i| of posture g.
template <class S> std::array<S, 6> stewartLegLengths(const StewartPlatform<S>& P, const SE3<S>& g);

/// Size of the platform: max over |p_i − p̄|, |q_i − q̄|, L_i (the unit of the residuals).
template <class S> S stewartScale(const StewartPlatform<S>& P);

/// max_i | |R q_i + t − p_i| − L_i | / stewartScale(P).
template <class S> S stewartResidual(const StewartPlatform<S>& P, const SE3<S>& g);

/// The leg system at x: (a·c, u_i·u_i − L_i² a·a for i = 1..6), 7 values (no chart).
/// GF §11.5.4, GF-11.5.4-stewart-leg-quadric
template <class S>
std::array<std::complex<S>, 7> stewartSystem(const StewartComplexPlatform<S>& P, const StudyPointC<S>& x);

/// The real platform as complex parameters (no centring or scaling).
template <class S> StewartComplexPlatform<S> stewartComplexPlatform(const StewartPlatform<S>& P);

/// The fixed random complex start platform (seeded; the same in every scalar).
template <class S> StewartComplexPlatform<S> stewartStartPlatform();

/// Every finite nonsingular solution of a complex platform by the total-degree homotopy
/// (128 paths, gamma trick); several gammas are tried until two runs agree. Slow (used once per
/// process for the start platform, and by the tests as an independent check).
std::vector<StudyPointC<double>> stewartTotalDegreeSolve(const StewartComplexPlatform<double>& P,
                                                         std::uint64_t seed = 1);

/// The 40 solutions of the start platform, computed at first use (in double, by the total-
/// degree homotopy) and Newton-polished in S; cached.
template <class S> const std::vector<StudyPointC<S>>& stewartStartSolutions();

/// The path tracker of solveStewartForward.
///   Auto     in double on a general 6-6 platform (six distinct joints on each side, 40 postures):
///            the fast tracker (one LU per Newton step, Hermite predictor, hand-written complex
///            arithmetic), which falls back to the general tracker, with a note, when a path fails,
///            ends singular or at infinity, or two endpoints coincide; otherwise General.
///   General  the general tracker only (RK4 predictor; the cross-check of the fast one).
///   Fine     the general tracker to √eps of S (never below float128's) instead of √eps of double:
///            the escalation used when a few paths end singular (two solutions very close
///            together); slow in float128/mpfr.
enum class StewartTracking { Auto, General, Fine };

/// The fast tracker's kernel that StewartTracking::Auto runs now: the widest this CPU has, "avx512"
/// (eight paths per AVX-512 register), "avx2" (four per AVX2 register; both with fused multiply–adds)
/// or "portable" (four per pack, the default instruction set), chosen at run time; the environment
/// variable SOMA_STEWART_KERNEL=portable|avx2 caps it (the cross-check of the kernels; read per call).
const char* stewartFastKernel();

/// All postures of a platform by the parameter homotopy from the start platform.
/// GF §11.5.4, GF-11.5.4-stewart-forty
template <class S>
StewartForwardSolution<S> solveStewartForward(const StewartPlatform<S>& P, StewartTracking tracking = StewartTracking::Auto);

/// A complex solution x of solveStewartForward (in its centred and scaled coordinates) as a
/// posture of the user's platform P: rotation, translation and Study parameters (complex).
template <class S> StewartComplexPosture<S> stewartComplexPosture(const StewartPlatform<S>& P, const StudyPointC<S>& x);

/// max_i |e_i·e_i − L_i²| / max(|e_i|², L_i²), e_i = R q_i + t − p_i, for a complex posture (e_i·e_i
/// the bilinear dot, |e_i|² the Hermitian one): the leg equations' relative residual.
template <class S> S stewartComplexResidual(const StewartPlatform<S>& P, const StewartComplexPosture<S>& g);

/// True when the solution set holds x's complex conjugate (as a point of CP⁷) within tol.
template <class S> bool containsConjugate(const std::vector<StudyPointC<S>>& set, const StudyPointC<S>& x,
                                          const S& tol);

#define SOMA_STEWART_EXTERN(S)                                                                            \
  extern template void validateStewartPlatform<S>(const StewartPlatform<S>&);                             \
  extern template std::array<S, 6> stewartLegLengths<S>(const StewartPlatform<S>&, const SE3<S>&);        \
  extern template S stewartScale<S>(const StewartPlatform<S>&);                                           \
  extern template S stewartResidual<S>(const StewartPlatform<S>&, const SE3<S>&);                         \
  extern template std::array<std::complex<S>, 7> stewartSystem<S>(const StewartComplexPlatform<S>&,       \
                                                                  const StudyPointC<S>&);                 \
  extern template StewartComplexPlatform<S> stewartComplexPlatform<S>(const StewartPlatform<S>&);         \
  extern template StewartComplexPlatform<S> stewartStartPlatform<S>();                                    \
  extern template const std::vector<StudyPointC<S>>& stewartStartSolutions<S>();                          \
  extern template StewartForwardSolution<S> solveStewartForward<S>(const StewartPlatform<S>&, StewartTracking);      \
  extern template StewartComplexPosture<S> stewartComplexPosture<S>(const StewartPlatform<S>&, const StudyPointC<S>&); \
  extern template S stewartComplexResidual<S>(const StewartPlatform<S>&, const StewartComplexPosture<S>&);         \
  extern template bool containsConjugate<S>(const std::vector<StudyPointC<S>>&, const StudyPointC<S>&,    \
                                            const S&);
SOMA_FOR_EACH_SCALAR(SOMA_STEWART_EXTERN)
#undef SOMA_STEWART_EXTERN

}  // namespace soma
