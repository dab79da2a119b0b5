// Studies of GF §15.2 (double): mobility of single loops — Kutzbach–Grübler, the completion group,
// the subalgebra (totally geodesic) criterion, Table 15.1, the Bennett loop as the paradoxical
// exception, the flat 4-bar, and the self-motions of a singular robot (erratum E15.13 is OCR).
#include "gf15_common.hpp"

#include <Eigen/SVD>

namespace soma::studies::gf15::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

std::vector<V6> planar4R() {
  const V3 z = V3::UnitZ();
  return {lineScrew(z, V3(0, 0, 0)), lineScrew(z, V3(1, 0, 0)), lineScrew(z, V3(1, 2, 0)), lineScrew(z, V3(-1, 1, 0))};
}
std::vector<V6> spherical4R() {  // four axes through the origin
  return {lineScrew(V3(1, 0, 0), V3::Zero()), lineScrew(V3(0, 1, 0), V3::Zero()), lineScrew(V3(0, 0.6, 0.8), V3::Zero()),
          lineScrew(V3(0.48, 0.6, 0.64), V3::Zero())};
}

void definitions(Context& ctx) {
  // the flat 4-bar: links 1, 1, 1 along x and the ground 3 — all joints on the x-axis
  const V3 z = V3::UnitZ();
  const std::vector<V6> flat = {lineScrew(z, V3(0, 0, 0)), lineScrew(z, V3(1, 0, 0)), lineScrew(z, V3(2, 0, 0)), lineScrew(z, V3(3, 0, 0))};
  ctx.checkEqual("joint screws (planar: (1, 0, −x_i)) span a 2-system", 2, screwSystemDimension(flat));
  ctx.checkEqual("infinitesimal mobility of the flat 4-bar", 2, infinitesimalMobility(flat));
  // configuration space: crank angle φ at joint 1 (ground from (0,0) to (3,0)); the coupler must join
  // (cos φ, sin φ) to the rocker of length 1 about (3, 0): |P − (3,0)| ≤ 2 is needed
  int feasible = 0;
  for (int k = -1000; k <= 1000; ++k) {
    const double phi = k * 1e-3;
    const double d = std::hypot(std::cos(phi) - 3, std::sin(phi));
    if (d <= 2 + 1e-15) ++feasible;
  }
  ctx.checkEqual("crank angles in [−1, 1] rad (step 1e-3) at which the loop closes: only φ = 0", 1, feasible);
  const LoopTrace<double> t = traceLoop<double>(flat, 0.05, 5);
  ctx.checkEqual("kernel dimension 2 at the flat configuration (no 1-dim solution curve to trace)", 2, t.kernelDimension);
  ctx.note("Global dimension 0 (a single real point) with infinitesimal mobility 2: infinitesimal mobility is only an upper bound.");
}

void kutzbach(Context& ctx) {
  auto g = std::mt19937_64(1521);
  ctx.checkEqual("single loop, n = 7 joints: m = n − 6", 1, kutzbachGrubler(7, 7, 7));
  ctx.checkEqual("single loop, n = 5: m = −1", -1, kutzbachGrubler(5, 5, 5));
  const auto s7 = randomScrews(g, 7);
  const LoopTrace<double> t7 = traceLoop<double>(s7, 0.05, 30);
  ctx.checkEqual("random 7R loop: kernel of Σθ̇_is_i = 0 at θ = 0", 1, t7.kernelDimension);
  ctx.checkResidual("the 7R loop traced for 1.5 rad of arc: max |log ρ(θ)|", t7.maxResidual, 1e-12);
  ctx.checkEqual("and every corrector converged", 1, t7.closed ? 1 : 0);
  const auto s5 = randomScrews(g, 5);
  ctx.checkEqual("random 5R loop: kernel dimension 0 (rigid, local mobility 0)", 0, traceLoop<double>(s5, 0.05, 3).kernelDimension);
}

