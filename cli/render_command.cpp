// `soma render SCENE.json --png FILE [--size WxH]` (DESIGN §6, issue 19): the scene's entities drawn
// off-screen — robots at the postures of the scene's ik and fk outputs, platforms at their Stewart
// postures, lines, screws, points, cylindroids — and written as a PNG (only when it all worked).
#include "command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/scene_file.hpp"
#include "soma/scene/scene_graph.hpp"

#include <fmt/format.h>
#include <iostream>
#include <regex>

namespace soma::cli {

namespace {

class RenderCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "render";
    spec.help = "draw a scene's entities off-screen into a PNG";
    spec.add("scene", file_, "scene JSON (docs/cli.md, soma scene)").mustBeGiven();
    spec.add("--png", png_, "the PNG to write").mustBeGiven();
    spec.add("--size", size_, "image size WxH in pixels (16..8192 each)").withDefault();
    spec.flag("--trace", trace_, "list every node built, its time and why");
  }
  int run(const Spec&, const Invocation&) override {
    std::smatch m;
    if (!std::regex_match(size_, m, std::regex("([0-9]{2,4})x([0-9]{2,4})")))
      throw InvalidInput("--size: \"" + size_ + "\" is not WxH (e.g. 1200x900)");
    const int w = std::stoi(m[1]), h = std::stoi(m[2]);
    if (w < 16 || h < 16 || w > 8192 || h > 8192) throw InvalidInput("--size: each side must be in [16, 8192] pixels");
    scene::SceneGraph graph(io::readScene(file_));
    const scene::SceneResult r = graph.render(png_, w, h);
    std::cout << fmt::format("wrote {} ({}x{}) from {}\n", png_, w, h, file_);
    if (trace_)
      for (const auto& e : r.trace) std::cout << fmt::format("  {:>10.3f} ms  {:<32} {}\n", e.seconds * 1e3, e.id, e.reason);
    return 0;
  }

 private:
  std::string file_, png_, size_ = "1200x900";
  bool trace_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(RenderCommand, 96);

}  // namespace soma::cli
