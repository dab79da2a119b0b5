// Representation theory (GF ch. 7, algebra/rep/): the so(3) irreps in the ladder basis,
// Kronecker sums, Clebsch–Gordan by Casimir multiplicities, Sym^n and ⋀^n, the se(3)
// representations and their Casimirs (erratum E7.6), the invariant forms, transference and the
// dual angle of an SO(3, 𝔻) matrix.
#include "soma/algebra/lie_algebra.hpp"
#include "soma/algebra/rep/direct_sum.hpp"
#include "soma/algebra/rep/dual_angle_axis.hpp"
#include "soma/algebra/rep/exterior_power.hpp"
#include "soma/algebra/rep/se3_casimirs.hpp"
#include "soma/algebra/rep/so3_irrep.hpp"
#include "soma/algebra/reciprocal_product.hpp"
#include "soma/algebra/rep/subrepresentation.hpp"
#include "soma/algebra/rep/symmetric_power.hpp"
#include "soma/algebra/screw.hpp"
#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::rep;
using namespace soma::test;

namespace {
template <class T> auto absOf(const T& x) {
  using std::abs;
  return abs(x);
}
template <class S> S absOf(const std::complex<S>& z) {
  using std::abs;
  return abs(z.real()) + abs(z.imag());  // ≥ |z|, no complex abs (generic for mpreal, float128)
}
template <class D> auto maxAbs(const Eigen::MatrixBase<D>& m) {
  decltype(absOf(m(0, 0))) r(0);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (absOf(m(i, j)) > r) r = absOf(m(i, j));
  return r;
}
template <class M> M comm(const M& a, const M& b) { return M(a * b - b * a); }
template <class S> int nullity(const Matrix<S>& m) {
  Eigen::FullPivLU<Matrix<S>> lu(m);
  lu.setThreshold(Tolerance<S>::rank());
  return int(m.cols() - lu.rank());
}
}  // namespace

TEMPLATE_TEST_CASE("so(3) irreps L_j: ladder relations, Casimir, representation of so(3)", "[rep]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(701);
  for (int twoJ = 0; twoJ <= 10; ++twoJ) {
    const So3Irrep<S> l = so3Irrep<S>(twoJ);
    INFO("2j = " << twoJ);
    // GF-7.3-so3-ladder-relations in the real form J₃ = iH: [H, J±] = ±J±, [J₊, J₋] = −2H (integers: exact).
    CHECK(maxAbs(Matrix<S>(comm(l.H, l.Jp) - l.Jp)) == S(0));
    CHECK(maxAbs(Matrix<S>(comm(l.H, l.Jm) + l.Jm)) == S(0));
    CHECK(maxAbs(Matrix<S>(comm(l.Jp, l.Jm) + S(2) * l.H)) == S(0));
    // Casimir −j(j + 1) (quarter-integers: exact).
    const S j = S(twoJ) / S(2);
    CHECK(maxAbs(Matrix<S>(l.casimir() + j * (j + S(1)) * Matrix<S>::Identity(twoJ + 1, twoJ + 1))) == S(0));
    CHECK(bool(so3Decomposition<S>(l.H) == std::map<int, int>{{twoJ, 1}}));
    // L([x, y]) = [L(x), L(y)] for random real elements; entries up to ~j², products of two.
    const S tol = Tolerance<S>::identity(64) * S((twoJ + 1) * (twoJ + 1) * (twoJ + 1));
    for (int n = 0; n < 5; ++n) {
      const Vec3<S> x = uniformVec<S, 3>(g), y = uniformVec<S, 3>(g);
      const auto lx = l.element(x), ly = l.element(y);
      CHECK(maxAbs(decltype(lx)(comm(lx, ly) - l.element(Vec3<S>(x.cross(y))))) <= tol);
    }
  }
  CHECK_THROWS_AS(so3Irrep<S>(-1), InvalidInput);
}

