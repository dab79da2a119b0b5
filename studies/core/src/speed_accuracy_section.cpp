// The report's "speed vs accuracy" section (issue 22): the trade tables the speed/accuracy studies
// recorded (Context::trade), one table and one figure per solver, gathered in one place. Kept
// apart from the report's page layout (report.cpp calls it once).
#include "soma/studies/report.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <sstream>

namespace soma::studies {


std::string speedAccuracySectionHtml(const std::vector<StudyResult>& results) {
  std::ostringstream h;
  int tables = 0;
  for (const auto& r : results) tables += int(r.trades.size());
  if (tables == 0) return {};
  // class "extra" like the other added sections: the page's filter hides every section.chapter
  // that holds no visible study (report_page.hpp), which would hide this one always.
  h << "<section class=\"extra\" id=\"speed-vs-accuracy\">\n<h2>Speed vs accuracy</h2>\n"
    << "<p>Each headline solver on every rung of the scalar ladder: the time per sample (median and "
       "95th percentile, wall time on the machine above) and the worst error, with the samples that "
       "escalated to a higher rung counted (their time is in the rung's time). The errors are "
       "written in the rung's own digits.</p>\n";
  for (const auto& r : results)
    for (const auto& t : r.trades) {
      h << "<h3 style=\"margin-top:18px\">" << htmlEscape(t.solver) << " <span style=\"font-weight:normal\">— <a href=\"#"
        << htmlEscape(studyAnchor(r.study ? r.study->id : "")) << "\">" << htmlEscape(r.study ? r.study->id : "")
        << "</a></span></h3>\n";
      h << "<table class=\"checks trade\"><colgroup><col class=\"t-scalar\"><col class=\"t-n\"><col class=\"t-time\">"
           "<col class=\"t-time\"><col class=\"t-err\"><col class=\"t-esc\"><col></colgroup><thead><tr><th>scalar</th><th>" << htmlEscape(t.sample)
        << "s</th><th>median</th><th>p95</th><th>" << htmlEscape(t.errorLabel)
        << "</th><th>escalated</th><th></th></tr></thead>\n<tbody>\n";
      for (const auto& g : t.rungs) {
        const std::string esc = g.escalated == 0
                                    ? std::string("none")
                                    : fmt::format("{} of {} (to {})", g.escalated, g.samples,
                                                  g.escalatedTo.empty() ? "a higher rung" : g.escalatedTo);
        h << "<tr><td>" << htmlEscape(g.scalar) << "</td><td class=\"num\">" << g.samples
          << "</td><td class=\"num\">" << htmlEscape(formatSeconds(g.medianSeconds)) << "</td><td class=\"num\">"
          << htmlEscape(formatSeconds(g.p95Seconds)) << "</td><td class=\"value\">" << htmlEscape(g.worstErrorText)
          << "</td><td>" << htmlEscape(esc) << "</td><td>" << htmlEscape(g.comment) << "</td></tr>\n";
      }
      h << "</tbody></table>\n";
      if (!t.figure.empty())
        h << "<figure><img src=\"" << htmlEscape(t.figure) << "\" alt=\"" << htmlEscape(t.solver)
          << ": time against error\" loading=\"lazy\"><figcaption>" << htmlEscape(t.solver)
          << ": median time per " << htmlEscape(t.sample) << " (point; bar to the p95) against the "
          << htmlEscape(t.errorLabel) << ", one point per scalar (log–log).</figcaption></figure>\n";
    }
  h << "</section>\n";
  return h.str();
}

}  // namespace soma::studies