void completion(Context& ctx) {
  const auto p = planar4R(), s = spherical4R();
  ctx.checkEqual("planar 4R: dim Δ∞ (se(2))", 3, int(completionAlgebra(p).cols()));
  ctx.checkEqual("planar 4R: m = n − dim Δ∞", 1, completionMobility(p));
  const LoopTrace<double> tp = traceLoop<double>(p, 0.05, 40);
  ctx.checkEqual("planar 4R traced (2 rad of arc) and closed", 1, (tp.kernelDimension == 1 && tp.closed) ? 1 : 0);
  ctx.checkEqual("spherical 4R: dim Δ∞ (so(3))", 3, int(completionAlgebra(s).cols()));
  ctx.checkEqual("spherical 4R: m = n − dim Δ∞", 1, completionMobility(s));
  const LoopTrace<double> ts = traceLoop<double>(s, 0.05, 40);
  ctx.checkEqual("spherical 4R traced and closed", 1, (ts.kernelDimension == 1 && ts.closed) ? 1 : 0);
  const auto b = bennettLoop<double>(1, 0.5, 1.1, 0.7);
  ctx.checkEqual("Bennett 4R: dim Δ∞ = 6 (the completion group is SE(3))", 6, int(completionAlgebra(b).cols()));
  ctx.checkEqual("Bennett 4R: n − dim Δ∞", -2, completionMobility(b));
  const LoopTrace<double> tb = traceLoop<double>(b, 0.05, 60);
  ctx.checkEqual("Bennett 4R: kernel dimension at θ = 0", 1, tb.kernelDimension);
  ctx.checkResidual("Bennett 4R traced for 3 rad of arc: max |log ρ(θ)| (mobility 1, the paradoxical exception)", tb.maxResidual, 1e-12);
  ctx.checkEqual("every corrector converged", 1, tb.closed ? 1 : 0);
  // the traced Bennett path obeys Bennett's relation θ₃ = −θ₁, θ₄ = −θ₂ relative to the home pose
  double rel = 0;
  for (const DV& th : tb.path) rel = std::max({rel, abs(th(2) + th(0)), abs(th(3) + th(1))});
  ctx.checkResidual("along the trace θ₃ = −θ₁ and θ₄ = −θ₂ (Bennett's joint relations)", rel, 1e-10);
  auto bent = b;
  bent[3](2) += 0.05;
  bent[3].head<3>().normalize();
  ctx.checkEqual("one twist perturbed by 0.05: rigid (kernel 0), as Kutzbach says", 0, traceLoop<double>(bent, 0.05, 3).kernelDimension);
  ctx.note("Bennett a = 1, α = 0.5, β = 1.1 (b = a sin β / sin α = " + toString(std::sin(1.1) / std::sin(0.5), 4) +
           "), closed at θ₁ = 0.7 by tan(θ₁/2)tan(θ₂/2) = sin((β+α)/2)/sin((β−α)/2).");
}

void totallyGeodesic(Context& ctx) {
  auto g = std::mt19937_64(1523);
  // Δ₁ a subalgebra (se(2): three parallel revolutes): ρ's image is the subgroup; ∇_UV stays in Δ₁
  const V3 z = V3::UnitZ();
  const std::vector<V6> se2 = {lineScrew(z, V3(0, 0, 0)), lineScrew(z, V3(1, 0.5, 0)), lineScrew(z, V3(-0.3, 1, 0))};
  const std::vector<V6> skew = {lineScrew(V3(1, 0, 0), V3(0, 0, 0)), lineScrew(V3(0, 1, 0), V3(0, 0, 1)), lineScrew(V3(0, 0, 1), V3(1, 0, 0))};
  auto outOfSpan = [&](const std::vector<V6>& s) {
    const JointSpaceGeometry<double> geo(s);
    const SM B = completionAlgebra(std::vector<V6>(s.begin(), s.end()));
    double worst = 0, logWorst = 0;
    const SM span0 = [&] {
      DM M(6, 3);
      for (int i = 0; i < 3; ++i) M.col(i) = s[std::size_t(i)];
      Eigen::JacobiSVD<DM> svd(M, Eigen::ComputeThinU);
      return SM(svd.matrixU());
    }();
    for (int t = 0; t < 10; ++t) {
      const DV th = rvec(g, 3), td = rvec(g, 3), pd = rvec(g, 3), pdd = rvec(g, 3);
      const V6 nab = geo.covariantDerivative(th, td, pd, pdd);
      const SM J = geo.screws(th);
      Eigen::JacobiSVD<DM> svd(DM(J), Eigen::ComputeThinU);
      const DM U = svd.matrixU();
      worst = std::max(worst, (nab - U * (U.transpose() * nab)).norm());
      const V6 l = geo.forward(th).log().coeffs();
      logWorst = std::max(logWorst, (l - span0 * (span0.transpose() * l)).norm());
    }
    (void)B;
    return std::pair<double, double>(worst, logWorst);
  };
  const auto [n1, l1] = outOfSpan(se2);
  ctx.checkEqual("three parallel revolutes: Δ₁ is a subalgebra", 1, isSubalgebra(se2) ? 1 : 0);
  ctx.checkResidual("∇_UV is tangent to the image (distance from the tangent space, 10 random U, V)", n1, 1e-13);
  ctx.checkResidual("log ρ(θ) ∈ Δ₁ (BCH: the image is the subgroup)", l1, 1e-13);
  const auto [n2, l2] = outOfSpan(skew);
  ctx.checkEqual("three mutually skew revolutes: not a subalgebra", 0, isSubalgebra(skew) ? 1 : 0);
  recordFails(ctx, "control: ∇_UV tangent for a non-subalgebra", "— control", n2, 1e-6);
  // the proof's ∇_UV at line 9674 equals the §15.1 formula (relabelled); E15.13 (θ̇^1 for θ̇_1) is OCR
  const JointSpaceGeometry<double> geo(randomScrews(g, 4));
  const DV th = rvec(g, 4), td = rvec(g, 4), pd = rvec(g, 4), pdd = rvec(g, 4);
  const SM J = geo.screws(th);
  V6 line9674 = J * pdd;
  for (int i = 0; i < 4; ++i)
    for (int k = i + 1; k < 4; ++k) line9674 += 0.5 * (td(i) * pd(k) + td(k) * pd(i)) * br(V6(J.col(i)), V6(J.col(k)));
  ctx.checkResidual("line 9674, ½Σ_{i<k}(θ̇_iφ̇_k + θ̇_kφ̇_i)[s_i, s_k], equals the §15.1 ∇_UV (relabelled k < i sum)",
                    (line9674 - geo.covariantDerivative(th, td, pd, pdd)).cwiseAbs().maxCoeff(), 1e-14);
  ctx.note("E15.13 (θ̇^1 for θ̇_1 at line 9674) is an OCR superscript with no numerical content: the formula with θ̇_1 is "
           "the one checked here. The necessity argument holds: the coefficients of [s_i, s_k] are arbitrary, so [s_i, s_k] ∈ Δ₁.");
}

