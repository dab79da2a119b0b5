#pragma once
// `soma planar SCENE.json [--json] [--png FILE]`: planar kinematics on the user's own data.
//  * {"positions": [{"x", "y", "angle"}, ...], "angles": "degrees"|"radians"} with 3–5 positions of
//    a moving frame: poles; for 3 positions the centre of each given "circle_points" entry; for 4
//    the centre-point and circle-point cubics; for 5 the Burmester pairs and every 4-bar made
//    from two of them, driven through the positions (errors, one circuit or not, Grashof class).
//  * {"fourbar": {"ground": [[x, y], [x, y]], "crank", "coupler", "rocker", "coupler_point": [u, v]},
//     "crank_angle", "mode": ±1, "crank_rates": [ω₁, ω̇₁, ω̈₁, ω⃛₁], "angles"}: Grashof class,
//    circuits, the pose, and the instantaneous invariants of the coupler motion (GF §5.3–5.4).
// Runs in double. Bad input → InvalidInput (the caller prints it and exits 2).
#include <filesystem>
#include <ostream>
#include <string>

namespace soma::studies {

int planarCommand(const std::filesystem::path& file, bool json, const std::string& png, std::ostream& out);

}  // namespace soma::studies
