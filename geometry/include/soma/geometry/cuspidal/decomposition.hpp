#pragma once
// Which 6R robots the cuspidality question decomposes for, and how (GF §5.2.3; DESIGN §3).
// A robot is cuspidal when two inverse-kinematic postures of one pose lie in one aspect (a
// connected component of det J ≠ 0 in the joint torus T⁶; Wenger, Parenti-Castelli & Innocenti).
//
// 1. Spherical wrist last (axes 4, 5, 6 meet in C; or first, axes 1, 2, 3, by reversing the chain,
//    which maps postures to postures and aspects to aspects). With C as reference point the
//    Jacobian is block-triangular, det J = det A(θ1, θ2, θ3) · w(θ5), A the 3 × 3 Jacobian of C
//    under joints 1–3 (the positioning 3R arm) and w = v4·(v5 × v6), a function of θ5 alone
//    (Siciliano et al. §3.3; Baili, Wenger & Chablat 2004 for orthogonal arms with a wrist). So
//    the aspects are products (aspect of the arm) × (θ5-arc of one sign of w). The wrist angle θ5
//    solves v4·Rot(v5, θ5) u = k, whose two roots have opposite signs of the derivative w: for a
//    fixed arm posture the two wrist postures lie in opposite θ5-arcs. Hence two postures of one
//    pose in one aspect have different arm postures of C in one arm aspect (the 6R cuspidal ⇒
//    the arm is), and conversely two arm postures of C in one arm aspect, each completed by its
//    wrist posture with w > 0, lie in one 6R aspect (the arm cuspidal ⇒ the 6R is). The 6R is
//    cuspidal exactly when its positioning 3R arm is, and the arm's verdict is exact (cusps.hpp:
//    Salunkhe, Spartalis, Capco, Chablat & Wenger 2022; arms whose IK splits into quadratics are
//    not cuspidal). The arm's witness path is lifted with the wrist holding the orientation.
// 2. Three parallel axes 2, 3, 4 followed by two meeting axes 5, 6 (the UR family; or reversed:
//    meeting axes 1, 2 followed by parallel 3, 4, 5). The IK is a chain of linear trigonometric
//    equations: n·(C − P1) = h in θ1 (n the parallel direction, C = axis 5 ∩ axis 6, known from
//    the pose, P1 on axis 1), n·z6 = v4·Rot(v5, θ5) v6 in θ5, then θ6 and θ2 + θ3 + θ4 unique,
//    and the planar elbow cos θ3 = k. Each of the three two-root steps has roots with opposite
//    signs of its derivative g (g1 = (z1 × n)·(C − P1), g5 = n·(z5 × z6), g3 = the planar elbow
//    area), and each g vanishes only where det J does (at a regular posture the inverse function
//    theorem keeps a real root under every small change of the pose; a double root of a step can
//    be pushed to no root by moving C along n, turning z6, or moving the elbow's target radially).
//    So the signs (g1, g5, g3) are constant on every aspect and differ between any two postures
//    of one pose: no two postures share an aspect, the robot is NOT cuspidal, for every length.
//    (Wenger's "posture parameters" of non-cuspidal robots; Borrel & Liégeois 1986.)
// Not decomposed (the witness search of witness6r.hpp decides only "cuspidal"): a wrist in the
// middle (axes 2, 3, 4 or 3, 4, 5 meeting: the positioning part is not a 3R arm of a point), three
// parallel axes not next to a meeting pair (their reduced problem is not a chain of quadratics),
// and general 6R robots. Joint limits are not part of either argument (the verdict is about the
// full joint torus, as for 3R arms).
#include "soma/geometry/cuspidal/witness.hpp"
#include "soma/geometry/cuspidal/witness6r.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <optional>
#include <string>

namespace soma {

enum class CuspidalDecompositionKind {
  None,            ///< no decomposition applies: search
  SphericalWrist,  ///< verdict = the positioning 3R arm's
  ParallelChain    ///< not cuspidal (the IK is a chain of two-root trigonometric steps)
};

struct CuspidalDecomposition {
  CuspidalDecompositionKind kind = CuspidalDecompositionKind::None;
  /// The chain was reversed to put the wrist last (or the parallel triple at 2–4).
  bool reversed = false;
  /// Axes of the wrist (or of the parallel triple), 1-based as in the robot's input: e.g. "4, 5, 6".
  std::string axes;
  /// One line: what was found and why it decides the question (or why nothing applies).
  std::string reason;
  /// SphericalWrist: the positioning 3R arm (joints 1–3 of the chain, tool point the wrist
  /// centre C, identity tool rotation; in the reversed chain's joints when `reversed`).
  std::optional<SerialRobot<double>> arm;
  /// SphericalWrist: the (possibly reversed) 6R robot the arm belongs to, and the wrist centre at home.
  std::optional<SerialRobot<double>> chain;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// Which decomposition applies to a 6R revolute robot (axes meeting within Tolerance::input()·L,
/// parallel within Tolerance::input()). Throws InvalidInput unless the robot has 6 revolute joints.
// GF §5.2.3, GF-5.2.3-cuspidal-posture-change
CuspidalDecomposition decomposeForCuspidality(const SerialRobot<double>& robot);

/// The 6R witness from a witness path of the positioning arm (SphericalWrist): the wrist holds the
/// orientation of the start posture (wrist angles `wristStart`, det J sign of the wrist kept)
/// along the arm's path; the result is re-checked densely in the 6R (≤ 0.002 rad steps) and given
/// in the robot's own joint order. `found` is false (with a note) when the orientation cannot be
/// held without a wrist singularity.
Witness6R liftArmWitness(const SerialRobot<double>& robot, const CuspidalDecomposition& d, const WitnessPath& w,
                         const Eigen::Vector3d& wristStart = Eigen::Vector3d(0.3, 1.1, -0.4));

}  // namespace soma
