#pragma once
// Combinatorial and geometric class of a Stewart–Gough platform, and the number of complex
// postures for it (Faugère & Lazard 1995, "Combinatorial classes of parallel manipulators", Mech.
// Mach. Theory 30; Merlet, "Parallel Robots", 2nd ed. 2006, §4.5). The class is the leg–joint
// incidence (which legs share a base or a platform joint) up to renumbering and swapping base and
// platform: stewartPattern. Counts tabulated here (kStewartClassCounts; any other class has no
// expected count and its solve is never certified):
//   6-6, base and/or platform planar or not: 40 (Raghavan 1993; Husty 1996; Lazard 1992 for planar);
//   6-3 and 3-6 (joints coincide in pairs on one side): 16 (Innocenti & Parenti-Castelli 1990;
//     GF §11.5.2, GF-11.5.2-6-3-stewart-sixteen);
//   3-3 octahedral (each base joint meets two platform joints, no two legs on the same pair):
//     16 (Nanua, Waldron & Murthy 1990);
//   planar base and platform both 3-fold symmetric with the same leg permutation (a standard
//     hexapod): 28, numerical (homotopy and PHCpack); general planar ones keep 40;
//   6-5 40; 6-4 32 (two pairs) or 16 (three legs on a joint); 5-5 40 (the two pairs share a leg)
//     or 24; 4-4 24, 16 or 8 by pattern; 6-3 with three legs on a joint 8; the non-octahedral 3-3
//     that are not singular 8: Faugère & Lazard enumerate these classes but we could not read their
//     counts, so each was determined here numerically — soma's parameter homotopy and PHCpack's
//     total-degree blackbox solver agree on a random platform of every pattern
//     (study SOMA-11.5-stewart-classes).
// Architecturally singular (refused, the reason names the defect): all joints of one side on a
// line (the platform turns about that line with every leg length fixed: a self-motion; Merlet
// §6.3.4); two legs joining the same base joint to the same platform joint (a repeated leg: five
// constraints); four or more legs meeting at one joint (three fix it, the others are redundant);
// three legs meeting at one base joint and the other three at one platform joint (the platform
// turns about the line through the two joints; both solvers find no isolated posture).
#include "soma/algebra/safe_norm.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/stewart.hpp"

#include <algorithm>
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
  /// Planar base and platform that a third of a turn about each plane's centre maps onto
  /// themselves with the same permutation of the legs (a 3-fold symmetric hexapod).
  bool threefold = false;
  /// "6-6", "6-3", "3-6", "3-3 octahedral", "5-4", … (base distinct − platform distinct).
  std::string name;
  /// The leg–joint incidence up to renumbering the legs and the joints and swapping base and
  /// platform (stewartPattern): "aabbcd|abcdef" = legs 1, 2 share a joint, legs 3, 4 another, on
  /// one side; six distinct joints on the other.
  std::string pattern;
  /// Complex postures for a generic platform of the class (see the header); nullopt: not tabulated.
  std::optional<int> expected_count;
  /// Non-empty when the platform is architecturally singular: the reason (the solve refuses it).
  std::string singular_reason;
};

/// One tabulated class: its pattern (stewartPattern), its name and its number of complex postures.
struct StewartClassCount {
  const char* pattern;
  const char* name;
  int count;
  const char* source;
};

