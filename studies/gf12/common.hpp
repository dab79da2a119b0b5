#pragma once
// Helpers shared by the studies of GF chapter 12 (gf12/statics.cpp, gf12/grasp.cpp): the chapter's
// report section, random draws in double cast to the working scalar S (the same inputs on every rung
// of the ladder), exact fractions, a NaN-propagating max and the smaller samples of the slow scalars.
#include "soma/studies/scalar_draws.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <random>
#include <string>
#include <type_traits>

namespace soma::studies::gf12 {

inline constexpr const char* kChapter = "GF 12 — Statics";

using draws::frac;
using draws::maxOf;
using draws::rv3;
using draws::rv6;
using draws::uni;  // soma/studies/scalar_draws.hpp
/// float128 and mpfr run in software: long searches (thousands of linear programs) use a smaller
/// sample there, and say the count in the check's name.
template <class S> inline constexpr bool kSlowScalar = std::is_same_v<S, float128> || std::is_same_v<S, mpreal>;
template <class S> int samples(int full, int slow) { return kSlowScalar<S> ? slow : full; }
inline std::string yesNo(bool b) { return b ? "yes" : "no"; }

}  // namespace soma::studies::gf12
