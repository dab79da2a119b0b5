#pragma once
// Builders of primitives: parametric surfaces and their iso-parameter curves, spheres.
#include "soma/render/primitives.hpp"

#include <functional>
#include <utility>
#include <vector>

namespace soma::render {

using SurfaceMap = std::function<Eigen::Vector3d(double u, double v)>;

/// Triangulated surface f(u, v) on [u0, u1] x [v0, v1] with nu x nv quads (nu, nv >= 1), vertex
/// normals from central differences of f (falling back to the mesh normal where f is singular).
/// The front (counter-clockwise triangles, normals) is the side of f_u x f_v, whichever way the
/// ranges run.
/// Throws std::invalid_argument for nu or nv < 1, a non-finite range, or f returning NaN.
Mesh parametricSurface(const SurfaceMap& f, std::pair<double, double> uRange,
                       std::pair<double, double> vRange, int nu, int nv,
                       Color c = palette::skyBlue);

/// Iso-parameter curves of f: `uLines` curves u = const and `vLines` curves v = const (ends
/// included), each sampled with `samples` points; drawn as thin polylines they give a surface its grid.
std::vector<Polyline> parametricIsolines(const SurfaceMap& f, std::pair<double, double> uRange,
                                         std::pair<double, double> vRange, int uLines, int vLines,
                                         int samples = 64, Color c = palette::darkGrey, double width = 1);

/// A UV sphere mesh (closed, outward normals).
Mesh sphere(const Eigen::Vector3d& centre, double radius, Color c = palette::skyBlue, int slices = 32,
            int stacks = 16);

}  // namespace soma::render
