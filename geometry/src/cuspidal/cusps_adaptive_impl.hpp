// The cluster parameter that decides the precision escalation of the cusp points (GF §5.2.3; see
// cusps.hpp), for one scalar; findCuspsAdaptive itself is in cusps_adaptive.cpp.
#pragma once
#include "soma/geometry/cuspidal/cusps.hpp"

#include <algorithm>

namespace soma {

template <class S> S cuspClusterParameter(const Arm3RFrame<S>& f) {
  const S a1 = f.a1 / f.scale;
  return std::min<S>(f.s1 * f.s1, S(4) * a1 * a1);
}

template <class S> bool cuspsIllConditioned(const Arm3RFrame<S>& f) {
  return !f.decoupled && cuspClusterParameter(f) <= Tolerance<S>::sqrtEpsilon();
}

#define SOMA_INSTANTIATE_CUSPS_ADAPTIVE(S)                                                     \
  template S cuspClusterParameter<S>(const Arm3RFrame<S>&);                                   \
  template bool cuspsIllConditioned<S>(const Arm3RFrame<S>&);

}  // namespace soma
