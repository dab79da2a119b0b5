#pragma once
// Bad input (DESIGN §10): a clear message naming the input and what is wrong. Thrown by
// constructors and parsers that validate; the CLI turns it into a message and exit code 2.
#include <stdexcept>
#include <string>

namespace soma {

/// Input that violates a precondition: NaN, a non-unit quaternion, a non-orthogonal matrix,
/// a point off the Study quadric, a malformed file. what() names the input and the defect.
class InvalidInput : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace soma
