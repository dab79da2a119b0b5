// The general-6R solver's hand-written numerical kernels (general_6r_impl.hpp, written for speed)
// against Eigen's: the 12×12 LU's reciprocal condition estimate against PartialPivLU::rcond()
// (the same Hager–Higham algorithm, so equal up to the rounding of two factorisations), and its
// solves (one column, transposed, 24 columns at once) against PartialPivLU::solve, on random,
// nearly rank-deficient and badly row-scaled matrices (fixed seed); the 14×8 QR with column
// pivoting against ColPivHouseholderQR.
#include "soma/geometry/serial/general_6r_impl.hpp"

#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

TEST_CASE("general 6R kernels: Lu12 rcond and solves agree with Eigen's PartialPivLU", "[sixr][kernels]") {
  auto& g = test::rng(20261206);
  using M = detail6r::M12<double>;
  using V = Eigen::Matrix<double, 12, 1>;
  for (int t = 0; t < 600; ++t) {
    M a;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) a(i, j) = test::uniform<double>(g);
    if (t % 3 == 1) a.col(3) = 2 * a.col(4) + 1e-9 * double(1 + t % 7) * a.col(5);  // nearly singular
    if (t % 3 == 2) a.row(7) *= 1e-6;                                             // badly scaled
    const Eigen::PartialPivLU<M> ref(a);
    const detail6r::Lu12<double> lu(a);
    REQUIRE(lu.ok);
    double l1 = 0;
    for (int c = 0; c < 12; ++c) l1 = std::max(l1, a.col(c).cwiseAbs().sum());
    // The estimator takes the same branches on the same pivots; its value is a norm of computed
    // solves, whose relative error is ≲ κ·n²·eps (κ = 1/rcond, n = 12, and this LU multiplies by
    // reciprocal pivots where Eigen divides): |Δrcond| ≲ rcond·κ·144 eps = 144 eps. The solver's
    // decisions (rcond against Tolerance::precision(2) and Tolerance::rank()) must agree.
    INFO("matrix " << t);
    const double rc = ref.rcond(), mine = lu.rcond(l1);
    CHECK(std::abs(mine - rc) <= 144 * Tolerance<double>::epsilon());
    CHECK((mine > Tolerance<double>::precision(2)) == (rc > Tolerance<double>::precision(2)));
    CHECK((mine > Tolerance<double>::rank()) == (rc > Tolerance<double>::rank()));
    // Solves compared where the system is well posed (rcond > √eps); nearer singular both answers
    // are rounding, and the reference's LU of aᵀ may meet an exactly zero pivot.
    if (!(ref.rcond() > Tolerance<double>::sqrtEpsilon())) continue;
    const V b = test::uniformVec<double, 12>(g);
    V x = b, y = b;
    lu.solve(x);
    lu.solveTransposed(y);
    const double kappa = 1 / ref.rcond();  // forward error ≤ κ × backward error (12² eps)
    const double tol = kappa * 144 * Tolerance<double>::epsilon();
    CHECK((x - ref.solve(b)).norm() <= tol * x.norm());
    const V yRef = Eigen::PartialPivLU<M>(M(a.transpose())).solve(b);
    CHECK((y - yRef).norm() <= tol * y.norm());
    // 24 right-hand sides at once (the companion block −A⁻¹[C B]): every column within the same
    // bound of Eigen's solve.
    Eigen::Matrix<double, 12, 24> bs;
    for (int j = 0; j < 24; ++j) bs.col(j) = test::uniformVec<double, 12>(g);
    Eigen::Matrix<double, 12, 24> xs = bs;
    lu.solveColumns(xs);
    const Eigen::Matrix<double, 12, 24> xsRef = ref.solve(bs);
    for (int j = 0; j < 24; ++j) {
      INFO("right-hand side " << j);
      CHECK((xs.col(j) - xsRef.col(j)).norm() <= tol * xs.col(j).norm());
    }
  }
}

TEMPLATE_TEST_CASE("general 6R kernels: Lu12 factorisations in lockstep are the one-at-a-time ones", "[sixr][kernels]",
                   float, double, long double) {
  // factorTogether (the back-substitution's roots, up to four at once) interleaves the columns of
  // independent factorisations; each must come out as Lu12::factor alone makes it, bit for bit,
  // also when one of them meets an exactly zero pivot (ok = false) and stops.
  using S = TestType;
  using M = detail6r::M12<S>;
  auto& g = test::rng(20261207);
  for (int t = 0; t < 50; ++t) {
    const int n = 1 + t % 4;
    std::array<M, 4> ms;
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) ms[k](i, j) = test::uniform<S>(g);
    if (t % 5 == 3) ms[n - 1].col(5).setZero();  // singular: stops at column 5
    std::array<detail6r::Lu12<S>, 4> together;
    detail6r::factorTogether<S>(together.data(), ms.data(), n);
    for (int k = 0; k < n; ++k) {
      INFO("batch " << t << " matrix " << k << " of " << n);
      const detail6r::Lu12<S> alone(ms[k]);
      REQUIRE(together[k].ok == alone.ok);
      CHECK(together[k].ok == !(t % 5 == 3 && k == n - 1));
      if (!alone.ok) continue;
      bool same = true;
      for (int i = 0; i < 12; ++i) {
        same = same && together[k].perm[i] == alone.perm[i] && together[k].rdiag[i] == alone.rdiag[i];
        for (int j = 0; j < 12; ++j)
          same = same && together[k].a[i][j] == alone.a[i][j] && (j >= i || together[k].l[i][j] == alone.l[i][j]);
      }
      CHECK(same);
    }
  }
}

