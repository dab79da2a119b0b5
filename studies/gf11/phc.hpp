#pragma once
// PHCpack (Debian's `phc`) as an independent solver for the chapter's polynomial systems: a system
// written as text (quadrics xᵀQx, linear charts), `phc -b` run in a scratch folder, its refined
// solution list parsed (studies/gf11/phcpack.cpp, studies/gf11/stewart_classes.cpp).
#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace soma::studies::phc {

/// xᵀ Q x over the variables named names[i] (Q symmetric), as PHCpack input.
inline std::string quadricPolynomial(const Eigen::MatrixXd& Q, const std::vector<std::string>& names) {
  std::string s;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (Eigen::Index j = i; j < Q.cols(); ++j) {
      const double c = Q(i, j) * (i == j ? 1.0 : 2.0);
      if (c != 0.0) s += fmt::format(" {:+.17e}*{}*{}", c, names[i], names[j]);
    }
  return s + ";";
}
inline std::string linearPolynomial(const Eigen::VectorXd& w, const std::vector<std::string>& names, double rhs) {
  std::string s;
  for (Eigen::Index i = 0; i < w.size(); ++i) s += fmt::format(" {:+.17e}*{}", w(i), names[i]);
  return s + fmt::format(" {:+.17e};", -rhs);
}

struct PhcSolution {
  Eigen::VectorXcd x;
  bool regular = false;
  bool real = false;  ///< PHCpack's own verdict ("real regular")
};
struct PhcRun {
  std::vector<PhcSolution> solutions;
  int reportedRegular = -1;
  int paths = 0;
  double seconds = 0;
};

/// Runs `phc OPTIONS` (default `-b -0`: the blackbox solver, fixed seed; `-b2 -0`: in double double) on the system and parses the refined solution list (variables by name).
inline PhcRun runPhc(const std::vector<std::string>& equations, const std::vector<std::string>& names, const std::string& tag,
                     const std::string& options = "-b -0") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / fmt::format("soma-phc-{}-{}", static_cast<long>(getpid()), tag);
  std::filesystem::create_directories(dir);
  const auto in = dir / "system.txt", out = dir / "phc.out";
  {
    std::ofstream f(in);
    f << equations.size() << "\n";  // square systems: the number of equations = of unknowns
    for (const auto& e : equations) f << e << "\n";
  }
  if (std::system("command -v phc > /dev/null 2>&1") != 0)
    throw std::runtime_error("PHCpack's `phc` is not on PATH: install Debian's phcpack (scripts/bootstrap.sh does)");
  const auto t0 = std::chrono::steady_clock::now();
  const std::string cmd = fmt::format("cd '{}' && timeout 900 phc {} system.txt phc.out > phc.log 2>&1", dir.string(), options);
  const int rc = std::system(cmd.c_str());
  PhcRun run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rc != 0) throw std::runtime_error("phc failed (exit " + std::to_string(rc) + "), see " + out.string());
  std::ifstream f(out);
  std::stringstream buf;
  buf << f.rdbuf();
  const std::string text = buf.str();
  // The last "THE SOLUTIONS" block is the refined list.
  const auto start = text.rfind("THE SOLUTIONS :");
  if (start == std::string::npos) throw std::runtime_error("phc output has no solution list: " + out.string());
  std::istringstream lines(text.substr(start));
  std::string line;
  std::getline(lines, line);
  std::getline(lines, line);
  std::getline(lines, line);
  run.paths = std::stoi(line);
  const std::regex coord(R"(^\s*(\w+)\s*:\s*(\S+)\s+(\S+)\s*$)");
  const std::regex verdict(R"(== err :.*= (real|complex) (regular|singular) ==)");
  const std::regex summary(R"(Number of regular solutions\s*:\s*(\d+))");
  PhcSolution cur;
  cur.x = Eigen::VectorXcd::Zero(Eigen::Index(names.size()));
  bool inSolution = false;
  std::smatch m;
  while (std::getline(lines, line)) {
    if (line.rfind("the solution for t", 0) == 0) {
      inSolution = true;
      cur.x.setZero();
      continue;
    }
    if (inSolution && std::regex_match(line, m, coord)) {
      const auto it = std::find(names.begin(), names.end(), m[1].str());
      if (it != names.end()) cur.x(it - names.begin()) = {std::stod(m[2].str()), std::stod(m[3].str())};
      continue;
    }
    if (line.rfind("== err", 0) == 0) {
      const bool matched = std::regex_search(line, m, verdict);
      cur.regular = matched && m[2] == "regular";
      cur.real = matched && m[1] == "real";
      run.solutions.push_back(cur);
      inSolution = false;
      continue;
    }
    if (std::regex_search(line, m, summary)) run.reportedRegular = std::stoi(m[1].str());
  }
  std::filesystem::remove_all(dir);
  return run;
}

}  // namespace soma::studies::phc
