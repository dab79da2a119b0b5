#pragma once
// The mpfr precision of a speed/accuracy study's rung, restored on every exit: a study computes
// its mpfr reference at more bits than the rung it measures (--bits), then returns to it.
#include "soma/algebra/scalar.hpp"

namespace soma::studies {

class MpfrBitsRestore {
 public:
  MpfrBitsRestore() : bits_(mpfrBits()) {}
  ~MpfrBitsRestore() { setMpfrBits(bits_); }
  MpfrBitsRestore(const MpfrBitsRestore&) = delete;
  MpfrBitsRestore& operator=(const MpfrBitsRestore&) = delete;
  int bits() const { return bits_; }  ///< the precision at construction (the rung's)

 private:
  int bits_;
};

}  // namespace soma::studies
