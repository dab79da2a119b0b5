// SE(3) exp, log, compose, act (point) and inverse: soma on the five scalars side by side with
// Orocos KDL's KDL::Frame (double only), in one binary.
//
// Which KDL operation corresponds (see the labels, printed in papers/benchmarks/se3.md):
//   compose  F1 * F2          same map (KDL stores the 3×3 matrix, soma a unit quaternion)
//   act      F * p            same map
//   inverse  F.Inverse()      same map
//   exp      KDL has no SE(3) exponential. addDelta(Identity, Twist(v, ω), 1) is the
//            exponential of SO(3) × R³ (rotation Rot(ω), translation v), which is NOT the screw
//            motion exp of the twist (ω, v) unless ω = 0. The row "Rot+V" builds the real SE(3)
//            exp from KDL's Rotation::Rot plus the translation V(ω)v written here (not KDL code).
//   log      likewise: diff(Identity, F) = (GetRot(R), p) is the SO(3) × R³ log; "GetRot+V⁻¹"
//            adds V(ω)⁻¹p written here to give the SE(3) log.
#include "bench_support.hpp"

namespace soma::bench {
namespace {

// ---- soma on the scalar ladder -------------------------------------------------------------
template <class S> void registerSoma() {
  reg(somaName<S>("SE3.exp"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.twist[i].exp(); };
  });
  reg(somaName<S>("SE3.log"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.a[i].log(); };
  });
  reg(somaName<S>("SE3.compose"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.a[i].compose(in.b[i]); };
  });
  reg(somaName<S>("SE3.act"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.a[i].act(in.p[i]); };
  });
  reg(somaName<S>("SE3.inverse"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.a[i].inverse(); };
  });
}

/// Every rung against the 256-bit mpfr result of the same input (64 ulps of S, relative to the
/// result's size); the largest error per operation is kept for the table.
template <class S> void checkAgainstMpfr(Checker& c) {
  const auto& in = inputs<S>();
  const auto& mp = inputs<mpreal>();
  const std::string s(scalarName<S>());
  auto check = [&](const std::string& op, std::size_t i, double err, double scale) {
    c.expect(op + " " + s + " vs mpfr", i, err, ladderTol<S>(scale));
    recordError(somaName<S>(op), err);
  };
  for (std::size_t i = 0; i < kPool; ++i) {
    const Mat4<mpreal> e = mp.twist[i].exp().matrix();
    check("SE3.exp", i, toDouble(maxDiff<S>(in.twist[i].exp().matrix(), e)), maxAbs(e));
    const Vec6<mpreal> l = mp.a[i].log().coeffs();
    check("SE3.log", i, toDouble(maxDiff<S>(in.a[i].log().coeffs(), l)), maxAbs(l));
    const Mat4<mpreal> cm = mp.a[i].compose(mp.b[i]).matrix();
    check("SE3.compose", i, toDouble(maxDiff<S>(in.a[i].compose(in.b[i]).matrix(), cm)),
          maxAbs(cm));
    const Vec3<mpreal> am = mp.a[i].act(mp.p[i]);
    check("SE3.act", i, toDouble(maxDiff<S>(in.a[i].act(in.p[i]), am)), maxAbs(am));
    const Mat4<mpreal> im = mp.a[i].inverse().matrix();
    check("SE3.inverse", i, toDouble(maxDiff<S>(in.a[i].inverse().matrix(), im)), maxAbs(im));
  }
}

/// The mpfr reference itself: exp(log X) = X and log(exp s) = s at 256 bits.
void checkMpfrRoundTrip(Checker& c) {
  const auto& mp = inputs<mpreal>();
  for (std::size_t i = 0; i < kPool; ++i) {
    const Mat4<mpreal> x = mp.a[i].matrix();
    c.expect("SE3 exp(log X) = X in mpfr", i,
             toDouble(maxDiff<mpreal>(mp.a[i].log().exp().matrix(), x)),
             ladderTol<mpreal>(maxAbs(x)));
    const Vec6<mpreal> s = mp.twist[i].coeffs();
    c.expect("SE3 log(exp s) = s in mpfr", i,
             toDouble(maxDiff<mpreal>(mp.twist[i].exp().log().coeffs(), s)),
             ladderTol<mpreal>(maxAbs(s)));
  }
}

