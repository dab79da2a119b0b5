#pragma once
// The planar 4-bar linkage (GF §5.4, Fig. 5.5): ground pivots c1, c4, crank c1–c2, coupler
// c2–c3, rocker c4–c3. Grashof classification (Barker's names, change-point, parallelogram and
// deltoid forms), position analysis in both assembly modes, the circuits of the configuration
// curve traced continuously (one branch through a full cycle, through change points along the
// smooth branch), the coupler curve's degree-6 equation, the coupler motion's jet at any crank
// angle (so every GF §5.3 invariant of the coupler motion), and the book's §5.4 formulas.
#include "soma/geometry/planar/instant_invariants.hpp"

#include <optional>
#include <string>
#include <vector>

namespace soma::planar {

enum class GrashofType {
  CrankRocker,    ///< Grashof, crank (input) shortest: crank turns fully, rocker oscillates
  DoubleCrank,    ///< Grashof, ground shortest (drag link)
  RockerCrank,    ///< Grashof, rocker (output) shortest
  DoubleRocker,   ///< Grashof, coupler shortest: only the coupler turns fully
  TripleRocker,   ///< non-Grashof: no link turns fully relative to another
  ChangePoint     ///< s + l = p + q: the links can become collinear (a node of the configuration curve)
};
std::string grashofName(GrashofType t);

template <class S> struct GrashofClass {
  GrashofType type = GrashofType::CrankRocker;
  S margin{0};              ///< (p + q) − (s + l): > 0 Grashof, < 0 non-Grashof, ≈ 0 change point
  int shortest = 0, longest = 0;  ///< link index: 0 ground, 1 crank, 2 coupler, 3 rocker
  bool parallelogram = false;     ///< opposite links equal (ground = coupler, crank = rocker)
  bool deltoid = false;           ///< adjacent links equal in pairs (kite)
  bool crankRotates = false;      ///< the input crank turns fully relative to the ground
};

template <class S> struct FourBarPose {
  S theta1{0}, theta4{0}, psi{0};  ///< crank angle, rocker angle (world), coupler angle (c2→c3)
  Vec2<S> c2 = Vec2<S>::Zero(), c3 = Vec2<S>::Zero();
  S h{0};    ///< signed height of c3 over the diagonal c2→c4 (sign = assembly mode)
  int mode = 1;  ///< +1: c3 left of c2→c4, −1: right (0 at a branch point)
  SE2<S> coupler;  ///< body frame of the coupler: origin c2, x axis along c2→c3
};

/// Derived quantities of a configuration with the crank driven at ω₁, ω̇₁ (GF §5.4).
template <class S> struct FourBarRates {
  S omega{0}, omega4{0}, omegaDot{0};
  Vec3<S> instantCentre = Vec3<S>::Zero();  ///< homogeneous: lines c1c2 ∩ c4c3
};

template <class S> class FourBar {
 public:
  /// Ground pivots c1, c4; link lengths; the coupler point in the coupler frame (origin c2,
  /// x along c2→c3). Throws InvalidInput for a non-positive or non-finite length, c1 = c4, or a
  /// linkage that cannot be assembled in any crank angle.
  FourBar(const Vec2<S>& c1, const Vec2<S>& c4, const S& crank, const S& coupler, const S& rocker,
          const Vec2<S>& couplerPoint = Vec2<S>::Zero());
  /// From the four joints of one configuration (lengths measured; the coupler point in world).
  static FourBar fromJoints(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4,
                            const Vec2<S>& couplerPointWorld);

  const Vec2<S>& c1() const { return c1_; }
  const Vec2<S>& c4() const { return c4_; }
  S ground() const { return l0_; }
  S crank() const { return l1_; }
  S coupler() const { return l2_; }
  S rocker() const { return l3_; }
  const Vec2<S>& couplerPoint() const { return pc_; }

  GrashofClass<S> classify() const;

  /// Position analysis at crank angle θ₁ (world angle of c2 − c1) in assembly mode ±1;
  /// empty when the loop does not close there. At a branch point both modes give the same pose.
  std::optional<FourBarPose<S>> solve(const S& theta1, int mode) const;
  /// The coupler point of a pose in world coordinates.
  Vec2<S> couplerPointWorld(const FourBarPose<S>& p) const { return p.coupler.act(pc_); }

  /// Number of circuits (closed branches of the configuration curve) and their traversal by a
  /// parameter s ∈ [0, period): continuous, periodic, through turning points (where the mode
  /// flips) and change-point nodes (along the smooth branch).
  int circuitCount() const;
  S circuitPeriod(int circuit) const;
  FourBarPose<S> circuitPose(int circuit, const S& s) const;
  std::vector<FourBarPose<S>> traceCircuit(int circuit, int samples) const;
  /// The circuit a pose lies on (poses from solve() or circuitPose()).
  int circuitOf(const FourBarPose<S>& p) const;
  /// Crank angle limits of the assembly (empty: the crank turns fully), as world angles.
  std::vector<std::pair<S, S>> crankIntervals() const;

  /// Jet of the coupler motion (body frame: origin c2, x along c2→c3) when the crank follows
  /// θ₁(t) with derivatives law = (θ₁, θ̇₁, θ̈₁, θ⃛₁, θ⁗₁). Throws InvalidInput at a branch point
  /// (h = 0: the derivatives are infinite).
  MotionJet<S> couplerJet(const S& theta1, int mode, const std::array<S, kJetSize>& law) const;

  /// The coupler curve: the algebraic curve of degree 6 traced by the coupler point (both
  /// circuits), by eliminating the coupler angle from the two circle conditions.
  Poly2<S> couplerCurve() const;

  // ---- GF §5.4 formulas (joints at one configuration) ------------------------------------------
  /// Intersection of the lines c1c2 and c4c3, homogeneous (W = 0: parallel, the coupler translates).
  static Vec3<S> instantCentre(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4);
  /// (ω/ω₁, ω₄/ω₁) by the determinant ratios of GF §5.4. Throws InvalidInput at a dead centre.
  static std::pair<S, S> velocityRatios(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4);
  /// ω̇ of the coupler by the book's closed form (GF §5.4, GF-5.4-fourbar-angular-acceleration).
  static S omegaDot(const Vec2<S>& c1, const Vec2<S>& c2, const Vec2<S>& c3, const Vec2<S>& c4, const S& w1, const S& w1dot);
  /// ṙ from 2ω²ṙ = (ω̇ω_i − ωω̇_i)(c_b − c_a) + (ωω_i² − ω²ω_i)E₂(c_b − c_a) (crank: a = c1, b = c2).
  static Vec2<S> poleVelocity(const Vec2<S>& ca, const Vec2<S>& cb, const S& w, const S& wdot, const S& wi, const S& widot);

 private:
  struct Range {
    int kind = 0;  // 0 full, 1 interval through α = 0, 2 interval through π, 3 two intervals
    S A{0}, B{0};
    bool nodeAt0 = false, nodeAtPi = false;
  };
  Range range() const;
  FourBarPose<S> poseAt(const S& alpha, const S& hSign) const;  // hSign·|h|
  Vec2<S> c1_, c4_, pc_;
  S l0_, l1_, l2_, l3_, gamma_;
};

}  // namespace soma::planar
