// SE(3): the generic Lie-group property suite (lie_suite.hpp) for all five scalars; the book's
// closed forms (Ad and its product/inverse, commutators, 4×4 exp, the Hermite log coefficients,
// the adjoint exp and the corrected adjoint log (erratum E4.8), the se(3) dexp and its inverse,
// twist velocity); rejection of bad input with a message naming the defect.
#include "lie_suite.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;
using Catch::Matchers::Contains;
using lie::maxAbs;

TEMPLATE_TEST_CASE("SE3 group properties over identity, 1e-8, edges, switches, random", "[se3]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(61);
  for (const auto& smp : lie::samples<SE3<S>>(g, std::is_same_v<S, mpreal> ? 3 : 30))
    lie::checkGroupProperties(smp, g);
}

TEMPLATE_TEST_CASE("SE3 matches the book's closed forms (ch. 2, 4)", "[se3]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  const S eps = Tolerance<S>::epsilon();
  const S tol = S(64) * eps;
  auto& g = rng(67);
  const int n = std::is_same_v<S, mpreal> ? 2 : 10;
  for (int i = 0; i < n; ++i) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    const Mat3<S> Ra = a.rotation(), Rb = b.rotation();
    const Mat3<S> Ta = skew<S>(a.translation()), Tb = skew<S>(b.translation());
    // GF-4.2-adjoint-SE3: Ad = [[R, 0], [TR, R]]; product block (T1 + R1T2R1ᵀ)R1R2; inverse.
    Mat6<S> book;
    book << Ra, Mat3<S>::Zero(), Ta * Ra, Ra;
    CHECK(maxAbs(Mat6<S>(a.adjoint() - book)) <= tol);
    CHECK(maxAbs(Mat3<S>((a * b).adjoint().template bottomLeftCorner<3, 3>() -
                         (Ta + Ra * Tb * Ra.transpose()) * Ra * Rb)) <= S(4) * tol);
    Mat6<S> inv;
    inv << Ra.transpose(), Mat3<S>::Zero(), -Ra.transpose() * Ta, Ra.transpose();
    CHECK(maxAbs(Mat6<S>(a.inverse().adjoint() - inv)) <= S(4) * tol);
    // GF-2.5.1-homogeneous: the inverse is [[Rᵀ, −Rᵀt], [0, 1]].
    CHECK(maxAbs(Vec3<S>(a.inverse().translation() + Ra.transpose() * a.translation())) <= tol);
    // GF-4.3-se3-commutators-ad: [s1, s2] = (ω1×ω2; ω1×v2 − ω2×v1) = vee[ŝ1, ŝ2].
    // θ in [0.5, 2.5]: the book's closed forms divide by θ^k or sin θ and are only
    // well-conditioned away from 0 and π (the library switches to series there).
    const SE3Tangent<S> s1(Vec3<S>(unitVec3<S>(g) * uniform<S>(g, 0.5, 2.5)), uniformVec<S, 3>(g));
    const SE3Tangent<S> s2(uniformVec<S, 6>(g));
    const Vec6<S> br = bracket(s1, s2).coeffs();
    Vec6<S> bookBr;
    bookBr << s1.ang().cross(s2.ang()), s1.ang().cross(s2.lin()) - s2.ang().cross(s1.lin());
    CHECK(maxAbs(Vec6<S>(br - bookBr)) <= tol);
    CHECK(maxAbs(Vec6<S>(SE3Tangent<S>::vee(s1.hat() * s2.hat() - s2.hat() * s1.hat()).coeffs() -
                         br)) <= tol);
    // GF-4.4.2-se3-exp-4x4: e^S = I + S + (1−cosθ)/θ² S² + (θ−sinθ)/θ³ S³.
    const S th = s1.ang().norm();
    const Mat4<S> H = s1.hat();
    const Mat4<S> e4 = Mat4<S>::Identity() + H + (S(1) - cos(th)) / (th * th) * H * H +
                       (th - sin(th)) / (th * th * th) * H * H * H;
    CHECK(maxAbs(Mat4<S>(s1.exp().matrix() - e4)) <= tol);
    // GF-4.4.2-se3-log-4x4: log G = aI + bG + cG² + dG³ with the book's Hermite coefficients.
    {
      const Mat4<S> G = s1.exp().matrix();
      const S c3 = S(1) / S(8) / (sin(th / S(2)) * sin(th / S(2)) * sin(th / S(2)) * cos(th / S(2)));
      const S A = c3 * (th * cos(S(2) * th) - sin(th));
      const S B = -c3 * (th * cos(th) + S(2) * th * cos(S(2) * th) - sin(th) - sin(S(2) * th));
      const S C = c3 * (S(2) * th * cos(th) + th * cos(S(2) * th) - sin(th) - sin(S(2) * th));
      const S D = -c3 * (th * cos(th) - sin(th));
      const Mat4<S> lg = A * Mat4<S>::Identity() + B * G + C * G * G + D * G * G * G;
      CHECK(maxAbs(Mat4<S>(lg - H)) <= S(16) * tol * (S(1) + c3));  // c3 amplifies rounding
    }
    // GF-4.4.3-adjoint-exp: e^Z closed form = Ad(e^s); quintic Z⁵ + 2θ²Z³ + θ⁴Z = 0.
    const Mat6<S> Zm = s1.ad();
    const Mat6<S> Z2 = Zm * Zm, Z3 = Z2 * Zm, Z4 = Z3 * Zm;
    const Mat6<S> eZ = Mat6<S>::Identity() + (S(3) * sin(th) - th * cos(th)) / (S(2) * th) * Zm +
                       (S(4) - S(4) * cos(th) - th * sin(th)) / (S(2) * th * th) * Z2 +
                       (sin(th) - th * cos(th)) / (S(2) * th * th * th) * Z3 +
                       (S(2) - S(2) * cos(th) - th * sin(th)) / (S(2) * th * th * th * th) * Z4;
    CHECK(maxAbs(Mat6<S>(eZ - s1.exp().adjoint())) <= S(16) * tol);
    CHECK(maxAbs(Mat6<S>(Z4 * Zm + S(2) * th * th * Z3 + th * th * th * th * Zm)) <= S(16) * tol);
    // GF-4.5.4-se3-dexp-and-inverse: the closed forms equal ljac and ljacinv.
    const Mat6<S> dexp =
        Mat6<S>::Identity() + (S(4) - th * sin(th) - S(4) * cos(th)) / (S(2) * th * th) * Zm +
        (S(4) * th - S(5) * sin(th) + th * cos(th)) / (S(2) * th * th * th) * Z2 +
        (S(2) - th * sin(th) - S(2) * cos(th)) / (S(2) * th * th * th * th) * Z3 +
        (S(2) * th - S(3) * sin(th) + th * cos(th)) / (S(2) * th * th * th * th * th) * Z4;
    CHECK(maxAbs(Mat6<S>(s1.ljac() - dexp)) <= S(64) * tol);
    const Mat6<S> dexpInv =
        Mat6<S>::Identity() - Zm / S(2) +
        (S(2) / (th * th) + (th + S(3) * sin(th)) / (S(4) * th * (cos(th) - S(1)))) * Z2 +
        (S(1) / (th * th * th * th) + (th + sin(th)) / (S(4) * th * th * th * (cos(th) - S(1)))) * Z4;
    CHECK(maxAbs(Mat6<S>(s1.ljacinv() - dexpInv)) <= S(64) * tol);
    // GF-4.1-se3-twist-velocity: d/dt exp(t s) p at t = 0 is ω × p + v (central difference).
    if constexpr (std::is_same_v<S, double> || std::is_same_v<S, long double>) {
      using std::cbrt;
      const S h = cbrt(eps);
      const Vec3<S> p = uniformVec<S, 3>(g);
      const Vec3<S> vel = ((s1 * h).exp().act(p) - (s1 * -h).exp().act(p)) / (S(2) * h);
      CHECK(maxAbs(Vec3<S>(vel - (s1.ang().cross(p) + s1.lin()))) <= S(64) * h * h);
    }
  }
}

