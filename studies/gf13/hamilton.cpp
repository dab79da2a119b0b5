// Studies of GF §13.5 (in the asked scalar; reference differences in __float128 below it, in S for
// __float128 and mpfr): Hamilton's equations against
// Lagrange's, canonical (symplectic) point transformations and Poisson brackets (erratum 10).
#include "gf13/common.hpp"

#include "soma/algebra/small_linalg.hpp"

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

template <class S> void hamiltonian(Context& ctx) {
  using DVS = DynVector<S>;
  auto g = std::mt19937_64(1347);
  const SerialDynamics<S> r = castRobotUnit<S>(randomRobot(g, 4));
  const DVS th = rjointsS<S>(g, 4), thd = rjointsS<S>(g, 4), tau = rjointsS<S>(g, 4, -2, 2);
  // ½ ∂_iA_jk θ̇_jθ̇_k = B_jik θ̇_jθ̇_k; the printed Σ B_ijk θ̇_jθ̇_k is the Coriolis torque instead
  const auto B = r.coriolisTensor(th);
  const DVS gk = r.kineticEnergyGradient(th, thd);
  DVS bji = DVS::Zero(4), bij = DVS::Zero(4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        bji(i) += B[std::size_t(j)](i, k) * thd(j) * thd(k);
        bij(i) += B[std::size_t(i)](j, k) * thd(j) * thd(k);
      }
  // two closed forms from 4 tail sums of 6×6 products, relative: 512 ε (1.1e-13 in double; 1e-13 before)
  ctx.checkResidual("½∂_iA_jkθ̇_jθ̇_k = B_jikθ̇_jθ̇_k (relative, 512 ε)", S(maxAbsOf(DVS(gk - bji)) / maxAbsOf(gk)), tol<S>(512));
  ctx.checkPrintedFails("π̇_i = B_ijkθ̇_iθ̇_k − C_i + τ_i (line 8289), read as B_ijkθ̇_jθ̇_k", "10", S(maxAbsOf(DVS(gk - bij)) / maxAbsOf(gk)),
                        tol<S>(512));
  // Hamilton (RK4 on (θ, π)) and Lagrange (RK4 on (θ, θ̇)) from the same state agree
  JointState<S> y{th, thd};
  DVS q = th, p = r.momentum(th, thd);
  const S h = frac<S>(1, 1000);
  auto field = [&](const DVS& a, const DVS& b, DVS& da, DVS& db) { r.hamiltonField(a, b, tau, da, db); };
  for (int k = 0; k < 1000; ++k) {
    y = rk4Step(r, y, h, tau);
    DVS a1, b1, a2, b2, a3, b3, a4, b4;
    field(q, p, a1, b1);
    field(DVS(q + h / S(2) * a1), DVS(p + h / S(2) * b1), a2, b2);
    field(DVS(q + h / S(2) * a2), DVS(p + h / S(2) * b2), a3, b3);
    field(DVS(q + h * a3), DVS(p + h * b3), a4, b4);
    q += h / S(6) * (a1 + S(2) * a2 + S(2) * a3 + a4);
    p += h / S(6) * (b1 + S(2) * b2 + S(2) * b3 + b4);
  }
  // both order 4: their truncation errors over 1 s, 1000 h⁴ (1e-9, the bound before), plus the rounding
  // of 1000 steps, 64 ε each
  const S bound = S(1000) * h * h * h * h + tol<S>(64 * 1000);
  ctx.checkResidual("Hamilton's and Lagrange's equations, RK4 h = 1 ms, 1 s with τ ≠ 0: |θ_H − θ_L| (1000 h⁴ + 1000 · 64 ε)",
                    maxAbsOf(DVS(q - y.theta)), bound);
  ctx.checkResidual("and π_H = A θ̇_L (relative; 1000 h⁴ + 1000 · 64 ε)", S(maxAbsOf(DVS(p - r.momentum(y.theta, y.thetaDot))) / maxAbsOf(p)), bound);
  ctx.note("Both are order 4 in h; they differ by their truncation errors (≈ h⁴). Energy behaviour of the symplectic "
           "midpoint rule: GF-13.4-lagrangian-energies.");
}

