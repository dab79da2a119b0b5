#pragma once
// `soma cuspidal ROBOT.json [--json] [--png FILE]` (DESIGN §6): is a 3R arm cuspidal? The cusp
// points of its workspace section (algebraically, from the triple root of the IK equation), the
// singular curves det J = 0 in (θ2, θ3) and their images in (ρ, z), the aspects, the verdict
// (generic 3R: cuspidal ⇔ a cusp point exists — Salunkhe, Spartalis, Capco, Chablat, Wenger 2022),
// and for a cuspidal arm a witness path planned with OMPL. --png FILE writes the joint-space
// figure to FILE, the workspace section to FILE's stem + "_section.png" and the witness path to
// stem + "_witness.png". Runs in double (near-degenerate arms: float128 / mpfr, said in the
// output). With --map: a parameter-space map of cusp counts (parameter_map.hpp). Bad input →
// InvalidInput (the caller exits 2).
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/parameter_map.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace soma::studies {

/// Figures: joint space (aspects coloured, singular curves, cusp postures), the workspace section
/// (singular images and cusp points), the witness path in joint space.
void plotJointSpace(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);
void plotSection(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);
void plotWitness(const CuspidalAnalysis& r, const std::string& title, const std::filesystem::path& png);

/// The cusp-count map as coloured cells (one colour per count, legend swatches), optional
/// check points (x, y, traced count) marked on top.
struct MapCheckPoint {
  double x = 0, y = 0;
  int algebraic = 0, traced = 0;
};
void plotCuspMap(const CuspMap& m, const std::string& title, const std::filesystem::path& png,
                 const std::vector<MapCheckPoint>& checks = {});

/// `soma cuspidal ROBOT.json --map a2:MIN:MAX:N,a3:MIN:MAX:N [--threads N]`: the cusp count of every
/// arm of the family (the robot's DH lengths varied), in parallel; text or JSON, and --png.
int cuspidalMapCommand(const std::filesystem::path& robot, const std::string& map, int threads, bool json,
                       const std::string& png, std::ostream& out);

/// For a 6R robot: the witness search of witness6r.hpp (`poses` random poses, `secondsPerPair` of
/// OMPL per same-sign posture pair).
int cuspidalCommand(const std::filesystem::path& robot, bool json, const std::string& png, std::ostream& out,
                    int poses = 4, double secondsPerPair = 0.5);

}  // namespace soma::studies
