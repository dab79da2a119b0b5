// Serial-robot dynamics (GF §13.2–13.5): the three formulations of the inverse dynamics — the
// recursive Newton–Euler algorithm (§13.3), the closed form A θ̈ + B θ̇ θ̇ + C (§13.2.2, errata 1, 2
// corrected) and the Euler–Lagrange equations obtained by DIFFERENTIATING the Lagrangian
// L = E_K − E_P (energies from link velocities and c.o.m. heights, never from A) — agree to 1e-12
// in double on random robots and states; structural identities for five scalars; edge inputs.
#include "soma/algebra/screw_bracket.hpp"
#include "soma/geometry/dynamics/serial_dynamics.hpp"

#include "serial_dynamics_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

namespace {
using Q = __float128;

/// τ by the Euler–Lagrange equations, differentiating L numerically in __float128:
///   ∂L/∂θ̇_i: central difference with step 1 — exact up to rounding because L is quadratic in θ̇;
///   d/dt ∂L/∂θ̇_i: 8th-order central difference of t ↦ ∂L/∂θ̇_i(θ + tθ̇ + ½t²θ̈, θ̇ + tθ̈);
///   ∂L/∂θ_i: 8th-order central difference.
/// With d = 2⁻⁸ the truncation bound d⁸ max|f⁽⁹⁾|/630 is ≈ 1e-22·max|f⁽⁹⁾| and the rounding
/// 2.3 ε_q max|f|/d ≈ 1e-31·max|f|: for f analytic with O(1–100) derivatives in radians the
/// Lagrangian τ is good to ~1e-19 relative, seven orders below the 1e-12 being tested.
DynVector<Q> lagrangeTorque(const SerialDynamics<Q>& r, const DynVector<Q>& th, const DynVector<Q>& thd,
                            const DynVector<Q>& thdd) {
  const int n = r.dof();
  auto L = [&](const DynVector<Q>& a, const DynVector<Q>& b) { return r.kineticEnergy(a, b) - r.potentialEnergy(a); };
  auto dLdv = [&](const DynVector<Q>& a, const DynVector<Q>& b, int i) {
    DynVector<Q> bp = b, bm = b;
    bp(i) += Q(1);
    bm(i) -= Q(1);
    return (L(a, bp) - L(a, bm)) / Q(2);
  };
  const Q d = Q(1) / Q(256);
  DynVector<Q> tau(n);
  for (int i = 0; i < n; ++i) {
    const Q ddt = centralDiff8<Q>(
        [&](const Q& t) {
          return dLdv(DynVector<Q>(th + t * thd + (t * t / Q(2)) * thdd), DynVector<Q>(thd + t * thdd), i);
        },
        d);
    const Q dth = centralDiff8<Q>(
        [&](const Q& t) {
          DynVector<Q> a = th;
          a(i) += t;
          return L(a, thd);
        },
        d);
    tau(i) = ddt - dth;
  }
  return tau;
}
template <class S> S maxAbs(const DynVector<S>& v) { return v.cwiseAbs().maxCoeff(); }

// GF §13.2.2 line 7899 as printed (erratum 1): C_i = +s_iᵀ N̄_i g
DynVector<double> gravityTorqueAsPrinted(const SerialDynamics<double>& r, const ChainConfiguration<double>& c) {
  DynVector<double> C(r.dof());
  for (int i = 0; i < r.dof(); ++i) C(i) = c.screws[std::size_t(i)].dot(c.tails[std::size_t(i)] * r.gravityScrew());
  return C;
}
// GF §13.2.2 lines 7889–7895 as printed (erratum 2): B_ijk θ̇_jθ̇_k with the third brackets
// [s_k, s_i] (j ≤ k) and [s_i, s_k] (k < j), x = max(i, j, k)
DynVector<double> coriolisTorqueAsPrinted(const ChainConfiguration<double>& c, const DynVector<double>& thd) {
  const int n = int(thd.size());
  DynVector<double> b = DynVector<double>::Zero(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Mat6<double>& N = c.tails[std::size_t(std::max(i, std::max(j, k)))];
        const Vec6<double>&si = c.screws[std::size_t(i)], &sj = c.screws[std::size_t(j)], &sk = c.screws[std::size_t(k)];
        const Vec6<double> third = j <= k ? screwBracket(sk, si) : screwBracket(si, sk);
        b(i) += thd(j) * thd(k) *
                (sj.dot(N * screwBracket(si, sk)) + sk.dot(N * screwBracket(si, sj)) - si.dot(N * third)) / 2;
      }
  return b;
}
// GF §13.4.3 lines 8206–8210 as printed (erratum 8): Q_ij = s_aᵀN̄_a[g, s_b], a = max, b = min
DynMatrix<double> potentialHessianAsPrinted(const SerialDynamics<double>& r, const DynVector<double>& th) {
  const ChainConfiguration<double> c = r.configuration(th);
  DynMatrix<double> H(r.dof(), r.dof());
  for (int a = 0; a < r.dof(); ++a)
    for (int b = 0; b <= a; ++b)
      H(a, b) = H(b, a) = c.screws[std::size_t(a)].dot(c.tails[std::size_t(a)] * screwBracket(r.gravityScrew(), c.screws[std::size_t(b)]));
  return H;
}
}  // namespace