TEMPLATE_TEST_CASE("SE3 adjoint log: the printed 1/(8 sin³θ) is half the true log (E4.8)",
                   "[se3]", double, long double, __float128) {
  using S = TestType;
  using std::cos;
  using std::sin;
  auto& g = rng(71);
  for (int i = 0; i < 4; ++i) {
    const SE3Tangent<S> s(Vec3<S>(unitVec3<S>(g) * uniform<S>(g, 0.5, 2.5)), uniformVec<S, 3>(g));
    const S th = s.ang().norm();
    const Mat6<S> H = s.exp().adjoint();
    const Mat6<S> H2 = H * H, H3 = H2 * H, H4 = H3 * H;
    auto logWith = [&](const S& pre) {  // GF §4.4.3, GF-4.4.3-adjoint-log (ζ = 0)
      const S al = -pre * (S(2) * th + S(4) * th * cos(th) - th * cos(S(3) * th) - sin(S(2) * th) -
                           sin(S(3) * th));
      const S be = pre * (S(8) * th + S(8) * th * cos(th) + S(2) * th * cos(S(2) * th) -
                          S(2) * sin(th) - S(3) * sin(S(2) * th) - S(2) * sin(S(3) * th) -
                          sin(S(4) * th));
      const S ga = -pre * (S(8) * th + S(11) * th * cos(th) + S(4) * th * cos(S(2) * th) +
                           th * cos(S(3) * th) - S(3) * sin(th) - S(4) * sin(S(2) * th) -
                           S(3) * sin(S(3) * th) - sin(S(4) * th));
      const S de = pre * (S(4) * th + S(8) * th * cos(th) + S(2) * th * cos(S(2) * th) -
                          S(2) * sin(th) - S(3) * sin(S(2) * th) - S(2) * sin(S(3) * th));
      const S ep = -pre * (S(2) * th + th * cos(th) - sin(th) - sin(S(2) * th));
      return Mat6<S>(al * Mat6<S>::Identity() + be * H + ga * H2 + de * H3 + ep * H4);
    };
    const S s3 = sin(th) * sin(th) * sin(th);
    const Mat6<S> corrected = logWith(S(1) / (S(4) * s3)), printed = logWith(S(1) / (S(8) * s3));
    const S z = maxAbs(s.ad());
    // The polynomial log is ill-conditioned (1/sin³θ); 1e-9 still separates ½ from 1.
    CHECK(maxAbs(Mat6<S>(corrected - s.ad())) <= S(1e-9) * z);
    CHECK(maxAbs(Mat6<S>(printed - s.ad() / S(2))) <= S(1e-9) * z);  // printed = ½ log
    CHECK(maxAbs(Mat6<S>(printed - s.ad())) >= z / S(4));
  }
}

