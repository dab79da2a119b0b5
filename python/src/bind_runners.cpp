// Scenes (DESIGN §5: SceneGraph, only the asked outputs built, traced) and the study runner
// (DESIGN §4: list, select by ID or glob, run with checks), as the CLI's `scene` and `study` do.
#include "common.hpp"

#include "soma/io/scene_file.hpp"
#include "soma/scene/scene_graph.hpp"
#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"

namespace soma::python {

namespace {
using namespace soma::studies;

py::dict sceneResult(scene::SceneGraph& graph, const std::vector<std::string>& only) {
  const scene::SceneResult r = graph.evaluate(only);
  py::module_ json = py::module_::import("json");
  py::dict outputs;
  for (const auto& o : r.outputs) outputs[py::str(o.name)] = json.attr("loads")(o.json);
  py::list trace;
  for (const auto& e : r.trace) {
    py::dict t;
    t["id"] = e.id;
    t["seconds"] = e.seconds;
    t["reason"] = e.reason;
    trace.append(t);
  }
  py::list written;
  for (const auto& w : r.written) written.append(w.string());
  py::dict d;
  d["ok"] = r.ok();
  d["outputs"] = outputs;
  d["trace"] = trace;
  d["written"] = written;
  return d;
}

py::dict studyResult(const StudyResult& r) {
  py::dict d;
  d["id"] = r.study->id;
  d["title"] = r.study->title;
  d["source"] = r.study->source;
  d["scalar"] = std::string(scalarName(r.scalar));
  d["passed"] = r.passed();
  d["seconds"] = r.seconds;
  d["error"] = r.error;
  d["notes"] = r.notes;
  py::list checks;
  for (const auto& c : r.checks) {
    py::dict k;
    k["name"] = c.name;
    k["expected"] = c.expected;
    k["got"] = c.got;
    k["error"] = c.error;
    k["tolerance"] = c.tolerance;
    k["seconds"] = c.seconds;
    k["passed"] = c.passed;
    checks.append(k);
  }
  d["checks"] = checks;
  py::list figures;
  for (const auto& f : r.figures) figures.append(py::make_tuple(f.file, f.caption));
  d["figures"] = figures;
  return d;
}

}  // namespace

void bindRunners(py::module_& m) {
  m.def(
      "_run_scene_file",
      [](const std::string& file, const std::vector<std::string>& only) {
        scene::SceneGraph graph(io::readScene(file));
        return sceneResult(graph, only);
      },
      py::arg("file"), py::arg("only") = std::vector<std::string>{});
  m.def(
      "_run_scene_text",
      [](const std::string& text, const std::string& origin, const std::string& folder, const std::vector<std::string>& only) {
        io::SceneFile s = io::parseScene(text, origin, folder);
        io::validateScene(s);
        scene::SceneGraph graph(std::move(s));
        return sceneResult(graph, only);
      },
      py::arg("text"), py::arg("origin"), py::arg("folder"), py::arg("only") = std::vector<std::string>{});

  m.def(
      "_studies",
      [](const std::vector<std::string>& patterns) {
        const std::vector<const Study*> sel = patterns.empty() ? allStudies() : selectStudies(patterns);
        py::list out;
        for (const Study* s : sel) {
          py::dict d;
          d["id"] = s->id;
          d["title"] = s->title;
          d["source"] = s->source;
          d["chapter"] = s->chapter;
          d["scalar_generic"] = s->scalarGeneric;
          out.append(d);
        }
        return out;
      },
      py::arg("patterns") = std::vector<std::string>{});
  m.def(
      "_run_studies",
      [](const std::vector<std::string>& patterns, const std::string& scalar, int bits, const std::string& outDir,
         bool figures) {
        RunOptions o;
        o.scalar = scalarArgument(scalar, bits);
        o.outDir = outDir;
        o.makeFigures = figures;
        const std::vector<const Study*> sel = selectStudies(patterns);
        std::vector<StudyResult> results;
        {
          py::gil_scoped_release release;
          results = runStudies(sel, o);
        }
        py::list out;
        for (const auto& r : results) out.append(studyResult(r));
        return out;
      },
      py::arg("patterns"), py::arg("scalar") = "double", py::arg("bits") = 256, py::arg("out_dir") = "out/report",
      py::arg("figures") = false);
}

}  // namespace soma::python
