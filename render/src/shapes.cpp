// Builders: parametric surfaces, their iso-parameter curves, spheres.
#include "soma/render/shapes.hpp"

#include "detail.hpp"
#include "tessellate.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace soma::render {

namespace {
void checkRange(std::pair<double, double> r, const char* name, const char* fn) {
  if (!std::isfinite(r.first) || !std::isfinite(r.second))
    detail::invalid(std::string(fn) + ": " + name + " range is not finite");
}
Eigen::Vector3d evaluate(const SurfaceMap& f, double u, double v, const char* fn) {
  const Eigen::Vector3d p = f(u, v);
  if (!detail::finite(p))
    detail::invalid(std::string(fn) + ": f(" + std::to_string(u) + ", " + std::to_string(v) + ") = " + detail::str(p) +
                    " is not finite");
  return p;
}
}  // namespace

Mesh parametricSurface(const SurfaceMap& f, std::pair<double, double> ur, std::pair<double, double> vr, int nu, int nv,
                       Color c) {
  const char* fn = "parametricSurface";
  if (!f) detail::invalid("parametricSurface: empty function");
  if (nu < 1 || nv < 1) detail::invalid("parametricSurface: nu = " + std::to_string(nu) + ", nv = " + std::to_string(nv) + "; both must be >= 1");
  checkRange(ur, "u", fn);
  checkRange(vr, "v", fn);
  Mesh m;
  m.c = c;
  m.twoSided = true;
  const double du = (ur.second - ur.first) / nu, dv = (vr.second - vr.first) / nv;
  m.v.reserve(std::size_t(nu + 1) * (nv + 1));
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) m.v.push_back(evaluate(f, ur.first + i * du, vr.first + j * dv, fn));
  auto id = [&](int i, int j) { return j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      // Split each quad along its shorter diagonal.
      const Eigen::Vector3d& a = m.v[id(i, j)];
      const Eigen::Vector3d& b = m.v[id(i + 1, j)];
      const Eigen::Vector3d& cc = m.v[id(i + 1, j + 1)];
      const Eigen::Vector3d& d = m.v[id(i, j + 1)];
      if ((a - cc).squaredNorm() <= (b - d).squaredNorm()) {
        m.tri.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        m.tri.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      } else {
        m.tri.emplace_back(id(i, j), id(i + 1, j), id(i, j + 1));
        m.tri.emplace_back(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
    }
  // Normals: f_u x f_v by central differences on the grid (one-sided at the border); where that
  // degenerates (a pole, a ruling's singular point) use the mesh's area-weighted normal.
  const std::vector<Eigen::Vector3d> meshN = detail::vertexNormals(m.v, m.tri);
  m.n.resize(m.v.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, nu), j0 = std::max(j - 1, 0), j1 = std::min(j + 1, nv);
      const Eigen::Vector3d fu = m.v[id(i1, j)] - m.v[id(i0, j)], fv = m.v[id(i, j1)] - m.v[id(i, j0)];
      Eigen::Vector3d n = fu.cross(fv);
      const double scale = fu.squaredNorm() * fv.squaredNorm();
      if (n.squaredNorm() > 1e-12 * scale && scale > 0) n.normalize();
      else n = meshN[id(i, j)];
      // The grid differences are du f_u and dv f_v, so n is along du dv (f_u x f_v), like the
      // triangles' winding: when exactly one range is reversed, turn both round so that the front
      // is always the side of f_u x f_v.
      if (du * dv < 0) n = -n;
      m.n[id(i, j)] = n;
    }
  if (du * dv < 0)
    for (auto& t : m.tri) std::swap(t[1], t[2]);
  return m;
}

std::vector<Polyline> parametricIsolines(const SurfaceMap& f, std::pair<double, double> ur, std::pair<double, double> vr,
                                         int uLines, int vLines, int samples, Color c, double width) {
  const char* fn = "parametricIsolines";
  if (!f) detail::invalid("parametricIsolines: empty function");
  if (uLines < 0 || vLines < 0 || samples < 2)
    detail::invalid("parametricIsolines: need uLines, vLines >= 0 and samples >= 2");
  checkRange(ur, "u", fn);
  checkRange(vr, "v", fn);
  auto at = [](std::pair<double, double> r, int k, int n) { return n <= 1 ? (r.first + r.second) / 2 : r.first + (r.second - r.first) * k / (n - 1); };
  std::vector<Polyline> out;
  for (int k = 0; k < uLines; ++k) {
    Polyline pl;
    pl.c = c;
    pl.width = width;
    const double u = at(ur, k, uLines);
    for (int s = 0; s < samples; ++s) pl.p.push_back(evaluate(f, u, at(vr, s, samples), fn));
    out.push_back(std::move(pl));
  }
  for (int k = 0; k < vLines; ++k) {
    Polyline pl;
    pl.c = c;
    pl.width = width;
    const double v = at(vr, k, vLines);
    for (int s = 0; s < samples; ++s) pl.p.push_back(evaluate(f, at(ur, s, samples), v, fn));
    out.push_back(std::move(pl));
  }
  return out;
}

Mesh sphere(const Eigen::Vector3d& centre, double radius, Color c, int slices, int stacks) {
  if (!detail::finite(centre) || !(radius > 0) || !std::isfinite(radius))
    detail::invalid("sphere: centre must be finite and radius positive (got radius " + std::to_string(radius) + ")");
  if (slices < 3 || stacks < 2) detail::invalid("sphere: need slices >= 3 and stacks >= 2");
  Mesh m;
  m.c = c;
  m.twoSided = false;
  for (int i = 0; i <= stacks; ++i) {
    const double th = std::numbers::pi * i / stacks;
    for (int j = 0; j <= slices; ++j) {
      const double ph = 2 * std::numbers::pi * j / slices;
      const Eigen::Vector3d d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      m.v.push_back(centre + radius * d);
      m.n.push_back(d);
    }
  }
  const int row = slices + 1;
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const int a = i * row + j, b = a + row;
      if (i > 0) m.tri.emplace_back(a, b, a + 1);
      if (i + 1 < stacks) m.tri.emplace_back(a + 1, b, b + 1);
    }
  return m;
}

}  // namespace soma::render
