// Studies of GF §13.5 (double, with __float128 differences): Hamilton's equations against
// Lagrange's, canonical (symplectic) point transformations and Poisson brackets (erratum 10).
#include "gf13/common.hpp"

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

void hamiltonian(Context& ctx) {
  auto g = std::mt19937_64(1347);
  const SerialDynamics<double> r = randomRobot(g, 4);
  const DV th = rjoints(g, 4), thd = rjoints(g, 4), tau = rjoints(g, 4, -2, 2);
  // ½ ∂_iA_jk θ̇_jθ̇_k = B_jik θ̇_jθ̇_k; the printed Σ B_ijk θ̇_jθ̇_k is the Coriolis torque instead
  const auto B = r.coriolisTensor(th);
  const DV gk = r.kineticEnergyGradient(th, thd);
  DV bji = DV::Zero(4), bij = DV::Zero(4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        bji(i) += B[std::size_t(j)](i, k) * thd(j) * thd(k);
        bij(i) += B[std::size_t(i)](j, k) * thd(j) * thd(k);
      }
  ctx.checkResidual("½∂_iA_jkθ̇_jθ̇_k = B_jikθ̇_jθ̇_k (relative)", maxAbs(DV(gk - bji)) / maxAbs(gk), 1e-13);
  ctx.checkPrintedFails("π̇_i = B_ijkθ̇_iθ̇_k − C_i + τ_i (line 8289), read as B_ijkθ̇_jθ̇_k", "10", maxAbs(DV(gk - bij)) / maxAbs(gk), 1e-6);
  // Hamilton (RK4 on (θ, π)) and Lagrange (RK4 on (θ, θ̇)) from the same state agree
  JointState<double> y{th, thd};
  DV q = th, p = r.momentum(th, thd);
  const double h = 1e-3;
  auto field = [&](const DV& a, const DV& b, DV& da, DV& db) { r.hamiltonField(a, b, tau, da, db); };
  for (int k = 0; k < 1000; ++k) {
    y = rk4Step(r, y, h, tau);
    DV a1, b1, a2, b2, a3, b3, a4, b4;
    field(q, p, a1, b1);
    field(DV(q + h / 2 * a1), DV(p + h / 2 * b1), a2, b2);
    field(DV(q + h / 2 * a2), DV(p + h / 2 * b2), a3, b3);
    field(DV(q + h * a3), DV(p + h * b3), a4, b4);
    q += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    p += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
  }
  ctx.checkResidual("Hamilton's and Lagrange's equations, RK4 h = 1 ms, 1 s with τ ≠ 0: |θ_H − θ_L|", maxAbs(DV(q - y.theta)), 1e-9);
  ctx.checkResidual("and π_H = A θ̇_L (relative)", maxAbs(DV(p - r.momentum(y.theta, y.thetaDot))) / maxAbs(p), 1e-9);
  ctx.note("Both are order 4 in h; they differ by their truncation errors (≈ h⁴). Energy behaviour of the symplectic "
           "midpoint rule: GF-13.4-lagrangian-energies.");
}

void canonical(Context& ctx) {
  auto g = std::mt19937_64(1348);
  const int n = 3;
  DM E = DM::Zero(2 * n, 2 * n);
  E.topRightCorner(n, n).setIdentity();
  E.bottomLeftCorner(n, n) = -DM::Identity(n, n);
  auto phi = [&](const DV& t) {
    DV f(n);
    for (int i = 0; i < n; ++i) f(i) = t(i) + 0.3 * std::sin(t((i + 1) % n)) + 0.1 * t(i) * t(i);
    return f;
  };
  auto Kof = [&](const DV& t) {
    DM K(n, n);
    for (int j = 0; j < n; ++j) {
      K.col(j) = dmat([&](double u) {
        DV a = t;
        a(j) += u;
        return phi(a);
      });
    }
    return K;
  };
  double worst = 0, bad = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const DV t = rjoints(g, n, -0.5, 0.5), p = rjoints(g, n);
    auto F = [&](const DV& x, bool canon) {
      const DV a = x.head(n), b = x.tail(n);
      const DM K = Kof(a);
      DV out(2 * n);
      out.head(n) = phi(a);
      out.tail(n) = canon ? DV(K.transpose().partialPivLu().solve(b)) : DV(K * b);
      return out;
    };
    DV x(2 * n);
    x << t, p;
    for (const bool canon : {true, false}) {
      DM Jm(2 * n, 2 * n);
      for (int j = 0; j < 2 * n; ++j)
        Jm.col(j) = dmat([&](double u) {
          DV a = x;
          a(j) += u;
          return F(a, canon);
        }, 1e-3);
      const double res = maxAbs(DM(Jm * E * Jm.transpose() - E));
      if (canon) worst = std::max(worst, res);
      else bad = std::max(bad, res);
    }
  }
  // nested 4th-order differences (d = 1e-3): error ≈ d⁴·|f⁽⁵⁾| ≈ 1e-11 per level
  ctx.checkResidual("point transformation φ(θ), π' = K⁻ᵀπ: J E Jᵀ = E (10 random points)", worst, 1e-8);
  ctx.checkPrintedFails("non-canonical π' = Kπ (control): J E Jᵀ = E", "— (control, not an erratum)", bad, 1e-8);
}

