#pragma once
// The primitives a Scene is made of. Coordinates are world coordinates (double). A size given as 0
// means "automatic": a fixed fraction of the scene's size (see Scene::autoSize), so that a scene
// looks right whatever its units.
#include "soma/render/color.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace soma::render {

/// Points, drawn as small shaded spheres of the given world radius (0 = automatic).
struct Points {
  std::vector<Eigen::Vector3d> p;
  Color c = palette::vermillion;
  double radius = 0;
};

/// A polyline of constant width in output pixels, not lit (a curve drawn with a pen). Joints and ends
/// are round. Dashes are measured in output pixels along the projected curve.
struct Polyline {
  std::vector<Eigen::Vector3d> p;
  Color c = palette::black;
  double width = 2;          ///< pixels of the output image
  bool closed = false;       ///< join the last point to the first
  bool dashed = false;
  double dashLength = 10;    ///< pixels; a dash followed by a gap of the same length
};

/// A tube: a circle of world radius swept along the polyline (parallel-transported frame), shaded,
/// with flat end caps. Gives curves a solid "paper" look.
struct Tube {
  std::vector<Eigen::Vector3d> p;
  double radius = 0;  ///< world units; 0 = automatic
  Color c = palette::blue;
  bool closed = false;
};

/// A triangle mesh. Normals n are per vertex; leave n empty to get smooth area-weighted normals.
/// Triangles are counter-clockwise seen from the front. A colour with a < 1 is drawn transparent
/// (after all opaque geometry, without depth writes; no sorting).
struct Mesh {
  std::vector<Eigen::Vector3d> v, n;
  std::vector<Eigen::Vector3i> tri;
  Color c = palette::skyBlue;
  bool twoSided = true;  ///< light the back faces too (surfaces); false culls them (closed solids)
};

/// Flat-coloured triangles, not lit (a filled region of a 2-D figure: a heat-map cell, a shaded
/// area). Colours per vertex (`vc`, one per vertex) or one colour `c` for all; drawn before lines
/// and points, with depth test, so curves drawn at the same depth stay on top.
struct Fill {
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> tri;
  std::vector<Color> vc;  ///< empty: every vertex has colour c
  Color c = palette::skyBlue;
};
/// A coordinate frame: arrows along the pose's x, y, z axes coloured palette::axisX/Y/Z.
struct Frame {
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();  ///< homogeneous; the rotation block is used as given
  double scale = 0;  ///< arrow length in world units; 0 = automatic
};

/// A shaded arrow (cylinder and cone) from `from` to `to`.
struct Arrow {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::UnitX();
  Color c = palette::black;
  double radius = 0;  ///< shaft radius in world units; 0 = automatic
};

enum class HAlign { Left, Center, Right };
enum class VAlign { Top, Middle, Bottom };

/// Text drawn flat on the image at the projection of `at` (always on top, never hidden by geometry).
/// The text box is placed so that its (hAlign, vAlign) corner sits at the projected point plus
/// `offset` (pixels, x right, y down). UTF-8; DejaVu Sans covers Greek and mathematical symbols.
struct Label {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  std::string text;
  Color c = palette::black;
  double pixelHeight = 22;  ///< nominal font size in output pixels (em height)
  Eigen::Vector2d offset{6, -6};
  HAlign hAlign = HAlign::Left;
  VAlign vAlign = VAlign::Bottom;
  bool halo = true;  ///< a thin outline in the background colour keeps text legible over geometry
};

}  // namespace soma::render
