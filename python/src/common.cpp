// Shared helpers of the Python module (common.hpp).
#include "common.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/number.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace soma::python {

ScalarKind scalarArgument(const std::string& name, int bits) {
  std::string n = name;
  std::replace(n.begin(), n.end(), ' ', '-');
  const auto k = parseScalarKind(n);
  if (!k) throw InvalidInput("scalar: \"" + name + "\" is not one of " + scalarNames() + " (\"long double\" also)");
  if (bits < 16 || bits > 8192)
    throw InvalidInput("bits: " + std::to_string(bits) + " is outside 16..8192 (the precision of mpfr in bits)");
  setMpfrBits(bits);
  return *k;
}

template <class S> int significandBits() {
  if constexpr (std::is_same_v<S, mpreal>)
    return mpfrBits();
  else if constexpr (std::is_same_v<S, __float128>)
    return 113;
  else
    return std::numeric_limits<S>::digits;
}

template <class S> py::object number(const S& x) {
  if constexpr (std::is_same_v<S, double> || std::is_same_v<S, float>) {
    return py::float_(double(x));
  } else {
    // io::numberText writes the scalar's own digits (read back exactly); mpmath reads them at the
    // scalar's precision (soma/_numbers.py).
    return py::module_::import("soma._numbers").attr("mpf")(io::numberText(x), significandBits<S>());
  }
}

template <class S> S scalarFrom(py::handle h, const std::string& where) {
  if (py::isinstance<py::bool_>(h)) throw InvalidInput(where + ": a boolean is not a number");
  if (py::isinstance<py::float_>(h)) {
    const double d = h.cast<double>();
    if (!std::isfinite(d)) throw InvalidInput(where + ": " + toString(d) + " is not a finite number");
    return scalarCast<S>(d);
  }
  const std::string text = py::module_::import("soma._numbers").attr("text")(h, where).cast<std::string>();
  return io::parseDecimal<S>(text, where);
}

template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> vectorFrom(py::handle h, int n, const std::string& where) {
  if (py::isinstance<py::str>(h) || !py::hasattr(h, "__len__"))
    throw InvalidInput(where + ": expected a sequence of numbers");
  const py::list seq = py::module_::import("soma._numbers").attr("flat")(h, where).cast<py::list>();
  const int len = int(py::len(seq));
  if (n >= 0 && len != n)
    throw InvalidInput(where + ": expected " + std::to_string(n) + " numbers, got " + std::to_string(len));
  Eigen::Matrix<S, Eigen::Dynamic, 1> v(len);
  for (int i = 0; i < len; ++i) v(i) = scalarFrom<S>(seq[std::size_t(i)], where + "[" + std::to_string(i) + "]");
  return v;
}

#define SOMA_PY_COMMON(S)                                                           \
  template int significandBits<S>();                                                \
  template py::object number<S>(const S&);                                          \
  template S scalarFrom<S>(py::handle, const std::string&);                         \
  template Eigen::Matrix<S, Eigen::Dynamic, 1> vectorFrom<S>(py::handle, int, const std::string&);
SOMA_FOR_EACH_SCALAR(SOMA_PY_COMMON)
#undef SOMA_PY_COMMON

}  // namespace soma::python
