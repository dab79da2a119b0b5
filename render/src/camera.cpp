// Camera: view/projection matrices (OpenGL conventions), pixel projection, fitting a scene.
#include "soma/render/camera.hpp"

#include "detail.hpp"
#include "soma/render/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace soma::render {

using detail::invalid;

Camera Camera::lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up,
                      double fovYDegrees) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = up;
  c.fovYDegrees = fovYDegrees;
  c.orthographic = false;
  c.validate();
  return c;
}

Camera Camera::ortho(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, const Eigen::Vector3d& up,
                     double height) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = up;
  c.orthographic = true;
  c.orthoHeight = height;
  c.validate();
  return c;
}

void Camera::validate() const {
  if (!detail::finite(eye)) invalid("Camera.eye has a non-finite coordinate " + detail::str(eye));
  if (!detail::finite(target)) invalid("Camera.target has a non-finite coordinate " + detail::str(target));
  if (!detail::finite(up)) invalid("Camera.up has a non-finite coordinate " + detail::str(up));
  const Eigen::Vector3d f = target - eye;
  const double scale = std::max({eye.norm(), target.norm(), 1e-300});
  // Relative tests against the machine epsilon (render works in double only).
  const double eps = std::numeric_limits<double>::epsilon();
  if (f.squaredNorm() <= (64 * eps * scale) * (64 * eps * scale))
    invalid("Camera.eye " + detail::str(eye) + " coincides with Camera.target");
  if (up.squaredNorm() == 0) invalid("Camera.up is the zero vector");
  const double s = f.normalized().cross(up.normalized()).norm();
  if (s <= 1e3 * eps) invalid("Camera.up " + detail::str(up) + " is parallel to the view direction " + detail::str(f));
  if (orthographic) {
    if (!(orthoHeight > 0) || !std::isfinite(orthoHeight))
      invalid("Camera.orthoHeight is " + std::to_string(orthoHeight) + "; it must be positive");
  } else if (!(fovYDegrees > 0 && fovYDegrees < 180)) {
    invalid("Camera.fovYDegrees is " + std::to_string(fovYDegrees) + "; it must be in (0, 180)");
  }
}

Eigen::Vector3d Camera::forward() const { return (target - eye).normalized(); }