template <class S> void canonical(Context& ctx) {
  using R = Ref<S>;
  using M3R = Mat3<R>;
  using V3R = Vec3<R>;
  using V6R = Vec6<R>;
  auto g = std::mt19937_64(1348);
  constexpr int n = 3;
  Mat6<S> E = Mat6<S>::Zero();
  E.template topRightCorner<n, n>().setIdentity();
  E.template bottomLeftCorner<n, n>() = -Mat3<S>::Identity();
  const R c3 = R(3) / R(10), c1 = R(1) / R(10);
  auto phi = [&](const V3R& t) {
    using std::sin;
    V3R f;
    for (int i = 0; i < n; ++i) f(i) = t(i) + c3 * sin(t((i + 1) % n)) + c1 * t(i) * t(i);
    return f;
  };
  // K = ∂φ/∂θ, written out: K_ii = 1 + 0.2 θ_i, K_i,i+1 = 0.3 cos θ_{i+1}
  auto Kof = [&](const V3R& t) {
    using std::cos;
    M3R K = M3R::Zero();
    for (int i = 0; i < n; ++i) {
      K(i, i) = R(1) + R(2) * c1 * t(i);
      K(i, (i + 1) % n) += c3 * cos(t((i + 1) % n));
    }
    return K;
  };
  S worst = 0, bad = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const DynVector<S> t = rjointsS<S>(g, n, -0.5, 0.5), p = rjointsS<S>(g, n);
    auto F = [&](const V6R& x, bool canon) {
      const V3R a = x.template head<3>(), b = x.template tail<3>();
      const M3R K = Kof(a);
      V6R out;
      out.template head<3>() = phi(a);
      V3R pb = b;
      if (canon)
        detail::smallSolveInPlace<R, 3>(M3R(K.transpose()), pb);
      else
        pb = K * b;
      out.template tail<3>() = pb;
      return out;
    };
    V6R x;
    x << castMatrix<R>(t), castMatrix<R>(p);
    for (const bool canon : {true, false}) {
      Mat6<S> Jm;
      for (int j = 0; j < 2 * n; ++j)
        Jm.col(j) = refDiffM<S>([&](const R& u) {
          V6R a = x;
          a(j) += u;
          return F(a, canon);
        });
      const S res = maxAbsOf(Mat6<S>(Jm * E * Jm.transpose() - E));
      if (canon) worst = maxOf(worst, res);
      else bad = maxOf(bad, res);
    }
  }
  // J E Jᵀ of O(1) entries: 64 ε, plus the difference bound of J (K written out, J by one level of
  // reference differences; before: nested 4th-order differences at d = 1e-3 with the bound 1e-8)
  const S bound = tol<S>(64) + refTol<S>();
  ctx.checkResidual(std::string("point transformation φ(θ), π' = K⁻ᵀπ: J E Jᵀ = E (10 random points; J by ") + refHow<S>() +
                        ", 64 ε + difference bound)", worst, bound);
  ctx.checkPrintedFails("non-canonical π' = Kπ (control): J E Jᵀ = E", "— (control, not an erratum)", bad, bound);
}

