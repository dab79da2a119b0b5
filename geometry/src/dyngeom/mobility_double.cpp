// Explicit instantiation of mobility (GF ch. 15) for double (one scalar per TU: compile time).
#define SOMA_DYNGEOM_MOBILITY_NONTEMPLATES  // kutzbachGrubler (not a template) lives here
#include "mobility_impl.hpp"

namespace soma {
SOMA_MOBILITY_INST(double)
}  // namespace soma
