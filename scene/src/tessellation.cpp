// Render primitives of a scene's entities (tessellation.hpp).
#include "soma/scene/tessellation.hpp"

#include "soma/geometry/lines/screw_axis.hpp"
#include "soma/render/shapes.hpp"

#include <cmath>

namespace soma::scene {

namespace {
Eigen::Matrix4d homogeneous(const SE3<double>& g) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = g.rotation();
  m.block<3, 1>(0, 3) = g.translation();
  return m;
}
render::Label label(const Eigen::Vector3d& at, const std::string& text) {
  render::Label l;
  l.at = at;
  l.text = text;
  return l;
}
const render::Color kPostureColours[] = {render::palette::blue, render::palette::vermillion, render::palette::bluishGreen,
                                         render::palette::reddishPurple, render::palette::orange, render::palette::skyBlue,
                                         render::palette::darkGrey, render::palette::yellow};
}  // namespace

render::Scene robotTessellation(const SerialRobot<double>& robot, const std::vector<JointVector<double>>& postures,
                                const std::vector<std::vector<JointVector<double>>>& paths, const std::string& text) {
  render::Scene s;
  for (const auto& path : paths) {
    render::Polyline trace;
    trace.c = render::palette::vermillion;
    trace.width = 3;
    for (const JointVector<double>& q : path) trace.p.push_back(robot.fk(q).translation());
    s.add(std::move(trace));
  }
  std::vector<JointVector<double>> qs = postures;
  if (qs.empty()) qs.push_back(JointVector<double>::Zero(robot.dof()));
  for (std::size_t k = 0; k < qs.size(); ++k) {
    const std::vector<SE3<double>> frames = robot.frames(qs[k]);
    render::Tube chain;
    chain.c = kPostureColours[k % std::size(kPostureColours)];
    for (const SE3<double>& f : frames) chain.p.push_back(f.translation());
    const SE3<double> tool = robot.fk(qs[k]);
    if ((tool.translation() - chain.p.back()).norm() > 0) chain.p.push_back(tool.translation());
    render::Points joints;
    joints.c = render::palette::darkGrey;
    joints.p = chain.p;
    s.add(std::move(chain));
    s.add(std::move(joints));
    render::Frame f;
    f.pose = homogeneous(tool);
    s.add(f);
  }
  s.add(label(robot.frames(qs[0]).front().translation(), text));
  return s;
}

render::Scene platformTessellation(const StewartPlatform<double>& P, const std::vector<SE3<double>>& postures,
                                   const std::string& text) {
  render::Scene s;
  render::Tube base;
  base.closed = true;
  base.c = render::palette::darkGrey;
  for (const Vec3<double>& b : P.base) base.p.push_back(b);
  s.add(std::move(base));
  for (std::size_t k = 0; k < postures.size(); ++k) {
    const render::Color c = kPostureColours[k % std::size(kPostureColours)];
    render::Tube top;
    top.closed = true;
    top.c = c;
    for (const Vec3<double>& p : P.platform) top.p.push_back(postures[k].act(p));
    for (int i = 0; i < 6; ++i) {
      render::Tube leg;
      leg.c = c.lighter(0.4f);
      leg.p = {P.base[std::size_t(i)], top.p[std::size_t(i)]};
      s.add(std::move(leg));
    }
    s.add(std::move(top));
  }
  s.add(label(P.base[0], text));
  return s;
}

render::Scene lineTessellation(const PluckerLine<double>& line, double halfLength, const std::string& text) {
  render::Scene s;
  const PluckerLine<double> u = line.normalized();
  const Vec3<double> d = u.direction(), foot = d.cross(u.moment());  // the point nearest the origin
  render::Tube t;
  t.c = render::palette::bluishGreen;
  t.p = {foot - halfLength * d, foot + halfLength * d};
  s.add(std::move(t));
  s.add(label(foot + halfLength * d, text));
  return s;
}

render::Scene screwTessellation(const Vec6<double>& screw, double length, const std::string& text) {
  render::Scene s;
  const ScrewAxis<double> a = screwAxis(screw);
  if (a.infinitePitch) {
    render::Arrow arrow;
    arrow.from = Vec3<double>::Zero();
    arrow.to = length * screw.tail<3>().normalized();
    arrow.c = render::palette::reddishPurple;
    s.add(arrow);
    s.add(label(arrow.to, text + " (h = ∞)"));
    return s;
  }
  const Vec3<double> d = a.axis.direction(), foot = d.cross(a.axis.moment());
  render::Arrow arrow;
  arrow.from = foot - 0.5 * length * d;
  arrow.to = foot + 0.5 * length * d;
  arrow.c = render::palette::reddishPurple;
  s.add(arrow);
  s.add(label(arrow.to, text + " (h = " + toString(a.pitch, 3) + ")"));
  return s;
}

render::Scene pointTessellation(const Vec3<double>& point, const std::string& text) {
  render::Scene s;
  render::Points p;
  p.p = {point};
  s.add(std::move(p));
  s.add(label(point, text));
  return s;
}

render::Scene cylindroidTessellation(const Cylindroid<double>& c, double radius, const std::string& text) {
  render::Scene s;
  const Mat3<double> R = c.frame();
  const Vec3<double> o = c.centre();
  // GF §6.5.2: the axis at angle θ is the line through (0, 0, z(θ)) along (cos θ, sin θ, 0).
  const render::SurfaceMap f = [&](double r, double theta) -> Eigen::Vector3d {
    return o + R * Vec3<double>(r * std::cos(theta), r * std::sin(theta), c.height(theta));
  };
  render::Mesh m = render::parametricSurface(f, {-radius, radius}, {0.0, pi<double>()}, 24, 96);
  m.c = render::palette::skyBlue.withAlpha(0.6f);
  s.add(std::move(m));
  for (int i = 1; i <= 2; ++i) {
    render::Tube axis;
    axis.c = i == 1 ? render::palette::vermillion : render::palette::blue;
    const Vec3<double> d = R.col(i - 1);
    const Vec3<double> at = o + R * Vec3<double>(0, 0, c.height(i == 1 ? 0.0 : pi<double>() / 2));
    axis.p = {at - radius * d, at + radius * d};
    s.add(std::move(axis));
  }
  s.add(label(o + R * Vec3<double>(0, 0, c.height(pi<double>() / 4)), text));
  return s;
}

void merge(render::Scene& into, const render::Scene& part) {
  into.add(part.points);
  into.add(part.polylines);
  into.add(part.tubes);
  into.add(part.meshes);
  into.add(part.fills);
  into.add(part.frames);
  into.add(part.arrows);
  into.add(part.labels);
}

}  // namespace soma::scene