TEST_CASE("serial dynamics: RNEA, closed form A/B/C, spatial formula and Lagrange agree to 1e-12 (double)",
          "[dynamics][serial]") {
  auto& g = rng(1330);
  double worstRc = 0, worstRs = 0, worstRl = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int n = 2 + trial % 6;  // 2 … 7 joints
    const RobotSpec spec = randomRobot(g, n, trial % 3 == 2);
    const SerialDynamics<double> r = build<double>(spec);
    const SerialDynamics<Q> rq = build<Q>(spec);
    const DynVector<double> th = randomJoints<double>(g, n, -3, 3), thd = randomJoints<double>(g, n, -2, 2),
                            thdd = randomJoints<double>(g, n, -2, 2);
    const DynVector<double> rnea = r.inverseDynamics(th, thd, thdd);
    const DynVector<double> closed = r.inverseDynamicsClosedForm(th, thd, thdd);
    const DynVector<double> spatial = r.inverseDynamicsSpatial(th, thd, thdd);
    const DynVector<double> lag =
        castVec<double>(lagrangeTorque(rq, castVec<Q>(th), castVec<Q>(thd), castVec<Q>(thdd)));
    const double scale = std::max(1.0, maxAbs(rnea));
    worstRc = std::max(worstRc, maxAbs<double>(rnea - closed) / scale);
    worstRs = std::max(worstRs, maxAbs<double>(rnea - spatial) / scale);
    worstRl = std::max(worstRl, maxAbs<double>(rnea - lag) / scale);
  }
  INFO("RNEA − closed " << worstRc << ", RNEA − spatial " << worstRs << ", RNEA − Lagrange " << worstRl);
  CHECK(worstRc <= 1e-12);
  CHECK(worstRs <= 1e-12);
  CHECK(worstRl <= 1e-12);
}

TEST_CASE("serial dynamics: the printed B and C (errata 1, 2) do not reproduce RNEA", "[dynamics][serial]") {
  auto& g = rng(1331);
  const RobotSpec spec = randomRobot(g, 5);
  const SerialDynamics<double> r = build<double>(spec);
  const DynVector<double> th = randomJoints<double>(g, 5), thd = randomJoints<double>(g, 5), z = DynVector<double>::Zero(5);
  const auto c = r.configuration(th);
  // C: RNEA with θ̇ = θ̈ = 0 is the gravity torque
  const DynVector<double> grav = r.inverseDynamics(th, z, z);
  CHECK(maxAbs<double>(grav - r.gravityTorque(c)) <= 1e-12 * maxAbs(grav));
  CHECK(maxAbs<double>(grav + gravityTorqueAsPrinted(r, c)) <= 1e-12 * maxAbs(grav));
  CHECK(maxAbs<double>(grav - gravityTorqueAsPrinted(r, c)) >= 0.1 * maxAbs(grav));
  // B: RNEA(θ, θ̇, 0) − C = B θ̇ θ̇
  const DynVector<double> cor = r.inverseDynamics(th, thd, z) - grav;
  const auto Bc = r.coriolisTensor(c);
  DynVector<double> bc(5);
  for (int i = 0; i < 5; ++i) bc(i) = thd.dot(Bc[std::size_t(i)] * thd);
  const DynVector<double> bp = coriolisTorqueAsPrinted(c, thd);
  CHECK(maxAbs<double>(cor - bc) <= 1e-12 * maxAbs(cor));
  CHECK(maxAbs<double>(cor - bp) >= 1e-2 * maxAbs(cor));
}

