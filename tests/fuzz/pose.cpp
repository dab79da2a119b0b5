// libFuzzer harness: the pose reader (io::parsePose: rotation matrix or quaternion, translation).
#include "harness.hpp"

#include "soma/io/pose_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("pose", [&] { (void)soma::io::parsePose<double>(body, "fuzz.json"); });
  return 0;
}
