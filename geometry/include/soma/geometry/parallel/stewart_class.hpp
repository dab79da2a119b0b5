#pragma once
// Combinatorial and geometric class of a Stewart–Gough platform, and the number of complex
// postures the literature gives for it (Faugère & Lazard 1995, "Combinatorial classes of parallel
// manipulators", Mech. Mach. Theory 30; Merlet, "Parallel Robots", 2nd ed. 2006, §4.5).
// Counts tabulated here (only those we are sure of; any other class has no expected count and
// its solve is never certified):
//   6-6, base and/or platform planar or not: 40 (Raghavan 1993; Husty 1996; Lazard 1992 for planar);
//   6-3 and 3-6 (joints coincide in pairs on one side): 16 (Innocenti & Parenti-Castelli 1990;
//     GF §11.5.2, GF-11.5.2-6-3-stewart-sixteen);
//   3-3 octahedral (each base joint meets two platform joints, no two legs on the same pair):
//     16 (Nanua, Waldron & Murthy 1990).
// Architecturally singular: all joints of one side on a line (the platform turns about that line
// with every leg length fixed: a self-motion for any lengths; Merlet §6.3.4). Refused.
#include "soma/algebra/safe_norm.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/stewart.hpp"

#include <array>
#include <optional>
#include <string>

namespace soma {

/// The class of a platform (classifyStewart).
struct StewartClassification {
  int base_distinct = 6;      ///< distinct base joint centres (coincident within tol count once)
  int platform_distinct = 6;  ///< distinct platform joint centres
  bool base_planar = false, platform_planar = false;
  bool base_collinear = false, platform_collinear = false;
  /// Planar base and platform with |q_i − q_j| = k |p_i − p_j| for all i, j (similar hexagons).
  bool similar = false;
  /// "6-6", "6-3", "3-6", "3-3 octahedral", "5-4", … (base distinct − platform distinct).
  std::string name;
  /// Complex postures for a generic platform of the class (see the header); nullopt: not tabulated.
  std::optional<int> expected_count;
  /// Non-empty when the platform is architecturally singular: the reason (the solve refuses it).
  std::string singular_reason;
};

namespace stewart_class_detail {
template <class S> struct Side {
  int distinct = 0;
  std::array<int, 6> cluster{};  // index of the cluster of joint i
  bool planar = false, collinear = false;
};

template <class S> Side<S> side(const std::array<Vec3<S>, 6>& x, const S& tol) {
  Side<S> s;
  for (int i = 0; i < 6; ++i) {
    s.cluster[i] = -1;
    for (int j = 0; j < i; ++j)
      if (safeNorm(Vec3<S>(x[i] - x[j])) <= tol) {
        s.cluster[i] = s.cluster[j];
        break;
      }
    if (s.cluster[i] < 0) s.cluster[i] = s.distinct++;
  }
  // The farthest pair (a, b), then c farthest from the line ab: collinear when that distance is
  // within tol; else the plane abc, planar when every joint is within tol of it.
  int a = 0, b = 0;
  S best = S(0);
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const S d = safeNorm(Vec3<S>(x[i] - x[j]));
      if (d > best) best = d, a = i, b = j;
    }
  if (best <= tol) {  // all one point (validateStewartPlatform refuses it)
    s.planar = s.collinear = true;
    return s;
  }
  const Vec3<S> u = Vec3<S>(x[b] - x[a]) / best;
  int c = a;
  S far = S(0);
  for (int i = 0; i < 6; ++i) {
    const S d = safeNorm(Vec3<S>(Vec3<S>(x[i] - x[a]).cross(u)));
    if (d > far) far = d, c = i;
  }
  if (far <= tol) {
    s.planar = s.collinear = true;
    return s;
  }
  Vec3<S> n = Vec3<S>(x[b] - x[a]).cross(Vec3<S>(x[c] - x[a]));
  n /= safeNorm(n);
  s.planar = true;
  for (int i = 0; i < 6; ++i) {
    using std::abs;
    if (abs(n.dot(Vec3<S>(x[i] - x[a]))) > tol) s.planar = false;
  }
  return s;
}
}  // namespace stewart_class_detail

/// The class of P. Two joints coincide, three are collinear, six coplanar when within
/// tol = √eps(S) · stewartScale(P) (the threshold of the 6-3 test of the solver).
template <class S> StewartClassification classifyStewart(const StewartPlatform<S>& P) {
  using namespace stewart_class_detail;
  const S tol = Tolerance<S>::sqrtEpsilon() * stewartScale<S>(P);
  const Side<S> B = side<S>(P.base, tol), Q = side<S>(P.platform, tol);
  StewartClassification c;
  c.base_distinct = B.distinct;
  c.platform_distinct = Q.distinct;
  c.base_planar = B.planar;
  c.platform_planar = Q.planar;
  c.base_collinear = B.collinear;
  c.platform_collinear = Q.collinear;
  c.name = std::to_string(B.distinct) + "-" + std::to_string(Q.distinct);
  if (B.planar && Q.planar && !B.collinear && !Q.collinear) {
    // |q_i − q_j| = k |p_i − p_j| with k from the farthest base pair.
    S k = S(-1), dmax = S(0);
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j) {
        const S d = safeNorm(Vec3<S>(P.base[i] - P.base[j]));
        if (d > dmax) dmax = d, k = safeNorm(Vec3<S>(P.platform[i] - P.platform[j])) / d;
      }
    c.similar = true;
    for (int i = 0; i < 6 && c.similar; ++i)
      for (int j = i + 1; j < 6; ++j) {
        using std::abs;
        const S dp = safeNorm(Vec3<S>(P.base[i] - P.base[j])), dq = safeNorm(Vec3<S>(P.platform[i] - P.platform[j]));
        if (abs(dq - k * dp) > tol) {
          c.similar = false;
          break;
        }
      }
  }
  // Pairs of coincident joints: for 6-3 every platform cluster holds two joints; 3-3 octahedral:
  // every cluster holds two and no two legs join the same base and platform cluster.
  const auto pairsOnly = [](const Side<S>& s) {
    std::array<int, 6> n{};
    for (int i = 0; i < 6; ++i) ++n[s.cluster[i]];
    for (int k = 0; k < s.distinct; ++k)
      if (n[k] != 2) return false;
    return true;
  };
  if (B.collinear || Q.collinear) {
    c.singular_reason = std::string("the ") + (B.collinear ? "base" : "platform") +
                        " joints are collinear: the platform turns about that line with all six leg lengths "
                        "fixed (a self-motion; architecturally singular)";
  } else if (B.distinct == 6 && Q.distinct == 6) {
    if (!c.similar) c.expected_count = 40;
  } else if ((B.distinct == 6 && Q.distinct == 3 && pairsOnly(Q)) || (B.distinct == 3 && Q.distinct == 6 && pairsOnly(B))) {
    c.expected_count = 16;
  } else if (B.distinct == 3 && Q.distinct == 3 && pairsOnly(B) && pairsOnly(Q)) {
    bool octahedral = true;
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j)
        if (B.cluster[i] == B.cluster[j] && Q.cluster[i] == Q.cluster[j]) octahedral = false;
    if (octahedral) {
      c.name = "3-3 octahedral";
      c.expected_count = 16;
    }
  }
  return c;
}

}  // namespace soma