TEST_CASE("general 6R kernels: Qr14x8 agrees with Eigen's ColPivHouseholderQR", "[sixr][kernels]") {
  // The same algorithm (pivot = largest remaining column norm, LAWN 176 downdates): the same
  // column permutation, |R(i,i)| within rounding of Eigen's, and Q·R = M·P within the backward
  // error of Householder QR (taken as 14·8·eps·‖M‖), on random and badly column-scaled 14×8
  // matrices (full rank: 8 nonzero pivots, as Eigen) and exactly rank-deficient ones (rank 7).
  auto& g = test::rng(20261207);
  using M = detail6r::M14x8<double>;
  const double eps = Tolerance<double>::epsilon();
  for (int t = 0; t < 300; ++t) {
    M a;
    for (int i = 0; i < 14; ++i)
      for (int j = 0; j < 8; ++j) a(i, j) = test::uniform<double>(g);
    if (t % 3 == 1) a.col(6) = 0.5 * a.col(0) - 2 * a.col(1);  // rank 7
    if (t % 3 == 2) a.col(2) *= 1e-7;                           // badly scaled
    const Eigen::ColPivHouseholderQR<M> ref(a);
    const detail6r::Qr14x8<double> qr(a);
    INFO("matrix " << t);
    if (t % 3 == 1) {
      // Rank 7: R's last diagonal entry is rounding. The nonzero-pivot count compares its square
      // with (eps·max column norm)²/2, a threshold at the rounding level itself: Eigen's count is 7
      // or 8 by the matrix (both occur here), and so is this one; only R's revealing entry is checked.
      CHECK(std::abs(qr.qr(7, 7)) <= 14 * 8 * eps * a.norm());
    } else {
      CHECK(qr.nonzero == int(ref.nonzeroPivots()));
      CHECK(qr.nonzero == 8);
    }
    for (int i = 0; i < 8; ++i) {
      CHECK(qr.perm[i] == int(ref.colsPermutation().indices()(i)));
      CHECK(std::abs(std::abs(qr.qr(i, i)) - std::abs(ref.matrixQR()(i, i))) <= 14 * 8 * eps * a.norm());
    }
    // Q·R from the reflectors: R's columns, reflectors 7..0 applied (x ← (I − τ v vᵀ) x).
    M qrProd = qr.qr.triangularView<Eigen::Upper>();
    for (int j = 0; j < 8; ++j)
      for (int k = 7; k >= 0; --k) {
        double d = qrProd(k, j);
        for (int i = k + 1; i < 14; ++i) d += qr.qr(i, k) * qrProd(i, j);
        d *= qr.tau[k];
        qrProd(k, j) -= d;
        for (int i = k + 1; i < 14; ++i) qrProd(i, j) -= d * qr.qr(i, k);
      }
    M ap;
    for (int j = 0; j < 8; ++j) ap.col(j) = a.col(qr.perm[j]);
    CHECK((qrProd - ap).norm() <= 14 * 8 * eps * a.norm());
  }
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {

// The trigonometry of the back-substitution and the polish without sin/cos calls (Posture6):
// doubleAngleOf(n, d) = (cos, sin) of 2·atan2(n, d), unitAngleOf(y, x) = (cos, sin) of atan2(y, x),
// stepSinCos(δ) = (sin δ, cos δ), against the library functions of each scalar, at random
// arguments over many magnitudes, at zero, and on both sides of stepSinCos's switch |δ| = 1.
// Each is a few roundings of a well-conditioned formula: 8 eps (a handful of ulps of values ≤ 1).
TEMPLATE_TEST_CASE("general 6R kernels: cosines and sines from ratios and small steps match sin and cos",
                   "[sixr][kernels]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::atan2;
  using std::cos;
  using std::ldexp;
  using std::sin;
  auto& g = test::rng(20261207);
  const S tol = S(8) * Tolerance<S>::epsilon();
  for (int t = 0; t < 200; ++t) {
    const int e = t % 40 - 20;  // magnitudes 2^−20 … 2^19
    const S n = ldexp(test::uniform<S>(g), e), d = ldexp(test::uniform<S>(g), t % 7 - 3);
    S c, s;
    detail6r::doubleAngleOf(n, d, c, s);
    const S phi = S(2) * atan2(n, d);
    INFO("t " << t << " n " << toDouble(n) << " d " << toDouble(d));
    CHECK(abs(S(c - cos(phi))) <= tol);
    CHECK(abs(S(s - sin(phi))) <= tol);
    detail6r::unitAngleOf(n, d, c, s);
    CHECK(abs(S(c - cos(atan2(n, d)))) <= tol);
    CHECK(abs(S(s - sin(atan2(n, d)))) <= tol);
    const S delta = t % 2 == 0 ? ldexp(test::uniform<S>(g), -(t % 30)) : S(test::uniform<S>(g) * S(3));
    detail6r::stepSinCos(delta, s, c);
    INFO("delta " << toDouble(delta));
    CHECK(abs(S(s - sin(delta))) <= tol * std::max<S>(S(1), abs(delta)));
    CHECK(abs(S(c - cos(delta))) <= tol);
  }
  for (const S delta : {S(1), S(-1), S(1) + Tolerance<S>::epsilon(), S(0)}) {
    S s, c;
    detail6r::stepSinCos(delta, s, c);
    CHECK(abs(S(s - sin(delta))) <= tol);
    CHECK(abs(S(c - cos(delta))) <= tol);
  }
  S c, s;
  detail6r::doubleAngleOf(S(0), S(0), c, s);  // atan2(0, 0) = 0
  CHECK((c == S(1) && s == S(0)));
  detail6r::unitAngleOf(S(0), S(0), c, s);
  CHECK((c == S(1) && s == S(0)));
}

}  // namespace SOMA_UNITY_ID
