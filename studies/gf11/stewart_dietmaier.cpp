// Dietmaier's platform (P. Dietmaier, "The Stewart–Gough platform of general geometry can have 40
// real postures", Advances in Robot Kinematics 1998): a 6-6 platform and leg lengths for which all
// 40 complex postures of GF §11.5.4 are real. The published values (6 decimals; as quoted in
// martyushev/fkSGP python/test1_fkSGP.py, commit a7baed0) are studies/platforms/dietmaier.json.
// soma's homotopy and PHCpack (an independent solver, Debian's) must both find 40 real postures, the
// same ones. Double (PHCpack's).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/studies/study.hpp"
#include "stewart_phc.hpp"

#include <fmt/format.h>

#include <random>

namespace soma::studies::gf11dietmaier::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
constexpr const char* kChapter = "GF 11 — The Study quadric";
constexpr const char* kWhyDouble = "PHCpack, the independent solver, works in double";

// GF §11.5.4, Dietmaier 1998; SOMA-11.5.4-dietmaier-forty-real
void fortyReal(Context& c) {
  const auto P = io::readPlatform<S>(sourceRoot() / "studies/platforms/dietmaier.json");
  const auto s = solveStewartForward<S>(P);
  c.checkEqual("soma's homotopy: complex postures (GF §11.5.4: 40)", 40, s.complexCount());
  c.checkEqual("soma's homotopy: real postures (Dietmaier 1998: all 40)", 40, static_cast<long long>(s.count()));
  c.checkEqual("the answer is certified (count = the class's 40)", 1, s.expected_count == s.complexCount() ? 1 : 0);
  double worstLeg = 0, scale = 0;
  for (const S L : P.legs) scale = std::max(scale, L);
  for (const auto& g : s.postures)
    for (std::size_t i = 0; i < 6; ++i)
      worstLeg = std::max(worstLeg, std::abs((g.act(P.platform[i]) - P.base[i]).norm() - P.legs[i]));
  c.checkResidual("every posture has the six leg lengths: max | |R qᵢ + t − pᵢ| − Lᵢ | ≤ 64ε·max L", worstLeg,
                  64 * Tolerance<S>::epsilon() * scale);
  // Distinct: the closest two postures, 1 − cos² of their Study points in PR⁷.
  double closest = 1;
  for (std::size_t i = 0; i < s.count(); ++i)
    for (std::size_t j = i + 1; j < s.count(); ++j) {
      const auto x = StudyParameters<S>::fromSE3(s.postures[i]).coeffs(), y = StudyParameters<S>::fromSE3(s.postures[j]).coeffs();
      closest = std::min(closest, 1 - (x.dot(y) * x.dot(y)) / (x.squaredNorm() * y.squaredNorm()));
    }
  c.recordIn("the 40 postures are distinct: min over pairs of 1 − cos² in PR⁷ > √ε", "> 1.5e-8", fmt::format("{:.3g}", closest),
             closest, Tolerance<S>::sqrtEpsilon(), closest > Tolerance<S>::sqrtEpsilon());
  // Independent: PHCpack's blackbox on the same equations. A posture matches a PHCpack solution when
  // 1 − cos² ≤ 1e-12 (an angle of 1e-6 in PR⁷; both are polished to ~1e-15, distinct postures here
  // are ≥ 0.011 apart: the check above).
  const PhcResult run = solveWithPhc(stewart_phc::equations(P, stewart_phc::randomChart(1998)), stewart_phc::studyNames(), "dietmaier");
  const auto phc = stewart_phc::classify(run);
  c.note(fmt::format("PHCpack: {} paths, {} regular finite solutions, {} real; {:.1f} s. soma: {:.1f} ms.", run.paths,
                     phc.finite, phc.real.size(), run.seconds, 1e3 * s.seconds));
  c.checkEqual("PHCpack: regular finite solutions (40)", 40, phc.finite);
  c.checkEqual("PHCpack: real solutions (Dietmaier 1998: 40)", 40, static_cast<long long>(phc.real.size()));
  c.checkResidual("every soma posture is one of PHCpack's real solutions (1 − cos² in PR⁷)",
                  stewart_phc::worstMatch(s.postures, phc.real), 1e-12);
}

}  // namespace

SOMA_STUDY_DOUBLE("SOMA-11.5.4-dietmaier-forty-real",
                  "Dietmaier's platform: all 40 postures of a general Stewart platform real (soma and PHCpack agree)",
                  "GF §11.5.4; Dietmaier 1998", fortyReal);

}  // namespace soma::studies::gf11dietmaier::SOMA_UNITY_ID
