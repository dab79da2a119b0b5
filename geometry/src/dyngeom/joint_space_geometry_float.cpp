// Explicit instantiation of joint_space_geometry (GF ch. 15) for float (one scalar per TU: compile time).
#include "joint_space_geometry_impl.hpp"

namespace soma {
SOMA_JOINT_SPACE_GEOMETRY_INST(float)
}  // namespace soma
