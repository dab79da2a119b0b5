#pragma once
// A 6R robot given by its joint axes (POE, a URDF chain, modified DH) written as standard DH rows
// with a base and a tool transform, the form the general-6R solver takes (general_6r.hpp).
#include "soma/geometry/serial/serial_robot.hpp"

namespace soma {

/// The robot as six standard DH rows between a base and a tool transform, with the same joint
/// limits (GF §3.4: DH frames from the common normals of consecutive axes). Frame i-1 has z along
/// axis i; x_i runs along the common normal of axes i and i+1 (for parallel axes: the normal
/// through the previous origin, d_i = 0); frame 6 = frame 5 turned by joint 6. Joint offsets go
/// into the θ_i. Checked: the DH robot's FK equals the robot's at three joint vectors, else
/// InvalidInput. Needs 6 revolute joints (InvalidInput otherwise).
template <class S> SerialRobot<S> toStandardDH(const SerialRobot<S>& robot);

#define SOMA_STANDARD_DH_EXTERN(S) extern template SerialRobot<S> toStandardDH<S>(const SerialRobot<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_STANDARD_DH_EXTERN)
#undef SOMA_STANDARD_DH_EXTERN

}  // namespace soma