TEMPLATE_TEST_CASE("Clebsch–Gordan: Casimir eigenvalue multiplicities of L_m ⊗ L_n", "[rep]", SOMA_TEST_SCALARS) {
  using S = TestType;
  for (int twoM = 0; twoM <= 4; ++twoM)
    for (int twoN = 0; twoN <= twoM; ++twoN) {
      INFO("2m = " << twoM << ", 2n = " << twoN);
      const So3Irrep<S> a = so3Irrep<S>(twoM), b = so3Irrep<S>(twoN);
      const Matrix<S> H = algebraTensor(a.H, b.H), Jp = algebraTensor(a.Jp, b.Jp), Jm = algebraTensor(a.Jm, b.Jm);
      // Kronecker sums keep the bracket relations (exact: integer entries).
      CHECK(maxAbs(Matrix<S>(comm(H, Jp) - Jp)) == S(0));
      CHECK(maxAbs(Matrix<S>(comm(Jp, Jm) + S(2) * H)) == S(0));
      const Matrix<S> C = -H * H + (Jp * Jm + Jm * Jp) / S(2);
      const int d = int(H.rows());
      CHECK(d == (twoM + 1) * (twoN + 1));
      int total = 0;
      for (int twoK : clebschGordan(twoM, twoN)) {
        const S k = S(twoK) / S(2);
        // each L_k once: the eigenvalue −k(k + 1) of the Casimir has multiplicity 2k + 1
        CHECK(nullity<S>(Matrix<S>(C + k * (k + S(1)) * Matrix<S>::Identity(d, d))) == twoK + 1);
        total += twoK + 1;
      }
      CHECK(total == d);
      std::map<int, int> expected;
      for (int twoK : clebschGordan(twoM, twoN)) expected[twoK] = 1;
      CHECK(bool(so3Decomposition<S>(H) == expected));
    }
}

TEMPLATE_TEST_CASE("Sym^n and ⋀^n: dimensions, projectors, so(3) content", "[rep]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const long long binom[8][8] = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}, {1, 4, 6, 4, 1}, {1, 5, 10, 10, 5, 1},
                                 {1, 6, 15, 20, 15, 6, 1}, {1, 7, 21, 35, 35, 21, 7, 1}};
  for (int d = 1; d <= 4; ++d)
    for (int n = 0; n <= 3; ++n) {
      INFO("d = " << d << ", n = " << n);
      CHECK(symmetricPowerDimension(d, n) == binom[n + d - 1][n]);
      CHECK(exteriorPowerDimension(d, n) == (n <= d ? binom[d][n] : 0));
      const Matrix<S> ps = symmetriser<S>(d, n), pa = antisymmetriser<S>(d, n);
      const Matrix<S> bs = symmetricPowerBasis<S>(d, n), ba = exteriorPowerBasis<S>(d, n);
      CHECK(bs.cols() == symmetricPowerDimension(d, n));
      CHECK(ba.cols() == exteriorPowerDimension(d, n));
      const S tol = Tolerance<S>::identity(64);
      // projectors: P² = P, rank = trace = the binomial, basis in the image
      CHECK(maxAbs(Matrix<S>(ps * ps - ps)) <= tol);
      CHECK(maxAbs(Matrix<S>(pa * pa - pa)) <= tol);
      CHECK(absOf(ps.trace() - S(double(symmetricPowerDimension(d, n)))) <= tol * S(64));
      CHECK(absOf(pa.trace() - S(double(exteriorPowerDimension(d, n)))) <= tol * S(64));
      CHECK(maxAbs(Matrix<S>(ps * bs - bs)) <= tol);
      if (ba.cols() > 0) CHECK(maxAbs(Matrix<S>(pa * ba - ba)) <= tol);
    }
  // GF-7.4-sym-and-wedge: Sym^n L_{1/2} = L_{n/2}; ⋀² L₁ = L₁; Sym²(L₁ ⊕ L₁) = 3L₂ + L₁ + 3L₀.
  const So3Irrep<S> half = so3Irrep<S>(1), one = so3Irrep<S>(2);
  for (int n = 1; n <= 6; ++n) {
    const Matrix<S> b = symmetricPowerBasis<S>(2, n);
    CHECK(bool(so3Decomposition<S>(restrictToSubspace(algebraTensorPower(half.H, n), b)) == std::map<int, int>{{n, 1}}));
  }
  CHECK(bool(so3Decomposition<S>(restrictToSubspace(algebraTensorPower(one.H, 2), exteriorPowerBasis<S>(3, 2))) ==
        std::map<int, int>{{2, 1}}));
  const Matrix<S> h2 = directSum(one.H, one.H);
  CHECK(bool(so3Decomposition<S>(restrictToSubspace(algebraTensorPower(h2, 2), symmetricPowerBasis<S>(6, 2))) ==
        std::map<int, int>{{4, 3}, {2, 1}, {0, 3}}));
}