void poisson(Context& ctx) {
  auto g = std::mt19937_64(1349);
  // Jacobi identity on random quadratic functions f = ½xᵀFx + aᵀx of x = (θ, π), 2 dof: ∇f = Fx + a
  const int d = 4;
  DM E = DM::Zero(d, d);
  E.topRightCorner(2, 2).setIdentity();
  E.bottomLeftCorner(2, 2) = -DM::Identity(2, 2);
  struct Quad {
    DM F;
    DV a;
  };
  auto rq = [&]() {
    Quad q{DM(d, d), DV(d)};
    for (int i = 0; i < d; ++i) {
      q.a(i) = uni(g);
      for (int j = 0; j <= i; ++j) q.F(i, j) = q.F(j, i) = uni(g);
    }
    return q;
  };
  // [f, g] = ∇fᵀE∇g is quadratic: matrix F E G − G E F (symmetrised), linear part from the cross terms
  auto bracket = [&](const Quad& f, const Quad& h) {
    Quad o{DM(f.F * E * h.F - h.F * E * f.F), DV(f.F * E * h.a - h.F * E * f.a)};
    return o;  // ∇[f, h] = o.F x + o.a
  };
  double jac = 0;
  for (int t = 0; t < 50; ++t) {
    const Quad f = rq(), h = rq(), k = rq();
    const DV x = rjoints(g, d);
    auto val = [&](const Quad& a, const Quad& b) { return DV(a.F * x + a.a).dot(E * DV(b.F * x + b.a)); };
    jac = std::max(jac, abs(val(f, bracket(h, k)) + val(h, bracket(k, f)) + val(k, bracket(f, h))));
  }
  ctx.checkResidual("Jacobi identity [f,[g,k]] + [g,[k,f]] + [k,[f,g]] = 0 (50 random quadratic triples)", jac, 1e-13);
  // [θ_i, h] = A⁻¹π, [π_i, h] = −∂h/∂θ_i = B_jikθ̇_jθ̇_k − C_i (differences of h in __float128)
  const SerialDynamics<double> r = randomRobot(g, 4);
  const SerialDynamics<Q> rqd = castRobot<Q>(r);
  const DV th = rjoints(g, 4), thd = rjoints(g, 4), z = DV::Zero(4);
  const DV p = r.momentum(th, thd);
  DV qdot, pdot;
  r.hamiltonField(th, p, z, qdot, pdot);
  double et = 0, ep = 0;
  for (int i = 0; i < 4; ++i) {
    et = std::max(et, abs(dq([&](const Q& u) {
                            DynVector<Q> b = castV<Q>(p);
                            b(i) += u;
                            return rqd.hamiltonian(castV<Q>(th), b);
                          }) - qdot(i)));
    ep = std::max(ep, abs(-dq([&](const Q& u) {
                             DynVector<Q> a = castV<Q>(th);
                             a(i) += u;
                             return rqd.hamiltonian(a, castV<Q>(p));
                           }) - pdot(i)));
  }
  ctx.checkResidual("[θ_i, h] = ∂h/∂π_i = A⁻¹_ijπ_j = θ̇_i", et / maxAbs(qdot), 1e-12);
  ctx.checkResidual("[π_i, h] = −∂h/∂θ_i = B_jikθ̇_jθ̇_k − C_i (corrected, erratum 10)", ep / maxAbs(pdot), 1e-12);
  // dh/dt = [h, h] + ∂h/∂π_i τ_i = θ̇ᵀτ along a forced motion
  const DV tau = rjoints(g, 4, -3, 3);
  const double dhdt = dq([&](const Q& t) {
    const SerialDynamics<Q>& rr = rqd;
    DynVector<Q> a = castV<Q>(th), v = castV<Q>(thd);
    const DynVector<Q> acc = rr.forwardDynamics(a, v, castV<Q>(tau));
    // second-order Taylor state along the motion is enough for the first derivative at t = 0
    return rr.kineticEnergy(DynVector<Q>(a + t * v + t * t / 2 * acc), DynVector<Q>(v + t * acc)) +
           rr.potentialEnergy(DynVector<Q>(a + t * v + t * t / 2 * acc));
  });
  ctx.checkNear("df/dt = [f, h] + ∂f/∂π_iτ_i for f = h: dh/dt = θ̇ᵀτ (power)", thd.dot(tau), dhdt, 1e-12 * abs(thd.dot(tau)) + 1e-13);
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-13.5-hamiltonian", "Hamilton's equations π̇_i = B_jikθ̇_jθ̇_k − C_i + τ_i (erratum 10)", "GF §13.5", hamiltonian);
SOMA_STUDY_DOUBLE("GF-13.5-canonical-symplectic", "Point transformations with π' = K⁻ᵀπ are canonical: JEJᵀ = E", "GF §13.5", canonical);
SOMA_STUDY_DOUBLE("GF-13.5-poisson-bracket", "Poisson brackets: Jacobi identity, [θ, h], [π, h], dh/dt = θ̇ᵀτ (erratum 10)", "GF §13.5", poisson);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
