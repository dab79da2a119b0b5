#pragma once
// Reading a planar scene file (`soma planar`, GF §5.3–5.4), in double:
//  * {"positions": [{"x", "y", "angle"}, ...], "circle_points": [[u, v], ...], "angles"}: 3–5
//    positions of a moving frame (the count is the synthesis's to check) and, for 3 positions,
//    circle points in moving-frame coordinates;
//  * {"fourbar": {"ground": [[x, y], [x, y]], "crank", "coupler", "rocker", "coupler_point": [u, v]},
//     "crank_angle", "mode": ±1, "crank_rates": [ω₁, ω̇₁, ω̈₁, ω⃛₁], "angles"}.
// "angles" is "radians" (the default) or "degrees"; every angle of the struct is in radians.
// Numbers through the one number reader (number.hpp). Bad input → InvalidInput.
#include "soma/algebra/scalar.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace soma::io {

/// One pose of the moving frame: translation (x, y), rotation angle (radians).
struct PlanarPosition {
  double x = 0, y = 0, angle = 0;
};

/// A 4-bar c1–c2–c3–c4 on the ground pivots c1, c4, and the state its analysis is asked at.
struct PlanarFourBarInput {
  Vec2<double> c1 = Vec2<double>::Zero(), c4 = Vec2<double>::Zero();
  double crank = 0, coupler = 0, rocker = 0;
  Vec2<double> couplerPoint = Vec2<double>::Zero();  ///< in the coupler's frame; default (0, 0)
  double crankAngle = 0;                              ///< θ₁ (radians)
  int mode = 1;                                       ///< assembly mode, ±1
  std::array<double, 4> crankRates{1, 0, 0, 0};       ///< ω₁, ω̇₁, ω̈₁, ω⃛₁ (radians per unit time)
};

struct PlanarScene {
  bool degrees = false;  ///< the file's "angles"
  double angleUnit = 1;  ///< radians per angle unit of the file (π/180 for degrees)
  std::vector<PlanarPosition> positions;   ///< a positions scene (else empty)
  std::vector<Vec2<double>> circlePoints;  ///< its "circle_points"
  bool hasCirclePoints = false;
  std::optional<PlanarFourBarInput> fourbar;  ///< a 4-bar scene
};

/// Read a scene file. InvalidInput "cannot read scene file '<file>'" when it cannot be read.
PlanarScene readPlanarScene(const std::filesystem::path& file);
/// The same from the file's text; `origin` names it in messages (a scene's planar-mechanism entity).
PlanarScene parsePlanarScene(const std::string& text, const std::string& origin);

}  // namespace soma::io
