// The non-template part of urdf_file.hpp (urdfdom's parse under one lock); the readers: urdf_file_impl.hpp.
#include "urdf_file_impl.hpp"
#include "urdf_scan.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/io/json_file.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace soma::io {

namespace {

// urdfdom reports why a file is rejected through console_bridge: collect the messages so that
// they go into the InvalidInput, instead of being printed on their own.
class Collect : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages += (messages.empty() ? "" : "; ") + text;
  }
  std::string messages;
};

std::mutex parseMutex;  // console_bridge's handler is global

}  // namespace

urdf::ModelInterfaceSharedPtr detail::parseUrdfModel(const std::string& xml, const std::string& origin) {
  // The text, its size and its joint graph first (urdf_scan.hpp): TinyXML and urdfdom see only a
  // well-formed, bounded tree of links.
  checkUrdfText(xml, origin);
  std::lock_guard<std::mutex> lock(parseMutex);
  Collect collect;
  console_bridge::useOutputHandler(&collect);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {
    collect.messages += std::string(collect.messages.empty() ? "" : "; ") + e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model)
    throw InvalidInput(origin + ": not a valid URDF robot" +
                       (collect.messages.empty() ? std::string() : " (" + collect.messages + ")"));
  return model;
}

}  // namespace soma::io
