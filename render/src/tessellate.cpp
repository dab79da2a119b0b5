// Tessellation of the shaded primitives.
#include "tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace soma::render::detail {

namespace {
constexpr double pi = std::numbers::pi;

// Any unit vector orthogonal to unit t.
Eigen::Vector3d orthogonal(const Eigen::Vector3d& t) {
  const Eigen::Vector3d a = std::abs(t.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return t.cross(a).normalized();
}

// A ring of `n` vertices (the first repeated at the end for the seam) around centre c in the plane
// spanned by unit e1, e2; normals radial. Returns the index of the first vertex.
unsigned ring(Batch& b, const Eigen::Vector3d& c, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, double r,
              int n, const Color& color) {
  unsigned first = 0;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * pi * k / n;
    const Eigen::Vector3d d = std::cos(a) * e1 + std::sin(a) * e2;
    const unsigned i = b.vertex(c + r * d, d, color);
    if (k == 0) first = i;
  }
  return first;
}

void connect(Batch& b, unsigned r0, unsigned r1, int n) {
  for (int k = 0; k < n; ++k) {
    b.triangle(r0 + k, r0 + k + 1, r1 + k + 1);
    b.triangle(r0 + k, r1 + k + 1, r1 + k);
  }
}

// A flat disc of radius r at c facing along unit normal nrm (e1, e2 span its plane, e1 x e2 = nrm).
void disc(Batch& b, const Eigen::Vector3d& c, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2,
          const Eigen::Vector3d& nrm, double r, int n, const Color& color) {
  const unsigned centre = b.vertex(c, nrm, color);
  const unsigned first = centre + 1;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * pi * k / n;
    b.vertex(c + r * (std::cos(a) * e1 + std::sin(a) * e2), nrm, color);
  }
  const bool ccw = e1.cross(e2).dot(nrm) > 0;
  for (int k = 0; k < n; ++k) {
    if (ccw) b.triangle(centre, first + k, first + k + 1);
    else b.triangle(centre, first + k + 1, first + k);
  }
}
}  // namespace

unsigned Batch::vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Color& c) {
  const unsigned i = unsigned(pos.size() / 3);
  const Eigen::Vector3d q = p - origin;
  pos.insert(pos.end(), {float(q.x()), float(q.y()), float(q.z())});
  nrm.insert(nrm.end(), {float(n.x()), float(n.y()), float(n.z())});
  col.insert(col.end(), {c.r, c.g, c.b, c.a});
  return i;
}

int circleSegments(double r, const Eigen::Vector3d& centre, const PixelScale& pixelsPerUnit) {
  const double rpx = r * pixelsPerUnit(centre);
  // Sagitta r(1 - cos(pi/n)) below 0.2 px, at least 16 segments for smooth Gouraud shading.
  if (!(rpx > 0.2)) return 16;
  const int n = int(std::ceil(pi / std::acos(1 - 0.2 / rpx)));
  return std::clamp(n, 16, 96);
}

void addSphere(Batch& b, const Eigen::Vector3d& c, double r, const Color& color, int segments) {
  const int slices = std::max(8, segments), stacks = std::max(4, segments / 2);
  const unsigned first = unsigned(b.pos.size() / 3);
  std::vector<double> cp(slices + 1), sp(slices + 1);
  for (int j = 0; j <= slices; ++j) cp[j] = std::cos(2 * pi * j / slices), sp[j] = std::sin(2 * pi * j / slices);
  for (int i = 0; i <= stacks; ++i) {
    const double th = pi * i / stacks;  // from +z down to -z
    const double st = std::sin(th), ct = std::cos(th);
    for (int j = 0; j <= slices; ++j) {
      const Eigen::Vector3d d(st * cp[j], st * sp[j], ct);
      b.vertex(c + r * d, d, color);
    }
  }
  const unsigned row = unsigned(slices + 1);
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const unsigned a = first + i * row + j, bb = a + row;
      // Outward (counter-clockwise seen from outside): a, a+row, a+1 ...
      if (i > 0) b.triangle(a, bb, a + 1);
      if (i + 1 < stacks) b.triangle(a + 1, bb, bb + 1);
    }
}