template <class S> void poisson(Context& ctx) {
  using R = Ref<S>;
  using DVS = DynVector<S>;
  using DMS = DynMatrix<S>;
  auto g = std::mt19937_64(1349);
  // Jacobi identity on random quadratic functions f = ½xᵀFx + aᵀx of x = (θ, π), 2 dof: ∇f = Fx + a
  const int d = 4;
  DMS E = DMS::Zero(d, d);
  E.topRightCorner(2, 2).setIdentity();
  E.bottomLeftCorner(2, 2) = -DMS::Identity(2, 2);
  struct Quad {
    DMS F;
    DVS a;
  };
  auto rq = [&]() {
    Quad q{DMS(d, d), DVS(d)};
    for (int i = 0; i < d; ++i) {
      q.a(i) = uni<S>(g);
      for (int j = 0; j <= i; ++j) q.F(i, j) = q.F(j, i) = uni<S>(g);
    }
    return q;
  };
  // [f, g] = ∇fᵀE∇g is quadratic: matrix F E G − G E F (symmetrised), linear part from the cross terms
  auto bracket = [&](const Quad& f, const Quad& h) {
    Quad o{DMS(f.F * E * h.F - h.F * E * f.F), DVS(f.F * E * h.a - h.F * E * f.a)};
    return o;  // ∇[f, h] = o.F x + o.a
  };
  S jac = 0;
  for (int t = 0; t < 50; ++t) {
    const Quad f = rq(), h = rq(), k = rq();
    const DVS x = rjointsS<S>(g, d);
    auto val = [&](const Quad& a, const Quad& b) { return S(DVS(a.F * x + a.a).dot(E * DVS(b.F * x + b.a))); };
    jac = maxOf(jac, S(abs(S(val(f, bracket(h, k)) + val(h, bracket(k, f)) + val(k, bracket(f, h))))));
  }
  // triple products of 4×4 matrices with entries ≤ 1 (terms up to ≈ 50): 512 ε (1.1e-13 in double; 1e-13 before)
  ctx.checkResidual("Jacobi identity [f,[g,k]] + [g,[k,f]] + [k,[f,g]] = 0 (50 random quadratic triples, 512 ε)", jac, tol<S>(512));
  // [θ_i, h] = A⁻¹π, [π_i, h] = −∂h/∂θ_i = B_jikθ̇_jθ̇_k − C_i (reference differences of h)
  const SerialDynamics<double> rd = randomRobot(g, 4);
  const SerialDynamics<S> r = castRobotUnit<S>(rd);
  const SerialDynamics<R> rqd = castRobotUnit<R>(rd);
  const DVS th = rjointsS<S>(g, 4), thd = rjointsS<S>(g, 4), z = DVS::Zero(4);
  const DVS p = r.momentum(th, thd);
  DVS qdot, pdot;
  r.hamiltonField(th, p, z, qdot, pdot);
  S et = 0, ep = 0;
  for (int i = 0; i < 4; ++i) {
    et = maxOf(et, S(abs(S(refDiff<S>([&](const R& u) {
                             DynVector<R> b = castV<R>(p);
                             b(i) += u;
                             return R(rqd.hamiltonian(castV<R>(th), b));
                           }) - qdot(i)))));
    ep = maxOf(ep, S(abs(S(-refDiff<S>([&](const R& u) {
                              DynVector<R> a = castV<R>(th);
                              a(i) += u;
                              return R(rqd.hamiltonian(a, castV<R>(p)));
                            }) - pdot(i)))));
  }
  // A⁻¹π through a 4×4 solve and B, C from tail sums, relative: 4096 ε (9.1e-13 in double; 1e-12
  // before), plus the difference bound
  const S bound = tol<S>(4096) + refTol<S>();
  ctx.checkResidual("[θ_i, h] = ∂h/∂π_i = A⁻¹_ijπ_j = θ̇_i (4096 ε + difference bound)", S(et / maxAbsOf(qdot)), bound);
  ctx.checkResidual("[π_i, h] = −∂h/∂θ_i = B_jikθ̇_jθ̇_k − C_i (corrected, erratum 10; 4096 ε + difference bound)", S(ep / maxAbsOf(pdot)), bound);
  // dh/dt = [h, h] + ∂h/∂π_i τ_i = θ̇ᵀτ along a forced motion
  const DVS tau = rjointsS<S>(g, 4, -3, 3);
  const DynVector<R> a0 = castV<R>(th), v0 = castV<R>(thd);
  const DynVector<R> acc = rqd.forwardDynamics(a0, v0, castV<R>(tau));
  // the path's time scale T = 1/√max(1, |θ̈|∞): differentiated in s = t/T, where its derivatives are O(1)
  // (at the fixed step 2⁻⁸ in t the 8th-order truncation of this path, |θ̈| ≈ 50, was 7.5e-15 relative);
  // the difference bound scales by 1/T
  using std::sqrt;
  const R T = R(1) / R(sqrt(std::max<R>(R(1), R(acc.cwiseAbs().maxCoeff()))));
  const S dhdt = refDiff<S>([&](const R& s) {
    const R t = T * s;
    // second-order Taylor state along the motion is enough for the first derivative at t = 0
    return R(rqd.kineticEnergy(DynVector<R>(a0 + t * v0 + t * t / R(2) * acc), DynVector<R>(v0 + t * acc)) +
             rqd.potentialEnergy(DynVector<R>(a0 + t * v0 + t * t / R(2) * acc)));
  }) / scalarCast<S>(T);
  const S power = thd.dot(tau);
  ctx.checkNear("df/dt = [f, h] + ∂f/∂π_iτ_i for f = h: dh/dt = θ̇ᵀτ (power; 4096 ε|θ̇ᵀτ| + 512 ε + difference bound / T)", power, dhdt,
                S(tol<S>(4096) * abs(power) + tol<S>(512) + refTol<S>() / scalarCast<S>(T)));
}

}  // namespace

SOMA_STUDY_SCALAR("GF-13.5-hamiltonian", "Hamilton's equations π̇_i = B_jikθ̇_jθ̇_k − C_i + τ_i (erratum 10)", "GF §13.5", hamiltonian);
SOMA_STUDY_SCALAR("GF-13.5-canonical-symplectic", "Point transformations with π' = K⁻ᵀπ are canonical: JEJᵀ = E", "GF §13.5", canonical);
SOMA_STUDY_SCALAR("GF-13.5-poisson-bracket", "Poisson brackets: Jacobi identity, [θ, h], [π, h], dh/dt = θ̇ᵀτ (erratum 10)", "GF §13.5", poisson);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
