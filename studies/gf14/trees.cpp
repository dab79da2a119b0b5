// Studies of GF §14.1 (in the asked scalar; reference differences in __float128, or in S when S is as wide): tree combinatorics (Fig. 14.1),
// the joint equations summed over the subtree (erratum 1), the star root equation (a free-floating
// two-body "astronaut"), a ball joint as three passive freedoms, the POE along the ancestry, tree
// velocities/accelerations, and the recursive up/down pass (errata 2, 3); Fig. 14.1 drawn.
#include "gf14/common.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

namespace soma::studies::gf14::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

constexpr const char* kWhyDouble = "a figure: soma::render draws double geometry";

const std::vector<int> kFig141 = {-1, 0, 0, 2, 2, 3};  // book: (0, 1, 1, 3, 3, 4)

/// The two printed slips of the up/down pass (one at a time).
enum class PrintedPass {
  ParentAngleInDownPass,         ///< P_i += Ad(−θ_i s_c⁰)ᵀ P_c: the parent's angle with the child's screw (erratum 2)
  ParentVelocityForAcceleration  ///< q̈_i⁰ with Ad(−θ_i s_i⁰) q̇_parent⁰, a velocity (erratum 3)
};
/// The recursive pass of TreeDynamics::inverseDynamics (home coordinates, q̈_ground = −g) with one printed slip.
// GF §14.1.3 box, lines 8824 and 8838 as printed (errata 2, 3)
template <class S>
DynVector<S> treeInverseDynamicsAsPrinted(const TreeDynamics<S>& t, const DynVector<S>& th, const DynVector<S>& thd, const DynVector<S>& thdd,
                                          PrintedPass slip) {
  using V6 = Vec6<S>;
  using M6 = Mat6<S>;
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
    Hinv[k] = SE3Tangent<S>(V6(-th(i) * s0[k])).exp().adjoint();
    const V6 vp = p < 0 ? V6::Zero() : v[std::size_t(p)];
    const V6 ap = p < 0 ? ground : a[std::size_t(p)];
    v[k] = thd(i) * s0[k] + Hinv[k] * vp;
    const V6 parentTerm = slip == PrintedPass::ParentVelocityForAcceleration ? vp : ap;
    a[k] = thdd(i) * s0[k] + thd(i) * screwBracket(v[k], s0[k]) + Hinv[k] * parentTerm;
    P[k] = N0[k] * a[k] + coadjoint(SE3Tangent<S>(v[k]), V6(N0[k] * v[k]));
  }
  DynVector<S> tau(t.dof());
  const std::vector<int>& order = topo.breadthFirst();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const auto k = std::size_t(*it);
    for (int c : topo.children(*it)) {
      const auto kc = std::size_t(c);
      const M6 X = slip == PrintedPass::ParentAngleInDownPass ? M6(SE3Tangent<S>(V6(-th(*it) * s0[kc])).exp().adjoint()) : Hinv[kc];
      P[k] += X.transpose() * P[kc];
    }
    tau(*it) = P[k].dot(s0[k]);
  }
  return tau;
}

