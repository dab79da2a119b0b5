// Studies of GF §14.1 (double, reference differences in __float128): tree combinatorics (Fig. 14.1),
// the joint equations summed over the subtree (erratum 1), the star root equation (a free-floating
// two-body "astronaut"), a ball joint as three passive freedoms, the POE along the ancestry, tree
// velocities/accelerations, and the recursive up/down pass (errata 2, 3); Fig. 14.1 drawn.
#include "gf14/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

namespace soma::studies::gf14::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

const std::vector<int> kFig141 = {-1, 0, 0, 2, 2, 3};  // book: (0, 1, 1, 3, 3, 4)

/// The two printed slips of the up/down pass (one at a time).
enum class PrintedPass {
  ParentAngleInDownPass,         ///< P_i += Ad(−θ_i s_c⁰)ᵀ P_c: the parent's angle with the child's screw (erratum 2)
  ParentVelocityForAcceleration  ///< q̈_i⁰ with Ad(−θ_i s_i⁰) q̇_parent⁰, a velocity (erratum 3)
};
/// The recursive pass of TreeDynamics::inverseDynamics (home coordinates, q̈_ground = −g) with one printed slip.
// GF §14.1.3 box, lines 8824 and 8838 as printed (errata 2, 3)
DV treeInverseDynamicsAsPrinted(const TreeDynamics<double>& t, const DV& th, const DV& thd, const DV& thdd, PrintedPass slip) {
  const TreeTopology& topo = t.topology();
  const std::vector<V6>& s0 = t.homeScrews();
  const std::vector<M6>& N0 = t.homeInertias();
  const auto n = std::size_t(t.dof());
  std::vector<M6> Hinv(n);  // Ad(−θ_i s_i⁰)
  std::vector<V6> v(n), a(n), P(n);
  const V6 ground = -t.gravityScrew();
  for (int i : topo.breadthFirst()) {
    const auto k = std::size_t(i);
    const int p = topo.parent(i);
    Hinv[k] = SE3Tangent<double>(V6(-th(i) * s0[k])).exp().adjoint();
    const V6 vp = p < 0 ? V6::Zero() : v[std::size_t(p)];
    const V6 ap = p < 0 ? ground : a[std::size_t(p)];
    v[k] = thd(i) * s0[k] + Hinv[k] * vp;
    const V6 parentTerm = slip == PrintedPass::ParentVelocityForAcceleration ? vp : ap;
    a[k] = thdd(i) * s0[k] + thd(i) * screwBracket(v[k], s0[k]) + Hinv[k] * parentTerm;
    P[k] = N0[k] * a[k] + coadjoint(SE3Tangent<double>(v[k]), V6(N0[k] * v[k]));
  }
  DV tau(t.dof());
  const std::vector<int>& order = topo.breadthFirst();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const auto k = std::size_t(*it);
    for (int c : topo.children(*it)) {
      const auto kc = std::size_t(c);
      const M6 X = slip == PrintedPass::ParentAngleInDownPass ? M6(SE3Tangent<double>(V6(-th(*it) * s0[kc])).exp().adjoint()) : Hinv[kc];
      P[k] += X.transpose() * P[kc];
    }
    tau(*it) = P[k].dot(s0[k]);
  }
  return tau;
}

void treeStructure(Context& ctx) {
  const TreeTopology t = TreeTopology::fromBookParents({0, 1, 1, 3, 3, 4});
  std::string anc;
  for (int i : t.ancestry(5)) anc += (anc.empty() ? "" : ",") + std::to_string(i + 1);
  ctx.checkEqual("ancestry of link 6 in Fig. 14.1 (book numbering)", "1,3,4,6", anc);
  ctx.checkEqual("nested-parenthesis form (line 9044)", "(1(2, 3(4(6), 5)))", t.nested());
  ctx.checkEqual("leaves (links with one joint)", 3, (long long)t.leaves().size());
  ctx.checkEqual("level of link 6 (root = 1)", 4, t.level(5));
  // ⪯ is a partial order: reflexive, antisymmetric, transitive over all pairs/triples
  int bad = 0, pairs = 0;
  for (int i = 0; i < 6; ++i) {
    bad += !t.precedes(i, i);
    for (int j = 0; j < 6; ++j) {
      pairs += t.precedes(i, j) && i != j;
      if (i != j && t.precedes(i, j) && t.precedes(j, i)) ++bad;
      for (int k = 0; k < 6; ++k)
        if (t.precedes(i, j) && t.precedes(j, k) && !t.precedes(i, k)) ++bad;
    }
  }
  ctx.checkEqual("violations of reflexivity, antisymmetry, transitivity", 0, bad);
  ctx.checkEqual("strict pairs i ≺ j (Σ over links of depth − 1)", 9, pairs);
  std::string cyc = "accepted";
  try {
    TreeTopology({1, 2, 0});
  } catch (const InvalidInput&) {
    cyc = "rejected";
  }
  ctx.checkEqual("a parent list with a cycle (1→2→3→1) is InvalidInput", "rejected", cyc);
}

