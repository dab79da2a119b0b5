#pragma once
// A robot as Python holds it: the text it was read from (robot JSON or URDF), so that fk and ik in
// any scalar read it again in that scalar through io's readers (exact decimal input), and its
// double model for everything else.
#include "soma/io/robot_file.hpp"
#include "soma/io/urdf_file.hpp"

#include <string>

namespace soma::python {

struct RobotHandle {
  std::string text;    ///< robot JSON or URDF XML
  bool urdf = false;
  std::string origin;  ///< the file name or "<python dict>", starting every message
  std::string tip;     ///< URDF: the chain's tip link
  io::RobotFile<double> file;

  template <class S> io::RobotFile<S> in() const {
    if constexpr (std::is_same_v<S, double>) return file;
    else return urdf ? io::parseUrdf<S>(text, origin, tip) : io::parseRobot<S>(text, origin);
  }
  const SerialRobot<double>& robot() const { return file.robot; }
};

}  // namespace soma::python
