#pragma once
// A Stewart platform's plate as the chapter's figures draw it (GF Fig. 11.1, the posture grid of
// GF-11.5.4-stewart-forty): a rim tube through the joint centres and, optionally, a fan over them
// (the centres need not be coplanar: the plate is then slightly bent).
#include "soma/render/render.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace soma::studies::gf11 {

inline void addPlate(render::Scene& scene, const std::vector<Eigen::Vector3d>& joints, render::Color rim, double rimRadius,
                     std::optional<render::Color> fill = std::nullopt) {
  if (fill) {
    render::Mesh m;
    Eigen::Vector3d ctr = Eigen::Vector3d::Zero();
    for (const auto& x : joints) ctr += x / double(joints.size());
    m.v = joints;
    m.v.push_back(ctr);
    const int n = int(joints.size());
    for (int i = 0; i < n; ++i) m.tri.push_back(Eigen::Vector3i(n, i, (i + 1) % n));
    m.c = *fill;
    scene.add(m);
  }
  render::Tube t;
  t.p = joints;
  t.closed = true;
  t.radius = rimRadius;
  t.c = rim;
  scene.add(t);
}

}  // namespace soma::studies::gf11