template <class S> void treeStructure(Context& ctx) {
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

template <class S> DynVector<S> lagrangeTau(const TreeDynamics<Ref<S>>& t, const DynVector<Ref<S>>& th, const DynVector<Ref<S>>& thd,
                                            const DynVector<Ref<S>>& thdd) {
  using R = Ref<S>;
  const int n = t.dof();
  auto L = [&](const DynVector<R>& a, const DynVector<R>& b) { return R(t.kineticEnergy(a, b) - t.potentialEnergy(a)); };
  auto dLdv = [&](const DynVector<R>& a, const DynVector<R>& b, int i) {
    DynVector<R> bp = b, bm = b;
    bp(i) += 1;
    bm(i) -= 1;
    return R((L(a, bp) - L(a, bm)) / 2);  // exact: L is quadratic in θ̇
  };
  DynVector<S> tau(n);
  const R d = diffStep<S>();
  for (int i = 0; i < n; ++i) {
    const R ddt = diff8<R>([&](const R& s) { return dLdv(DynVector<R>(th + s * thd + (s * s / 2) * thdd), DynVector<R>(thd + s * thdd), i); }, d);
    const R dq = diff8<R>([&](const R& s) {
      DynVector<R> a = th;
      a(i) += s;
      return L(a, thd);
    }, d);
    tau(i) = S(ddt - dq);
  }
  return tau;
}

template <class S> void jointEquations(Context& ctx) {
  using DVS = DynVector<S>;
  using R = Ref<S>;
  auto g = std::mt19937_64(1411);
  const TreeDynamics<S> t = randomTree<S>(g, kFig141);
  const TreeDynamics<R> tq = castTree<R>(t);
  S eL = S(0), eR = S(0), eStrict = S(0), sc = S(0);
  for (int c = 0; c < 5; ++c) {
    const DVS th = rvecS<S>(g, 6, 3), thd = rvecS<S>(g, 6), thdd = rvecS<S>(g, 6);
    const DVS sp = t.inverseDynamicsSpatial(th, thd, thdd);
    const DVS lag = lagrangeTau<S>(tq, castMatrix<R>(th), castMatrix<R>(thd), castMatrix<R>(thdd));
    sc = std::max<S>(sc, maxAbsS<S>(sp));
    eL = std::max<S>(eL, maxAbsS<S>(DVS(sp - lag)));
    eR = std::max<S>(eR, maxAbsS<S>(DVS(sp - t.inverseDynamics(th, thd, thdd))));
    // printed "Σ_{i≺j}" read as strict: link i's own term left out
    const TreeConfiguration<S> cf = t.configuration(th);
    const auto v = t.linkVelocities(cf, thd), a = t.linkAccelerations(cf, thd, thdd);
    DVS strict = sp;
    for (int i = 0; i < 6; ++i) {
      const Mat6<S>& N = cf.inertias[std::size_t(i)];
      const Vec6<S>& s = cf.screws[std::size_t(i)];
      strict(i) -= Vec6<S>(a[std::size_t(i)] - t.gravityScrew()).dot(N * s) + v[std::size_t(i)].dot(N * screwBracket(s, v[std::size_t(i)]));
    }
    eStrict = std::max<S>(eStrict, maxAbsS<S>(DVS(strict - lag)));
  }
  // the corrected sums and the recursive pass: 6 links of products of exponentials, 512 ε relative
  // (1.1e-13 in double); the Euler–Lagrange reference adds its difference error (fdTol, 0 below __float128)
  const S tolRel = tol<S>(512);
  ctx.checkResidual(std::string("joint equations Σ_{i⪯j} (spatial, corrected) = Euler–Lagrange by differentiating E_K − E_P (") +
                        (kWideRef<S> ? "__float128" : "in S at d = ε^(1/9)") + ", relative; 512 ε + difference bound)",
                    S(eL / sc), S(tolRel + fdTol<S>()));
  ctx.checkResidual("joint equations = recursive up/down pass (relative, 512 ε)", S(eR / sc), tolRel);
  ctx.checkPrintedFails("Σ over i ≺ j (link i left out, lines 8736/8740)", "1", S(eStrict / sc), S(tolRel + fdTol<S>()));
  ctx.note("Random Fig. 14.1 tree (6 revolute joints on random lines, masses 0.5–3 kg, g = 9.81), 5 random states; max |τ| = " +
           toString(toDouble(sc), 4) + " N·m.");
}

template <class S> void starRoot(Context& ctx) {
  using DVS = DynVector<S>;
  // free-floating "astronaut": six massless basis joints (x, y, z slides, rotations about x, y, z)
  // carry the root body; a second body hangs on a revolute joint. No gravity, all joints passive.
  auto g = std::mt19937_64(1412);
  std::vector<Vec6<S>> s;
  for (int k = 0; k < 3; ++k) s.push_back(v6<S>(Vec3<S>::Zero(), Vec3<S>::Unit(k)));
  for (int k = 0; k < 3; ++k) s.push_back(v6<S>(Vec3<S>::Unit(k), Vec3<S>::Zero()));
  const Vec3<S> w = castMatrix<S>(unit3(g)), p(frac<S>(3, 10), frac<S>(1, 10), frac<S>(-1, 5));
  Vec6<S> sw = v6<S>(w, p.cross(w));
  using std::sqrt;
  sw /= S(sqrt(S(sw.template head<3>().squaredNorm())));
  s.push_back(sw);
  std::vector<Mat6<S>> N(5, Mat6<S>::Zero());
  N.push_back(bodyS<S>(g));
  N.push_back(bodyS<S>(g));
  const TreeDynamics<S> t(TreeTopology({-1, 0, 1, 2, 3, 4, 5}), s, N, Vec3<S>::Zero());
  DVS th = DVS::Zero(7), thd(7);
  thd << frac<S>(1, 10), frac<S>(-1, 5), frac<S>(1, 20), frac<S>(3, 10), frac<S>(-1, 5), frac<S>(1, 4), S(1);
  const Vec6<S> P0 = t.momentum(th, thd);
  const S E0 = t.kineticEnergy(th, thd);
  S dP = S(0), dE = S(0), root = S(0);
  const DVS z = DVS::Zero(7);
  const S h = frac<S>(1, 500);
  const int steps = 500;
  for (int k = 0; k < steps; ++k) {  // RK4, 1 s
    auto f = [&](const DVS& a, const DVS& b) { return t.forwardDynamics(a, b, z); };
    const DVS a1 = f(th, thd), a2 = f(DVS(th + h / 2 * thd), DVS(thd + h / 2 * a1));
    const DVS a3 = f(DVS(th + h / 2 * DVS(thd + h / 2 * a1)), DVS(thd + h / 2 * a2));
    const DVS a4 = f(DVS(th + h * DVS(thd + h / 2 * a2)), DVS(thd + h * a3));
    const DVS v2 = thd + h / 2 * a1, v3 = thd + h / 2 * a2, v4 = thd + h * a3;
    th += h / 6 * DVS(thd + 2 * v2 + 2 * v3 + v4);
    thd += h / 6 * DVS(a1 + 2 * a2 + 2 * a3 + a4);
    using std::abs;
    dP = std::max<S>(dP, maxAbsM<S>(Vec6<S>(t.momentum(th, thd) - P0)));
    dE = std::max<S>(dE, S(abs(S(t.kineticEnergy(th, thd) - E0))));
    root = std::max<S>(root, maxAbsM<S>(Vec6<S>(t.totalWrench(th, thd, t.forwardDynamics(th, thd, z)))));
  }
  // RK4's global error ≈ C·h⁴ (h⁴ = 1.6e-11; 64 h⁴ = 1.0e-9) plus rounding, 64 ε per step over 500 steps
  const S drift = S(64) * h * h * h * h + S(steps) * tol<S>(64);
  ctx.checkResidual("star root equation Σ_j (N_j q̈_j + {q̇_j, N_j q̇_j}) = 0 along the motion (line 8746; 4096 ε)", root, tol<S>(4096));
  ctx.checkResidual("total spatial momentum conserved over 1 s (RK4, h = 2 ms; 64 h⁴ + 500·64 ε)", S(dP / S(P0.norm())), drift);
  ctx.checkResidual("kinetic energy conserved over 1 s (relative; 64 h⁴ + 500·64 ε)", S(dE / E0), drift);
  ctx.note("Free-floating 2-body star (root as a tree with a massless 6-dof root joint, GF §14.1.2), E_K = " + toString(toDouble(E0), 5) +
           " J, |P| = " + toString(toDouble(S(P0.norm())), 5) + ".");
}

template <class S> void ballJoint(Context& ctx) {
  using DVS = DynVector<S>;
  // a ball-joint pendulum: three passive revolutes about x, y, z through the pivot (massless links)
  // = a rigid body with a fixed point (freedoms (i,0), (j,0), (k,0)): compare accelerations
  auto g = std::mt19937_64(1413);
  std::vector<Vec6<S>> s;
  for (int k = 0; k < 3; ++k) s.push_back(v6<S>(Vec3<S>::Unit(k), Vec3<S>::Zero()));
  const Mat6<S> bodyM = bodyS<S>(g);
  const SpatialInertia<S> body = SpatialInertia<S>::fromMatrix(bodyM);
  const TreeDynamics<S> t(TreeTopology({-1, 0, 1}), s, {Mat6<S>::Zero(), Mat6<S>::Zero(), body.matrix()},
                          Vec3<S>(S(0), S(0), frac<S>(-981, 100)));
  Mat6X<S> Z = Mat6X<S>::Zero(6, 3);
  Z.template topRows<3>().setIdentity();
  const ConstrainedRigidBody<S> rb(body, Z);
  S worst = S(0), jointEq = S(0);
  for (int c = 0; c < 5; ++c) {
    const DVS th = rvecS<S>(g, 3, 1), thd = rvecS<S>(g, 3, 1);
    const DVS thdd = t.forwardDynamics(th, thd, DVS::Zero(3));
    const TreeConfiguration<S> cf = t.configuration(th);
    const Vec6<S> qd = t.linkVelocities(cf, thd)[2], qdd = t.linkAccelerations(cf, thd, thdd)[2];
    const SE3<S> K = cf.placements[2];
    const Mat6<S> NK = coadjointTransform(K, body.matrix());
    const Vec6<S> G = NK * t.gravityScrew();
    worst = std::max<S>(worst, maxAbsM<S>(Vec6<S>(rb.acceleration(K, qd, G) - qdd)));
    jointEq = std::max<S>(jointEq, maxAbsS<S>(t.inverseDynamicsSpatial(th, thd, thdd)));
  }
  // forces of size m·g ≈ 30 N: 4096 ε absolute (9.1e-13 in double)
  ctx.checkResidual("three passive joint equations (k = 1, 2, 3) hold: τ = 0 at the simulated θ̈ (4096 ε)", jointEq, tol<S>(4096));
  ctx.checkResidual("ball joint as three freedom screws = rigid body with a fixed point (q̈ of the body; 4096 ε)", worst, tol<S>(4096));
}

template <class S> void treeKinematics(Context& ctx) {
  auto g = std::mt19937_64(1414);
  const TreeDynamics<S> t = randomTree<S>(g, kFig141);
  const DynVector<S> th = rvecS<S>(g, 6, 3);
  const TreeConfiguration<S> c = t.configuration(th);
  // serial POE of the ancestry (1, 3, 4, 6)
  SE3<S> K = SE3<S>::Identity();
  for (int j : t.topology().ancestry(5)) K = K * SE3Tangent<S>(Vec6<S>(th(j) * t.homeScrews()[std::size_t(j)])).exp();
  // four exponentials and products of unit-scale transforms (|p| ≲ 3): 64 ε
  ctx.checkResidual("K₆ = e^{θ₁s₁}e^{θ₃s₃}e^{θ₄s₄}e^{θ₆s₆} (POE along the ancestry; 64 ε)", maxAbsM<S>(Mat4<S>(K.matrix() - c.placements[5].matrix())), tol<S>(64));
  // star (GF line 8782): a tree with a 6-dof root joint (six massless basis joints) whose links are
  // placed by K_i = K_root · (POE of the joints above the root), the latter computed on its own
  const TreeDynamics<S> sub = randomTree<S>(g, {-1, 0, 0, 2});
  std::vector<Vec6<S>> s;
  std::vector<Mat6<S>> N(5, Mat6<S>::Zero());
  for (int k = 0; k < 3; ++k) s.push_back(v6<S>(Vec3<S>::Zero(), Vec3<S>::Unit(k)));
  for (int k = 0; k < 3; ++k) s.push_back(v6<S>(Vec3<S>::Unit(k), Vec3<S>::Zero()));
  N.push_back(bodyS<S>(g));
  std::vector<int> parent{-1, 0, 1, 2, 3, 4};
  for (int i = 0; i < 4; ++i) {
    parent.push_back(sub.topology().parent(i) < 0 ? 5 : 6 + sub.topology().parent(i));
    s.push_back(sub.homeScrews()[std::size_t(i)]);
    N.push_back(sub.homeInertias()[std::size_t(i)]);
  }
  const TreeDynamics<S> star(TreeTopology(parent), s, N, Vec3<S>::Zero());
  const DynVector<S> ths = rvecS<S>(g, 10, 2);
  const TreeConfiguration<S> cs = star.configuration(ths), cr = sub.configuration(DynVector<S>(ths.tail(4)));
  S starErr = S(0);
  for (int i = 0; i < 4; ++i)
    starErr = std::max<S>(starErr, maxAbsM<S>(Mat4<S>((cs.placements[5] * cr.placements[std::size_t(i)]).matrix() - cs.placements[std::size_t(6 + i)].matrix())));
  ctx.checkResidual("star: K_i = K_root · e^{θ_{i1}s_{i1}}···e^{θ_i s_i} (root as a 6-dof joint, 4 links; 64 ε)", starErr, tol<S>(64));
}

template <class S> void treeVelocities(Context& ctx) {
  using R = Ref<S>;
  auto g = std::mt19937_64(1415);
  const TreeDynamics<S> t = randomTree<S>(g, kFig141);
  const TreeDynamics<R> tq = castTree<R>(t);
  const DynVector<S> th = rvecS<S>(g, 6, 3), thd = rvecS<S>(g, 6), thdd = rvecS<S>(g, 6);
  const TreeConfiguration<S> c = t.configuration(th);
  const auto v = t.linkVelocities(c, thd), a = t.linkAccelerations(c, thd, thdd);
  S ev = S(0), ea = S(0);
  const R d = diffStep<S>();
  const DynVector<R> thq = castMatrix<R>(th), thdq = castMatrix<R>(thd), thddq = castMatrix<R>(thdd);
  for (int i = 0; i < 6; ++i) {
    Mat4<R> Kd;
    for (int r = 0; r < 4; ++r)
      for (int col = 0; col < 4; ++col)
        Kd(r, col) = diff8<R>([&](const R& s) { return R(tq.configuration(DynVector<R>(thq + s * thdq + (s * s / 2) * thddq)).placements[std::size_t(i)].matrix()(r, col)); }, d);
    const Mat4<R> Xi = Kd * tq.configuration(thq).placements[std::size_t(i)].inverse().matrix();
    const Vec6<S> qv = castMatrix<S>(Vec6<R>(SE3Tangent<R>::vee(Xi).coeffs()));
    ev = std::max<S>(ev, maxAbsM<S>(Vec6<S>(qv - v[std::size_t(i)])));
    Vec6<R> qa;
    for (int k = 0; k < 6; ++k)
      qa(k) = diff8<R>([&](const R& s) {
        const auto cf = tq.configuration(DynVector<R>(thq + s * thdq + (s * s / 2) * thddq));
        return R(tq.linkVelocities(cf, DynVector<R>(thdq + s * thddq))[std::size_t(i)](k));
      }, d);
    ea = std::max<S>(ea, maxAbsM<S>(Vec6<S>(castMatrix<S>(qa) - a[std::size_t(i)])));
  }
  // velocities and accelerations of size ≲ 10 from sums over ≤ 4 joints: 4096 ε, plus the difference bound
  const std::string how = kWideRef<S> ? "differences in __float128" : "differences in S at d = ε^(1/9)";
  ctx.checkResidual("q̇_i = Σ_{j⪯i} θ̇_j s_j = K̇_iK_i⁻¹ (" + how + "; 4096 ε + difference bound)", ev, S(tol<S>(4096) + fdTol<S>()));
  ctx.checkResidual("q̈_i = Σ_{j⪯i} (θ̈_j s_j + θ̇_j[q̇_j, s_j]) = d q̇_i/dt (4096 ε + difference bound)", ea, S(tol<S>(4096) + fdTol<S>()));
}

template <class S> void recursive(Context& ctx) {
  using DVS = DynVector<S>;
  auto g = std::mt19937_64(1416);
  const S tolRel = tol<S>(512);  // relative, 1.1e-13 in double: ≤ 10 links of exponentials and 6×6 products
  // (1) a path-shaped tree = the serial RNE of §13.3
  {
    const TreeDynamics<S> t = randomTree<S>(g, {-1, 0, 1, 2, 3, 4});
    std::vector<SE3Tangent<S>> s;
    std::vector<SpatialInertia<S>> L;
    for (int i = 0; i < 6; ++i) {
      s.emplace_back(t.homeScrews()[std::size_t(i)]);
      L.push_back(SpatialInertia<S>::fromMatrix(t.homeInertias()[std::size_t(i)]));
    }
    const SerialDynamics<S> chain(s, L, frac<S>(981, 100));
    S e = S(0), sc = S(0);
    for (int c = 0; c < 5; ++c) {
      const DVS th = rvecS<S>(g, 6, 3), thd = rvecS<S>(g, 6), thdd = rvecS<S>(g, 6);
      const DVS ref = chain.inverseDynamics(th, thd, thdd);
      sc = std::max<S>(sc, maxAbsS<S>(ref));
      e = std::max<S>(e, maxAbsS<S>(DVS(t.inverseDynamics(th, thd, thdd) - ref)));
    }
    ctx.checkResidual("path-shaped tree: up/down pass = serial RNE of GF §13.3 (relative, 512 ε)", S(e / sc), tolRel);
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
  S e2 = S(0), p2 = S(1e9), p3 = S(1e9);
  for (const Case& cs : cases) {
    const TreeDynamics<S> t = randomTree<S>(g, cs.parent);
    const int n = t.dof();
    const DVS th = rvecS<S>(g, n, 3), thd = rvecS<S>(g, n), thdd = rvecS<S>(g, n);
    const DVS sp = t.inverseDynamicsSpatial(th, thd, thdd);
    const S sc = maxAbsS<S>(sp);
    e2 = std::max<S>(e2, S(maxAbsS<S>(DVS(t.inverseDynamics(th, thd, thdd) - sp)) / sc));
    p2 = std::min<S>(p2, S(maxAbsS<S>(DVS(treeInverseDynamicsAsPrinted<S>(t, th, thd, thdd, PrintedPass::ParentAngleInDownPass) - sp)) / sc));
    p3 = std::min<S>(p3, S(maxAbsS<S>(DVS(treeInverseDynamicsAsPrinted<S>(t, th, thd, thdd, PrintedPass::ParentVelocityForAcceleration) - sp)) / sc));
  }
  ctx.checkResidual("branched (Fig. 14.1), wide and deep trees: up/down pass = joint equations (relative, 512 ε)", e2, tolRel);
  // bound: the corrected passes' tolerance (relative, 512 ε, the check above)
  ctx.checkPrintedFails("down pass with Ad(−θ_i s_c⁰)ᵀ (parent's angle, line 8838)", "2", p2, tolRel);
  ctx.checkPrintedFails("up pass with the parent's velocity q̇_{i−1}⁰ for its acceleration (line 8824)", "3", p3, tolRel);
  // (3) a massless leaf: the pass still runs; its joint carries no own inertia term
  {
    auto t0 = randomTree<S>(g, kFig141);
    std::vector<Mat6<S>> N = t0.homeInertias();
    N[5].setZero();
    const TreeDynamics<S> t(t0.topology(), t0.homeScrews(), N, t0.gravity());
    const DVS th = rvecS<S>(g, 6, 3), thd = rvecS<S>(g, 6), thdd = rvecS<S>(g, 6);
    using std::abs;
    // torques up to ~100 N·m: 4096 ε absolute (9.1e-13 in double)
    ctx.checkResidual("zero-mass leaf: τ₆ = 0 and the pass = joint equations (4096 ε)", std::max<S>(S(abs(S(t.inverseDynamics(th, thd, thdd)(5)))),
                      maxAbsS<S>(DVS(t.inverseDynamics(th, thd, thdd) - t.inverseDynamicsSpatial(th, thd, thdd)))), tol<S>(4096));
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

SOMA_STUDY_SCALAR("GF-14.1-tree-structure", "Tree of Fig. 14.1: ancestry, levels, partial order, cycles rejected", "GF §14.1", treeStructure);
SOMA_STUDY_SCALAR("GF-14.1.1-tree-joint-equations", "Joint equations over the subtree = Euler–Lagrange (erratum 1)", "GF §14.1.1", jointEquations);
SOMA_STUDY_SCALAR("GF-14.1.1-star-root-equation", "Free-floating star: root equation, momentum and energy conserved", "GF §14.1.1", starRoot);
SOMA_STUDY_SCALAR("GF-14.1.1-multi-dof-passive-joint", "Ball joint as three passive freedoms = body with a fixed point", "GF §14.1.1", ballJoint);
SOMA_STUDY_SCALAR("GF-14.1.2-tree-kinematics", "POE along the ancestry; star relative to the root", "GF §14.1.2", treeKinematics);
SOMA_STUDY_SCALAR("GF-14.1.2-tree-velocities-accelerations", "Tree velocities and accelerations = derivatives of K_i", "GF §14.1.2", treeVelocities);
SOMA_STUDY_SCALAR("GF-14.1.3-tree-recursive-dynamics", "Up/down Newton–Euler pass over a tree (errata 2, 3)", "GF §14.1.3", recursive);
SOMA_STUDY_DOUBLE("GF-14-fig-14.1", "Fig. 14.1: the tree-structured mechanism", "GF §14.1 Fig. 14.1", figure141);

}  // namespace soma::studies::gf14::SOMA_UNITY_ID
