// SO(3) exp and log: soma on the five scalars side by side with Orocos KDL's KDL::Rotation
// (double only), in one binary.
//
// Which KDL operation corresponds (labels, printed in papers/benchmarks/se3.md):
//   exp  KDL::Rot(ω) (inline free function, rotation vector in, matrix out) and
//        Rotation::Rot(ω, |ω|) (library call): both are the SO(3) exponential (Rodrigues).
//        soma returns a unit quaternion, KDL a 3×3 matrix.
//   log  Rotation::GetRot(): the rotation vector, the SO(3) logarithm. soma reads it off the
//        quaternion, KDL off the matrix.
// SO3.matrix (soma only) times the quaternion → matrix conversion inside soma's act.
#include "bench_support.hpp"

namespace soma::bench {
namespace {

template <class S> void registerSoma() {
  reg(somaName<S>("SO3.exp"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.w[i].exp(); };
  });
  reg(somaName<S>("SO3.log"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.r[i].log(); };
  });
  // Not an exp/log: the quaternion → matrix step that soma's act (and so SE3 act, compose and
  // inverse) pays on every call, while KDL stores the matrix. Timed to explain those rows.
  reg(somaName<S>("SO3.matrix"), "", [] {
    return [&in = inputs<S>()](std::size_t i) { return in.r[i].matrix(); };
  });
}

/// Every rung against the 256-bit mpfr result of the same input; exp is compared as a matrix
/// (the quaternion has two signs).
template <class S> void checkAgainstMpfr(Checker& c) {
  const auto& in = inputs<S>();
  const auto& mp = inputs<mpreal>();
  const std::string s(scalarName<S>());
  for (std::size_t i = 0; i < kPool; ++i) {
    const Mat3<mpreal> e = mp.w[i].exp().matrix();
    const double ee = toDouble(maxDiff<S>(in.w[i].exp().matrix(), e));
    c.expect("SO3.exp " + s + " vs mpfr", i, ee, ladderTol<S>(maxAbs(e)));
    recordError(somaName<S>("SO3.exp"), ee);
    const Vec3<mpreal> l = mp.r[i].log().coeffs();
    const double le = toDouble(maxDiff<S>(in.r[i].log().coeffs(), l));
    c.expect("SO3.log " + s + " vs mpfr", i, le, ladderTol<S>(maxAbs(l)));
    recordError(somaName<S>("SO3.log"), le);
    const Mat3<mpreal> m = mp.r[i].matrix();
    const double me = toDouble(maxDiff<S>(in.r[i].matrix(), m));
    c.expect("SO3.matrix " + s + " vs mpfr", i, me, ladderTol<S>(maxAbs(m)));
    recordError(somaName<S>("SO3.matrix"), me);
  }
}

void checkMpfrRoundTrip(Checker& c) {
  const auto& mp = inputs<mpreal>();
  for (std::size_t i = 0; i < kPool; ++i) {
    const Mat3<mpreal> r = mp.r[i].matrix();
    c.expect("SO3 exp(log R) = R in mpfr", i,
             toDouble(maxDiff<mpreal>(mp.r[i].log().exp().matrix(), r)),
             ladderTol<mpreal>(maxAbs(r)));
    const Vec3<mpreal> w = mp.w[i].coeffs();
    c.expect("SO3 log(exp w) = w in mpfr", i,
             toDouble(maxDiff<mpreal>(mp.w[i].exp().log().coeffs(), w)),
             ladderTol<mpreal>(maxAbs(w)));
  }
}

#ifdef SOMA_HAVE_KDL
void registerKdl() {
  reg("SO3.exp/KDL/Rot(w)", "KDL::Rot(Vector) (inline): SO(3) exp, returns a matrix", [] {
    return [&k = kdlInputs()](std::size_t i) { return KDL::Rot(k.w[i]); };
  });
  reg("SO3.exp/KDL/Rotation::Rot", "Rotation::Rot(w, w.Norm()) (library): SO(3) exp, a matrix",
      [] {
        return [&k = kdlInputs()](std::size_t i) {
          return KDL::Rotation::Rot(k.w[i], k.w[i].Norm());
        };
      });
  reg("SO3.log/KDL/GetRot", "Rotation::GetRot() (library): SO(3) log, read off the matrix", [] {
    return [&k = kdlInputs()](std::size_t i) { return k.r[i].GetRot(); };
  });
}

/// KDL against soma double (agreement) and against mpfr (error column). GetRot reads the axis
/// off R − Rᵀ (size 2 sin θ), so its error grows like eps / sin θ near θ = π: the log
/// comparison allows Tolerance<double>::identity() times 1 / max(sin θ, sqrt(eps)).
void checkKdl(Checker& c) {
  using std::sin;
  const auto& in = inputs<double>();
  const auto& mp = inputs<mpreal>();
  const auto& k = kdlInputs();
  double worstErr = 0, worstTheta = 0;
  for (std::size_t i = 0; i < kPool; ++i) {
    const Mat3<double> e = in.w[i].exp().matrix();
    const Mat3<mpreal> em = mp.w[i].exp().matrix();
    const Mat3<double> k1 = fromKdl(KDL::Rot(k.w[i]));
    c.expect("SO3.exp soma vs KDL::Rot(w)", i, maxDiff<double>(k1, e), kdlTol(maxAbs(e)));
    recordError("SO3.exp/KDL/Rot(w)", maxDiff<double>(k1, em));
    const Mat3<double> k2 = fromKdl(KDL::Rotation::Rot(k.w[i], k.w[i].Norm()));
    c.expect("SO3.exp soma vs KDL Rotation::Rot", i, maxDiff<double>(k2, e), kdlTol(maxAbs(e)));
    recordError("SO3.exp/KDL/Rotation::Rot", maxDiff<double>(k2, em));

    const SO3Tangent<double> l = in.r[i].log();
    const double cond = 1 / std::max(sin(l.angle()), toDouble(Tolerance<double>::sqrtEpsilon()));
    const Vec3<double> kl = fromKdl(k.r[i].GetRot());
    c.expect("SO3.log soma vs KDL GetRot", i, maxDiff<double>(kl, l.coeffs()),
             kdlTol(maxAbs(l.coeffs())) * cond, ", theta = " + std::to_string(l.angle()));
    const double err = maxDiff<double>(kl, mp.r[i].log().coeffs());
    recordError("SO3.log/KDL/GetRot", err);
    if (err > worstErr) {
      worstErr = err;
      worstTheta = l.angle();
    }
  }
  // Where KDL's log is least accurate on these inputs (for the table's notes).
  char buf[96];
  std::snprintf(buf, sizeof buf, "error %.3g at theta = pi - %.3g", worstErr,
                pi<double>() - worstTheta);
  benchmark::AddCustomContext("soma_kdl_getrot_worst", buf);
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
