#pragma once
// "Numeric search in double, Newton polish in S" (DESIGN §2, §3): soma's numerical methods (Ceres,
// NLopt) run in double; in a wider (or narrower) scalar each candidate they find is the start of
// Newton steps in that scalar. One helper for every solver that does this (the general 6R's ceres
// and nlopt methods and its numerical completion, the Stewart platform's ceres and nlopt methods),
// so that the search, the polish and the time are done, and reported, the same way.
#include "soma/algebra/scalar.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace soma {

/// What a search in double gave and what became of it in S.
template <class Found, class Polished> struct PolishedSearch {
  Found found;                      ///< the search's own answer, in double (method, notes, counts)
  std::vector<Polished> polished;   ///< per candidate kept, in the search's order, carried to S
  double seconds = 0;               ///< search and polish together
};

/// Runs `search()` (in double; returns an answer with `.postures`) and maps each posture by
/// `polish(posture)`, which returns `std::optional<P>`: the candidate carried to S (Newton steps in
/// S from the posture converted to S, or the posture itself when S is double and the search has
/// polished it already), or nothing to drop it.
template <class Search, class Polish> auto searchInDoublePolishInS(Search&& search, Polish&& polish) {
  const auto t0 = std::chrono::steady_clock::now();
  auto found = search();
  using Posture = typename decltype(found.postures)::value_type;
  using P = typename std::invoke_result_t<Polish&, const Posture&>::value_type;
  PolishedSearch<decltype(found), P> out{std::move(found), {}, 0};
  for (const auto& c : out.found.postures)
    if (std::optional<P> p = polish(c)) out.polished.push_back(std::move(*p));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

/// The note a solver writes when its candidates were found in double and polished in S.
template <class S> std::string polishedInNote(const std::string& method) {
  return method + " enumerates in double; each posture Newton-polished in " + std::string(scalarName<S>());
}

}  // namespace soma
