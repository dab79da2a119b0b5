// libFuzzer harness: the planar scene reader (io::parsePlanarScene: positions or a four-bar).
#include "harness.hpp"

#include "soma/io/planar_scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("planar_scene", [&] { (void)soma::io::parsePlanarScene(body, "fuzz.json"); });
  return 0;
}