TEMPLATE_TEST_CASE("serial dynamics: the three inverse dynamics agree, A symmetric positive definite",
                   "[dynamics][serial][scalars]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1332);
  const bool mp = std::is_same_v<S, mpfr::mpreal>;
  const int trials = mp ? 2 : 8;
  // Error model: each τ_i is a sum of O(n²) products of O(1) numbers built from n exponentials;
  // we allow 512 ε relative to max |τ| (measured worst in double: ~30 ε; see the INFO line).
  const S tol = Tolerance<S>::identity(512);
  S worst = S(0);
  for (int t = 0; t < trials; ++t) {
    const int n = 3 + t % 4;
    const RobotSpec spec = randomRobot(g, n, t % 2 == 1);
    const SerialDynamics<S> r = build<S>(spec);
    const DynVector<S> th = randomJoints<S>(g, n, -3, 3), thd = randomJoints<S>(g, n), thdd = randomJoints<S>(g, n);
    const DynVector<S> a = r.inverseDynamics(th, thd, thdd);
    const DynVector<S> b = r.inverseDynamicsClosedForm(th, thd, thdd);
    const DynVector<S> c = r.inverseDynamicsSpatial(th, thd, thdd);
    S scale = maxAbs(a);
    if (scale < S(1)) scale = S(1);
    using std::max;
    worst = max(worst, S(max(maxAbs<S>(a - b), maxAbs<S>(a - c)) / scale));
    const DynMatrix<S> A = r.massMatrix(th);
    CHECK((A - A.transpose()).cwiseAbs().maxCoeff() == S(0));
    // the fast 3×3-block path equals the 6×6 path through configuration()
    CHECK((A - r.massMatrix(r.configuration(th))).cwiseAbs().maxCoeff() <= tol * A.cwiseAbs().maxCoeff());
    Eigen::LLT<DynMatrix<S>> llt(A);
    CHECK(llt.info() == Eigen::Success);
    // ½ θ̇ᵀ A θ̇ = E_K from the link velocities (GF-13.2.2-generalised-inertia-A)
    const S ek = r.kineticEnergy(th, thd);
    using std::abs;
    CHECK(abs(thd.dot(A * thd) / S(2) - ek) <= tol * ek);
  }
  INFO("worst relative disagreement " << toString(worst) << " (ε = " << toString(Tolerance<S>::epsilon()) << ")");
  CHECK(worst <= tol);
}