DV lagrangeTau(const TreeDynamics<Q>& t, const DynVector<Q>& th, const DynVector<Q>& thd, const DynVector<Q>& thdd) {
  const int n = t.dof();
  auto L = [&](const DynVector<Q>& a, const DynVector<Q>& b) { return t.kineticEnergy(a, b) - t.potentialEnergy(a); };
  auto dLdv = [&](const DynVector<Q>& a, const DynVector<Q>& b, int i) {
    DynVector<Q> bp = b, bm = b;
    bp(i) += 1;
    bm(i) -= 1;
    return (L(a, bp) - L(a, bm)) / 2;  // exact: L is quadratic in θ̇
  };
  DV tau(n);
  const Q d = Q(1) / 256;
  for (int i = 0; i < n; ++i) {
    const Q ddt = diff8<Q>([&](const Q& s) { return dLdv(DynVector<Q>(th + s * thd + (s * s / 2) * thdd), DynVector<Q>(thd + s * thdd), i); }, d);
    const Q dq = diff8<Q>([&](const Q& s) {
      DynVector<Q> a = th;
      a(i) += s;
      return L(a, thd);
    }, d);
    tau(i) = double(ddt - dq);
  }
  return tau;
}

void jointEquations(Context& ctx) {
  auto g = std::mt19937_64(1411);
  const TreeDynamics<double> t = randomTree(g, kFig141);
  const TreeDynamics<Q> tq = castTree<Q>(t);
  double eL = 0, eR = 0, eStrict = 0, sc = 0;
  for (int c = 0; c < 5; ++c) {
    const DV th = rvec(g, 6, 3), thd = rvec(g, 6), thdd = rvec(g, 6);
    const DV sp = t.inverseDynamicsSpatial(th, thd, thdd);
    const DV lag = lagrangeTau(tq, castMatrix<Q>(th), castMatrix<Q>(thd), castMatrix<Q>(thdd));
    sc = std::max(sc, maxAbs(sp));
    eL = std::max(eL, maxAbs(DV(sp - lag)));
    eR = std::max(eR, maxAbs(DV(sp - t.inverseDynamics(th, thd, thdd))));
    // printed "Σ_{i≺j}" read as strict: link i's own term left out
    const TreeConfiguration<double> cf = t.configuration(th);
    const auto v = t.linkVelocities(cf, thd), a = t.linkAccelerations(cf, thd, thdd);
    DV strict = sp;
    for (int i = 0; i < 6; ++i) {
      const M6& N = cf.inertias[std::size_t(i)];
      const V6& s = cf.screws[std::size_t(i)];
      strict(i) -= V6(a[std::size_t(i)] - t.gravityScrew()).dot(N * s) + v[std::size_t(i)].dot(N * screwBracket(s, v[std::size_t(i)]));
    }
    eStrict = std::max(eStrict, maxAbs(DV(strict - lag)));
  }
  ctx.checkResidual("joint equations Σ_{i⪯j} (spatial, corrected) = Euler–Lagrange by differentiating E_K − E_P (__float128, relative)", eL / sc, 1e-12);
  ctx.checkResidual("joint equations = recursive up/down pass (relative)", eR / sc, 1e-13);
  ctx.checkPrintedFails("Σ over i ≺ j (link i left out, lines 8736/8740)", "1", eStrict / sc, 1e-6);
  ctx.note("Random Fig. 14.1 tree (6 revolute joints on random lines, masses 0.5–3 kg, g = 9.81), 5 random states; max |τ| = " +
           toString(sc, 4) + " N·m.");
}

