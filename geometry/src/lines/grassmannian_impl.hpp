// Explicit instantiations of the Grassmannian embedding for one scalar (DESIGN §2). GF §6.8
#pragma once
#include "soma/geometry/lines/grassmannian.hpp"

namespace soma {

#define SOMA_INSTANTIATE_GRASSMANNIAN(S)                                                                       \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerEmbedding<S>(const Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>&); \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> pluckerRelationsG2<S>(const Eigen::Matrix<S, Eigen::Dynamic, 1>&, int);
}  // namespace soma