void addTube(Batch& b, const std::vector<Eigen::Vector3d>& input, double r, const Color& color, bool closed,
             const PixelScale& pixelsPerUnit) {
  // Drop repeated points (relative to the radius): they have no direction.
  std::vector<Eigen::Vector3d> p;
  for (const auto& q : input)
    if (p.empty() || (q - p.back()).norm() > 1e-9 * r) p.push_back(q);
  if (closed && p.size() > 2 && (p.front() - p.back()).norm() <= 1e-9 * r) p.pop_back();
  if (p.size() < 2) {
    if (p.size() == 1) addSphere(b, p[0], r, color, circleSegments(r, p[0], pixelsPerUnit));
    return;
  }
  if (p.size() < 3) closed = false;
  const std::size_t n = p.size(), nseg = closed ? n : n - 1;
  int segs = 0;
  for (const auto& q : p) segs = std::max(segs, circleSegments(r, q, pixelsPerUnit));
  segs = std::min(segs, 48);

  std::vector<Eigen::Vector3d> dir(nseg);  // unit direction of segment i (p[i] -> p[i+1])
  for (std::size_t i = 0; i < nseg; ++i) dir[i] = (p[(i + 1) % n] - p[i]).normalized();

  // Rings: at each vertex either one ring in the bisecting plane (a smooth bend) or, at a sharp
  // corner (turning more than 30 degrees), two rings square to the segments and a sphere filling the joint.
  struct Ring { Eigen::Vector3d c, t; bool connectToPrevious; };
  std::vector<Ring> rings;
  const double sharp = std::cos(30 * pi / 180);
  for (std::size_t i = 0; i < n; ++i) {
    const bool hasIn = closed || i > 0, hasOut = closed || i + 1 < n;
    const Eigen::Vector3d din = hasIn ? dir[(i + nseg - 1) % nseg] : dir[0];
    const Eigen::Vector3d dout = hasOut ? dir[i % nseg] : dir[nseg - 1];
    if (hasIn && hasOut && din.dot(dout) < sharp) {
      rings.push_back({p[i], din, true});
      rings.push_back({p[i], dout, false});
      addSphere(b, p[i], r, color, segs);
    } else {
      const Eigen::Vector3d t = (hasIn && hasOut) ? (din + dout).normalized() : hasIn ? din : dout;
      rings.push_back({p[i], t, !rings.empty()});
    }
  }
  if (closed) rings.push_back({rings.front().c, rings.front().t, true});

  // Parallel transport of the ring's reference direction along the tangents.
  std::vector<Eigen::Vector3d> e1(rings.size());
  e1[0] = orthogonal(rings[0].t);
  for (std::size_t k = 1; k < rings.size(); ++k) {
    const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(rings[k - 1].t, rings[k].t);
    Eigen::Vector3d e = q * e1[k - 1];
    e = (e - e.dot(rings[k].t) * rings[k].t).normalized();
    e1[k] = e;
  }
  if (closed) {  // spread the holonomy (the twist accumulated around the loop) evenly along the tube
    const Eigen::Vector3d& t0 = rings[0].t;
    const Eigen::Vector3d eEnd = e1.back();
    const double twist = std::atan2(e1[0].cross(eEnd).dot(t0), e1[0].dot(eEnd));
    for (std::size_t k = 1; k < rings.size(); ++k) {
      const double a = -twist * double(k) / double(rings.size() - 1);
      e1[k] = Eigen::AngleAxisd(a, rings[k].t) * e1[k];
    }
  }
  unsigned prev = 0;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const Eigen::Vector3d e2 = rings[k].t.cross(e1[k]);
    const unsigned cur = ring(b, rings[k].c, e1[k], e2, r, segs, color);
    if (k > 0 && rings[k].connectToPrevious) connect(b, prev, cur, segs);
    prev = cur;
  }
  if (!closed) {
    const Eigen::Vector3d t0 = rings.front().t, t1 = rings.back().t;
    disc(b, rings.front().c, e1.front(), t0.cross(e1.front()), -t0, r, segs, color);
    disc(b, rings.back().c, e1.back(), t1.cross(e1.back()), t1, r, segs, color);
  }
}

