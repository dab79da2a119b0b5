#pragma once
// Definitions of identification.hpp; included only by the explicit instantiations (soma_instantiate).
#include "soma/geometry/screws/identification.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <limits>

namespace soma {
namespace detail {

template <class S> struct ScrewIdRaw {
  ScrewSystemType type{ScrewSystemType::Unknown};
  std::array<S, 3> p{};
  Mat3<S> R{Mat3<S>::Identity()};
  Vec3<S> d{Vec3<S>::Zero()};
};

/// Records the decisions of one run; flips the `flip`-th decision (to find the nearest other type).
template <class S> class ScrewDecider {
 public:
  ScrewDecider(int flip, std::vector<ScrewSystemDecision<S>>* log) : flip_(flip), log_(log) {}
  bool nonzero(const char* quantity, const S& value, const S& tol) {
    bool nz = value > tol;
    if (log_) log_->push_back(ScrewSystemDecision<S>{quantity, value, tol, nz});
    if (count_ == flip_) nz = !nz;
    ++count_;
    return nz;
  }

 private:
  int flip_;
  int count_ = 0;
  std::vector<ScrewSystemDecision<S>>* log_;
};

template <class S> Vec3<S> unitOf(const Vec3<S>& v) {
  using std::sqrt;
  return v / sqrt(v.squaredNorm());
}
/// A unit vector perpendicular to the unit u.
template <class S> Vec3<S> perpendicularTo(const Vec3<S>& u) {
  using std::abs;
  Vec3<S> a = Vec3<S>::Zero();
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (abs(u(i)) < abs(u(k))) k = i;
  a(k) = S(1);
  return unitOf<S>(Vec3<S>(u.cross(a)));
}
/// Unit vector along the part of x orthogonal to the unit u (two Gram–Schmidt passes: x may be
/// nearly parallel to u near a type boundary).
template <class S> Vec3<S> orthoUnit(const Vec3<S>& x, const Vec3<S>& u) {
  Vec3<S> y = x - u * u.dot(x);
  y -= u * u.dot(y);
  return unitOf<S>(y);
}
template <class S> Mat3<S> frameOf(const Vec3<S>& e1, const Vec3<S>& e2) {
  const Vec3<S> f2 = orthoUnit<S>(e2, e1);
  Mat3<S> r;
  r << e1, f2, e1.cross(f2);
  return r;
}

/// Symmetric 2×2 / 3×3 eigen-decomposition, eigenvalues descending.
template <class S> void pitchEigen(const ScrewMatX<S>& m, ScrewMatX<S>& vecs, std::array<S, 3>& vals) {
  std::vector<S> ev;
  smallSymEigen<S>(m, ev, vecs);
  for (std::size_t i = 0; i < ev.size(); ++i) vals[i] = ev[i];
}

// GF §8.2.7 and §8.3.6 (geometric reduction; see identification.hpp). B: orthonormal 6×n, n ≤ 3.
template <class S> ScrewIdRaw<S> classifyLow(const ScrewBasis<S>& B, ScrewDecider<S>& dec) {
  using std::abs;
  using std::sqrt;
  using T = ScrewSystemType;
  const int n = int(B.cols());
  ScrewIdRaw<S> out;
  const S tolR = Tolerance<S>::rank();
  const ScrewMatX<S> om = B.topRows(3), vm = B.bottomRows(3);
  // Ω = U Σ Wᵀ (thin SVD of the 3×n ω-block; n ≤ 3 so U is 3×n).
  ScrewMatX<S> U, W;
  std::vector<S> sv;
  smallSvd<S>(om, U, sv, W);
  const ScrewMatX<S> VW = vm * W;
  auto sig = [&](int i) { return sv[std::size_t(i)]; };
  int r0 = 0;
  while (r0 < n && sig(r0) > tolR) ++r0;
  int r = r0;
  if (r0 > 0 && !dec.nonzero("smallest kept singular value of the ω-block", sig(r0 - 1), tolR)) r = r0 - 1;
  if (r == r0 && r0 < n && dec.nonzero("largest dropped singular value of the ω-block", sig(r0), tolR))
    r = r0 + 1;
  // Translations T (orthonormal, Gram–Schmidt) and rotational screws (u_i unit, v_i ⟂ T).
  std::vector<Vec3<S>> t, u, v;
  for (int i = r; i < n; ++i) {
    Vec3<S> x = VW.col(i);
    for (const auto& y : t) x -= y * y.dot(x);
    t.push_back(unitOf<S>(x));
  }
  S L(1);
  for (int i = 0; i < r; ++i) {
    u.push_back(U.col(i));
    Vec3<S> x = VW.col(i) / sig(i);
    for (const auto& y : t) x -= y * y.dot(x);
    v.push_back(x);
    const S nx = sqrt(x.squaredNorm());
    if (nx + S(1) > L) L = nx + S(1);
  }
  const S tolL = tolR * L;
  auto pitchType = [&](const S& h, T zeroT, T nonzeroT) {
    if (dec.nonzero("|p|", abs(h), tolL)) {
      out.type = nonzeroT;
      out.p[0] = h;
    } else {
      out.type = zeroT;
    }
  };
  // Planar pitch problem on the ω-plane of u[0], u[1]: e1, e2 principal directions with
  // pitches ph ≥ pl and their v's.
  auto planar = [&](Vec3<S>& e1, Vec3<S>& e2, Vec3<S>& ve1, Vec3<S>& ve2, S& ph, S& pl) {
    ScrewMatX<S> m(2, 2), E;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) m(i, j) = u[std::size_t(i)].dot(v[std::size_t(j)]);
    std::array<S, 3> vals{};
    pitchEigen<S>(m, E, vals);
    ph = vals[0];
    pl = vals[1];
    e1 = u[0] * E(0, 0) + u[1] * E(1, 0);
    e2 = u[0] * E(0, 1) + u[1] * E(1, 1);
    ve1 = v[0] * E(0, 0) + v[1] * E(1, 0);
    ve2 = v[0] * E(0, 1) + v[1] * E(1, 1);
  };