/// The tabulated classes (see the header for the sources).
inline constexpr StewartClassCount kStewartClassCounts[] = {
    {"abcdef|abcdef", "6-6", 40, "Raghavan 1993; Ronga & Vust, Lazard, Mourrain 1992-93"},
    {"aabbcc|abcdef", "6-3", 16, "Innocenti & Parenti-Castelli 1990; GF §11.5.2"},
    {"aabbcc|abacbc", "3-3 octahedral", 16, "Nanua, Waldron & Murthy 1990"},
    // Determined numerically (soma's homotopy = PHCpack's count, SOMA-11.5-stewart-classes):
    {"aabcde|abcdef", "6-5", 40, "numerical: homotopy and PHCpack"},
    {"aabbcd|abcdef", "6-4", 32, "numerical: homotopy and PHCpack"},
    {"aaabcd|abcdef", "6-4", 16, "numerical: homotopy and PHCpack"},
    {"aabcde|abacde", "5-5", 40, "numerical: homotopy and PHCpack"},
    {"aabcde|abccde", "5-5", 24, "numerical: homotopy and PHCpack"},
    {"aabbcd|ababcd", "4-4", 16, "numerical: homotopy and PHCpack"},
    {"aabbcd|abacbd", "4-4", 24, "numerical: homotopy and PHCpack"},
    {"aabbcd|abacdd", "4-4", 16, "numerical: homotopy and PHCpack"},
    {"aabbcd|abcdac", "4-4", 16, "numerical: homotopy and PHCpack"},
    {"aaabcd|abcabd", "4-4", 16, "numerical: homotopy and PHCpack"},
    {"aaabcd|abcaad", "4-4", 8, "numerical: homotopy and PHCpack"},
    {"aaabcd|abcadd", "4-4", 8, "numerical: homotopy and PHCpack"},
    {"aaabbc|abcdef", "6-3", 8, "numerical: homotopy and PHCpack"},
    {"aaabbc|abcaba", "3-3", 8, "numerical: homotopy and PHCpack"},
    {"aaabbc|abcabc", "3-3", 8, "numerical: homotopy and PHCpack"},
};

