// The pybind11 module `soma._soma` (issue 23), on the library's entry points (never on the CLI);
// python/soma/__init__.py is the package users import. soma's InvalidInput (bad input, the message
// naming the input and the defect) arrives in Python as ValueError with soma's message.
#include "common.hpp"

#include "soma/algebra/errors.hpp"

PYBIND11_MODULE(_soma, m) {
  using namespace soma::python;
  m.doc() = "soma: geometry of robot kinematics (C++ library bindings; import the package `soma`)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const soma::InvalidInput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("scalars", [] { return soma::scalarNames(); }, "The scalar ladder's names (the `scalar=` argument).");
  m.def("mpfr_bits", [] { return soma::mpfrBits(); }, "The current precision of mpfr in bits.");
  bindAlgebra(m);
  bindLines(m);
  bindSerial(m);
  bindParallel(m);
  bindAnalyses(m);
  bindRunners(m);
}
