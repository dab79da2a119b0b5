// libFuzzer harness: one file read in all five scalars (float, double, long double, __float128,
// mpfr at 256 bits) by the robot, pose and platform readers must be one robot, pose or platform:
//   1. acceptance is monotone along the ladder: a scalar that accepts the file implies every wider
//      one accepts it (a wider scalar has a wider range and finer rounding, so it never has a reason
//      to refuse what a narrower one took; the other way is allowed: 1e39 does not fit a float);
//   2. every accepting scalar's numbers agree with mpfr's to within the rounding bound below.
// A file that is a different object per scalar (the hex strings read as 16 in double and as 0 in
// mpfr; a rotation judged at float's looser tolerance in float only) fails one of the two.
//
// The rounding bound, for a scalar S with unit roundoff u = eps(S)/2 compared with mpfr at 256 bits
// (whose own error, 2^-256 relative, is negligible):
//   - a number stored as read (platform points and legs, a pose's translation, DH a and d, POE
//     points): correct rounding, |x_S - x| <= u |x| + denorm_min(S) (a subnormal's absolute spacing);
//   - a pose's rotation, an entry of R(q) with q normalised from the quaternion read or from the
//     matrix read (Shepperd's chart, pivot >= 1/2): about 14 u in q from reading (1 u per entry),
//     the chart (sqrt, sums, one division) and normalising (norm, sqrt, division), times |dR/dq| <= 4,
//     plus 4 u for R's own sums: <= 64 u per entry (|R_ij| <= 1);
//   - a robot's derived data (joint axes, points and offsets in POE form, home, base, tool, limits):
//     each of the n DH frames adds one frame's rotation error (64 u, as above, plus the argument
//     error u |theta| of sin and cos, 2 u for the degree factor) and the 3-term dot products of one
//     4x4 product (3 u), so after n joints a rotation entry is off by <= (n + 2) 64 u (1 + Theta)
//     (Theta: the largest |angle| of the file, radians) and a position by that times (|x| + L + 1)
//     (L: the sum of the file's lengths |a|, |d|, |t|, which the rotation errors multiply).
// These are a few dozen ulp of the narrower type for ordinary files: a disagreement beyond them is a
// different object, not rounding.
#include "harness.hpp"

#include "soma/io/platform_file.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>

namespace {

using mpfr::mpreal;
using Ref = mpreal;

template <class S> Ref ref(const S& x) { return soma::scalarCast<mpreal>(x); }
template <class S> Ref unitRoundoff() { return ref(std::numeric_limits<S>::epsilon()) / 2; }
template <class S> Ref denormMin() {
  if constexpr (std::is_same_v<S, __float128>) return ref(S(1)) * mpfr::pow(mpreal(2), -16494);
  else return ref(std::numeric_limits<S>::denorm_min());
}

[[noreturn]] void disagree(const std::string& what) {
  std::fprintf(stderr, "fuzz differential: %s\n", what.c_str());
  std::abort();
}

/// One comparison: |x_S - x_mpfr| <= bound, both infinite with one sign, or a finding.
template <class S>
void same(const char* reader, const std::string& what, const S& x, const mpreal& r, const mpreal& bound) {
  if (mpfr::isinf(r) || std::isinf(soma::toDouble(x))) {
    if (mpfr::isinf(r) && std::isinf(soma::toDouble(x)) && (r > 0) == (soma::toDouble(x) > 0)) return;
  } else if (mpfr::abs(ref(x) - r) <= bound) {
    return;
  }
  disagree(std::string(reader) + ": " + what + " is " + soma::toString(ref(x), 20) + " in " +
           std::string(soma::scalarName<S>()) + ", " + soma::toString(r, 25) + " in mpfr (bound " +
           soma::toString(bound, 3) + ")");
}

template <class S> Ref storedBound(const mpreal& r) {
  return unitRoundoff<S>() * (mpfr::isinf(r) ? mpreal(0) : mpfr::abs(r)) + denormMin<S>();
}

// ---- pose -----------------------------------------------------------------------------------------
template <class S> void comparePose(const char* reader, const std::string& where, const soma::SE3<S>& g,
                                    const soma::SE3<mpreal>& r, const mpreal& rotBound, const mpreal& scale,
                                    bool stored) {
  const soma::Mat3<S> R = g.rotation();
  const soma::Mat3<mpreal> Rr = r.rotation();
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k)
      same(reader, where + " rotation(" + std::to_string(i) + "," + std::to_string(k) + ")", R(i, k), Rr(i, k),
           rotBound);
    const mpreal t = r.translation()(i);
    same(reader, where + " translation[" + std::to_string(i) + "]", g.translation()(i), t,
         stored ? storedBound<S>(t) : rotBound * (mpfr::abs(t) + scale + 1));
  }
}

