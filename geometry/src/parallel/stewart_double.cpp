// One scalar per translation unit (they compile in parallel): parallel/stewart.hpp for double.
#include "stewart_impl.hpp"

namespace soma {
SOMA_STEWART_INSTANTIATE(double)
}  // namespace soma

namespace soma {
std::vector<StudyPointC<double>> stewartTotalDegreeSolve(const StewartComplexPlatform<double>& P, std::uint64_t seed) {
  return totalDegreeSolve<double>(P, seed);
}
}  // namespace soma
