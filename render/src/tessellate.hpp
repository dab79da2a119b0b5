#pragma once
// Internal: shaded primitives (spheres, tubes, arrows, meshes) tessellated into triangle batches.
#include "soma/render/primitives.hpp"

#include <functional>
#include <vector>

namespace soma::render::detail {

/// Triangles with per-vertex position (relative to `origin`, as float), unit normal and colour.
struct Batch {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::vector<float> pos, nrm, col;
  std::vector<unsigned> idx;

  unsigned vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Color& c);
  void triangle(unsigned a, unsigned b, unsigned c) { idx.insert(idx.end(), {a, b, c}); }
  bool empty() const { return idx.empty(); }
};

/// Number of segments around a circle of radius r world units so that the polygon deviates from the
/// circle by well under a pixel; `pixelsPerUnit(centre)` converts world lengths to output pixels.
using PixelScale = std::function<double(const Eigen::Vector3d&)>;
int circleSegments(double r, const Eigen::Vector3d& centre, const PixelScale& pixelsPerUnit);

void addSphere(Batch& b, const Eigen::Vector3d& c, double r, const Color& color, int segments);
void addTube(Batch& b, const std::vector<Eigen::Vector3d>& p, double r, const Color& color, bool closed,
             const PixelScale& pixelsPerUnit);
void addArrow(Batch& b, const Eigen::Vector3d& from, const Eigen::Vector3d& to, double r, const Color& color,
              const PixelScale& pixelsPerUnit);
void addMesh(Batch& b, const Mesh& m);

/// Area-weighted vertex normals of a triangle mesh (zero where a vertex has no non-degenerate face).
std::vector<Eigen::Vector3d> vertexNormals(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3i>& tri);

}  // namespace soma::render::detail