TEMPLATE_TEST_CASE("SE3 rejects bad input with a message naming the defect", "[se3]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  auto& g = rng(73);
  const Mat4<S> m = SE3<S>::Random(g).matrix();
  Mat4<S> bad = m;
  bad(0, 3) = nan;
  CHECK_THROWS_WITH(SE3<S>::fromMatrix(bad), Contains("NaN"));
  bad = m;
  bad(3, 1) = S(1) / S(2);
  CHECK_THROWS_WITH(SE3<S>::fromMatrix(bad), Contains("last row"));
  bad = m;
  bad(1, 1) += S(4) * Tolerance<S>::input();
  CHECK_THROWS_WITH(SE3<S>::fromMatrix(bad), Contains("rotation block") && Contains("not orthogonal"));
  bad = m;
  bad.template topLeftCorner<3, 3>() *= S(-1);
  CHECK_THROWS_WITH(SE3<S>::fromMatrix(bad), Contains("rotation block") && Contains("det = −1"));
  CHECK_THROWS_WITH(SE3<S>(SO3<S>(), Vec3<S>(S(0), nan, S(0))), Contains("translation") && Contains("NaN"));
  CHECK_THROWS_WITH(SE3Tangent<S>(Vec3<S>::Zero(), Vec3<S>(nan, S(0), S(0))).exp(), Contains("NaN"));
  CHECK_NOTHROW(SE3<S>::fromMatrix(m));
}

}  // namespace SOMA_UNITY_ID
