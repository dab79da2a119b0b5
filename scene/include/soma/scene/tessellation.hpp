#pragma once
// The render primitives of a scene's entities (the figure output and `soma render`): a robot at
// its postures (a tube through its chain's frames, the tool frame) and the tool's trace along paths, a Stewart platform (base and
// platform hexagons, legs), a line (a tube along it), a screw (an arrow on its axis, its pitch as
// a label), a point, a cylindroid's surface (GF §6.5.2: the axes z(θ) = ½(h₂ − h₁) sin 2θ). In
// double: a figure needs no more.
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/lines/line.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/serial/serial_robot.hpp"
#include "soma/render/scene.hpp"

#include <string>
#include <vector>

namespace soma::scene {

/// `paths` (joint paths, e.g. a cuspidal witness) are drawn as the tool's trace along them.
render::Scene robotTessellation(const SerialRobot<double>& robot, const std::vector<JointVector<double>>& postures,
                                const std::vector<std::vector<JointVector<double>>>& paths, const std::string& label);
render::Scene platformTessellation(const StewartPlatform<double>& platform, const std::vector<SE3<double>>& postures,
                                   const std::string& label);
/// The segment of the line within `halfLength` of its point nearest the origin.
render::Scene lineTessellation(const PluckerLine<double>& line, double halfLength, const std::string& label);
render::Scene screwTessellation(const Vec6<double>& screw, double length, const std::string& label);
render::Scene pointTessellation(const Vec3<double>& point, const std::string& label);
/// The patch |r| ≤ radius of the cylindroid's surface, with its two principal axes.
render::Scene cylindroidTessellation(const Cylindroid<double>& c, double radius, const std::string& label);
/// Appends every primitive of `part` to `into`.
void merge(render::Scene& into, const render::Scene& part);

}  // namespace soma::scene