/// The leg–joint incidence of a platform as a canonical string: b[i], q[i] are the indices of the
/// base and platform joint (cluster) of leg i; the string is the lexicographically least of
/// "<base>|<platform>" (each side's joints lettered a, b, … in leg order) over every renumbering of
/// the six legs and both orders of the sides. Two platforms have the same pattern iff one's legs
/// can be renumbered (and base and platform swapped) to give the other's incidence.
inline std::string stewartPattern(const std::array<int, 6>& b, const std::array<int, 6>& q) {
  std::array<int, 6> perm{0, 1, 2, 3, 4, 5};
  const auto letters = [&](const std::array<int, 6>& c) {
    std::array<int, 6> map;
    map.fill(-1);
    int next = 0;
    std::string s;
    for (int k = 0; k < 6; ++k) {
      int& m = map[static_cast<std::size_t>(c[static_cast<std::size_t>(perm[k])])];
      if (m < 0) m = next++;
      s += static_cast<char>('a' + m);
    }
    return s;
  };
  std::string best;
  do {
    const std::string x = letters(b), y = letters(q);
    for (const std::string& k : {x + "|" + y, y + "|" + x})
      if (best.empty() || k < best) best = k;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

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
/// The permutation of the joints induced by a rotation through +120° about the normal of the
/// (planar, not collinear) side through its centroid; nullopt when some joint maps onto none.
template <class S> std::optional<std::array<int, 6>> thirdTurn(const std::array<Vec3<S>, 6>& x, const S& tol) {
  Vec3<S> c = Vec3<S>::Zero();
  for (const auto& v : x) c += v;
  c /= S(6);
  int a = 0, b = 0, k = 0;
  S best = S(0), far = S(0);
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const S d = safeNorm(Vec3<S>(x[i] - x[j]));
      if (d > best) best = d, a = i, b = j;
    }
  const Vec3<S> u = Vec3<S>(x[b] - x[a]) / best;
  for (int i = 0; i < 6; ++i) {
    const S d = safeNorm(Vec3<S>(Vec3<S>(x[i] - x[a]).cross(u)));
    if (d > far) far = d, k = i;
  }
  Vec3<S> n = Vec3<S>(x[b] - x[a]).cross(Vec3<S>(x[k] - x[a]));
  n /= safeNorm(n);
  using std::sqrt;
  const S cs = S(-1) / S(2), sn = sqrt(S(3)) / S(2);
  std::array<int, 6> perm{};
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> v = x[i] - c;
    const Vec3<S> w = c + cs * v + sn * n.cross(v) + (S(1) - cs) * n.dot(v) * n;
    perm[i] = -1;
    for (int j = 0; j < 6 && perm[i] < 0; ++j)
      if (safeNorm(Vec3<S>(w - x[j])) <= tol) perm[i] = j;
    if (perm[i] < 0) return std::nullopt;
  }
  return perm;
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
  c.pattern = stewartPattern(B.cluster, Q.cluster);
  // Combinatorial singularities: a repeated leg, or four legs (or more) on one joint.
  std::string repeated, crowded;
  for (int i = 0; i < 6 && repeated.empty(); ++i)
    for (int j = i + 1; j < 6; ++j)
      if (B.cluster[i] == B.cluster[j] && Q.cluster[i] == Q.cluster[j]) {
        repeated = "legs " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                   " join the same base joint to the same platform joint: a repeated leg leaves five independent "
                   "constraints (a self-motion, or no posture when their lengths differ; architecturally singular)";
        break;
      }
  for (const auto* side : {&B, &Q}) {
    for (int k = 0; k < side->distinct && crowded.empty(); ++k) {
      std::string legs;
      int n = 0;
      for (int i = 0; i < 6; ++i)
        if (side->cluster[i] == k) legs += (n++ ? ", " : "") + std::to_string(i + 1);
      if (n >= 4)
        crowded = "legs " + legs + " meet at one " + (side == &B ? "base" : "platform") +
                  " joint: three of them fix its position, the others are redundant (a self-motion, or no posture "
                  "when their lengths disagree; architecturally singular)";
    }
  }
  // Three legs on one base joint and the other three on one platform joint: the platform holds the
  // base joint's point fixed and the base holds the platform joint fixed, a line of fixed points.
  std::string hinge;
  for (int kb = 0; kb < B.distinct && hinge.empty(); ++kb)
    for (int kq = 0; kq < Q.distinct && hinge.empty(); ++kq) {
      int nb = 0, nq = 0;
      bool split = true;
      for (int i = 0; i < 6; ++i) {
        const bool inB = B.cluster[i] == kb, inQ = Q.cluster[i] == kq;
        nb += inB;
        nq += inQ;
        split = split && inB != inQ;
      }
      if (split && nb == 3 && nq == 3)
        hinge = "three legs meet at one base joint and the other three at one platform joint: the platform turns about "
                "the line through those two joints with every leg length fixed (a self-motion; architecturally singular)";
    }
  if (B.collinear || Q.collinear) {
    c.singular_reason = std::string("the ") + (B.collinear ? "base" : "platform") +
                        " joints are collinear: the platform turns about that line with all six leg lengths "
                        "fixed (a self-motion; architecturally singular)";
  } else if (!repeated.empty()) {
    c.singular_reason = repeated;
  } else if (!crowded.empty()) {
    c.singular_reason = crowded;
  } else if (!hinge.empty()) {
    c.singular_reason = hinge;
  } else if (B.planar && Q.planar && B.distinct == 6 && Q.distinct == 6 && !c.similar &&
             (c.threefold = [&] {
                const auto pb = thirdTurn<S>(P.base, tol), pq = thirdTurn<S>(P.platform, tol);
                if (!pb || !pq) return false;
                std::array<int, 6> inv{};
                for (int i = 0; i < 6; ++i) inv[(*pq)[i]] = i;
                for (int i = 0; i < 6; ++i)
                  if ((*pb)[i] == i) return false;
                return *pb == *pq || *pb == inv;
              }())) {
    // A 3-fold symmetric planar hexapod (the standard hexapod's semi-regular hexagons): 28,
    // determined numerically (homotopy and PHCpack, SOMA-11.5-stewart-classes).
    c.name = "6-6 planar 3-fold symmetric";
    c.expected_count = 28;
  } else if (!c.similar) {
    for (const auto& k : kStewartClassCounts)
      if (c.pattern == k.pattern) {
        c.expected_count = k.count;
        if (std::string(k.name) == "3-3 octahedral") c.name = k.name;
      }
  }
  return c;
}

}  // namespace soma
