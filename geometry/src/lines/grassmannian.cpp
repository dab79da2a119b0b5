// Grassmannian index sets (not a template; the templates of grassmannian.hpp are instantiated per
// scalar from grassmannian_impl.hpp). GF §6.8
#include "soma/geometry/lines/grassmannian.hpp"

namespace soma {

std::vector<std::vector<int>> pluckerIndexSets(int n, int m) {
  if (n < 1 || m < n) throw InvalidInput("pluckerIndexSets: need 1 ≤ n ≤ m");
  std::vector<std::vector<int>> out;
  std::vector<int> c(n);
  for (int i = 0; i < n; ++i) c[i] = i;
  while (true) {
    out.push_back(c);
    int i = n - 1;
    while (i >= 0 && c[i] == m - n + i) --i;
    if (i < 0) break;
    ++c[i];
    for (int j = i + 1; j < n; ++j) c[j] = c[j - 1] + 1;
  }
  return out;
}

}  // namespace soma
