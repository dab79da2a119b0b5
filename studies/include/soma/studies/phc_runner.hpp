#pragma once
// PHCpack (Debian's phcpack, /usr/bin/phc) as an independent solver for studies: a square
// polynomial system written in PHCpack's input syntax is solved by its blackbox (`phc -b -0`:
// fixed seed, total-degree homotopy, sequential), and the refined solution list is parsed.
// Studies use it to check counts (Bézout numbers, assembly modes) with a solver soma did not write.
// Double precision (PHCpack's).
#include "soma/algebra/scalar.hpp"  // before Eigen (float128 traits)

#include <Eigen/Core>

#include <string>
#include <vector>

namespace soma::studies {

struct PhcSolution {
  Eigen::VectorXcd x;    ///< the variables, in the order of the names given
  bool regular = false;  ///< PHCpack's verdict "regular" (else "singular")
  bool real = false;     ///< PHCpack's verdict "real" (else "complex")
};
struct PhcResult {
  std::vector<PhcSolution> solutions;  ///< every path's end point (finite or not)
  int reportedRegular = -1;            ///< PHCpack's own "Number of regular solutions"
  int paths = 0;
  double seconds = 0;
};

/// A real coefficient in PHCpack's syntax (17 significant digits, signed: "+1.2…e-01").
std::string phcNumber(double v);
/// xᵀ Q x (Q symmetric) and wᵀx − rhs over the variables `names`, in PHCpack's syntax.
std::string phcQuadric(const Eigen::MatrixXd& Q, const std::vector<std::string>& names);
std::string phcLinear(const Eigen::VectorXd& w, const std::vector<std::string>& names, double rhs);
/// Solves the square system (one polynomial per string, each ending with ';', in the variables
/// `names`) with `phc OPTIONS` (default `-b -0`: the blackbox, fixed seed; `-b2 -0` in double
/// double) in a temporary folder named after `tag`. Throws when phc is missing or fails.
PhcResult solveWithPhc(const std::vector<std::string>& equations, const std::vector<std::string>& names,
                       const std::string& tag, const std::string& options = "-b -0");

}  // namespace soma::studies
