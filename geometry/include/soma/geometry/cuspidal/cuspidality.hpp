#pragma once
// Is a robot cuspidal (GF §5.2.3)? One entry point for the whole analysis (DESIGN §3):
//   3R arm — the cusp points of its workspace section, algebraically, from the triple root of the
//            IK equation (cusps.hpp; near-degenerate arms re-solved in float128 / mpfr), the
//            singular curves det J = 0 in (θ2, θ3) and their images in (ρ, z) with the traced
//            count of image reversals (a second method), the aspects, the verdict (generic 3R:
//            cuspidal ⇔ a cusp point exists — Salunkhe, Spartalis, Capco, Chablat, Wenger 2022),
//            and for a cuspidal arm a witness path planned with OMPL (witness.hpp);
//   6R     — the witness search of witness6r.hpp (a witness proves cuspidality; none found is not
//            a proof of the contrary).
// Runs in double.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/geometry/cuspidal/witness.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"

#include <string>
#include <vector>

namespace soma {

struct CuspidalOptions {
  /// 3R: plan a witness path when the arm is cuspidal.
  bool witness = true;
  /// 3R: cells per side of the aspect map over (θ2, θ3).
  int aspectGrid = 256;
  /// 6R: random poses to try (fixed seed) and OMPL seconds per same-sign posture pair.
  int poses = 4;
  double secondsPerPair = 0.5;
};

struct CuspidalAnalysis {
  /// True for the 6R witness search (only `witness6r`, `cuspidal`, `method` and `seconds` are set).
  bool sixR = false;
  /// How the verdict was reached (one line).
  std::string method;
  /// 3R: cusp points found (a witness path found for 6R). For a 6R robot without a witness this is
  /// false and means "unknown".
  bool cuspidal = false;
  CuspAnalysis<double> cusps;              ///< 3R: the algebraic cusp points (the verdict)
  DetJSeries dj;                           ///< 3R: det J as a Fourier series in (θ2, θ3)
  std::vector<SingularBranch> branches;    ///< 3R: the singular curves and their images
  std::vector<Eigen::Vector2d> reversals;  ///< 3R: where an image turns back (second cusp count, traced)
  AspectMap aspectMap;                     ///< 3R: components of det J ≠ 0
  WitnessPath witness;                     ///< 3R: a posture change without singularity (when cuspidal)
  Witness6R witness6r;                     ///< 6R: the witness search
  double verdictSeconds = 0;               ///< 3R: the cusp points alone
  double seconds = 0;                      ///< everything
};

/// The analysis above for a 3R arm or a 6R robot. Throws InvalidInput for any other robot (the
/// message names the defect).
// GF §5.2.3, GF-5.2.3-cuspidal-posture-change
CuspidalAnalysis analyseCuspidality(const SerialRobot<double>& robot, const CuspidalOptions& options = {});

}  // namespace soma
