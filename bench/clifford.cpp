// Clifford-algebra products (issue 4, item 6): generic Cl(p,q,r) code against hand-written
// dual-quaternion arithmetic in the same binary, and the full products of Cl(0,6,2).
//
//   motor.compose   Cl(0,3,1) Even × Even (the generic product, a compile-time term table
//                   unrolled to straight-line code) | soma::DualQuaternion operator* |
//                   a hand-written 8-double dual-quaternion product (two Hamilton products
//                   and one more for the dual part, written out below)
//   motor.point     the point 1 + x𝐞 moved by M (1 + x𝐞) M†, M† = conj(M with 𝐞 ↦ −𝐞),
//                   GF §9.2 — generic: two Even × Even products | DualQuaternion::act (closed
//                   form R x + t) | hand-written: two 8-double products with the full conjugate
//   motor.line      a line / twist L (bivector) moved by M L M̃ — generic Even × Bivector then
//                   × Even, projected on grade 2 | DualQuaternion::adjoint | two hand products
//   motor.* float   the SIMD float motor (clifford/motor_simd.hpp: SSE2 closed forms) beside the
//                   generic Even<PGA, float> product it is tested against (tests/algebra/
//                   motor_simd.cpp); the float rows are checked against the double generic rows.
//   cl062.*         Cl(0,6,2) (SB): Even × Even (128 × 128 coefficients) and Dense × Dense
//                   (256 × 256), double; both use the blocked kernel of multivector.hpp.
//
// Every timed operation is first checked against an independent evaluation: the Cl(0,3,1)
// rows against the dual quaternions through the book's isomorphism (GF §9.3: e2e3 ↦ i,
// e3e1 ↦ j, e1e2 ↦ k, −e1e2e3𝐞 ↦ ε), the Cl(0,6,2) products against the 256 × 256 left-
// multiplication matrix applied to the dense right operand. Nothing is timed if a check fails.
#include "soma/algebra/clifford/motor_simd.hpp"
#include "soma/algebra/clifford/multivector.hpp"
#include "soma/algebra/dual_quaternion.hpp"

#include "bench_support.hpp"

