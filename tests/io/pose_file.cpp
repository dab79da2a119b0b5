// Pose files: both rotation forms, exact decimal strings, and every defect named in the message.
#include "soma/io/pose_file.hpp"

#include "soma/algebra/so3.hpp"

#include "support/scalars.hpp"

#include <nlohmann/json.hpp>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;

TEMPLATE_TEST_CASE("parsePose reads a rotation matrix or a quaternion", "[pose]", SOMA_TEST_SCALARS) {
  using S = TestType;
  // Rotation by π/2 about z, as a matrix and as the quaternion (cos π/4, 0, 0, sin π/4).
  const auto a = parsePose<S>(
      R"({"rotation": [[0,-1,0],[1,0,0],[0,0,1]], "translation": [1, 2, "0.1"]})", "a");
  const auto b = parsePose<S>(
      R"({"quaternion": ["0.70710678118654752440084436210484903928483593768847",0,0,
                         "0.70710678118654752440084436210484903928483593768847"],
          "translation": [1, 2, "0.1"]})", "b");
  CHECK(a.isApprox(b, S(8) * Tolerance<S>::epsilon()));
  CHECK(a.act(Vec3<S>(1, 0, 0)).isApprox(Vec3<S>(S(1), S(3), fromString<S>("0.1")),
                                         S(8) * Tolerance<S>::epsilon()));
  // A decimal string is parsed in S, not through double.
  CHECK(a.translation().z() == fromString<S>("0.1"));
}

TEMPLATE_TEST_CASE("poseJson: a pose in S's digits that parsePose reads back", "[pose][json_number]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng();
  for (int k = 0; k < 50; ++k) {
    // All of S's bits: the rotation of a random rotation vector, a translation of quotients.
    const SO3<S> R = SO3Tangent<S>(test::uniformVec<S, 3>(g, -3, 3)).exp();
    const Vec3<S> t = test::uniformVec<S, 3>(g) / test::uniform<S>(g, 0.5, 1);
    const SE3<S> pose(R, t);
    const nlohmann::json j = poseJson(pose);
    // Wider than double: decimal strings (a JSON number would round them to a double).
    CHECK(j.at("rotation").at(0).at(0).is_string() == !(std::is_same_v<S, float> || std::is_same_v<S, double>));
    const SE3<S> back = parsePose<S>(j.dump(), "<poseJson>");
    // The translation exactly; the rotation within a few ulps (the reader keeps a unit quaternion).
    CHECK((back.translation().array() == t.array()).all());
    CHECK((back.rotation() - pose.rotation()).cwiseAbs().maxCoeff() <= Tolerance<S>::identity(8));
  }
}

TEST_CASE("parsePose names the defect of bad input", "[pose]") {
  using S = double;
  const std::string t = R"("translation": [0,0,0])";
  CHECK_THROWS_WITH(parsePose<S>("{", "p.json"), Contains("p.json: not valid JSON"));
  CHECK_THROWS_WITH(parsePose<S>("[1]", "p.json"), Contains("must be a JSON object"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,0],[0,0,1]]})", "p.json"),
                    Contains("missing \"translation\""));
  CHECK_THROWS_WITH(parsePose<S>("{" + t + "}", "p.json"), Contains("exactly one of"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,0],[0,0,1]], "quaternion": [1,0,0,0], )" + t + "}", "p.json"),
                    Contains("exactly one of"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rot": 1, )" + t + "}", "p.json"), Contains("unknown field \"rot\""));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,0],[0,0,1]], "translation": [0, "nan", 0]})", "p.json"),
                    Contains("p.json: translation[1]: \"nan\" is not a decimal number"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,0],[0,0,1]], "translation": [0, "x", 0]})", "p.json"),
                    Contains("p.json: translation[1]: \"x\" is not a decimal number"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,"0x10"],[0,0,1]], )" + t + "}", "p.json"),
                    Contains("p.json: rotation[1][2]: \"0x10\" is not a decimal number (hexadecimal)"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0,0],[0,1,0]], )" + t + "}", "p.json"),
                    Contains("3 rows"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[1,0.1,0],[0,1,0],[0,0,1]], )" + t + "}", "p.json"),
                    Contains("p.json: SO3::fromMatrix: matrix is not orthogonal"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"rotation": [[-1,0,0],[0,1,0],[0,0,1]], )" + t + "}", "p.json"),
                    Contains("det = −1"));
  CHECK_THROWS_WITH(parsePose<S>(R"({"quaternion": [1,0,0,0.1], )" + t + "}", "p.json"),
                    Contains("quaternion is not unit"));
  CHECK_THROWS_WITH(readPose<S>("/nonexistent/pose.json"), Contains("cannot open"));
}

TEST_CASE("a rotation typed as doubles is accepted in mpfr, and taken exactly orthogonal", "[pose]") {
  // cos 30° and sin 30° as JSON doubles: orthogonal to double precision only.
  const std::string text = R"({"rotation": [[0.8660254037844387,-0.5,0],[0.5,0.8660254037844387,0],[0,0,1]],
                               "translation": [0,0,0]})";
  const auto g = parsePose<mpreal>(text, "p.json");
  const Mat3<mpreal> r = g.rotation();
  CHECK((r.transpose() * r - Mat3<mpreal>::Identity()).cwiseAbs().maxCoeff() <
        mpreal(64) * Tolerance<mpreal>::epsilon());
  CHECK(abs(r(0, 1) + mpreal("0.5")) < mpreal("1e-15"));
  // Exact decimal strings are judged at mpfr's own tolerance: 16 digits are not enough.
  CHECK_THROWS_WITH(parsePose<mpreal>(R"({"rotation": [["0.8660254037844387","-0.5",0],["0.5","0.8660254037844387",0],[0,0,1]],
                                          "translation": ["0","0","0"]})", "p.json"),
                    Contains("not orthogonal"));
  // A defect beyond double's tolerance is rejected in every scalar.
  CHECK_THROWS_WITH(parsePose<mpreal>(R"({"rotation": [[0.866,-0.5,0],[0.5,0.866,0],[0,0,1]], "translation": [0,0,0]})", "p.json"),
                    Contains("not orthogonal"));
  CHECK_THROWS_WITH(parsePose<__float128>(R"({"quaternion": [1, 0, 0, 1e-2], "translation": [0,0,0]})", "p.json"),
                    Contains("not unit"));
}

}  // namespace SOMA_UNITY_ID