TEMPLATE_TEST_CASE("serial dynamics: B is the Christoffel symbol of A and dA/dt − 2B(θ̇) is skew",
                   "[dynamics][serial][scalars]", double, __float128) {
  using S = TestType;
  auto& g = rng(1333);
  const int n = 5;
  const RobotSpec spec = randomRobot(g, n);
  const SerialDynamics<S> r = build<S>(spec);
  const SerialDynamics<Q> rq = build<Q>(spec);
  const DynVector<S> th = randomJoints<S>(g, n), thd = randomJoints<S>(g, n);
  const auto B = r.coriolisTensor(th);
  // ∂_k A_ij by 8th-order differences in __float128 (error ≤ 1e-19 relative, see lagrangeTorque)
  std::vector<DynMatrix<S>> dA;
  for (int k = 0; k < n; ++k) {
    DynMatrix<S> m(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        m(i, j) = scalarCast<S>(centralDiff8<Q>(
            [&](const Q& t) {
              DynVector<Q> a = castVec<Q>(th);
              a(k) += t;
              return Q(rq.massMatrix(a)(i, j));
            },
            Q(1) / Q(256)));
    dA.push_back(m);
  }
  S worstC = S(0), worstSkew = S(0), scale = S(0);
  using std::abs;
  using std::max;
  DynMatrix<S> Adot = DynMatrix<S>::Zero(n, n), Cm = DynMatrix<S>::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const S chr = (dA[std::size_t(k)](i, j) + dA[std::size_t(j)](i, k) - dA[std::size_t(i)](j, k)) / S(2);
        worstC = max(worstC, S(abs(chr - B[std::size_t(i)](j, k))));
        scale = max(scale, S(abs(chr)));
        Adot(i, j) += dA[std::size_t(k)](i, j) * thd(k);
        Cm(i, j) += B[std::size_t(i)](j, k) * thd(k);
      }
  const DynMatrix<S> M = Adot - S(2) * Cm;
  worstSkew = (M + M.transpose()).cwiseAbs().maxCoeff() / M.cwiseAbs().maxCoeff();
  // The reference ∂A is an 8th-order difference in __float128 with d = 2⁻⁸: θ_k enters A through
  // R I Rᵀ (angular frequency ≤ 2), so |∂⁹A| ≤ 2⁹|A| and the truncation is ≤ d⁸·2⁹|A|/630 ≈ 4e-20|A|.
  // The check is therefore ε-tight in double and bounded by 1e-18 (that reference) in __float128.
  using std::max;
  const S tol = max(S(Tolerance<S>::identity(512)), S(1e-18));
  CHECK(worstC <= tol * scale);
  CHECK(worstSkew <= tol);
}

TEMPLATE_TEST_CASE("serial dynamics: gradients — ∂E_P/∂θ = C, ∂E_K/∂θ, Hessian Q of E_P (erratum 8)",
                   "[dynamics][serial]", double) {
  using S = TestType;
  auto& g = rng(1334);
  const int n = 6;
  const RobotSpec spec = randomRobot(g, n);
  const SerialDynamics<S> r = build<S>(spec);
  const SerialDynamics<Q> rq = build<Q>(spec);
  const DynVector<S> th = randomJoints<S>(g, n), thd = randomJoints<S>(g, n);
  const DynVector<S> C = r.gravityTorque(th), gk = r.kineticEnergyGradient(th, thd);
  const DynMatrix<S> H = r.potentialHessian(th), Hp = potentialHessianAsPrinted(r, th);
  const Q d = Q(1) / Q(256);
  S eC = 0, eK = 0, eH = 0, eHp = 0;
  for (int i = 0; i < n; ++i) {
    auto shifted = [&](const Q& t) {
      DynVector<Q> a = castVec<Q>(th);
      a(i) += t;
      return a;
    };
    eC = std::max(eC, std::abs(double(centralDiff8<Q>([&](const Q& t) { return rq.potentialEnergy(shifted(t)); }, d)) - C(i)));
    eK = std::max(eK, std::abs(double(centralDiff8<Q>([&](const Q& t) { return rq.kineticEnergy(shifted(t), castVec<Q>(thd)); }, d)) - gk(i)));
    for (int j = 0; j < n; ++j) {
      const double fd = double(centralDiff8<Q>([&](const Q& t) { return rq.gravityTorque(shifted(t))(j); }, d));
      eH = std::max(eH, std::abs(fd - H(i, j)));
      eHp = std::max(eHp, std::abs(fd - Hp(i, j)));
    }
  }
  CHECK(eC <= 1e-12 * C.cwiseAbs().maxCoeff());
  CHECK(eK <= 1e-12 * gk.cwiseAbs().maxCoeff());
  CHECK(eH <= 1e-12 * H.cwiseAbs().maxCoeff());
  CHECK(eHp >= 0.5 * H.cwiseAbs().maxCoeff());  // the printed sign fails
  CHECK((H - H.transpose()).cwiseAbs().maxCoeff() == 0);
}