TEMPLATE_TEST_CASE("se(3) representations: brackets, group homomorphism, Casimirs (E7.6)", "[rep]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(702);
  const S tol = Tolerance<S>::identity(64);
  Mat3<S> X = skew(Vec3<S>(Vec3<S>::UnitX())), Y = skew(Vec3<S>(Vec3<S>::UnitY())), Z = skew(Vec3<S>(Vec3<S>::UnitZ()));
  const std::array<Matrix<S>, 3> so3{Matrix<S>(X), Matrix<S>(Y), Matrix<S>(Z)};
  const std::array<Se3Generators<S>, 4> reps{se3StandardGenerators<S>(), se3AdjointGenerators<S>(),
                                             se3CoadjointGenerators<S>(), transference(so3)};
  for (std::size_t r = 0; r < reps.size(); ++r) {
    INFO("representation " << r);
    for (int n = 0; n < 5; ++n) {
      const SE3Tangent<S> a(uniformVec<S, 6>(g)), b(uniformVec<S, 6>(g));
      const Matrix<S> la = se3Element(reps[r], a.coeffs()), lb = se3Element(reps[r], b.coeffs());
      CHECK(maxAbs(Matrix<S>(comm(la, lb) - se3Element(reps[r], bracket(a, b).coeffs()))) <= tol);
    }
    const Se3QuadraticElements<S> q = se3QuadraticElements(reps[r]);
    S mixed(0), trans(0), rot(0);
    for (const auto& m : reps[r]) {
      mixed = std::max(mixed, maxAbs(Matrix<S>(comm(q.mixed, m))));
      trans = std::max(trans, maxAbs(Matrix<S>(comm(q.translationSquare, m))));
      rot = std::max(rot, maxAbs(Matrix<S>(comm(q.rotationSquare, m))));
    }
    CHECK(mixed == S(0));  // P_t and Σ P_a² are Casimirs (integer entries: exact)
    CHECK(trans == S(0));
    if (r == 0) CHECK(rot >= S(1));  // E7.6: J_t does not commute with the translations in the 4×4 representation
    else CHECK(rot == S(0));
  }
  // The transference of the 3×3 representation is the adjoint representation (exactly).
  for (std::size_t a = 0; a < 6; ++a) CHECK(maxAbs(Matrix<S>(reps[3][a] - reps[1][a])) == S(0));
  // Group: Ad*_{gh} = Ad*_g Ad*_h, ⟨Ad*_g f, Ad_g s⟩ = ⟨f, s⟩.
  for (int n = 0; n < 10; ++n) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    CHECK(maxAbs(Mat6<S>(coadjoint(a * b) - coadjoint(a) * coadjoint(b))) <= tol * S(4));
    const Vec6<S> f = uniformVec<S, 6>(g), s = uniformVec<S, 6>(g);
    CHECK(absOf(Vec6<S>(coadjoint(a) * f).dot(Vec6<S>(a.adjoint() * s)) - f.dot(s)) <= tol * S(8));
  }
}