void starRoot(Context& ctx) {
  // free-floating "astronaut": six massless basis joints (x, y, z slides, rotations about x, y, z)
  // carry the root body; a second body hangs on a revolute joint. No gravity, all joints passive.
  auto g = std::mt19937_64(1412);
  std::vector<V6> s;
  for (int k = 0; k < 3; ++k) s.push_back((V6() << V3::Zero(), V3::Unit(k)).finished());
  for (int k = 0; k < 3; ++k) s.push_back((V6() << V3::Unit(k), V3::Zero()).finished());
  const V3 w = unit3(g), p(0.3, 0.1, -0.2);
  s.push_back((V6() << w, p.cross(w)).finished());
  std::vector<M6> N(5, M6::Zero());
  N.push_back(randomBody(g).matrix());
  N.push_back(randomBody(g).matrix());
  const TreeDynamics<double> t(TreeTopology({-1, 0, 1, 2, 3, 4, 5}), s, N, V3::Zero());
  DV th = DV::Zero(7), thd(7);
  thd << 0.1, -0.2, 0.05, 0.3, -0.2, 0.25, 1.0;
  const V6 P0 = t.momentum(th, thd);
  const double E0 = t.kineticEnergy(th, thd);
  double dP = 0, dE = 0, root = 0;
  const DV z = DV::Zero(7);
  const double h = 0.002;
  for (int k = 0; k < 500; ++k) {  // RK4, 1 s
    auto f = [&](const DV& a, const DV& b) { return t.forwardDynamics(a, b, z); };
    const DV a1 = f(th, thd), a2 = f(th + h / 2 * thd, thd + h / 2 * a1), a3 = f(th + h / 2 * (thd + h / 2 * a1), thd + h / 2 * a2);
    const DV a4 = f(th + h * (thd + h / 2 * a2), thd + h * a3);
    const DV v2 = thd + h / 2 * a1, v3 = thd + h / 2 * a2, v4 = thd + h * a3;
    th += h / 6 * (thd + 2 * v2 + 2 * v3 + v4);
    thd += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    dP = std::max(dP, (t.momentum(th, thd) - P0).cwiseAbs().maxCoeff());
    dE = std::max(dE, std::abs(t.kineticEnergy(th, thd) - E0));
    root = std::max(root, t.totalWrench(th, thd, t.forwardDynamics(th, thd, z)).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("star root equation Σ_j (N_j q̈_j + {q̇_j, N_j q̇_j}) = 0 along the motion (line 8746)", root, 1e-12);
  ctx.checkResidual("total spatial momentum conserved over 1 s (RK4, h = 2 ms)", dP / P0.norm(), 1e-9);
  ctx.checkResidual("kinetic energy conserved over 1 s (relative)", dE / E0, 1e-9);
  ctx.note("Free-floating 2-body star (root as a tree with a massless 6-dof root joint, GF §14.1.2), E_K = " + toString(E0, 5) +
           " J, |P| = " + toString(P0.norm(), 5) + ".");
}

void ballJoint(Context& ctx) {
  // a ball-joint pendulum: three passive revolutes about x, y, z through the pivot (massless links)
  // = a rigid body with a fixed point (freedoms (i,0), (j,0), (k,0)): compare accelerations
  auto g = std::mt19937_64(1413);
  std::vector<V6> s;
  for (int k = 0; k < 3; ++k) s.push_back((V6() << V3::Unit(k), V3::Zero()).finished());
  const SpatialInertia<double> body = randomBody(g);
  const TreeDynamics<double> t(TreeTopology({-1, 0, 1}), s, {M6::Zero(), M6::Zero(), body.matrix()}, V3(0, 0, -9.81));
  Mat6X<double> Z = Mat6X<double>::Zero(6, 3);
  Z.topRows<3>().setIdentity();
  const ConstrainedRigidBody<double> rb(body, Z);
  double worst = 0, jointEq = 0;
  for (int c = 0; c < 5; ++c) {
    const DV th = rvec(g, 3, 1), thd = rvec(g, 3, 1);
    const DV thdd = t.forwardDynamics(th, thd, DV::Zero(3));
    const TreeConfiguration<double> cf = t.configuration(th);
    const V6 qd = t.linkVelocities(cf, thd)[2], qdd = t.linkAccelerations(cf, thd, thdd)[2];
    const SE3<double> K = cf.placements[2];
    const M6 NK = coadjointTransform(K, body.matrix());
    const V6 G = NK * t.gravityScrew();
    worst = std::max(worst, (rb.acceleration(K, qd, G) - qdd).cwiseAbs().maxCoeff());
    jointEq = std::max(jointEq, maxAbs(t.inverseDynamicsSpatial(th, thd, thdd)));
  }
  ctx.checkResidual("three passive joint equations (k = 1, 2, 3) hold: τ = 0 at the simulated θ̈", jointEq, 1e-12);
  ctx.checkResidual("ball joint as three freedom screws = rigid body with a fixed point (q̈ of the body)", worst, 1e-12);
}

void treeKinematics(Context& ctx) {
  auto g = std::mt19937_64(1414);
  const TreeDynamics<double> t = randomTree(g, kFig141);
  const DV th = rvec(g, 6, 3);
  const TreeConfiguration<double> c = t.configuration(th);
  // serial POE of the ancestry (1, 3, 4, 6)
  SE3<double> K = SE3<double>::Identity();
  for (int j : t.topology().ancestry(5)) K = K * SE3Tangent<double>(V6(th(j) * t.homeScrews()[std::size_t(j)])).exp();
  ctx.checkResidual("K₆ = e^{θ₁s₁}e^{θ₃s₃}e^{θ₄s₄}e^{θ₆s₆} (POE along the ancestry)", (K.matrix() - c.placements[5].matrix()).cwiseAbs().maxCoeff(), 1e-14);
  // star (GF line 8782): a tree with a 6-dof root joint (six massless basis joints) whose links are
  // placed by K_i = K_root · (POE of the joints above the root), the latter computed on its own
  const TreeDynamics<double> sub = randomTree(g, {-1, 0, 0, 2});
  std::vector<V6> s;
  std::vector<M6> N(5, M6::Zero());
  for (int k = 0; k < 3; ++k) s.push_back((V6() << V3::Zero(), V3::Unit(k)).finished());
  for (int k = 0; k < 3; ++k) s.push_back((V6() << V3::Unit(k), V3::Zero()).finished());
  N.push_back(randomBody(g).matrix());
  std::vector<int> parent{-1, 0, 1, 2, 3, 4};
  for (int i = 0; i < 4; ++i) {
    parent.push_back(sub.topology().parent(i) < 0 ? 5 : 6 + sub.topology().parent(i));
    s.push_back(sub.homeScrews()[std::size_t(i)]);
    N.push_back(sub.homeInertias()[std::size_t(i)]);
  }
  const TreeDynamics<double> star(TreeTopology(parent), s, N, V3::Zero());
  const DV ths = rvec(g, 10, 2);
  const TreeConfiguration<double> cs = star.configuration(ths), cr = sub.configuration(DV(ths.tail(4)));
  double starErr = 0;
  for (int i = 0; i < 4; ++i)
    starErr = std::max(starErr, ((cs.placements[5] * cr.placements[std::size_t(i)]).matrix() - cs.placements[std::size_t(6 + i)].matrix()).cwiseAbs().maxCoeff());
  ctx.checkResidual("star: K_i = K_root · e^{θ_{i1}s_{i1}}···e^{θ_i s_i} (root as a 6-dof joint, 4 links)", starErr, 1e-14);
}

void treeVelocities(Context& ctx) {
  auto g = std::mt19937_64(1415);
  const TreeDynamics<double> t = randomTree(g, kFig141);
  const TreeDynamics<Q> tq = castTree<Q>(t);
  const DV th = rvec(g, 6, 3), thd = rvec(g, 6), thdd = rvec(g, 6);
  const TreeConfiguration<double> c = t.configuration(th);
  const auto v = t.linkVelocities(c, thd), a = t.linkAccelerations(c, thd, thdd);
  double ev = 0, ea = 0;
  const Q d = Q(1) / 128;
  const DynVector<Q> thq = castMatrix<Q>(th), thdq = castMatrix<Q>(thd), thddq = castMatrix<Q>(thdd);
  for (int i = 0; i < 6; ++i) {
    Mat4<Q> Kd;
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col)
        Kd(r, col) = diff8<Q>([&](const Q& s) { return tq.configuration(DynVector<Q>(thq + s * thdq + (s * s / 2) * thddq)).placements[std::size_t(i)].matrix()(r, col); }, d);
    const Mat4<Q> Xi = Kd * tq.configuration(thq).placements[std::size_t(i)].inverse().matrix();
    const V6 qv = castMatrix<double>(Vec6<Q>(SE3Tangent<Q>::vee(Xi).coeffs()));
    ev = std::max(ev, (qv - v[std::size_t(i)]).cwiseAbs().maxCoeff());
    Vec6<Q> qa;
    for (int k = 0; k < 6; ++k)
      qa(k) = diff8<Q>([&](const Q& s) {
        const auto cf = tq.configuration(DynVector<Q>(thq + s * thdq + (s * s / 2) * thddq));
        return tq.linkVelocities(cf, DynVector<Q>(thdq + s * thddq))[std::size_t(i)](k);
      }, d);
    ea = std::max(ea, (castMatrix<double>(qa) - a[std::size_t(i)]).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("q̇_i = Σ_{j⪯i} θ̇_j s_j = K̇_iK_i⁻¹ (differences in __float128)", ev, 1e-12);
  ctx.checkResidual("q̈_i = Σ_{j⪯i} (θ̈_j s_j + θ̇_j[q̇_j, s_j]) = d q̇_i/dt", ea, 1e-12);
}

void recursive(Context& ctx) {
  auto g = std::mt19937_64(1416);
  // (1) a path-shaped tree = the serial RNE of §13.3
  {
    const TreeDynamics<double> t = randomTree(g, {-1, 0, 1, 2, 3, 4});
    std::vector<SE3Tangent<double>> s;
    std::vector<SpatialInertia<double>> L;
    for (int i = 0; i < 6; ++i) {
      s.emplace_back(t.homeScrews()[std::size_t(i)]);
      L.push_back(SpatialInertia<double>::fromMatrix(t.homeInertias()[std::size_t(i)]));
    }
    const SerialDynamics<double> chain(s, L, 9.81);
    double e = 0, sc = 0;
    for (int c = 0; c < 5; ++c) {
      const DV th = rvec(g, 6, 3), thd = rvec(g, 6), thdd = rvec(g, 6);
      const DV ref = chain.inverseDynamics(th, thd, thdd);
      sc = std::max(sc, maxAbs(ref));
      e = std::max(e, maxAbs(DV(t.inverseDynamics(th, thd, thdd) - ref)));
    }
    ctx.checkResidual("path-shaped tree: up/down pass = serial RNE of GF §13.3 (relative)", e / sc, 1e-13);
  }
  // (2) branched, wide and deep trees = joint equations; printed passes fail
  struct Case {
    const char* name;
    std::vector<int> parent;
  };
  std::vector<int> wide{-1}, deep{-1};
  for (int k = 0; k < 8; ++k) wide.push_back(0);
  for (int k = 0; k < 9; ++k) deep.push_back(k);
  const Case cases[] = {{"Fig. 14.1", kFig141}, {"wide (root with 8 children)", wide}, {"deep (10-link path)", deep}};
  double e2 = 0, p2 = 1e9, p3 = 1e9;
  for (const Case& cs : cases) {
    const TreeDynamics<double> t = randomTree(g, cs.parent);
    const int n = t.dof();
    const DV th = rvec(g, n, 3), thd = rvec(g, n), thdd = rvec(g, n);
    const DV sp = t.inverseDynamicsSpatial(th, thd, thdd);
    const double sc = maxAbs(sp);
    e2 = std::max(e2, maxAbs(DV(t.inverseDynamics(th, thd, thdd) - sp)) / sc);
    p2 = std::min(p2, maxAbs(DV(treeInverseDynamicsAsPrinted(t, th, thd, thdd, PrintedPass::ParentAngleInDownPass) - sp)) / sc);
    p3 = std::min(p3, maxAbs(DV(treeInverseDynamicsAsPrinted(t, th, thd, thdd, PrintedPass::ParentVelocityForAcceleration) - sp)) / sc);
  }
  ctx.checkResidual("branched (Fig. 14.1), wide and deep trees: up/down pass = joint equations (relative)", e2, 1e-13);
  // bound: the corrected passes' tolerance (relative, 1e-13, the check above)
  ctx.checkPrintedFails("down pass with Ad(−θ_i s_c⁰)ᵀ (parent's angle, line 8838)", "2", p2, 1e-13);
  ctx.checkPrintedFails("up pass with the parent's velocity q̇_{i−1}⁰ for its acceleration (line 8824)", "3", p3, 1e-13);
  // (3) a massless leaf: the pass still runs; its joint carries no own inertia term
  {
    auto t0 = randomTree(g, kFig141);
    std::vector<M6> N = t0.homeInertias();
    N[5].setZero();
    const TreeDynamics<double> t(t0.topology(), t0.homeScrews(), N, t0.gravity());
    const DV th = rvec(g, 6, 3), thd = rvec(g, 6), thdd = rvec(g, 6);
    ctx.checkResidual("zero-mass leaf: τ₆ = 0 and the pass = joint equations", std::max(std::abs(t.inverseDynamics(th, thd, thdd)(5)),
                      maxAbs(DV(t.inverseDynamics(th, thd, thdd) - t.inverseDynamicsSpatial(th, thd, thdd)))), 1e-12);
  }
  ctx.note("Line 8812's input list names the acceleration q̈_i⁰ where θ̈_i is meant, and the Q update lost its braces (erratum 3, "
           "typos); the printed parent term q̇_{i−1}⁰ is the variant that fails above.");
}

void figure141(Context& ctx) {
  const TreeTopology t = TreeTopology::fromBookParents({0, 1, 1, 3, 3, 4});
  ctx.checkEqual("Fig. 14.1 has 6 links and 6 joints", 6, t.size());
  if (!ctx.makeFigures()) return;
  // node positions: level on y, spread on x
  const double xs[6] = {0, -1.2, 0.8, 0.2, 1.6, 0.2};
  rd::Plot p;
  p.title = "Fig. 14.1: a tree-structured mechanism (links = nodes, joints = edges)";
  p.x.label = "";
  p.y.label = "level";
  p.equalAspect = true;
  p.grid = false;
  p.add("ground", {-1.8, 2.2}, {0, 0}, rd::Color::hex(0x555555)).width = 6;
  for (int i = 0; i < 6; ++i) {
    const int par = t.parent(i);
    const double x0 = par < 0 ? 0.0 : xs[par], y0 = par < 0 ? 0.0 : t.level(par);
    auto& e = p.add(i == 0 ? "joint i joins link i to its parent" : "", {x0, xs[i]}, {y0, double(t.level(i))}, rd::Color::hex(0x0072B2));
    e.width = 4;
    p.texts.push_back({(x0 + xs[i]) / 2, (y0 + t.level(i)) / 2, "joint " + std::to_string(i + 1), rd::Color::hex(0x0072B2), 18});
  }
  for (int i = 0; i < 6; ++i) {
    auto& n = p.add(i == 0 ? "link (node)" : "", {xs[i]}, {double(t.level(i))}, rd::Color::hex(0xD55E00));
    n.line = false;
    n.markers = true;
    n.markerRadius = 12;
    p.texts.push_back({xs[i], double(t.level(i)), "link " + std::to_string(i + 1), rd::Color::hex(0x000000), 22});
  }
  auto& a = p.add("ancestry of link 6: (1, 3, 4, 6)", {-0.12, 0.68, 0.08, 0.08}, {1, 2, 3, 4}, rd::Color::hex(0x009E73));
  a.dashed = true;
  a.width = 3;
  p.legend = rd::LegendCorner::TopLeft;
  const std::string file = "GF-14-fig-14.1.png";
  rd::renderPlotPngAndSvg(p, ctx.figurePath(file));
  ctx.figure(file, "Fig. 14.1 rebuilt from the parent list (0, 1, 1, 3, 3, 4): root 1 on the ground, links 2, 3 on 1, 4, 5 on 3, 6 on 4; "
                   "the dashed path is the ancestry (1, 3, 4, 6) used for K₆ and q̇₆.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-14.1-tree-structure", "Tree of Fig. 14.1: ancestry, levels, partial order, cycles rejected", "GF §14.1", treeStructure);
SOMA_STUDY_DOUBLE("GF-14.1.1-tree-joint-equations", "Joint equations over the subtree = Euler–Lagrange (erratum 1)", "GF §14.1.1", jointEquations);
SOMA_STUDY_DOUBLE("GF-14.1.1-star-root-equation", "Free-floating star: root equation, momentum and energy conserved", "GF §14.1.1", starRoot);
SOMA_STUDY_DOUBLE("GF-14.1.1-multi-dof-passive-joint", "Ball joint as three passive freedoms = body with a fixed point", "GF §14.1.1", ballJoint);
SOMA_STUDY_DOUBLE("GF-14.1.2-tree-kinematics", "POE along the ancestry; star relative to the root", "GF §14.1.2", treeKinematics);
SOMA_STUDY_DOUBLE("GF-14.1.2-tree-velocities-accelerations", "Tree velocities and accelerations = derivatives of K_i", "GF §14.1.2", treeVelocities);
SOMA_STUDY_DOUBLE("GF-14.1.3-tree-recursive-dynamics", "Up/down Newton–Euler pass over a tree (errata 2, 3)", "GF §14.1.3", recursive);
SOMA_STUDY_DOUBLE("GF-14-fig-14.1", "Fig. 14.1: the tree-structured mechanism", "GF §14.1 Fig. 14.1", figure141);

}  // namespace soma::studies::gf14::SOMA_UNITY_ID