  if (n == 1) {
    if (r == 0) {
      out.type = T::Translation;
      out.R = frameOf<S>(t[0], perpendicularTo<S>(t[0]));
    } else {
      pitchType(u[0].dot(v[0]), T::Line, T::Screw);
      out.R = frameOf<S>(u[0], perpendicularTo<S>(u[0]));
      out.d = u[0].cross(v[0]);
    }
  } else if (n == 2) {
    if (r == 0) {
      out.type = T::IIC_2;
      out.R = frameOf<S>(t[0], t[1]);
    } else if (r == 1) {
      Vec3<S> tt = t[0];
      S ct = u[0].dot(tt);
      if (ct < S(0)) {
        tt = -tt;
        ct = -ct;
      }
      const S st = sqrt(u[0].cross(tt).squaredNorm());
      if (!dec.nonzero("|u·t| (cosine of the angle between ω and the translation)", ct, tolR)) {
        const S h = u[0].dot(v[0]);
        pitchType(h, T::IIB0_2, T::IIBp_2);
        out.R = frameOf<S>(u[0], unitOf<S>(Vec3<S>(tt - tt.dot(u[0]) * u[0])));
        const S hh = out.type == T::IIBp_2 ? h : S(0);
        out.d = u[0].cross(Vec3<S>(v[0] - hh * u[0]));
      } else if (!dec.nonzero("|u×t| (sine of the angle between ω and the translation)", st, tolR)) {
        out.type = T::IB0sup_2;
        out.R = frameOf<S>(u[0], perpendicularTo<S>(u[0]));
        out.d = u[0].cross(v[0]);
      } else {
        out.type = T::IBp_2;
        const Vec3<S> e2 = orthoUnit<S>(tt, u[0]);
        out.R = frameOf<S>(u[0], e2);
        out.p[0] = tt.dot(e2) / ct;
        const S mu = -v[0].dot(u[0]) / ct;
        out.d = u[0].cross(Vec3<S>(v[0] + mu * tt));
      }
    } else {
      Vec3<S> e1, e2, ve1, ve2;
      S ph, pl;
      planar(e1, e2, ve1, ve2, ph, pl);
      S p1 = ph, p2 = pl;
      if (dec.nonzero("|p_a − p_b|", ph - pl, tolL)) {
        out.type = T::IA_2;
        out.p = {ph, pl, S(0)};
      } else {
        const S pm = (ph + pl) / S(2);
        p1 = p2 = pm;
        pitchType(pm, T::IIA0_2, T::IIAp_2);
        if (out.type == T::IIA0_2) p1 = p2 = S(0);
      }
      out.R = frameOf<S>(e1, e2);
      const Vec3<S> e3 = e1.cross(e2);
      const Vec3<S> rhs = e1.cross(Vec3<S>(ve1 - p1 * e1)) + e2.cross(Vec3<S>(ve2 - p2 * e2));
      out.d = rhs - e3 * (e3.dot(rhs) / S(2));
    }
  } else if (n == 3) {
    if (r == 0) {
      out.type = T::IID_3;
    } else if (r == 1) {
      const Vec3<S> m = unitOf<S>(Vec3<S>(t[0].cross(t[1])));
      const S um = u[0].dot(m);
      const Vec3<S> uT = u[0] - um * m;
      const S nT2 = uT.squaredNorm(), nT = sqrt(nT2);
      if (!dec.nonzero("|ω_T| (cosine of the angle between ω and the normal of T)", nT, tolR)) {
        pitchType(u[0].dot(v[0]), T::IIC0_3, T::IICp_3);
        out.R = frameOf<S>(u[0], unitOf<S>(Vec3<S>(t[0] - t[0].dot(u[0]) * u[0])));
      } else {
        Vec3<S> e2 = orthoUnit<S>(Vec3<S>(m.cross(u[0])), u[0]);
        Vec3<S> e3 = u[0].cross(e2);
        if (dec.nonzero("|ω·m| (sine of the angle between ω and T)", abs(um), tolR)) {
          out.type = T::ICp_3;
          S p = -um / e3.dot(m);
          if (p < S(0)) {
            e2 = -e2;
            p = -p;
          }
          out.p[0] = p;
        } else {
          out.type = T::IC0_3;
        }
        out.R = frameOf<S>(u[0], e2);
        out.d = u[0].cross(Vec3<S>(v[0] - (v[0].dot(u[0]) / nT2) * uT));
      }
    } else if (r == 2) {
      const Vec3<S> k = u[0].cross(u[1]);
      const S tk = t[0].dot(k);
      const Vec3<S> tW = t[0] - tk * k;
      const S ntW = sqrt(tW.squaredNorm());
      if (!dec.nonzero("|t_W| (cosine of the angle between t and the ω-plane normal)", ntW, tolR)) {
        Vec3<S> e1, e2, ve1, ve2;
        S ph, pl;
        planar(e1, e2, ve1, ve2, ph, pl);
        S p1 = ph, p2 = pl;
        if (dec.nonzero("|p_a − p_b|", ph - pl, tolL)) {
          out.type = T::IB3_3;
          out.p = {ph, pl, S(0)};
        } else {
          p1 = p2 = (ph + pl) / S(2);
          out.type = T::IIB_3;
          out.p[0] = p1;
        }
        out.R = frameOf<S>(e1, e2);
        const S dz = (Vec3<S>(ve1 - p1 * e1).dot(e2) - Vec3<S>(ve2 - p2 * e2).dot(e1)) / S(2);
        out.d = dz * e1.cross(e2);
      } else {
        out.type = T::IB0_3;
        const Vec3<S> e1 = orthoUnit<S>(tW, k);
        const Vec3<S> e3 = tk < S(0) ? Vec3<S>(-k) : k;
        const Vec3<S> e2 = e3.cross(e1);
        out.R << e1, e2, e3;
        const S c = t[0].dot(e1), s = t[0].dot(e3);
        auto vOf = [&](const Vec3<S>& e) { return Vec3<S>(v[0] * e.dot(u[0]) + v[1] * e.dot(u[1])); };
        const Vec3<S> v1 = vOf(e1), v2 = vOf(e2);
        const S pa = e2.dot(v2);
        out.p = {pa, s / c, S(0)};
        const Vec3<S> w1 = out.R.transpose() * Vec3<S>(v1 - pa * e1);
        const Vec3<S> w2 = out.R.transpose() * Vec3<S>(v2 - pa * e2);
        const S mu1 = -w1(0) / c;
        const S dz = w1(1), dy = -(w1(2) + mu1 * s);
        const S mu2 = (-dz - w2(0)) / c;
        const S dx = w2(2) + mu2 * s;
        out.d = out.R * Vec3<S>(dx, dy, dz);
      }
    } else {
      ScrewMatX<S> m(3, 3), E;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = u[std::size_t(i)].dot(v[std::size_t(j)]);
      std::array<S, 3> vals{};
      pitchEigen<S>(m, E, vals);
      std::array<Vec3<S>, 3> e, ve;
      for (int i = 0; i < 3; ++i) {
        e[std::size_t(i)] = u[0] * E(0, i) + u[1] * E(1, i) + u[2] * E(2, i);
        ve[std::size_t(i)] = v[0] * E(0, i) + v[1] * E(1, i) + v[2] * E(2, i);
      }
      const bool nz12 = dec.nonzero("p_a − p_b (largest two principal pitches)", vals[0] - vals[1], tolL);
      const bool nz23 = dec.nonzero("p_b − p_c (smallest two principal pitches)", vals[1] - vals[2], tolL);
      std::array<int, 3> order{0, 1, 2};
      std::array<S, 3> pitch = vals;
      if (nz12 && nz23) {
        out.type = T::IA1_3;
        out.p = vals;
      } else if (nz12) {
        const S pd = (vals[1] + vals[2]) / S(2);
        out.type = T::IA2_3;
        out.p = {vals[0], pd, S(0)};
        pitch = {vals[0], pd, pd};
      } else if (nz23) {
        const S pd = (vals[0] + vals[1]) / S(2);
        out.type = T::IA2_3;
        out.p = {vals[2], pd, S(0)};
        order = {2, 0, 1};
        pitch = {vals[2], pd, pd};
      } else {
        const S pm = (vals[0] + vals[1] + vals[2]) / S(3);
        pitchType(pm, T::IIA0_3, T::IIAp_3);
        const S pp = out.type == T::IIAp_3 ? pm : S(0);
        pitch = {pp, pp, pp};
      }
      std::array<Vec3<S>, 3> f, vf;
      for (std::size_t i = 0; i < 3; ++i) {
        f[i] = e[std::size_t(order[i])];
        vf[i] = ve[std::size_t(order[i])];
      }
      out.R << f[0], f[1], f[2];
      if (out.R.determinant() < S(0)) out.R.col(2) = -out.R.col(2);
      Vec3<S> rhs = Vec3<S>::Zero();
      for (std::size_t i = 0; i < 3; ++i) {
        const Vec3<S> fi = out.R.col(Eigen::Index(i));
        const Vec3<S> vi = (fi.dot(f[i]) < S(0)) ? Vec3<S>(-vf[i]) : vf[i];
        rhs += fi.cross(Vec3<S>(vi - pitch[i] * fi));
      }
      out.d = rhs / S(2);
    }
  }
  return out;
}

}  // namespace detail