#ifdef SOMA_HAVE_KDL
// ---- Orocos KDL ----------------------------------------------------------------------------
// Coefficients of V(ω) = I + B Ω + C Ω² and V⁻¹ = I − ½Ω + D Ω², written out for the KDL rows
// (same formulas as soma; Taylor branch below Tolerance<double>::precision(3)).
// GF §4.4.2, GF-4.4.2-se3-exp-4x4
KDL::Frame kdlSe3Exp(const KDL::Twist& s) {
  const double th2 = KDL::dot(s.rot, s.rot);
  const double th = std::sqrt(th2);
  const double sw = Tolerance<double>::precision(3);
  double B, C;
  if (th2 < sw * sw) {
    B = 0.5 - th2 / 24;
    C = 1.0 / 6 - th2 / 120;
  } else {
    const double h = std::sin(th / 2);
    B = 2 * h * h / th2;
    C = (th - std::sin(th)) / (th2 * th);
  }
  const KDL::Vector wv = s.rot * s.vel;  // KDL: Vector * Vector is the cross product
  return KDL::Frame(KDL::Rotation::Rot(s.rot, th), s.vel + B * wv + C * (s.rot * wv));
}
// GF §4.4.2, GF-4.4.2-se3-log-4x4
KDL::Twist kdlSe3Log(const KDL::Frame& f) {
  const KDL::Vector w = f.M.GetRot();
  const double th2 = KDL::dot(w, w);
  const double sw = Tolerance<double>::precision(3);
  double D;
  if (th2 < sw * sw) {
    D = 1.0 / 12 + th2 / 720;
  } else {
    const double th = std::sqrt(th2);
    D = 1 / th2 - std::cos(th / 2) / (2 * th * std::sin(th / 2));
  }
  const KDL::Vector wp = w * f.p;
  return KDL::Twist(f.p - 0.5 * wp + D * (w * wp), w);
}

void registerKdl() {
  reg("SE3.exp/KDL/Rot+V", "Rotation::Rot(w,|w|) + t = V(w)v written in this bench: SE(3) exp", [] {
    return [&k = kdlInputs()](std::size_t i) { return kdlSe3Exp(k.twist[i]); };
  });
  reg("SE3.exp/KDL/addDelta",
      "addDelta(Frame::Identity(),Twist(v,w),1) = (Rot(w), v): SO(3)xR3 exp, NOT SE(3) exp", [] {
        return [&k = kdlInputs(), id = KDL::Frame::Identity()](std::size_t i) {
          return KDL::addDelta(id, k.twist[i], 1.0);
        };
      });
  reg("SE3.log/KDL/GetRot+Vinv", "M.GetRot() + v = V(w)^-1 p written in this bench: SE(3) log",
      [] { return [&k = kdlInputs()](std::size_t i) { return kdlSe3Log(k.a[i]); }; });
  reg("SE3.log/KDL/diff",
      "diff(Frame::Identity(),F) = (GetRot(M), p): SO(3)xR3 log, NOT SE(3) log", [] {
        return [&k = kdlInputs(), id = KDL::Frame::Identity()](std::size_t i) {
          return KDL::diff(id, k.a[i]);
        };
      });
  reg("SE3.compose/KDL/F1*F2", "Frame * Frame: same map", [] {
    return [&k = kdlInputs()](std::size_t i) { return k.a[i] * k.b[i]; };
  });
  reg("SE3.act/KDL/F*p", "Frame * Vector: same map", [] {
    return [&k = kdlInputs()](std::size_t i) { return k.a[i] * k.p[i]; };
  });
  reg("SE3.inverse/KDL/F.Inverse()", "Frame::Inverse(): same map", [] {
    return [&k = kdlInputs()](std::size_t i) { return k.a[i].Inverse(); };
  });
}

