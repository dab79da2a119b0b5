#pragma once
// A pinhole or orthographic camera, and the pixel coordinates it projects world points to.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace soma::render {

struct Scene;

/// Options of Camera::fit.
struct FitOptions {
  int width = 1200, height = 900;  ///< the image the camera is for: its aspect, and room for a title
  bool orthographic = false;
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< world "up" (robotics convention: z)
  double fovYDegrees = 30;
  double margin = 0.05;  ///< fraction of the image width/height left free on each side
};

/// Pixel coordinates: x to the right from the left edge, y downwards from the top edge; pixel
/// (i, j) covers [i, i+1) x [j, j+1), so its centre is (i + 0.5, j + 0.5). Rows of every image
/// soma::render returns are stored top row first, matching these coordinates.
struct Camera {
  Eigen::Vector3d eye{4, 3, 2.5}, target{0, 0, 0}, up{0, 0, 1};
  double fovYDegrees = 30;   ///< vertical field of view (perspective)
  bool orthographic = false;
  double orthoHeight = 2;    ///< world height of the visible window (orthographic)

  /// Perspective camera at eye looking at target.
  static Camera lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                       const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ(), double fovYDegrees = 30);
  /// Orthographic camera at eye looking at target, showing a window `height` world units tall.
  static Camera ortho(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                      const Eigen::Vector3d& up, double height);
  /// A camera looking along viewDir that frames the whole scene (the outline of its geometry) with a margin, leaving
  /// room at the top for the scene's title. An empty scene is framed as the unit cube at the origin.
  static Camera fit(const Scene& scene, const Eigen::Vector3d& viewDir, const FitOptions& options = {});

  /// Throws std::invalid_argument for a non-finite field, eye == target, up parallel to the view
  /// direction, a field of view outside (0, 180) degrees or a non-positive orthoHeight.
  void validate() const;

  /// Unit view direction (from eye to target).
  Eigen::Vector3d forward() const;
  /// World → eye coordinates (OpenGL convention: the camera looks down −z, y is up).
  Eigen::Matrix4d viewMatrix() const;
  /// Eye → clip coordinates (OpenGL convention) for an image of the given aspect (width / height).
  Eigen::Matrix4d projectionMatrix(double aspect, double zNear, double zFar) const;
  /// Pixel coordinates of world point p in a width x height image (see the convention above).
  /// For a perspective camera the point must be in front of the eye (else the result is not finite).
  Eigen::Vector2d project(const Eigen::Vector3d& p, int width, int height) const;
  /// Depth of p along the view direction, measured from the eye (positive in front).
  double depth(const Eigen::Vector3d& p) const { return (p - eye).dot(forward()); }
};

}  // namespace soma::render
