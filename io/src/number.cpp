// The non-template part of number.hpp; parseDecimal and readNumber: number_impl.hpp.
#include "soma/io/number.hpp"

#include <string_view>

namespace soma::io {

bool detail::decimalIsNonZero(std::string_view t) {
  for (const char c : t) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

}  // namespace soma::io