/// KDL against soma double (the agreement check) and against mpfr (the error column).
/// KDL's GetRot reads the axis off R − Rᵀ, whose size is 2 sin θ: its rounding error grows
/// like eps / sin θ near θ = π, so the log comparisons allow Tolerance<double>::identity()
/// times 1 / max(sin θ, sqrt(eps)) (soma's quaternion log has no such factor).
void checkKdl(Checker& c) {
  using std::sin;
  const auto& in = inputs<double>();
  const auto& mp = inputs<mpreal>();
  const auto& k = kdlInputs();
  const KDL::Frame id = KDL::Frame::Identity();
  double addDeltaGap = 0, diffGap = 0;
  for (std::size_t i = 0; i < kPool; ++i) {
    // exp: the real SE(3) exp, and addDelta against what it really is, (exp ω, v).
    const Mat4<double> em = in.twist[i].exp().matrix();
    const Mat4<double> kem = fromKdl(kdlSe3Exp(k.twist[i]));
    c.expect("SE3.exp soma vs KDL Rot+V", i, maxDiff<double>(kem, em), kdlTol(maxAbs(em)));
    recordError("SE3.exp/KDL/Rot+V", maxDiff<double>(kem, mp.twist[i].exp().matrix()));
    const Mat4<double> dm =
        SE3<double>(SO3Tangent<double>(in.twist[i].ang()).exp(), in.twist[i].lin()).matrix();
    const Mat4<double> kad = fromKdl(KDL::addDelta(id, k.twist[i], 1.0));
    c.expect("SE3.exp soma (exp w, v) vs KDL addDelta", i, maxDiff<double>(kad, dm),
             kdlTol(maxAbs(dm)));
    recordError("SE3.exp/KDL/addDelta",
                maxDiff<double>(kad, SE3<mpreal>(SO3Tangent<mpreal>(mp.twist[i].ang()).exp(),
                                                 mp.twist[i].lin())
                                         .matrix()));
    addDeltaGap = std::max(addDeltaGap, maxDiff<double>(kad, em));

    // log
    const double theta = in.a[i].so3().log().angle();
    const double cond = 1 / std::max(sin(theta), toDouble(Tolerance<double>::sqrtEpsilon()));
    const std::string at = ", theta = " + std::to_string(theta);
    const Vec6<double> l = in.a[i].log().coeffs();
    const KDL::Twist kl = kdlSe3Log(k.a[i]);
    Vec6<double> klv;
    klv << fromKdl(kl.rot), fromKdl(kl.vel);
    c.expect("SE3.log soma vs KDL GetRot+Vinv", i, maxDiff<double>(klv, l),
             kdlTol(maxAbs(l)) * cond, at);
    recordError("SE3.log/KDL/GetRot+Vinv", maxDiff<double>(klv, mp.a[i].log().coeffs()));
    const KDL::Twist kd = KDL::diff(id, k.a[i]);
    Vec6<double> kdv, dl;
    kdv << fromKdl(kd.rot), fromKdl(kd.vel);
    dl << in.a[i].so3().log().coeffs(), in.a[i].translation();
    c.expect("SE3.log soma (log R, t) vs KDL diff", i, maxDiff<double>(kdv, dl),
             kdlTol(maxAbs(dl)) * cond, at);
    Vec6<mpreal> dlm;
    dlm << mp.a[i].so3().log().coeffs(), mp.a[i].translation();
    recordError("SE3.log/KDL/diff", maxDiff<double>(kdv, dlm));
    diffGap = std::max(diffGap, maxDiff<double>(kdv, l));

    // compose, act, inverse: the same maps.
    const Mat4<double> cm = in.a[i].compose(in.b[i]).matrix();
    const Mat4<double> kcm = fromKdl(k.a[i] * k.b[i]);
    c.expect("SE3.compose soma vs KDL", i, maxDiff<double>(kcm, cm), kdlTol(maxAbs(cm)));
    recordError("SE3.compose/KDL/F1*F2", maxDiff<double>(kcm, mp.a[i].compose(mp.b[i]).matrix()));
    const Vec3<double> am = in.a[i].act(in.p[i]);
    const Vec3<double> kam = fromKdl(k.a[i] * k.p[i]);
    c.expect("SE3.act soma vs KDL", i, maxDiff<double>(kam, am), kdlTol(maxAbs(am)));
    recordError("SE3.act/KDL/F*p", maxDiff<double>(kam, mp.a[i].act(mp.p[i])));
    const Mat4<double> im = in.a[i].inverse().matrix();
    const Mat4<double> kim = fromKdl(k.a[i].Inverse());
    c.expect("SE3.inverse soma vs KDL", i, maxDiff<double>(kim, im), kdlTol(maxAbs(im)));
    recordError("SE3.inverse/KDL/F.Inverse()", maxDiff<double>(kim, mp.a[i].inverse().matrix()));
  }
  // How far the SO(3)×R³ maps are from the SE(3) ones on these inputs (recorded, not timed).
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", addDeltaGap);
  benchmark::AddCustomContext("soma_gap_addDelta_vs_se3_exp", buf);
  std::snprintf(buf, sizeof buf, "%.3g", diffGap);
  benchmark::AddCustomContext("soma_gap_diff_vs_se3_log", buf);
}
#endif

void checkAll(Checker& c) {
  checkMpfrRoundTrip(c);
  checkAgainstMpfr<float>(c);
  checkAgainstMpfr<double>(c);
  checkAgainstMpfr<long double>(c);
  checkAgainstMpfr<__float128>(c);
#ifdef SOMA_HAVE_KDL
  checkKdl(c);
#endif
}

void registerAll() {
  registerSoma<float>();
  registerSoma<double>();
  registerSoma<long double>();
  registerSoma<__float128>();
  registerSoma<mpreal>();
#ifdef SOMA_HAVE_KDL
  registerKdl();
#endif
}

}  // namespace
}  // namespace soma::bench

int main(int argc, char** argv) {
  return soma::bench::benchMain(argc, argv, soma::bench::checkAll, soma::bench::registerAll);
}