Eigen::Matrix4d Camera::viewMatrix() const {
  const Eigen::Vector3d f = forward();
  const Eigen::Vector3d s = f.cross(up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m.block<3, 1>(0, 3) = -m.block<3, 3>(0, 0) * eye;
  return m;
}

Eigen::Matrix4d Camera::projectionMatrix(double aspect, double n, double f) const {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (orthographic) {
    const double h = orthoHeight / 2, w = h * aspect;
    p(0, 0) = 1 / w;
    p(1, 1) = 1 / h;
    p(2, 2) = -2 / (f - n);
    p(2, 3) = -(f + n) / (f - n);
    p(3, 3) = 1;
  } else {
    const double t = 1 / std::tan(fovYDegrees * std::numbers::pi / 360);
    p(0, 0) = t / aspect;
    p(1, 1) = t;
    p(2, 2) = (f + n) / (n - f);
    p(2, 3) = 2 * f * n / (n - f);
    p(3, 2) = -1;
  }
  return p;
}

Eigen::Vector2d Camera::project(const Eigen::Vector3d& p, int width, int height) const {
  // x and y of the projection do not depend on the near and far planes.
  const Eigen::Vector4d c = projectionMatrix(double(width) / height, 1, 2) * viewMatrix() * p.homogeneous();
  return {(c.x() / c.w() + 1) / 2 * width, (1 - c.y() / c.w()) / 2 * height};
}

Camera Camera::fit(const Scene& scene, const Eigen::Vector3d& viewDir, const FitOptions& o) {
  if (!detail::finite(viewDir) || viewDir.squaredNorm() == 0)
    invalid("Camera::fit: viewDir " + detail::str(viewDir) + " is not a finite non-zero vector");
  if (o.width < 1 || o.height < 1) invalid("Camera::fit: image size must be positive");
  if (!(o.margin >= 0 && o.margin < 0.45)) invalid("Camera::fit: margin must be in [0, 0.45)");
  const Eigen::Vector3d f = viewDir.normalized();
  Eigen::Vector3d up = o.up;
  if (!detail::finite(up) || up.squaredNorm() == 0) invalid("Camera::fit: up is not a finite non-zero vector");
  if (f.cross(up.normalized()).norm() < 1e-6) {  // looking along "up": pick another up
    up = std::abs(f.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    up = f.cross(up).cross(f);
  }
  const Eigen::Vector3d s = f.cross(up).normalized(), u = s.cross(f);

  Eigen::AlignedBox3d box = scene.bounds();
  if (box.isEmpty()) box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  if (box.diagonal().norm() == 0) box.extend(box.min() + Eigen::Vector3d::Constant(1)), box.extend(box.min() - Eigen::Vector3d::Constant(1));
  const Eigen::Vector3d centre = box.center();
  // The outline of the geometry in the view basis (s, u, f), relative to the centre: tighter than
  // the corners of the bounding box, which project well outside a diagonal view of the scene.
  std::vector<Eigen::Vector3d> corner;
  for (const Eigen::Vector3d& p : detail::outlinePoints(scene, s, u)) {
    const Eigen::Vector3d c = p - centre;
    corner.emplace_back(c.dot(s), c.dot(u), c.dot(f));
  }
  double spread = 0;
  for (const auto& c : corner) spread = std::max({spread, std::abs(c.x()), std::abs(c.y())});
  if (!(spread > 1e-9 * box.diagonal().norm()))  // nothing, or a single point: frame the (enlarged) box
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d c = box.corner(Eigen::AlignedBox3d::CornerType(k)) - centre;
      corner.emplace_back(c.dot(s), c.dot(u), c.dot(f));
    }
  // The window available in normalised device coordinates: a margin all round, room for the title.
  const double titleFrac = scene.title.empty() ? 0.0 : (scene.titlePixelHeight * 1.8) / o.height;
  const double xlo = -1 + 2 * o.margin, xhi = 1 - 2 * o.margin;
  const double ylo = -1 + 2 * o.margin, yhi = 1 - 2 * o.margin - 2 * titleFrac;
  const double aspect = double(o.width) / o.height;
  const double extent = box.diagonal().norm();

  Camera cam;
  cam.up = up;
  cam.orthographic = o.orthographic;
  cam.fovYDegrees = o.fovYDegrees;
  if (o.orthographic) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& c : corner) x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), y0 = std::min(y0, c.y()), y1 = std::max(y1, c.y());
    // NDC y = (y - ty) / H, x = (x - tx) / (H * aspect), with H the half-height of the window.
    const double H = std::max({(y1 - y0) / (yhi - ylo), (x1 - x0) / ((xhi - xlo) * aspect), 1e-9 * extent});
    const double tx = (x0 + x1) / 2 - H * aspect * (xlo + xhi) / 2, ty = (y0 + y1) / 2 - H * (ylo + yhi) / 2;
    cam.orthoHeight = 2 * H;
    cam.target = centre + tx * s + ty * u;
    cam.eye = cam.target - 2 * extent * f;
  } else {
    if (!(o.fovYDegrees > 0 && o.fovYDegrees < 180)) invalid("Camera::fit: fovYDegrees must be in (0, 180)");
    const double ty = std::tan(o.fovYDegrees * std::numbers::pi / 360), tx = ty * aspect;
    // Iterate: distance d so that every corner fits the window, then re-centre the projected box.
    double cx = 0, cy = 0, d = extent;
    for (int it = 0; it < 8; ++it) {
      d = 0;
      for (const auto& c : corner) {
        d = std::max(d, std::abs(c.x() - cx) / (tx * (xhi - xlo) / 2) - c.z());
        d = std::max(d, std::abs(c.y() - cy) / (ty * (yhi - ylo) / 2) - c.z());
      }
      double nx0 = 1e300, nx1 = -1e300, ny0 = 1e300, ny1 = -1e300;
      for (const auto& c : corner) {
        const double w = d + c.z();
        nx0 = std::min(nx0, (c.x() - cx) / (w * tx)), nx1 = std::max(nx1, (c.x() - cx) / (w * tx));
        ny0 = std::min(ny0, (c.y() - cy) / (w * ty)), ny1 = std::max(ny1, (c.y() - cy) / (w * ty));
      }
      // Shift the centre so the projected box is centred in the window (at the centre's depth d).
      cx += ((nx0 + nx1) / 2 - (xlo + xhi) / 2) * d * tx;
      cy += ((ny0 + ny1) / 2 - (ylo + yhi) / 2) * d * ty;
    }
    cam.target = centre + cx * s + cy * u;
    cam.eye = cam.target - d * f;
  }
  cam.validate();
  return cam;
}

}  // namespace soma::render
