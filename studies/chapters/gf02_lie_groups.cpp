// Studies of GF chapter 2 — Lie groups.
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include <complex>

namespace soma::studies {
namespace {

// GF §2.1, GF-2.1-U1-unit-complex: z1 z2 = cos(θ1+θ2) + i sin(θ1+θ2); z̄ is the inverse.
template <class S> void u1UnitComplex(Context& c) {
  using std::cos;
  using std::sin;
  using std::abs;
  const S t1 = S(7) / S(10), t2 = S(23) / S(10);  // θ1 + θ2 = 3 < π
  const S re = cos(t1) * cos(t2) - sin(t1) * sin(t2);
  const S im = cos(t1) * sin(t2) + sin(t1) * cos(t2);
  const S tol = Tolerance<S>::identity(8);
  c.checkNear("Re(z1 z2) = cos(θ1+θ2), θ1 = 0.7, θ2 = 2.3", cos(t1 + t2), re, tol);
  c.checkNear("Im(z1 z2) = sin(θ1+θ2)", sin(t1 + t2), im, tol);
  // Wrap-around: θ and θ + 2π are the same element.
  const S t3 = S(1) / S(1000);
  c.checkNear("cos(θ + 2π) = cos θ at θ = 1e-3", cos(t3), cos(t3 + 2 * pi<S>()), S(16) * Tolerance<S>::epsilon() * 2 * pi<S>());
  // Inverse is the conjugate: z z̄ = 1.
  c.checkNear("z z̄ = 1", S(1), cos(t1) * cos(t1) + sin(t1) * sin(t1), tol);
}

SOMA_STUDY({.id = "GF-2.1-U1-unit-complex",
            .title = "Unit complex numbers U(1): angle addition, inverse, wrap-around",
            .source = "GF §2.1",
            .chapter = "GF 2 — Lie groups",
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { u1UnitComplex<S>(c); }); }});

}  // namespace
}  // namespace soma::studies
