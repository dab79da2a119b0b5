// Parameter-space maps of 3R arms by cusp count, in parallel with TBB (the only TU using TBB).
#include "soma/geometry/cuspidal/parameter_map.hpp"

#include "soma/algebra/errors.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <memory>

namespace soma {

ParameterAxis parseParameterAxis(const std::string& spec) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t k = spec.find(':', start);
    parts.push_back(spec.substr(start, k == std::string::npos ? std::string::npos : k - start));
    if (k == std::string::npos) break;
    start = k + 1;
  }
  if (parts.size() != 4)
    throw InvalidInput("map axis '" + spec + "': expected NAME:MIN:MAX:N (e.g. a2:0.5:4:100)");
  ParameterAxis a;
  a.name = parts[0];
  if (a.name.size() != 2 || (a.name[0] != 'a' && a.name[0] != 'd') || a.name[1] < '1' || a.name[1] > '3')
    throw InvalidInput("map axis '" + spec + "': parameter '" + a.name +
                       "' is not a DH length of a 3R arm (a1, a2, a3, d1, d2, d3)");
  a.isA = a.name[0] == 'a';
  a.row = a.name[1] - '1';
  // std::from_chars, not std::stod: stod read "0x10" as 16 and " 1" as 1 (issue 24); from_chars
  // takes decimal text only (then nothing else may follow), and refuses a value beyond a double.
  auto number = [&](const std::string& s, const char* what) {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::general);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty() || !std::isfinite(v))
      throw InvalidInput("map axis '" + spec + "': " + what + " '" + s + "' is not a finite number");
    return v;
  };
  a.min = number(parts[1], "MIN");
  a.max = number(parts[2], "MAX");
  const double n = number(parts[3], "N");
  if (!(n >= 2) || n != std::floor(n) || n > 4096)
    throw InvalidInput("map axis '" + spec + "': N must be an integer from 2 to 4096, got '" + parts[3] + "'");
  a.n = int(n);
  if (!(a.max > a.min)) throw InvalidInput("map axis '" + spec + "': MAX must exceed MIN");
  return a;
}

SerialRobot<double> mapArm(const SerialRobot<double>& base, const ParameterAxis& x, double xv, const ParameterAxis& y,
                           double yv) {
  std::vector<DHRow<double>> rows = base.dhRows();
  auto set = [&](const ParameterAxis& p, double v) {
    if (p.row < 0 || p.row >= int(rows.size()))
      throw InvalidInput("map: parameter '" + p.name + "' names DH row " + std::to_string(p.row + 1) + " of a robot with " +
                         std::to_string(rows.size()) + " rows");
    (p.isA ? rows[p.row].a : rows[p.row].d) = v;
  };
  set(x, xv);
  set(y, yv);
  return SerialRobot<double>::fromDH(rows, base.convention(), base.base(), base.tool(), base.name());
}

// GF §5.2.3 (cusp counts over a family of 3R arms)
CuspMap cuspMap(const SerialRobot<double>& base, const ParameterAxis& x, const ParameterAxis& y, int threads) {
  (void)arm3RFrame(base);  // validates: exactly three revolute joints
  if (base.dhRows().size() != 3 || base.convention() == DHConvention::POE)
    throw InvalidInput("map: robot '" + base.name() + "' is not given by 3 DH rows (a map varies DH lengths)");
  if (x.name == y.name) throw InvalidInput("map: both axes vary '" + x.name + "'; pick two different lengths");
  const auto t0 = std::chrono::steady_clock::now();
  CuspMap m;
  m.x = x;
  m.y = y;
  m.counts.assign(std::size_t(x.n) * y.n, 0);
  std::atomic<int> escalated{0}, decoupled{0};
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  m.threads = int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  tbb::parallel_for(tbb::blocked_range<int>(0, x.n * y.n), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k < r.end(); ++k) {
      const int i = k % x.n, j = k / x.n;
      const CuspAnalysis<double> c = findCuspsAdaptive(mapArm(base, x, x.value(i), y, y.value(j)));
      m.counts[std::size_t(k)] = int(c.cusps.size());
      if (!c.conditioning.empty()) ++escalated;
      if (c.frame.decoupled) ++decoupled;
    }
  });
  m.escalated = escalated;
  m.decoupled = decoupled;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

}  // namespace soma
