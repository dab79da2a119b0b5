// SB's Cl(0,6,2) rigid-body dynamics: the scalar-independent part (SB §4's literal shuffle).
// The templates are instantiated one scalar per TU by soma_instantiate (cmake/SomaInstantiate.cmake) from clifford_dynamics_impl.hpp.
#include "soma/geometry/dynamics/clifford_dynamics.hpp"

#include <vector>

namespace soma::clifford_dynamics {

ShuffleTerm shuffleByDefinition(Blade b, Blade c) {
  // SB's generator order as library indices.
  constexpr int sbOrder[8] = {a1, a2, a3, a, e1, e2, e3, e};
  auto sbList = [&](Blade x) {
    std::vector<int> v;  // generators of x in SB's order (SB positions)
    for (int k = 0; k < 8; ++k)
      if (x & (Blade(1) << sbOrder[k])) v.push_back(k);
    return v;
  };
  auto parity = [](const std::vector<int>& seq) {
    int inv = 0;
    for (std::size_t i = 0; i < seq.size(); ++i)
      for (std::size_t j = i + 1; j < seq.size(); ++j)
        if (seq[i] > seq[j]) ++inv;
    return (inv & 1) ? -1 : 1;
  };
  // library blade = (sign) · (product of its generators in SB's order)
  auto libToSb = [&](Blade x) {
    std::vector<int> lib;
    for (int k : sbList(x)) lib.push_back(sbOrder[k]);
    return parity(lib);
  };
  const std::vector<int> bv = sbList(b), cv = sbList(c);
  const int n = 8, j = int(bv.size()), k = int(cv.size());
  if (j + k < n) return {};
  const int take = n - k;
  int coeff = 0;
  Blade result = 0;
  for (unsigned subset = 0; subset < (1u << j); ++subset) {
    if (std::popcount(subset) != take) continue;
    std::vector<int> sigma, first, rest;
    for (int t = 0; t < j; ++t)
      if (subset & (1u << t)) sigma.push_back(t), first.push_back(bv[std::size_t(t)]);
    for (int t = 0; t < j; ++t)
      if (!(subset & (1u << t))) sigma.push_back(t), rest.push_back(bv[std::size_t(t)]);
    // det(b_σ(1..n−k), c_1..c_k) in SB coordinates: a permutation of the basis or 0
    std::vector<int> cols = first;
    cols.insert(cols.end(), cv.begin(), cv.end());
    unsigned seen = 0;
    bool repeated = false;
    for (int x : cols) {
      if (seen & (1u << x)) repeated = true;
      seen |= 1u << x;
    }
    if (repeated) continue;
    Blade r = 0;
    std::vector<int> restLib;
    for (int x : rest) r |= Blade(1) << sbOrder[x], restLib.push_back(sbOrder[x]);
    // rest wedge in SB order = parity(restLib) · library blade r
    coeff += parity(sigma) * parity(cols) * parity(restLib);
    result = r;
  }
  coeff *= libToSb(b) * libToSb(c);
  return {coeff, coeff == 0 ? Blade(0) : result};
}

}  // namespace soma::clifford_dynamics
