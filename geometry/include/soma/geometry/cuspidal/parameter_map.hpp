#pragma once
// Parameter-space maps of 3R arms (GF §5.2.3; Baili, Wenger, Chablat, "A classification of 3R
// orthogonal manipulators by the topology of their workspace", ICRA 2004): the number of cusp
// points of every arm of a two-parameter family, varying two DH lengths of a base arm. Each arm
// is classified by findCuspsAdaptive (algebraic, with precision escalation); the cells run in
// parallel with TBB (TBB stays in parameter_map.cpp: no TBB type in this header). Runs in double.
#include "soma/geometry/cuspidal/cusps.hpp"

#include <string>
#include <vector>

namespace soma {

/// One axis of a map: a DH length of one row ("a1".."a3", "d1".."d3" — standard or modified DH as
/// the base robot), sampled at n ≥ 2 equally spaced values from min to max inclusive.
struct ParameterAxis {
  std::string name;  ///< "a2", "d3", ...
  bool isA = true;   ///< a (link length) or d (offset)
  int row = 0;       ///< 0-based DH row
  double min = 0, max = 1;
  int n = 2;
  double value(int i) const { return min + (max - min) * double(i) / double(n - 1); }
};

/// Parse "a2:0.5:4:100" (name:min:max:n). Throws InvalidInput naming the defect.
ParameterAxis parseParameterAxis(const std::string& spec);

struct CuspMap {
  ParameterAxis x, y;
  std::vector<int> counts;  ///< cusp count per arm, counts[j * x.n + i] (i along x, j along y)
  int escalated = 0;        ///< arms re-solved in float128 or mpfr
  int decoupled = 0;        ///< arms whose IK splits into quadratics (0 cusps by structure)
  int threads = 0;          ///< TBB's concurrency used
  double seconds = 0;       ///< wall time
  int count(int i, int j) const { return counts[std::size_t(j) * x.n + i]; }
  /// histogram()[c]: the number of arms with c cusps, c = 0 .. the largest count.
  std::vector<int> histogram() const {
    int maxCount = 0;
    for (int c : counts) maxCount = c > maxCount ? c : maxCount;
    std::vector<int> h(std::size_t(maxCount) + 1, 0);
    for (int c : counts) ++h[std::size_t(c)];
    return h;
  }
};

/// The robot of one map cell: `base` (built from DH rows) with x's and y's lengths replaced.
SerialRobot<double> mapArm(const SerialRobot<double>& base, const ParameterAxis& x, double xv,
                           const ParameterAxis& y, double yv);

/// Classify the x.n × y.n arms by number of cusps, in parallel (threads ≤ 0: TBB's default).
/// Throws InvalidInput unless `base` is a 3R arm given by DH rows and x, y name different lengths.
// GF §5.2.3 (cusp counts over a family; Baili–Wenger–Chablat 2004 classification of orthogonal 3R arms)
CuspMap cuspMap(const SerialRobot<double>& base, const ParameterAxis& x, const ParameterAxis& y, int threads = 0);

}  // namespace soma