TEMPLATE_TEST_CASE("invariant forms, pitch and the dual angle of an SO(3, D) matrix", "[rep]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(703);
  const S tol = Tolerance<S>::identity(64);
  for (int n = 0; n < 10; ++n) {
    const SE3Tangent<S> a(uniformVec<S, 6>(g)), b(uniformVec<S, 6>(g));
    const DualNumber<S> k = dualKillingForm(a, b);
    CHECK(absOf(k.re + S(2) * a.ang().dot(b.ang())) <= tol);
    CHECK(absOf(k.du + S(2) * reciprocalProduct(a.coeffs(), b.coeffs())) <= tol);
    // Ad-invariance of both forms
    const Mat6<S> Ad = SE3<S>::Random(g).adjoint();
    const DualNumber<S> kg = dualKillingForm(SE3Tangent<S>(Vec6<S>(Ad * a.coeffs())), SE3Tangent<S>(Vec6<S>(Ad * b.coeffs())));
    CHECK(absOf(kg.re - k.re) <= S(8) * tol);
    CHECK(absOf(kg.du - k.du) <= S(16) * tol);
    CHECK(absOf(pitchFromInvariantForms(a) - a.ang().dot(a.lin()) / a.ang().squaredNorm()) <=
          tol / a.ang().squaredNorm());
  }
  CHECK(pitchFromInvariantForms(SE3Tangent<S>(Vec3<S>::Zero(), Vec3<S>(Vec3<S>::UnitX()))) == std::numeric_limits<S>::infinity());
  CHECK_THROWS_AS(pitchFromInvariantForms(SE3Tangent<S>()), InvalidInput);
  // Dual angle and axis of the screw motion about (v; r × v) by θ with slide d, θ from 1e-3 to π.
  const S angles[] = {S(1) / S(1000), S(1) / S(2), S(2), pi<S>() - S(1) / S(1000), pi<S>()};
  for (const S& theta : angles) {
    const Vec3<S> v = unitVec3<S>(g), r = uniformVec<S, 3>(g);
    const S pitch = uniform<S>(g);
    const SE3<S> m = screwMotion<S>(v, r, pitch, theta);
    const DualAngleAxis<S> da = dualAngleAxis(dualRotation(m));
    INFO("theta = " << toDouble(theta));
    CHECK_FALSE(da.pureTranslation);
    CHECK(absOf(da.angle.re - theta) <= S(16) * tol);
    S sign = da.direction.dot(v) < S(0) ? S(-1) : S(1);  // at θ = π the axis sign is free
    if (theta < pi<S>()) CHECK(sign == S(1));
    const S scale = S(1) / std::min(theta, S(1));
    CHECK(absOf(sign * da.angle.du - theta * pitch) <= S(64) * tol * scale);
    CHECK(maxAbs(Vec3<S>(sign * da.direction - v)) <= S(16) * tol);
    CHECK(maxAbs(Vec3<S>(sign * da.moment - r.cross(v))) <= S(64) * tol * scale);
    // Tr Ř = 1 + 2cos θ̌ (the book's dual trace)
    const DualNumber<S> tr = dualRotation(m).trace(), c = DualNumber<S>(theta, theta * pitch).cos();
    CHECK(absOf(tr.re - S(1) - S(2) * c.re) <= S(8) * tol);
    CHECK(absOf(tr.du - S(2) * c.du) <= S(16) * tol);
  }
  const DualAngleAxis<S> pt = dualAngleAxis(dualRotation(SE3<S>(SO3<S>(), Vec3<S>(S(0), S(3), S(4)))));
  CHECK(pt.pureTranslation);
  CHECK(absOf(pt.angle.du - S(5)) <= tol);
  DualMat3<S> bad = dualRotation(SE3<S>::Random(g));
  bad.du += Mat3<S>::Identity();
  CHECK_THROWS_AS(dualAngleAxis(bad), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