// ---- robot ----------------------------------------------------------------------------------------
struct RobotScale {
  mpreal theta = 0;  ///< the largest |angle|, radians
  mpreal length = 0; ///< the sum of the lengths
};
RobotScale robotScale(const soma::io::RobotFile<mpreal>& f) {
  RobotScale s;
  const auto& rb = f.robot;
  for (const auto& d : rb.dhRows()) {
    s.theta = mpfr::max(s.theta, mpfr::max(mpfr::abs(d.theta), mpfr::abs(d.alpha)));
    s.length += mpfr::abs(d.a) + mpfr::abs(d.d);
  }
  for (const auto& j : rb.joints()) {
    if (mpfr::isfinite(j.offset)) s.theta = mpfr::max(s.theta, mpfr::abs(j.offset));
    s.length += j.point.cwiseAbs().sum();
  }
  for (const soma::SE3<mpreal>* g : {&rb.base(), &rb.tool(), &rb.home()}) s.length += g->translation().cwiseAbs().sum();
  return s;
}

template <class S> void compareRobot(const soma::io::RobotFile<S>& f, const soma::io::RobotFile<mpreal>& r) {
  const auto& a = f.robot;
  const auto& b = r.robot;
  if (a.dof() != b.dof() || a.convention() != b.convention() || f.degrees != r.degrees ||
      a.dhRows().size() != b.dhRows().size())
    disagree("robot: the joint count, convention or angle unit differs in " + std::string(soma::scalarName<S>()));
  const RobotScale s = robotScale(r);
  const mpreal rot = unitRoundoff<S>() * 64 * (b.dof() + 2) * (1 + s.theta);
  const mpreal pos = rot * (s.length + 1);
  auto value = [&](const mpreal& x) { return rot * (1 + (mpfr::isinf(x) ? mpreal(0) : mpfr::abs(x))) + denormMin<S>(); };
  auto length = [&](const mpreal& x) { return pos + rot * (mpfr::isinf(x) ? mpreal(0) : mpfr::abs(x)) + denormMin<S>(); };
  for (std::size_t i = 0; i < b.dhRows().size(); ++i) {
    const auto& x = a.dhRows()[i];
    const auto& y = b.dhRows()[i];
    const std::string w = "joint " + std::to_string(i + 1) + " dh ";
    if (x.type != y.type) disagree("robot: " + w + "type differs");
    same("robot", w + "a", x.a, y.a, storedBound<S>(y.a));
    same("robot", w + "d", x.d, y.d, storedBound<S>(y.d));
    same("robot", w + "alpha", x.alpha, y.alpha, value(y.alpha));
    same("robot", w + "theta", x.theta, y.theta, value(y.theta));
  }
  for (std::size_t i = 0; i < b.joints().size(); ++i) {
    const auto& x = a.joints()[i];
    const auto& y = b.joints()[i];
    const std::string w = "joint " + std::to_string(i + 1) + " ";
    if (x.type != y.type) disagree("robot: " + w + "type differs");
    for (int k = 0; k < 3; ++k) {
      same("robot", w + "axis[" + std::to_string(k) + "]", x.axis(k), y.axis(k), rot);
      same("robot", w + "point[" + std::to_string(k) + "]", x.point(k), y.point(k), length(y.point(k)));
    }
    same("robot", w + "offset", x.offset, y.offset, value(y.offset));
    same("robot", w + "lower limit", x.lower, y.lower, value(y.lower));
    same("robot", w + "upper limit", x.upper, y.upper, value(y.upper));
  }
  comparePose<S>("robot", "home", a.home(), b.home(), rot, s.length, false);
  comparePose<S>("robot", "base", a.base(), b.base(), rot, s.length, false);
  comparePose<S>("robot", "tool", a.tool(), b.tool(), rot, s.length, false);
}

