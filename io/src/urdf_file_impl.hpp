#pragma once
// Definitions of urdf_file.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/urdf_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/io/json_file.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace soma::io {

namespace detail {
/// urdfdom's parse of `xml` after checkUrdfText (urdf_scan.hpp: the text, its size and its joint
/// graph, a tree), its console_bridge messages in the InvalidInput (urdf_file.cpp: one mutex for
/// all scalars, console_bridge's handler being global).
urdf::ModelInterfaceSharedPtr parseUrdfModel(const std::string& xml, const std::string& origin);
}  // namespace detail

namespace {

// A URDF <origin>: translation xyz, then the rotation urdfdom stores as a unit quaternion
// (from rpy: R = Rz(yaw)·Ry(pitch)·Rx(roll)). The quaternion is re-normalised in S: it carries
// double's rounding, which is far below the input tolerance of the longer scalars.
template <class S> SE3<S> pose(const urdf::Pose& p) {
  using std::sqrt;
  Vec4<S> c(scalarCast<S>(p.rotation.x), scalarCast<S>(p.rotation.y), scalarCast<S>(p.rotation.z),
            scalarCast<S>(p.rotation.w));
  c /= sqrt(c.squaredNorm());
  const Quat<S> q(c(3), c(0), c(1), c(2));
  return SE3<S>(SO3<S>::fromQuaternion(q),
                Vec3<S>(scalarCast<S>(p.position.x), scalarCast<S>(p.position.y), scalarCast<S>(p.position.z)));
}

std::string jointTypeName(int type) {
  switch (type) {
    case urdf::Joint::FLOATING: return "floating";
    case urdf::Joint::PLANAR: return "planar";
    case urdf::Joint::UNKNOWN: return "unknown";
    default: return "?";
  }
}

}  // namespace

// GF §4.5 (product of exponentials): each joint's twist at the home configuration, M = tip frame.
template <class S>
RobotFile<S> parseUrdf(const std::string& xml, const std::string& origin, const std::string& tip) {
  const urdf::ModelInterfaceSharedPtr model = detail::parseUrdfModel(xml, origin);
  const urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root) throw InvalidInput(origin + ": the URDF has no root link");
  // The tip: the named link, or the only leaf.
  urdf::LinkConstSharedPtr tipLink;
  if (!tip.empty()) {
    tipLink = model->getLink(tip);
    if (!tipLink) throw InvalidInput(origin + ": --tip: no link named \"" + tip + "\"");
  } else {
    std::vector<urdf::LinkSharedPtr> links;
    model->getLinks(links);
    std::vector<std::string> leaves;
    for (const auto& l : links)
      if (l->child_links.empty()) {
        leaves.push_back(l->name);
        tipLink = l;
      }
    if (leaves.size() != 1) {
      std::string names;
      for (const auto& n : leaves) names += (names.empty() ? "" : ", ") + n;
      throw InvalidInput(origin + ": the URDF tree branches (leaf links " + names +
                         "): choose the chain's tip link with --tip NAME");
    }
  }
  if (tipLink == root) throw InvalidInput(origin + ": no chain: the tip link \"" + tipLink->name + "\" is the root");
  // Joints from the tip up to the root, then reversed (the joint graph is a tree: checkUrdfText).
  std::vector<urdf::JointConstSharedPtr> chain;
  for (urdf::LinkConstSharedPtr l = tipLink; l != root;) {
    if (!l->parent_joint) throw InvalidInput(origin + ": link \"" + l->name + "\" has no parent joint");
    chain.push_back(l->parent_joint);
    l = l->getParent();
    if (!l) throw InvalidInput(origin + ": link chain from \"" + tipLink->name + "\" does not reach the root");
  }
  std::reverse(chain.begin(), chain.end());
  // Walk down: W is the frame of the current link at q = 0, in root coordinates.
  SE3<S> W;
  std::vector<SerialJoint<S>> joints;
  for (const auto& j : chain) {
    const std::string where = origin + ": joint \"" + j->name + "\"";
    W = W * pose<S>(j->parent_to_joint_origin_transform);
    if (j->type == urdf::Joint::FIXED) continue;
    if (j->type != urdf::Joint::REVOLUTE && j->type != urdf::Joint::CONTINUOUS &&
        j->type != urdf::Joint::PRISMATIC)
      throw InvalidInput(where + " is " + jointTypeName(j->type) +
                         ": only revolute, continuous, prismatic and fixed joints make a serial chain");
    if (j->mimic) throw InvalidInput(where + " mimics joint \"" + j->mimic->joint_name + "\": not a serial chain's own joint");
    const double n2 = j->axis.x * j->axis.x + j->axis.y * j->axis.y + j->axis.z * j->axis.z;
    if (!(std::abs(n2 - 1.0) <= 2.0 * Tolerance<double>::input()))
      throw InvalidInput(where + " axis is not a unit vector");
    SerialJoint<S> sj;
    sj.type = j->type == urdf::Joint::PRISMATIC ? JointType::Prismatic : JointType::Revolute;
    Vec3<S> a(scalarCast<S>(j->axis.x), scalarCast<S>(j->axis.y), scalarCast<S>(j->axis.z));
    using std::sqrt;
    a /= sqrt(a.squaredNorm());
    sj.axis = W.rotation() * a;
    sj.point = W.translation();
    if (j->type != urdf::Joint::CONTINUOUS && j->limits) {
      sj.lower = scalarCast<S>(j->limits->lower);
      sj.upper = scalarCast<S>(j->limits->upper);
      if (sj.lower > sj.upper) throw InvalidInput(where + " limits: lower limit exceeds upper limit");
    }
    joints.push_back(sj);
  }
  if (joints.empty())
    throw InvalidInput(origin + ": no chain: no revolute, continuous or prismatic joint between \"" + root->name +
                       "\" and \"" + tipLink->name + "\"");
  RobotFile<S> out;
  out.robot = SerialRobot<S>::fromPOE(joints, W, model->getName());
  return out;
}

template <class S> RobotFile<S> readUrdf(const std::filesystem::path& file, const std::string& tip) {
  return parseUrdf<S>(readTextFile(file, "robot"), file.string(), tip);
}

template <class S> RobotFile<S> readAnyRobot(const std::filesystem::path& file, const std::string& tip) {
  if (file.extension() == ".urdf" || file.extension() == ".URDF") return readUrdf<S>(file, tip);
  if (!tip.empty()) throw InvalidInput("--tip names a URDF link; " + file.string() + " is not a .urdf file");
  return readRobot<S>(file);
}

#define SOMA_INSTANTIATE_URDF_FILE(S) namespace io {                                                              \
  template RobotFile<S> parseUrdf<S>(const std::string&, const std::string&, const std::string&); \
  template RobotFile<S> readUrdf<S>(const std::filesystem::path&, const std::string&);            \
  template RobotFile<S> readAnyRobot<S>(const std::filesystem::path&, const std::string&); }

}  // namespace soma::io