template <class S>
ScrewBasis<S> screwSystemNormalForm(ScrewSystemType t, const std::array<S, 3>& p) {
  using T = ScrewSystemType;
  const int n = screwSystemTypeDimension(t);
  ScrewBasis<S> b = ScrewBasis<S>::Zero(6, n);
  auto scr = [&](int col, int axis, const S& pitch) {
    b(axis, col) = S(1);
    b(3 + axis, col) = pitch;
  };
  auto tr = [&](int col, int axis) { b(3 + axis, col) = S(1); };
  switch (t) {
    case T::Zero: break;
    case T::Whole: b = ScrewBasis<S>(Mat6<S>::Identity()); break;
    case T::Line: scr(0, 0, S(0)); break;
    case T::Screw: scr(0, 0, p[0]); break;
    case T::Translation: tr(0, 0); break;
    case T::IIC_2: tr(0, 0); tr(1, 1); break;
    case T::IB0sup_2: scr(0, 0, S(0)); tr(1, 0); break;
    case T::IIA0_2: scr(0, 0, S(0)); scr(1, 1, S(0)); break;
    case T::IIBp_2: scr(0, 0, p[0]); tr(1, 1); break;
    case T::IIB0_2: scr(0, 0, S(0)); tr(1, 1); break;
    case T::IBp_2: scr(0, 0, S(0)); tr(1, 0); b(4, 1) = p[0]; break;
    case T::IIAp_2: scr(0, 0, p[0]); scr(1, 1, p[0]); break;
    case T::IA_2: scr(0, 0, p[0]); scr(1, 1, p[1]); break;
    case T::IID_3: tr(0, 0); tr(1, 1); tr(2, 2); break;
    case T::IIA0_3: scr(0, 0, S(0)); scr(1, 1, S(0)); scr(2, 2, S(0)); break;
    case T::IIC0_3: scr(0, 0, S(0)); tr(1, 1); tr(2, 2); break;
    case T::IICp_3: scr(0, 0, p[0]); tr(1, 1); tr(2, 2); break;
    case T::ICp_3: scr(0, 0, S(0)); tr(1, 1); tr(2, 0); b(5, 2) = p[0]; break;
    case T::IC0_3: scr(0, 0, S(0)); tr(1, 1); tr(2, 0); break;
    case T::IIB_3: scr(0, 0, p[0]); scr(1, 1, p[0]); tr(2, 2); break;
    case T::IB0_3: scr(0, 0, p[0]); scr(1, 1, p[0]); tr(2, 0); b(5, 2) = p[1]; break;
    case T::IB3_3: scr(0, 0, p[0]); scr(1, 1, p[1]); tr(2, 2); break;
    case T::IIAp_3: scr(0, 0, p[0]); scr(1, 1, p[0]); scr(2, 2, p[0]); break;
    case T::IA2_3: scr(0, 0, p[0]); scr(1, 1, p[1]); scr(2, 2, p[1]); break;
    case T::IA1_3: scr(0, 0, p[0]); scr(1, 1, p[1]); scr(2, 2, p[2]); break;
    case T::Unknown: throw InvalidInput("screwSystemNormalForm: type Unknown has no normal form");
  }
  return b;
}