TEMPLATE_TEST_CASE("serial dynamics: payload increments A^p, B^p, C^p (GF §13.2.3)", "[dynamics][serial][scalars]",
                   SOMA_TEST_SCALARS_FAST) {
  using S = TestType;
  auto& g = rng(1335);
  const int n = 4;
  const RobotSpec spec = randomRobot(g, n);
  const SerialDynamics<S> r = build<S>(spec);
  const SpatialInertia<S> p(S(2), Vec3<S>(S(0.3), S(-0.2), S(0.5)), Mat3<S>(Vec3<S>(S(0.1), S(0.2), S(0.15)).asDiagonal()));
  const SerialDynamics<S> rp = r.withPayload(p);
  const DynVector<S> th = randomJoints<S>(g, n);
  const auto terms = r.payloadTerms(th, p);
  const S tol = Tolerance<S>::identity(512);
  const DynMatrix<S> dA = rp.massMatrix(th) - r.massMatrix(th);
  CHECK((dA - terms.A).cwiseAbs().maxCoeff() <= tol * dA.cwiseAbs().maxCoeff());
  const DynVector<S> dC = rp.gravityTorque(th) - r.gravityTorque(th);
  CHECK((dC - terms.C).cwiseAbs().maxCoeff() <= tol * dC.cwiseAbs().maxCoeff());
  const auto B1 = rp.coriolisTensor(th), B0 = r.coriolisTensor(th);
  S worst = 0, scale = 0;
  for (int i = 0; i < n; ++i) {
    using std::max;
    worst = max(worst, S((B1[std::size_t(i)] - B0[std::size_t(i)] - terms.B[std::size_t(i)]).cwiseAbs().maxCoeff()));
    scale = max(scale, S(terms.B[std::size_t(i)].cwiseAbs().maxCoeff()));
  }
  CHECK(worst <= tol * scale);
}

TEST_CASE("serial dynamics: forward dynamics inverts RNEA — Hamilton's equations match Lagrange's",
          "[dynamics][serial]") {
  auto& g = rng(1336);
  const int n = 6;
  const RobotSpec spec = randomRobot(g, n);
  const SerialDynamics<double> r = build<double>(spec);
  const DynVector<double> th = randomJoints<double>(g, n), thd = randomJoints<double>(g, n), tau = randomJoints<double>(g, n, -5, 5);
  const DynVector<double> acc = r.forwardDynamics(th, thd, tau);
  CHECK(maxAbs<double>(r.inverseDynamics(th, thd, acc) - tau) <= 1e-12 * maxAbs(tau));
  // Hamilton: θ̇ = A⁻¹π gives back θ̇; π̇ = d/dt (A θ̇) along the Lagrangian motion = Ȧθ̇ + Aθ̈
  const DynVector<double> pi = r.momentum(th, thd);
  DynVector<double> qd, pd;
  r.hamiltonField(th, pi, tau, qd, pd);
  CHECK(maxAbs<double>(qd - thd) <= 1e-12 * maxAbs(thd));
  const SerialDynamics<Q> rq = build<Q>(spec);
  DynVector<double> want(n);
  for (int i = 0; i < n; ++i)
    want(i) = double(centralDiff8<Q>(
        [&](const Q& t) {
          const DynVector<Q> a = castVec<Q>(th) + t * castVec<Q>(thd) + (t * t / Q(2)) * castVec<Q>(acc);
          return Q((rq.massMatrix(a) * DynVector<Q>(castVec<Q>(thd) + t * castVec<Q>(acc)))(i));
        },
        Q(1) / Q(256)));
  CHECK(maxAbs<double>(pd - want) <= 1e-12 * maxAbs(want));
  CHECK(std::abs(r.hamiltonian(th, pi) - r.kineticEnergy(th, thd) - r.potentialEnergy(th)) <=
        1e-14 * (r.kineticEnergy(th, thd) + std::abs(r.potentialEnergy(th))));
}

