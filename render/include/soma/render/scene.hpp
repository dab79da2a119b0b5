#pragma once
// A Scene: the lists of primitives to draw, the background, an optional title and world axes.
#include "soma/render/primitives.hpp"

#include <string>
#include <vector>

namespace soma::render {

struct Scene {
  std::vector<Points> points;
  std::vector<Polyline> polylines;
  std::vector<Tube> tubes;
  std::vector<Mesh> meshes;
  std::vector<Fill> fills;
  std::vector<Frame> frames;
  std::vector<Arrow> arrows;
  std::vector<Label> labels;

  Color background = palette::white;
  std::string title;           ///< drawn centred at the top of the image when not empty
  double titlePixelHeight = 28;
  bool axes = false;           ///< draw labelled world axes x, y, z at the origin
  double axesLength = 0;       ///< world units; 0 = automatic

  void add(Points x) { points.push_back(std::move(x)); }
  void add(Polyline x) { polylines.push_back(std::move(x)); }
  void add(Tube x) { tubes.push_back(std::move(x)); }
  void add(Mesh x) { meshes.push_back(std::move(x)); }
  void add(Fill x) { fills.push_back(std::move(x)); }
  void add(Frame x) { frames.push_back(std::move(x)); }
  void add(Arrow x) { arrows.push_back(std::move(x)); }
  void add(Label x) { labels.push_back(std::move(x)); }
  template <class T> void add(std::vector<T> xs) {
    for (auto& x : xs) add(std::move(x));
  }

  /// Bounding box of everything drawn (points, vertices, frames, arrows, label anchors, the world
  /// axes when enabled), enlarged by the radii of spheres, tubes and arrows. Empty box for an empty scene.
  Eigen::AlignedBox3d bounds() const;

  /// The world length that automatic sizes are fractions of: the diagonal of the bounding box of
  /// the scene's geometry (without radii), or 1 if that is empty or a single point.
  double characteristicLength() const;

  /// Throws std::invalid_argument naming the primitive and the defect (NaN or infinite coordinate,
  /// negative radius or width, a triangle index out of range, normals of the wrong count, ...).
  void validate() const;
};

/// Automatic sizes, as fractions of Scene::characteristicLength().
namespace autosize {
inline constexpr double pointRadius = 0.008;
inline constexpr double tubeRadius = 0.005;
inline constexpr double arrowRadius = 0.006;
inline constexpr double frameScale = 0.12;
inline constexpr double axesLength = 0.25;
}  // namespace autosize

}  // namespace soma::render