// ---- platform -------------------------------------------------------------------------------------
template <class S> void comparePlatform(const soma::StewartPlatform<S>& p, const soma::StewartPlatform<mpreal>& r) {
  for (std::size_t i = 0; i < 6; ++i) {
    const std::string w = "leg " + std::to_string(i + 1) + " ";
    for (int k = 0; k < 3; ++k) {
      same("platform", w + "base[" + std::to_string(k) + "]", p.base[i](k), r.base[i](k), storedBound<S>(r.base[i](k)));
      same("platform", w + "platform[" + std::to_string(k) + "]", p.platform[i](k), r.platform[i](k),
           storedBound<S>(r.platform[i](k)));
    }
    same("platform", w + "length", p.legs[i], r.legs[i], storedBound<S>(r.legs[i]));
  }
}

// ---- the five readings ----------------------------------------------------------------------------
template <class T> struct Reading {
  std::optional<T> value;
  std::string error;
};

template <class T, class F> Reading<T> readOne(F&& read) {
  Reading<T> r;
  try {
    r.value = read();
  } catch (const soma::InvalidInput& e) {
    r.error = e.what();
  }  // any other exception escapes to expectReadOrInvalidInput: a finding
  return r;
}

/// Rule 1 over the five readings (in ladder order), then rule 2 against mpfr's.
template <template <class> class Obj, class Reader, class Compare>
void differential(const char* reader, Reader&& read, Compare&& compare) {
  auto rf = readOne<Obj<float>>([&] { return read(float()); });
  auto rd = readOne<Obj<double>>([&] { return read(double()); });
  auto rl = readOne<Obj<long double>>([&] { return read((long double)0); });
  auto rq = readOne<Obj<__float128>>([&] { return read(__float128()); });
  auto rm = readOne<Obj<mpreal>>([&] { return read(mpreal()); });
  const std::array<bool, 5> ok = {bool(rf.value), bool(rd.value), bool(rl.value), bool(rq.value), bool(rm.value)};
  const std::array<const std::string*, 5> err = {&rf.error, &rd.error, &rl.error, &rq.error, &rm.error};
  static const char* names[5] = {"float", "double", "long double", "__float128", "mpfr"};
  for (int i = 0; i < 5; ++i)
    for (int k = i + 1; k < 5; ++k)
      if (ok[i] && !ok[k])
        disagree(std::string(reader) + ": accepted in " + names[i] + ", refused in " + names[k] + ": " + *err[k]);
  if (!rm.value) return;
  if (rf.value) compare(*rf.value, *rm.value);
  if (rd.value) compare(*rd.value, *rm.value);
  if (rl.value) compare(*rl.value, *rm.value);
  if (rq.value) compare(*rq.value, *rm.value);
}

template <class S> using RobotOf = soma::io::RobotFile<S>;
template <class S> using PoseOf = soma::SE3<S>;
template <class S> using PlatformOf = soma::StewartPlatform<S>;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("differential", [&] {
    differential<RobotOf>(
        "robot", [&](auto s) { return soma::io::parseRobot<decltype(s)>(body, "fuzz.json"); },
        [](const auto& f, const auto& r) { compareRobot(f, r); });
    differential<PoseOf>(
        "pose", [&](auto s) { return soma::io::parsePose<decltype(s)>(body, "fuzz.json"); },
        [](const auto& g, const auto& r) {
          using S = typename std::decay_t<decltype(g.translation())>::Scalar;
          comparePose<S>("pose", "pose", g, r, unitRoundoff<S>() * 64, mpreal(0), true);
        });
    differential<PlatformOf>(
        "platform", [&](auto s) { return soma::io::parsePlatform<decltype(s)>(body, "fuzz.json"); },
        [](const auto& p, const auto& r) { comparePlatform(p, r); });
  });
  return 0;
}
