#pragma once
// The JSON of a Stewart platform's forward kinematics shared by `soma stewart --json` and the scene
// output `stewart` (GF §11.5.4): the real postures (pose, residual, multiplicity) and, on request,
// every complex solution ([re, im] pairs in the digits of S).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <complex>

namespace soma::io {

/// [re, im] in the digits of S.
template <class S> nlohmann::json complexJson(const std::complex<S>& z) {
  return nlohmann::json::array({jsonNumber(z.real()), jsonNumber(z.imag())});
}
template <class S, std::size_t N> nlohmann::json complexJson(const std::array<std::complex<S>, N>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& z : v) a.push_back(complexJson(z));
  return a;
}

/// The real postures: each pose (pose_file.hpp's form) with its residual and multiplicity.
template <class S> nlohmann::json stewartPosturesJson(const StewartForwardSolution<S>& sol) {
  nlohmann::json arr = nlohmann::json::array();
  for (std::size_t k = 0; k < sol.count(); ++k) {
    nlohmann::json posture = poseJson(sol.postures[k]);
    posture["residual"] = jsonNumber(sol.residuals[k]);
    posture["multiplicity"] = k < sol.posture_multiplicity.size() ? sol.posture_multiplicity[k] : 1;
    arr.push_back(std::move(posture));
  }
  return arr;
}

/// Every complex solution: rotation quaternion a (a·a = 1), translation t, the Study point, whether
/// it is real, its multiplicity and its leg residual (stewartComplexResidual).
template <class S>
nlohmann::json stewartComplexSolutionsJson(const StewartPlatform<S>& P, const StewartForwardSolution<S>& sol) {
  nlohmann::json cs = nlohmann::json::array();
  for (const auto& c : sol.complex_postures) {
    nlohmann::json e;
    e["rotation"] = complexJson(c.rotation);
    e["translation"] = complexJson(c.translation);
    e["study"] = complexJson(c.study);
    e["real"] = c.real;
    e["multiplicity"] = c.multiplicity;
    e["residual"] = jsonNumber(stewartComplexResidual<S>(P, c));
    cs.push_back(std::move(e));
  }
  return cs;
}

}  // namespace soma::io
