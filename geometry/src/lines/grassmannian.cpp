// Grassmannian index sets and explicit instantiations (DESIGN §2). GF §6.8
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

#define SOMA_GRASS_INSTANTIATE(S)                                                                       \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerEmbedding<S>(const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>&); \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerRelationsG2<S>(const Eigen::Matrix<S, Eigen::Dynamic, 1>&, int);
SOMA_FOR_EACH_SCALAR(SOMA_GRASS_INSTANTIATE)
#undef SOMA_GRASS_INSTANTIATE
}  // namespace soma