void addArrow(Batch& b, const Eigen::Vector3d& from, const Eigen::Vector3d& to, double r, const Color& color,
              const PixelScale& pixelsPerUnit) {
  const Eigen::Vector3d d = to - from;
  const double len = d.norm();
  if (!(len > 0)) return;  // a zero vector draws nothing
  const Eigen::Vector3d t = d / len;
  const Eigen::Vector3d e1 = orthogonal(t), e2 = t.cross(e1);
  double headR = 2.6 * r, headL = 7 * r;
  if (headL > 0.45 * len) {  // short arrow: scale the head down, keep its shape
    const double k = 0.45 * len / headL;
    headL *= k, headR *= k;
    r = std::min(r, headR / 2.6 * 1.0);
  }
  const int n = std::max(circleSegments(headR, from, pixelsPerUnit), circleSegments(headR, to, pixelsPerUnit));
  const Eigen::Vector3d base = to - headL * t;
  // Shaft.
  const unsigned r0 = ring(b, from, e1, e2, r, n, color);
  const unsigned r1 = ring(b, base, e1, e2, r, n, color);
  connect(b, r0, r1, n);
  disc(b, from, e1, e2, -t, r, n, color);
  // Head: a cone; side normals tilted towards the tip by atan(headR / headL).
  const double s = std::hypot(headR, headL);
  const double cr = headL / s, ct = headR / s;
  const unsigned first = unsigned(b.pos.size() / 3);
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * pi * k / n, am = 2 * pi * (k + 0.5) / n;
    const Eigen::Vector3d radial = std::cos(a) * e1 + std::sin(a) * e2;
    const Eigen::Vector3d radialMid = std::cos(am) * e1 + std::sin(am) * e2;
    b.vertex(base + headR * radial, cr * radial + ct * t, color);
    b.vertex(to, cr * radialMid + ct * t, color);  // a tip vertex per facet: smooth shading
  }
  for (int k = 0; k < n; ++k) b.triangle(first + 2 * k, first + 2 * k + 2, first + 2 * k + 1);
  disc(b, base, e1, e2, -t, headR, n, color);
}

std::vector<Eigen::Vector3d> vertexNormals(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3i>& tri) {
  std::vector<Eigen::Vector3d> n(v.size(), Eigen::Vector3d::Zero());
  for (const auto& t : tri) {
    const Eigen::Vector3d a = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]);  // twice the area, outward
    for (int j = 0; j < 3; ++j) n[t[j]] += a;
  }
  for (auto& x : n)
    if (x.squaredNorm() > 0) x.normalize();
  return n;
}

void addMesh(Batch& b, const Mesh& m) {
  const std::vector<Eigen::Vector3d> computed = m.n.empty() ? vertexNormals(m.v, m.tri) : std::vector<Eigen::Vector3d>{};
  const auto& n = m.n.empty() ? computed : m.n;
  const unsigned first = unsigned(b.pos.size() / 3);
  for (std::size_t i = 0; i < m.v.size(); ++i) {
    Eigen::Vector3d ni = n[i];
    if (ni.squaredNorm() > 0) ni.normalize();
    b.vertex(m.v[i], ni, m.c);
  }
  for (const auto& t : m.tri) b.triangle(first + t[0], first + t[1], first + t[2]);
}

}  // namespace soma::render::detail
