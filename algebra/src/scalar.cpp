#include "soma/algebra/scalar.hpp"

#include <cstdio>
#include <stdexcept>

namespace soma {

std::string_view scalarName(ScalarKind k) {
  switch (k) {
    case ScalarKind::Float: return "float";
    case ScalarKind::Double: return "double";
    case ScalarKind::LongDouble: return "long-double";
    case ScalarKind::Float128: return "float128";
    case ScalarKind::Mpfr: return "mpfr";
  }
  return "?";
}

std::optional<ScalarKind> parseScalarKind(std::string_view name) {
  for (ScalarKind k : {ScalarKind::Float, ScalarKind::Double, ScalarKind::LongDouble,
                       ScalarKind::Float128, ScalarKind::Mpfr})
    if (scalarName(k) == name) return k;
  return std::nullopt;
}

std::string scalarNames() { return "float double long-double float128 mpfr"; }

namespace {
int gMpfrBits = 256;
struct MpfrInit {
  MpfrInit() { mpfr::mpreal::set_default_prec(gMpfrBits); }
} gMpfrInit;
}  // namespace

void setMpfrBits(int bits) {
  if (bits < MPFR_PREC_MIN || bits > 100000)
    throw std::invalid_argument("mpfr precision must be between " + std::to_string(MPFR_PREC_MIN) +
                                " and 100000 bits, got " + std::to_string(bits));
  gMpfrBits = bits;
  mpfr::mpreal::set_default_prec(bits);
}
int mpfrBits() { return gMpfrBits; }

std::string toString(float x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits > 0 ? digits : 9, double(x));
  return buf;
}
std::string toString(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits > 0 ? digits : 17, x);
  return buf;
}
std::string toString(long double x, int digits) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.*Lg", digits > 0 ? digits : 21, x);
  return buf;
}
std::string toString(const mpreal& x, int digits) {
  const int d = digits > 0 ? digits : int(mpfr::bits2digits(x.get_prec())) + 2;
  return x.toString(d);
}

template <> float fromString<float>(const std::string& t) { return std::stof(t); }
template <> double fromString<double>(const std::string& t) { return std::stod(t); }
template <> long double fromString<long double>(const std::string& t) { return std::stold(t); }
template <> __float128 fromString<__float128>(const std::string& t) {
  char* end = nullptr;
  const __float128 v = strtoflt128(t.c_str(), &end);
  if (end == t.c_str()) throw std::invalid_argument("not a number: '" + t + "'");
  return v;
}
template <> mpreal fromString<mpreal>(const std::string& t) { return mpreal(t); }

}  // namespace soma
