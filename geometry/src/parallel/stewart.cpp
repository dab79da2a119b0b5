// The total-degree homotopy of the Stewart forward kinematics in double only (not instantiated per
// scalar; the templates of stewart.hpp are in stewart_impl.hpp, instantiated by soma_instantiate).
#include "stewart_impl.hpp"

namespace soma {
std::vector<StudyPointC<double>> stewartTotalDegreeSolve(const StewartComplexPlatform<double>& P, std::uint64_t seed) {
  return totalDegreeSolve<double>(P, seed);
}
}  // namespace soma