TEST_CASE("serial dynamics: bad input is InvalidInput", "[dynamics][serial][edge]") {
  auto& g = rng(1337);
  const RobotSpec spec = randomRobot(g, 3);
  // massless link: rejected by SpatialInertia (GF-13.1 extreme m → 0)
  CHECK_THROWS_AS(SpatialInertia<double>(0.0, Vec3<double>::Zero(), Mat3<double>::Identity()), InvalidInput);
  Mat6<double> N = Mat6<double>::Zero();
  N.topLeftCorner<3, 3>().setIdentity();
  CHECK_THROWS_AS(SpatialInertia<double>::fromMatrix(N), InvalidInput);  // m = 0 in the 6×6 form
  std::vector<SE3Tangent<double>> s;
  std::vector<SpatialInertia<double>> l;
  for (int i = 0; i < 3; ++i) {
    s.emplace_back(spec.screws[std::size_t(i)]);
    l.emplace_back(spec.masses[std::size_t(i)], spec.coms[std::size_t(i)], spec.inertias[std::size_t(i)]);
  }
  CHECK_NOTHROW(SerialDynamics<double>(s, l, 9.81));
  CHECK_THROWS_AS(SerialDynamics<double>(s, l, -1.0), InvalidInput);
  CHECK_THROWS_AS(SerialDynamics<double>({}, {}, 9.81), InvalidInput);
  auto l2 = l;
  l2.pop_back();
  CHECK_THROWS_AS(SerialDynamics<double>(s, l2, 9.81), InvalidInput);
  auto s2 = s;
  s2[1] = SE3Tangent<double>(Vec6<double>(s[1].coeffs() * 2));
  CHECK_THROWS_AS(SerialDynamics<double>(s2, l, 9.81), InvalidInput);
  const SerialDynamics<double> r(s, l, 9.81);
  CHECK_THROWS_AS(r.inverseDynamics(DynVector<double>::Zero(2), DynVector<double>::Zero(3), DynVector<double>::Zero(3)),
                  InvalidInput);
  DynVector<double> bad = DynVector<double>::Zero(3);
  bad(1) = std::nan("");
  CHECK_THROWS_AS(r.massMatrix(bad), InvalidInput);
  CHECK_THROWS_AS(r.forwardDynamics(DynVector<double>::Zero(3), DynVector<double>::Zero(3), bad), InvalidInput);
}

TEST_CASE("serial dynamics: singular posture and huge/small scales", "[dynamics][serial][edge]") {
  auto& g = rng(1338);
  const RobotSpec spec = randomRobot(g, 6);
  const DynVector<double> th = randomJoints<double>(g, 6), thd = randomJoints<double>(g, 6), thdd = randomJoints<double>(g, 6);
  const DynVector<double> base = build<double>(spec).inverseDynamics(th, thd, thdd);
  // lengths × λ, masses × μ, g × λ: every term of τ scales by μλ² (dimensional analysis)
  for (const double lam : {1e-3, 1e3}) {
    for (const double mu : {1e-3, 1e3}) {
      const SerialDynamics<double> r = build<double>(spec, lam, mu);
      const DynVector<double> a = r.inverseDynamics(th, thd, thdd), b = r.inverseDynamicsClosedForm(th, thd, thdd);
      const double scale = mu * lam * lam;
      CHECK(maxAbs<double>(a / scale - base) <= 1e-12 * maxAbs(base));
      CHECK(maxAbs<double>(b / scale - base) <= 1e-12 * maxAbs(base));
    }
  }
  // a kinematically singular posture: two joint axes made collinear (same screw) — A stays PD
  // (GF-13.2.2-generalised-inertia-A extremes) and the formulations still agree.
  RobotSpec sing = spec;
  sing.screws[2] = sing.screws[1];
  const SerialDynamics<double> r = build<double>(sing);
  const DynVector<double> z = DynVector<double>::Zero(6);
  Eigen::LLT<DynMatrix<double>> llt(r.massMatrix(z));
  CHECK(llt.info() == Eigen::Success);
  const DynVector<double> a = r.inverseDynamics(z, thd, thdd), b = r.inverseDynamicsClosedForm(z, thd, thdd);
  CHECK(maxAbs<double>(a - b) <= 1e-12 * maxAbs(a));
}

}  // namespace SOMA_UNITY_ID
