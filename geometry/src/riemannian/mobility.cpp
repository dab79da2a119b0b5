// GF §15.2: the Kutzbach–Grübler count (not a template; the templates of mobility.hpp are in
// mobility_impl.hpp, instantiated per scalar by soma_instantiate).
#include "soma/geometry/riemannian/mobility.hpp"

#include "soma/algebra/errors.hpp"

#include <string>

namespace soma {

// GF §15.2 line 9645 (Hunt p. 33 for the multi-loop form)
int kutzbachGrubler(int links, int joints, int sumJointFreedoms, int d) {
  if (links < 1 || joints < 0 || sumJointFreedoms < 0)
    throw InvalidInput("kutzbachGrubler: links must be >= 1 and joints, freedoms >= 0");
  if (d != 3 && d != 6) throw InvalidInput("kutzbachGrubler: d must be 3 (planar/spherical) or 6 (spatial), got " + std::to_string(d));
  return d * (links - joints - 1) + sumJointFreedoms;
}

}  // namespace soma