template <class S> std::string ScrewSystemIdentification<S>::name() const {
  std::string s = screwSystemTypeName(type);
  if (parameterCount > 0) {
    static const char* names3[] = {"p_a", "p_b", "p_c"};
    s += "(";
    for (int i = 0; i < parameterCount; ++i) {
      if (i) s += ", ";
      s += (parameterCount == 1 ? std::string("p") : std::string(names3[i])) + " = " +
           toString(parameters[std::size_t(i)], 6);
    }
    s += ")";
  }
  if (viaReciprocal) s = std::to_string(dimension) + "-system reciprocal to " + s;
  return s;
}

// GF §8.2–8.4 (see identification.hpp for the reduction and the errata it avoids).
template <class S> ScrewSystemIdentification<S> identifyScrewSystem(const ScrewSystem<S>& sys) {
  using T = ScrewSystemType;
  ScrewSystemIdentification<S> out;
  const int n = sys.dimension();
  out.dimension = n;
  out.boundaryDistance = std::numeric_limits<S>::infinity();
  if (n == 0 || n == 6) {
    out.type = n == 0 ? T::Zero : T::Whole;
    out.normalForm = screwSystemNormalForm<S>(out.type, out.parameters);
    return out;
  }
  out.viaReciprocal = n >= 4;
  const ScrewSystem<S> low = out.viaReciprocal ? sys.reciprocal() : sys;
  detail::ScrewDecider<S> dec(-1, &out.decisions);
  const detail::ScrewIdRaw<S> raw = detail::classifyLow<S>(low.basis(), dec);
  out.type = raw.type;
  out.parameters = raw.p;
  out.parameterCount = screwSystemTypeParameterCount(raw.type);
  for (int i = out.parameterCount; i < 3; ++i) out.parameters[std::size_t(i)] = S(0);
  out.frame = SE3<S>(SO3<S>::fromMatrix(raw.R), raw.d);
  const ScrewBasis<S> nf = screwSystemNormalForm<S>(raw.type, out.parameters);
  out.normalForm = out.viaReciprocal ? ScrewSystem<S>(ScrewMatX<S>(nf)).reciprocal().basis() : nf;
  out.frameResidual =
      ScrewSystem<S>(ScrewMatX<S>(out.frame.adjoint() * out.normalForm)).distanceTo(sys);
  // Nearest other type: flip the decision nearest its tolerance (ratio), exact zeros excluded.
  int best = -1;
  S bestScore(0);
  for (std::size_t k = 0; k < out.decisions.size(); ++k) {
    const auto& dk = out.decisions[k];
    if (!(dk.value > S(0)) || !(dk.tolerance > S(0))) continue;
    const S score = dk.value > dk.tolerance ? dk.value / dk.tolerance : dk.tolerance / dk.value;
    if (best < 0 || score < bestScore) {
      best = int(k);
      bestScore = score;
    }
  }
  if (best >= 0) {
    out.boundaryDistance = out.decisions[std::size_t(best)].value;
    out.boundaryQuantity = out.decisions[std::size_t(best)].quantity;
    try {
      detail::ScrewDecider<S> flip(best, nullptr);
      out.nearestOtherType = detail::classifyLow<S>(low.basis(), flip).type;
    } catch (const std::exception&) {
      out.nearestOtherType = T::Unknown;
    }
  }
  return out;
}

}  // namespace soma

// Explicit instantiation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#define SOMA_INSTANTIATE_IDENTIFICATION(S)                                                        \
  template ScrewBasis<S> screwSystemNormalForm<S>(ScrewSystemType, const std::array<S, 3>&);      \
  template ScrewSystemIdentification<S> identifyScrewSystem<S>(const ScrewSystem<S>&);            \
  template struct ScrewSystemIdentification<S>;
