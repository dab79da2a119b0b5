#pragma once
// Is a robot cuspidal (GF §5.2.3)? One entry point for the whole analysis (DESIGN §3):
//   3R arm — the cusp points of its workspace section, algebraically, from the triple root of the
//            IK equation (cusps.hpp; near-degenerate arms re-solved in float128 / mpfr), the
//            singular curves det J = 0 in (θ2, θ3) and their images in (ρ, z) with the traced
//            count of image reversals (a second method), the aspects, the verdict (generic 3R:
//            cuspidal ⇔ a cusp point exists — Salunkhe, Spartalis, Capco, Chablat, Wenger 2022),
//            and for a cuspidal arm a witness path planned with OMPL (witness.hpp);
//   6R     — first the decompositions of decomposition.hpp, which decide exactly: a spherical wrist
//            at either end (the verdict, cusp points, aspects and witness of the positioning 3R
//            arm of the wrist centre, the witness lifted with the wrist holding the orientation),
//            or three parallel axes next to a meeting pair (the UR family: never cuspidal); any
//            other 6R gets the witness search of witness6r.hpp (a witness proves cuspidality;
//            none found within the budget is not a proof of the contrary).
// Runs in double.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/decomposition.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/geometry/cuspidal/witness.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"

#include <functional>
#include <string>
#include <vector>

namespace soma {

struct CuspidalOptions {
  /// 3R: plan a witness path when the arm is cuspidal.
  bool witness = true;
  /// 3R: cells per side of the aspect map over (θ2, θ3).
  int aspectGrid = 256;
  /// 6R search: random poses to try (fixed seed) and OMPL seconds per same-sign posture pair.
  int poses = 4;
  double secondsPerPair = 0.5;
  /// 6R search: total seconds (0: no limit); see Witness6ROptions.
  double budget = 0;
  /// 6R: skip the decompositions and search (to compare the two methods).
  bool forceSearch = false;
  /// 6R search: progress after every pose.
  std::function<void(const Witness6RProgress&)> progress;
};

struct CuspidalAnalysis {
  /// True for a 6R robot. Decomposed by a spherical wrist: the 3R fields below are those of the
  /// positioning arm (its joints 1–3 are the chain's, see decomposition.reversed) and `witness6r`
  /// is the arm's witness lifted; otherwise only `witness6r`, `cuspidal`, `decided`, `method` and
  /// `seconds` are set.
  bool sixR = false;
  /// How the verdict was reached (one line).
  std::string method;
  /// The verdict. 3R and decomposed 6R: exact. 6R search: a witness found (true); false with
  /// `decided` false means "unknown".
  bool cuspidal = false;
  /// False only for a 6R search that found no witness (the verdict is then unknown).
  bool decided = true;
  CuspidalDecomposition decomposition;     ///< 6R: which decomposition applied (kind None: searched)
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