void table(Context& ctx) {
  const auto rows = table15_1<double>(1.5);
  ctx.checkEqual("rows of Table 15.1", 10, int(rows.size()));
  int closed = 0;
  std::string list;
  for (const auto& r : rows) {
    const bool ok = isSubalgebra(r.basis) && int(completionAlgebra(r.basis).cols()) == int(r.basis.size());
    closed += ok ? 1 : 0;
    list += r.group + " (" + r.huntType + ", dim " + std::to_string(r.basis.size()) + "); ";
  }
  ctx.checkEqual("rows closed under the bracket with Δ = Δ∞ (p = 3/2)", 10, closed);
  double worst = 0;
  for (const auto& r : rows) worst = std::max(worst, subalgebraDefect(r.basis));
  ctx.checkResidual("max distance of a bracket [s_i, s_k] from Δ over all rows", worst, 1e-15);
  ctx.note(list);
  // the subalgebra of a row, placed anywhere (random rigid motion), remains closed: Ad is an automorphism
  auto g = std::mt19937_64(1525);
  int moved = 0;
  for (const auto& r : rows) {
    const M6 A = SE3<double>::Random(g).adjoint();
    std::vector<V6> b;
    for (const auto& s : r.basis) b.push_back(A * s);
    moved += isSubalgebra(b) ? 1 : 0;
  }
  ctx.checkEqual("the ten rows conjugated by a random rigid motion stay subalgebras", 10, moved);
}

void singularRobot(Context& ctx) {
  // a 6R with a spherical wrist: s₄, s₅, s₆ through the wrist centre w; at θ₅ = 0 the axes 4 and 6 coincide
  const V3 w(0.6, 0.1, 0.8);
  std::vector<V6> s = {lineScrew(V3(0, 0, 1), V3(0, 0, 0)), lineScrew(V3(0, 1, 0), V3(0, 0, 0.5)), lineScrew(V3(0, 1, 0), V3(0.5, 0, 0.7)),
                       lineScrew(V3(1, 0, 0), w), lineScrew(V3(0, 1, 0), w), lineScrew(V3(1, 0, 0), w)};
  ctx.checkEqual("wrist singular (s₄ = s₆): kernel dimension of J with the end effector held", 1, infinitesimalMobility(s));
  const JointSpaceGeometry<double> geo(s);
  // the self-motion θ₄ = t, θ₆ = −t keeps the end effector exactly still: a finite (mobility-1) motion
  double worst = 0;
  for (double t = -1; t <= 1; t += 0.1) {
    DV th = DV::Zero(6);
    th(3) = t;
    th(5) = -t;
    worst = std::max(worst, (geo.forward(th).matrix() - Mat4<double>::Identity()).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("self-motion θ₄ = −θ₆ ∈ [−1, 1]: max |ρ(θ) − I|", worst, 1e-15);
  // a doubly singular pose: also s₁ through w parallel to s₄ ... here: s₂ moved onto s₅'s line as well
  auto s2 = s;
  s2[1] = s[4];
  ctx.checkEqual("with s₂ = s₅ too: kernel dimension 2 (harder for a controller)", 2, infinitesimalMobility(s2));
}

}  // namespace

#define GF15(ID, TITLE, SRC, FN) \
  SOMA_STUDY({.id = ID, .title = TITLE, .source = SRC, .chapter = kChapter, .scalarGeneric = false, .run = FN})
GF15("GF-15.2-mobility-definitions", "Mobility vs infinitesimal mobility: the flat 4-bar (0 vs 2)", "GF §15.2", definitions);
GF15("GF-15.2-loop-equation-kutzbach", "Loop equation and Kutzbach–Grübler m = n − 6 (7R mobile, 5R rigid)", "GF §15.2", kutzbach);
GF15("GF-15.2-completion-group-mobility", "m = n − dim Δ∞: planar and spherical 4R; Bennett the exception", "GF §15.2", completion);
GF15("GF-15.2-totally-geodesic-subalgebra", "Subalgebra ⟺ totally geodesic image (line 9674, erratum E15.13)", "GF §15.2", totallyGeodesic);
GF15("GF-15.2-table-15.1", "Table 15.1: the ten screw systems guaranteeing full-cycle mobility are subalgebras", "GF §15.2", table);
GF15("GF-15.2-singular-robot-mobility", "A 6R held at its end effector: singular iff infinitesimally mobile; self-motions", "GF §15.2", singularRobot);
#undef GF15

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
