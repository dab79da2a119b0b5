#pragma once
// The pybind11 module `soma._soma` (issue 23): shared helpers of its translation units — the
// scalar named by `scalar=` / `bits=`, numbers out in the working scalar (float for float and
// double, mpmath.mpf in the scalar's own digits for the extended ones), numbers in from Python
// (float exact; str, int and mpmath.mpf through io's one number reader).
#include "soma/algebra/scalar.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace soma::python {

namespace py = pybind11;

/// "double", "float", "long double" (or "long-double"), "float128", "mpfr"; sets mpfr's precision
/// to `bits` (16..8192). Throws InvalidInput naming the argument.
ScalarKind scalarArgument(const std::string& name, int bits);

/// Bits of the significand of S (mpfr: the working precision).
template <class S> int significandBits();

/// A result number: a Python float for float and double, an mpmath.mpf carrying every digit of S
/// for long double, float128 and mpfr.
template <class S> py::object number(const S& x);
/// A vector or matrix of result numbers: a numpy float64 array for float and double, a numpy
/// object array of mpmath.mpf for the others.
template <class S, class M> py::object numbers(const M& m) {
  if constexpr (std::is_same_v<S, double> || std::is_same_v<S, float>) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> d = m.template cast<double>();
    if (m.cols() == 1) return py::cast(Eigen::VectorXd(d.col(0)));
    return py::cast(d);
  } else {
    py::list rows;
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      if (m.cols() == 1) {
        rows.append(number<S>(m(i, 0)));
        continue;
      }
      py::list row;
      for (Eigen::Index j = 0; j < m.cols(); ++j) row.append(number<S>(m(i, j)));
      rows.append(row);
    }
    return py::module_::import("numpy").attr("array")(rows, py::arg("dtype") = "object");
  }
}

/// A number given from Python: a float (exactly), an int, a decimal str, an mpmath.mpf (all its
/// digits), read in S through io::parseDecimal. `where` names the argument in messages.
template <class S> S scalarFrom(py::handle h, const std::string& where);
/// A sequence (or numpy array) of n numbers (n < 0: any length).
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> vectorFrom(py::handle h, int n, const std::string& where);

/// The binding of each part (one translation unit each, so they compile in parallel).
void bindAlgebra(py::module_& m);
void bindLines(py::module_& m);
void bindSerial(py::module_& m);
void bindParallel(py::module_& m);
void bindAnalyses(py::module_& m);
void bindRunners(py::module_& m);

}  // namespace soma::python
