// PHCpack's blackbox solver run on a system file, and its refined solution list read back.
#include "soma/studies/phc_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace soma::studies {

std::string phcNumber(double v) { return fmt::format("{:+.17e}", v); }

std::string phcQuadric(const Eigen::MatrixXd& Q, const std::vector<std::string>& names) {
  std::string s;
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (Eigen::Index j = i; j < Q.cols(); ++j) {
      const double c = Q(i, j) * (i == j ? 1.0 : 2.0);
      if (c != 0.0) s += " " + phcNumber(c) + "*" + names[std::size_t(i)] + "*" + names[std::size_t(j)];
    }
  return s + ";";
}

std::string phcLinear(const Eigen::VectorXd& w, const std::vector<std::string>& names, double rhs) {
  std::string s;
  for (Eigen::Index i = 0; i < w.size(); ++i) s += " " + phcNumber(w(i)) + "*" + names[std::size_t(i)];
  return s + " " + phcNumber(-rhs) + ";";
}

PhcResult solveWithPhc(const std::vector<std::string>& equations, const std::vector<std::string>& names,
                       const std::string& tag, const std::string& options) {
  if (std::system("command -v phc > /dev/null 2>&1") != 0)
    throw std::runtime_error("PHCpack's `phc` is not on PATH: install Debian's phcpack (scripts/bootstrap.sh does)");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / fmt::format("soma-phc-{}-{}", static_cast<long>(getpid()), tag);
  std::filesystem::create_directories(dir);
  {
    std::ofstream f(dir / "system.txt");
    f << equations.size() << "\n";
    for (const auto& e : equations) f << e << "\n";
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::string cmd = fmt::format("cd '{}' && timeout 900 phc {} system.txt phc.out > phc.log 2>&1", dir.string(), options);
  const int rc = std::system(cmd.c_str());
  PhcResult run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (rc != 0) throw std::runtime_error(fmt::format("phc failed (exit {}), see {}", rc, (dir / "phc.log").string()));
  std::stringstream buf;
  buf << std::ifstream(dir / "phc.out").rdbuf();
  const std::string text = buf.str();
  const auto start = text.rfind("THE SOLUTIONS :");  // the last list is the refined one
  if (start == std::string::npos) throw std::runtime_error("phc output has no solution list: " + (dir / "phc.out").string());
  std::istringstream lines(text.substr(start));
  std::string line;
  for (int k = 0; k < 3; ++k) std::getline(lines, line);
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
    } else if (inSolution && std::regex_match(line, m, coord)) {
      const auto it = std::find(names.begin(), names.end(), m[1].str());
      if (it != names.end()) cur.x(it - names.begin()) = {std::stod(m[2].str()), std::stod(m[3].str())};
    } else if (line.rfind("== err", 0) == 0) {
      const bool matched = std::regex_search(line, m, verdict);
      cur.regular = matched && m[2] == "regular";
      cur.real = matched && m[1] == "real";
      run.solutions.push_back(cur);
      inSolution = false;
    } else if (std::regex_search(line, m, summary)) {
      run.reportedRegular = std::stoi(m[1].str());
    }
  }
  std::filesystem::remove_all(dir);
  return run;
}

}  // namespace soma::studies
