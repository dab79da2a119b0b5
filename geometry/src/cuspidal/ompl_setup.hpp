#pragma once
// OMPL set-up shared by the cuspidal sub-area's OMPL translation units (private: OMPL stays out of
// soma's public headers). One process-wide switch: OMPL's log silenced and its RNG seeded once
// (OMPL allows the seed to be set only before its first random number).
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <mutex>

namespace soma::detail {

inline void quietOmpl() {
  static std::once_flag once;  // one flag for the whole process (an inline function's static)
  std::call_once(once, [] {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(20261130);  // reproducible samples and plans
  });
}

}  // namespace soma::detail
