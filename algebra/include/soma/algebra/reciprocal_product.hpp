#pragma once
// The reciprocal product of two 6-vectors (ω, v): lines in Plücker coordinates, screws, twists.
#include "soma/algebra/scalar.hpp"

namespace soma {

/// ω_a·v_b + v_a·ω_b = aᵀQ₀b (the Klein form). Two lines meet (possibly at infinity) iff it is 0
/// (GF §6.1, GF-6.1-meet-condition); two screws are reciprocal iff it is 0 (GF §8.1,
/// GF-8.1-reciprocal-system).
template <class S> S reciprocalProduct(const Vec6<S>& a, const Vec6<S>& b) {
  return a.template head<3>().dot(b.template tail<3>()) + a.template tail<3>().dot(b.template head<3>());
}

}  // namespace soma