namespace soma::bench {
namespace {

using namespace soma::clifford;
using PGA = Signature<0, 3, 1>;  // e1, e2, e3 ↦ indices 0, 1, 2; 𝐞 ↦ index 3
using Motor = Even<PGA, double>;
using Line = Bivector<PGA, double>;
using CL = Signature<0, 6, 2>;

// Blades (bitmasks) of the book's basis elements, generators 0-based.
constexpr Blade kE23 = 0b0110, kE13 = 0b0101, kE12 = 0b0011;        // e2e3, e1e3, e1e2
constexpr Blade kE1n = 0b1001, kE2n = 0b1010, kE3n = 0b1100, kI = 0b1111;  // eᵢ𝐞, e1e2e3𝐞

/// The Clifford image of a + εc (GF §9.3; e3e1 = −e1e3, ε = −e1e2e3𝐞).
Motor toMotor(const Vec4<double>& a, const Vec4<double>& c) {
  Motor m;
  m.setCoeff(0, a(0));
  m.setCoeff(kE23, a(1));
  m.setCoeff(kE13, -a(2));
  m.setCoeff(kE12, a(3));
  m.setCoeff(kE1n, c(1));
  m.setCoeff(kE2n, c(2));
  m.setCoeff(kE3n, c(3));
  m.setCoeff(kI, -c(0));
  return m;
}
/// (a, c) of a motor, inverse of toMotor.
std::pair<Vec4<double>, Vec4<double>> fromMotor(const Motor& m) {
  return {Vec4<double>(m.coeff(0), m.coeff(kE23), -m.coeff(kE13), m.coeff(kE12)),
          Vec4<double>(-m.coeff(kI), m.coeff(kE1n), m.coeff(kE2n), m.coeff(kE3n))};
}
/// M† = Clifford conjugate of M with 𝐞 ↦ −𝐞 (the right factor of the point action, GF §9.2).
template <class M> M dagger(const M& m) {
  M d = m.conjugate();
  for (int i = 0; i < d.size; ++i)
    if (d.blade(i) & 0b1000) d[i] = -d[i];
  return d;
}

// ---- the hand-written dual quaternion: 8 doubles, Hamilton products written out ------------
struct DQ8 {
  double w, x, y, z;      // real part a
  double cw, cx, cy, cz;  // dual part c
};
inline void qmul(double aw, double ax, double ay, double az, double bw, double bx, double by,
                 double bz, double& w, double& x, double& y, double& z) {
  w = aw * bw - ax * bx - ay * by - az * bz;
  x = aw * bx + ax * bw + ay * bz - az * by;
  y = aw * by - ax * bz + ay * bw + az * bx;
  z = aw * bz + ax * by - ay * bx + az * bw;
}
/// (a1 + εc1)(a2 + εc2) = a1a2 + ε(a1c2 + c1a2).
inline DQ8 mul(const DQ8& p, const DQ8& q) {
  DQ8 r;
  qmul(p.w, p.x, p.y, p.z, q.w, q.x, q.y, q.z, r.w, r.x, r.y, r.z);
  double w1, x1, y1, z1, w2, x2, y2, z2;
  qmul(p.w, p.x, p.y, p.z, q.cw, q.cx, q.cy, q.cz, w1, x1, y1, z1);
  qmul(p.cw, p.cx, p.cy, p.cz, q.w, q.x, q.y, q.z, w2, x2, y2, z2);
  r.cw = w1 + w2, r.cx = x1 + x2, r.cy = y1 + y2, r.cz = z1 + z2;
  return r;
}
inline DQ8 toDQ8(const DualQuaternion<double>& h) {
  const auto& a = h.real();
  const auto& c = h.dual();
  return DQ8{a.w(), a.x(), a.y(), a.z(), c.w(), c.x(), c.y(), c.z()};
}
/// a* − εc* (the full conjugate, right factor of the point action).
inline DQ8 fullConj(const DQ8& h) { return DQ8{h.w, -h.x, -h.y, -h.z, -h.cw, h.cx, h.cy, h.cz}; }
/// a* + εc* (the conjugate of the adjoint action).
inline DQ8 conj(const DQ8& h) { return DQ8{h.w, -h.x, -h.y, -h.z, h.cw, -h.cx, -h.cy, -h.cz}; }

struct Pools {
  std::vector<DualQuaternion<double>> ha, hb;
  std::vector<DQ8> da, db, dpt, dline;
  std::vector<Motor> ma, mb, mpt;
  std::vector<Line> ml;
  std::vector<Vec3<double>> x;
  std::vector<SE3Tangent<double>> xi;
  std::vector<MotorF> fa, fb;
  std::vector<MotorF::Generic> ga8, gb8, gpt8;
  std::vector<PointF> fpt;
  std::vector<LineF> fl;
  std::vector<Even<CL, double>> ea, eb;
  std::vector<Dense<CL, double>> ga, gb;
};

const Pools& pools() {
  static const Pools P = [] {
    Pools p;
    const DoubleInputs& d = doubleInputs();
    std::mt19937_64 g(kSeed + 9);
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t i = 0; i < kPool; ++i) {
      p.ha.push_back(DualQuaternion<double>::fromSE3(d.a[i]));
      p.hb.push_back(DualQuaternion<double>::fromSE3(d.b[i]));
      p.da.push_back(toDQ8(p.ha.back()));
      p.db.push_back(toDQ8(p.hb.back()));
      auto motor = [](const DualQuaternion<double>& h) {
        return toMotor(soma::detail::studyOrder(h.real()), soma::detail::studyOrder(h.dual()));
      };
      p.ma.push_back(motor(p.ha.back()));
      p.mb.push_back(motor(p.hb.back()));
      p.x.push_back(d.p[i]);
      // the point 1 + x𝐞 ↔ 1 + εx
      Motor pt(1.0);
      pt.setCoeff(kE1n, d.p[i](0));
      pt.setCoeff(kE2n, d.p[i](1));
      pt.setCoeff(kE3n, d.p[i](2));
      p.mpt.push_back(pt);
      p.dpt.push_back(DQ8{1, 0, 0, 0, 0, d.p[i](0), d.p[i](1), d.p[i](2)});
      // a twist (ω; v) ↔ ½ω + ε½v ↔ ½(ω₁ e2e3 + ω₂ e3e1 + ω₃ e1e2 + v₁ e1𝐞 + v₂ e2𝐞 + v₃ e3𝐞)
      const Vec3<double> w = d.w[i], v = d.v[i];
      Vec6<double> t;
      t << w, v;
      p.xi.emplace_back(t);
      Line l;
      l.setCoeff(kE23, w(0) / 2);
      l.setCoeff(kE13, -w(1) / 2);
      l.setCoeff(kE12, w(2) / 2);
      l.setCoeff(kE1n, v(0) / 2);
      l.setCoeff(kE2n, v(1) / 2);
      l.setCoeff(kE3n, v(2) / 2);
      p.ml.push_back(l);
      p.dline.push_back(DQ8{0, w(0) / 2, w(1) / 2, w(2) / 2, 0, v(0) / 2, v(1) / 2, v(2) / 2});
      auto toFloat = [](const Motor& m) {
        MotorF::Generic f;
        for (int k = 0; k < f.size; ++k) f[k] = float(m[k]);
        return f;
      };
      p.ga8.push_back(toFloat(p.ma.back()));
      p.gb8.push_back(toFloat(p.mb.back()));
      p.gpt8.push_back(toFloat(pt));
      p.fa.push_back(MotorF::fromGeneric(p.ga8.back()));
      p.fb.push_back(MotorF::fromGeneric(p.gb8.back()));
      p.fpt.push_back(PointF::make(float(d.p[i](0)), float(d.p[i](1)), float(d.p[i](2))));
      p.fl.push_back(LineF{simd::load(0, float(w(0) / 2), float(w(1) / 2), float(w(2) / 2)),
                           simd::load(0, float(v(0) / 2), float(v(1) / 2), float(v(2) / 2))});
      if (i < 16) {  // Cl(0,6,2) pools (smaller: 2 KB per dense element)
        Even<CL, double> e1, e2;
        Dense<CL, double> g1, g2;
        for (int k = 0; k < e1.size; ++k) e1[k] = u(g), e2[k] = u(g);
        for (int k = 0; k < g1.size; ++k) g1[k] = u(g), g2[k] = u(g);
        p.ea.push_back(e1), p.eb.push_back(e2), p.ga.push_back(g1), p.gb.push_back(g2);
      }
    }
    return p;
  }();
  return P;
}

double maxAbs8(const Vec4<double>& a, const Vec4<double>& c) {
  return std::max(a.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff());
}

void checkAll(Checker& c) {
  const Pools& p = pools();
  const double tol = toDouble(Tolerance<double>::identity());
  for (std::size_t i = 0; i < kPool; ++i) {
    // composition: all three agree with the dual quaternion product
    const auto h = p.ha[i] * p.hb[i];
    const Vec4<double> a = soma::detail::studyOrder(h.real()), cc = soma::detail::studyOrder(h.dual());
    const auto [ma, mc] = fromMotor(Motor(p.ma[i] * p.mb[i]));
    c.expect("motor.compose Cl(0,3,1) vs DualQuaternion", i, maxAbs8(ma - a, mc - cc),
             tol * (1 + maxAbs8(a, cc)));
    const DQ8 r = mul(p.da[i], p.db[i]);
    c.expect("motor.compose hand vs DualQuaternion", i,
             maxAbs8(Vec4<double>(r.w, r.x, r.y, r.z) - a, Vec4<double>(r.cw, r.cx, r.cy, r.cz) - cc),
             tol * (1 + maxAbs8(a, cc)));
    // point: 1 + (R x + t)𝐞
    const Vec3<double> y = p.ha[i].act(p.x[i]);
    const Motor mp = Motor(Motor(p.ma[i] * p.mpt[i]) * dagger(p.ma[i]));
    const Vec3<double> my(mp.coeff(kE1n), mp.coeff(kE2n), mp.coeff(kE3n));
    c.expect("motor.point Cl(0,3,1) vs DualQuaternion::act", i,
             std::max((my - y).cwiseAbs().maxCoeff(), std::abs(mp.coeff(0) - 1)),
             tol * (1 + y.cwiseAbs().maxCoeff()));
    const DQ8 hp = mul(mul(p.da[i], p.dpt[i]), fullConj(p.da[i]));
    c.expect("motor.point hand vs DualQuaternion::act", i,
             (Vec3<double>(hp.cx, hp.cy, hp.cz) - y).cwiseAbs().maxCoeff(),
             tol * (1 + y.cwiseAbs().maxCoeff()));
    // line / twist: Ad(g)(ω; v)
    const Vec6<double> ad = p.ha[i].adjoint(p.xi[i]).coeffs();
    const Line ml = Motor(Motor(p.ma[i] * p.ml[i]) * ~p.ma[i]).grade<2>();
    Vec6<double> mlv;
    mlv << 2 * ml.coeff(kE23), -2 * ml.coeff(kE13), 2 * ml.coeff(kE12), 2 * ml.coeff(kE1n),
        2 * ml.coeff(kE2n), 2 * ml.coeff(kE3n);
    c.expect("motor.line Cl(0,3,1) vs DualQuaternion::adjoint", i,
             (mlv - ad).cwiseAbs().maxCoeff(), tol * (1 + ad.cwiseAbs().maxCoeff()));
    const DQ8 hl = mul(mul(p.da[i], p.dline[i]), conj(p.da[i]));
    Vec6<double> hlv;
    hlv << 2 * hl.x, 2 * hl.y, 2 * hl.z, 2 * hl.cx, 2 * hl.cy, 2 * hl.cz;
    c.expect("motor.line hand vs DualQuaternion::adjoint", i, (hlv - ad).cwiseAbs().maxCoeff(),
             tol * (1 + ad.cwiseAbs().maxCoeff()));
  }
  // the float SIMD motor against the double generic rows (float tolerance: 64 eps of float)
  const double tolf = 64 * double(std::numeric_limits<float>::epsilon());
  for (std::size_t i = 0; i < kPool; ++i) {
    const Motor want = Motor(p.ma[i] * p.mb[i]);
    const MotorF::Generic got = (p.fa[i] * p.fb[i]).toGeneric();
    double err = 0, sz = 0;
    for (int k = 0; k < want.size; ++k)
      err = std::max(err, std::abs(double(got[k]) - want[k])), sz = std::max(sz, std::abs(want[k]));
    c.expect("motor.compose SIMD float vs Cl(0,3,1) double", i, err, tolf * (1 + sz));
    const Vec3<double> y = p.ha[i].act(p.x[i]);
    const PointF q = p.fa[i](p.fpt[i]);
    c.expect("motor.point SIMD float vs DualQuaternion::act", i,
             (Vec3<double>(q.x(), q.y(), q.z()) - y).cwiseAbs().maxCoeff(),
             tolf * (1 + y.cwiseAbs().maxCoeff()));
    const Vec6<double> ad = p.ha[i].adjoint(p.xi[i]).coeffs();
    const LineF l = p.fa[i](p.fl[i]);
    Vec6<double> lv;
    lv << 2 * simd::lane(l.d, 1), 2 * simd::lane(l.d, 2), 2 * simd::lane(l.d, 3),
        2 * simd::lane(l.m, 1), 2 * simd::lane(l.m, 2), 2 * simd::lane(l.m, 3);
    c.expect("motor.line SIMD float vs DualQuaternion::adjoint", i, (lv - ad).cwiseAbs().maxCoeff(),
             tolf * (1 + ad.cwiseAbs().maxCoeff()));
  }
  // Cl(0,6,2): the blocked kernel against the left-multiplication matrix (independent loop
  // over productSign) applied to the dense right operand.
  for (std::size_t i = 0; i < p.ea.size(); ++i) {
    auto against = [&](const std::string& what, const auto& x, const auto& y) {
      const auto xy = x * y;
      const Dense<CL, double> yd(y);
      Eigen::VectorXd yv(CL::dim);
      for (int k = 0; k < yd.size; ++k) yv(k) = yd[k];
      const Eigen::VectorXd want = leftMultiplicationMatrix(x) * yv;
      const Dense<CL, double> got(xy);
      double err = 0;
      for (int k = 0; k < got.size; ++k) err = std::max(err, std::abs(got[k] - want(k)));
      c.expect(what, i, err, tol * (1 + want.cwiseAbs().maxCoeff()) * 16);
    };
    against("cl062 even*even vs left-multiplication matrix", p.ea[i], p.eb[i]);
    against("cl062 dense*dense vs left-multiplication matrix", p.ga[i], p.gb[i]);
  }
}

template <class F> void regB(const std::string& name, const std::string& label, F f) {
  benchmark::RegisterBenchmark(name.c_str(), [label, f](benchmark::State& st) {
    st.SetLabel(label);
    loop(st, f);
  });
}

void registerAll() {
  const Pools& p = pools();
  regB("motor.compose/Cl031-Even/double", "M1 * M2, Even x Even (48 terms)",
       [&p](std::size_t i) { return p.ma[i] * p.mb[i]; });
  regB("motor.compose/DualQuaternion/double", "soma::DualQuaternion operator*",
       [&p](std::size_t i) { return p.ha[i] * p.hb[i]; });
  regB("motor.compose/hand8/double", "hand-written 8-double product",
       [&p](std::size_t i) { return mul(p.da[i], p.db[i]); });
  regB("motor.point/Cl031-Even/double", "M (1 + x e) M-dagger, two Even x Even",
       [&p](std::size_t i) { return Motor(p.ma[i] * p.mpt[i]) * dagger(p.ma[i]); });
  regB("motor.point/DualQuaternion/double", "DualQuaternion::act (closed form R x + t)",
       [&p](std::size_t i) { return p.ha[i].act(p.x[i]); });
  regB("motor.point/hand8/double", "h (1 + eps x) h-full-conjugate, two hand products",
       [&p](std::size_t i) { return mul(mul(p.da[i], p.dpt[i]), fullConj(p.da[i])); });
  regB("motor.line/Cl031-Even/double", "<M L ~M>_2, Even x Bivector x Even",
       [&p](std::size_t i) { return Motor(p.ma[i] * p.ml[i] * ~p.ma[i]).grade<2>(); });
  regB("motor.line/DualQuaternion/double", "DualQuaternion::adjoint on a twist",
       [&p](std::size_t i) { return p.ha[i].adjoint(p.xi[i]); });
  regB("motor.line/hand8/double", "h l h*, two hand products",
       [&p](std::size_t i) { return mul(mul(p.da[i], p.dline[i]), conj(p.da[i])); });
  regB("motor.compose/SIMD/float", "MotorF * MotorF, SSE2 (three Hamilton products)",
       [&p](std::size_t i) { return p.fa[i] * p.fb[i]; });
  regB("motor.compose/Cl031-Even/float", "M1 * M2, Even x Even (48 terms), float",
       [&p](std::size_t i) { return MotorF::Generic(p.ga8[i] * p.gb8[i]); });
  regB("motor.point/SIMD/float", "MotorF(point): closed form, two cross products",
       [&p](std::size_t i) { return p.fa[i](p.fpt[i]); });
  regB("motor.point/Cl031-Even/float", "M (1 + x e) M-dagger, two Even x Even, float",
       [&p](std::size_t i) {
         return MotorF::Generic(MotorF::Generic(p.ga8[i] * p.gpt8[i]) * dagger(p.ga8[i]));
       });
  regB("motor.line/SIMD/float", "MotorF(line): (R l, R m + t x R l)",
       [&p](std::size_t i) { return p.fa[i](p.fl[i]); });
  regB("cl062.even*even/Cl062/double", "Even x Even, 128 x 128 coefficients",
       [&p](std::size_t i) { return p.ea[i & 15] * p.eb[i & 15]; });
  regB("cl062.dense*dense/Cl062/double", "Dense x Dense, 256 x 256 coefficients",
       [&p](std::size_t i) { return p.ga[i & 15] * p.gb[i & 15]; });
  regB("cl062.even*bivector/Cl062/double", "Even x Bivector (28 coefficients)",
       [&p](std::size_t i) { return p.ea[i & 15] * p.eb[i & 15].grade<2>(); });
}

}  // namespace
}  // namespace soma::bench

int main(int argc, char** argv) {
  return soma::bench::benchMain(argc, argv, soma::bench::checkAll, soma::bench::registerAll);
}
