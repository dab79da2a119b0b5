#pragma once
// The speed–accuracy trade of one solver over the scalar ladder (issue 22): per rung the time per
// sample (median, p95), the worst error, and how many samples escalated to a higher rung. A study
// records it with Context::trade; `soma study run` prints it, report.json carries it, and the
// report's "speed vs accuracy" section gathers every table with its figure (tradeFigure: time
// against error, one point per rung).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace soma::studies {

struct TradeRung {
  std::string scalar;        ///< the rung: "float", "double", …, "mpfr (256 bits)"; a variant in
                             ///< parentheses, e.g. "float (no escalation)"
  std::size_t samples = 0;   ///< poses, platforms, angles … measured in this rung
  double medianSeconds = 0;  ///< time per sample
  double p95Seconds = 0;
  double worstError = 0;     ///< the worst error, rounded to double (for the plot)
  std::string worstErrorText;  ///< the same in the rung's own digits (io::numberText)
  std::size_t escalated = 0;   ///< samples re-solved in a higher rung (counted in this rung's time)
  std::string escalatedTo;     ///< where they went ("double"), empty when none
  std::string comment;         ///< one phrase (completeness, what the error is)
};

struct TradeTable {
  std::string solver;      ///< "general 6R, algebraic (GF §11.5)"
  std::string sample;      ///< what one sample is: "pose", "platform", "angle"
  std::string errorLabel;  ///< "worst residual", "worst error (ulps × ε)"
  std::vector<TradeRung> rungs;
  std::string figure;      ///< its figure, relative to the report directory ("figures/….png"), or empty
};

/// Median and 95th percentile of per-sample times (empty: 0, 0).
void timeQuantiles(std::vector<double> seconds, double& median, double& p95);

/// The table as aligned text (one row per rung; escalations said per row).
std::string tradeText(const TradeTable& t);

/// Time per sample (median) against the worst error, log–log, one labelled point per rung, a
/// horizontal bar from median to p95. The axes span the data with a small margin (no empty
/// decade), ticks at decades; the legend goes into a corner the points leave free, else each point
/// is labelled.
/// Rungs with a zero or non-finite error are left out of the figure (said in the caption).
/// Writes the PNG; returns the number of rungs drawn.
int tradeFigure(const TradeTable& t, const std::filesystem::path& png);

}  // namespace soma::studies
