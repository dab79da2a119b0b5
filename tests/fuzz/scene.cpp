// libFuzzer harness: the scene reader (io::parseScene, then io::validateScene, which reads every
// entity an output uses in the output's scalar: inline bodies and the files they name). Relative
// "file" paths resolve against examples/scenes/ (SOMA_FUZZ_SCENE_DIR), so the corpus's scenes
// reach the example robots, poses and platforms.
#include "harness.hpp"

#include "soma/io/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("scene", [&] {
    const soma::io::SceneFile scene = soma::io::parseScene(body, "fuzz.json", SOMA_FUZZ_SCENE_DIR);
    soma::io::validateScene(scene);
  });
  return 0;
}
