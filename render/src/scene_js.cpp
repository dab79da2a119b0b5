#include "soma/render/scene_js.hpp"

#include "detail.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace soma::render {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "0";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}
std::string vec(const Eigen::Vector3d& p) { return "[" + num(p.x()) + "," + num(p.y()) + "," + num(p.z()) + "]"; }
std::string pts(const std::vector<Eigen::Vector3d>& p) {
  std::string s = "[";
  for (std::size_t k = 0; k < p.size(); ++k) s += (k ? "," : "") + vec(p[k]);
  return s + "]";
}
std::string col(const Color& c) {
  return "[" + num(c.r) + "," + num(c.g) + "," + num(c.b) + "," + num(c.a) + "]";
}
/// A JSON string (UTF-8 passed through; quotes, backslashes, controls and "</" escaped).
std::string str(const std::string& t) {
  std::string s = "\"";
  for (std::size_t i = 0; i < t.size(); ++i) {
    const unsigned char ch = static_cast<unsigned char>(t[i]);
    if (ch == '"' || ch == '\\') s += '\\', s += char(ch);
    else if (ch == '<' && i + 1 < t.size() && t[i + 1] == '/') s += "<\\/", ++i;
    else if (ch < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", ch);
      s += b;
    } else s += char(ch);
  }
  return s + "\"";
}

/// One group's members of the given kinds as JSON fields (without braces).
std::string fields(const Scene& s, double L, const std::string& kinds) {
  auto want = [&](const char* k) { return kinds == "*" || kinds == k; };
  std::string o;
  auto field = [&](const char* name, const std::string& arr) {
    if (arr.size() > 2) o += std::string(o.empty() ? "" : ",") + "\"" + name + "\":" + arr;
  };
  std::string a = "[";
  if (want("points"))
    for (const Points& x : s.points)
      a += (a.size() > 1 ? "," : "") + std::string("{\"p\":") + pts(x.p) + ",\"c\":" + col(x.c) +
           ",\"r\":" + num(detail::pointRadius(x, L)) + "}";
  field("points", a + "]");
  a = "[";
  if (want("lines"))
    for (const Polyline& x : s.polylines)
      a += (a.size() > 1 ? "," : "") + std::string("{\"p\":") + pts(x.p) + ",\"c\":" + col(x.c) +
           ",\"closed\":" + (x.closed ? "true" : "false") + ",\"dashed\":" + (x.dashed ? "true" : "false") + "}";
  field("lines", a + "]");
  a = "[";
  if (want("tubes"))
    for (const Tube& x : s.tubes)
      a += (a.size() > 1 ? "," : "") + std::string("{\"p\":") + pts(x.p) + ",\"c\":" + col(x.c) +
           ",\"r\":" + num(detail::tubeRadius(x, L)) + ",\"closed\":" + (x.closed ? "true" : "false") + "}";
  field("tubes", a + "]");
  a = "[";
  if (want("meshes"))
    for (const Mesh& x : s.meshes) {
      std::string t = "[";
      for (std::size_t k = 0; k < x.tri.size(); ++k)
        t += (k ? "," : "") + std::to_string(x.tri[k](0)) + "," + std::to_string(x.tri[k](1)) + "," +
             std::to_string(x.tri[k](2));
      a += (a.size() > 1 ? "," : "") + std::string("{\"v\":") + pts(x.v) + ",\"t\":" + t + "],\"c\":" + col(x.c) + "}";
    }
  field("meshes", a + "]");
  a = "[";
  if (want("arrows")) {
    auto arrow = [&](const Eigen::Vector3d& f, const Eigen::Vector3d& t, const Color& c, double r) {
      a += (a.size() > 1 ? "," : "") + std::string("{\"from\":") + vec(f) + ",\"to\":" + vec(t) + ",\"c\":" + col(c) +
           ",\"r\":" + num(r) + "}";
    };
    for (const Arrow& x : s.arrows) arrow(x.from, x.to, x.c, detail::arrowRadius(x, L));
    for (const Frame& x : s.frames) {  // as the renderer draws them: three arrows
      const double k = detail::frameScale(x, L);
      const Eigen::Vector3d o = x.pose.block<3, 1>(0, 3);
      const Color cs[3] = {palette::axisX, palette::axisY, palette::axisZ};
      for (int i = 0; i < 3; ++i)
        arrow(o, o + k * x.pose.block<3, 1>(0, i), cs[i], detail::frameArrowRadius * k);
    }
  }
  field("arrows", a + "]");
  a = "[";
  if (want("labels"))
    for (const Label& x : s.labels)
      a += (a.size() > 1 ? "," : "") + std::string("{\"at\":") + vec(x.at) + ",\"text\":" + str(x.text) +
           ",\"c\":" + col(x.c) + "}";
  field("labels", a + "]");
  return o;
}

std::string script(const std::string& title, const std::vector<std::pair<std::string, std::string>>& groups,
                   const Eigen::AlignedBox3d& box) {
  std::string s = "somaScene({\"title\":" + str(title) + ",\"bounds\":[" + vec(box.min()) + "," + vec(box.max()) +
                  "],\"groups\":[";
  bool first = true;
  for (const auto& [name, body] : groups) {
    if (body.empty()) continue;
    s += std::string(first ? "" : ",\n") + "{\"name\":" + str(name) + "," + body + "}";
    first = false;
  }
  return s + "]});\n";
}

}  // namespace

std::string sceneJs(const Scene& scene) {
  const double L = scene.characteristicLength();
  std::vector<std::pair<std::string, std::string>> groups;
  for (const char* k : {"tubes", "meshes", "points", "lines", "arrows", "labels"})
    groups.emplace_back(k, fields(scene, L, k));
  return script(scene.title, groups, scene.bounds());
}

std::string sceneJs(const std::vector<std::pair<std::string, Scene>>& named, const std::string& title) {
  Scene all;
  for (const auto& [n, s] : named) {
    for (const auto& x : s.points) all.add(x);
    for (const auto& x : s.polylines) all.add(x);
    for (const auto& x : s.tubes) all.add(x);
    for (const auto& x : s.meshes) all.add(x);
    for (const auto& x : s.frames) all.add(x);
    for (const auto& x : s.arrows) all.add(x);
    for (const auto& x : s.labels) all.add(x);
  }
  const double L = all.characteristicLength();
  std::vector<std::pair<std::string, std::string>> groups;
  for (const auto& [n, s] : named) groups.emplace_back(n, fields(s, L, "*"));
  return script(!title.empty() ? title : named.empty() ? std::string() : named.front().second.title, groups,
                all.bounds());
}

void writeSceneJs(const std::string& text, const std::filesystem::path& js) {
  std::ofstream out(js, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + js.string());
}

}  // namespace soma::render
