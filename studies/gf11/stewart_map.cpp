// GF §11.5.4: the number of real postures of a Stewart–Gough platform over a two-parameter family
// of leg lengths — the example platform (studies/platforms/general.json) with every leg extended by
// s and legs 1, 3, 5 against 2, 4, 6 by ±d: L_i = L_i⁰ + s + (−1)^i d. Each cell is solved by the
// homotopy (all 40 complex solutions, with multiplicity), the real count drawn as a map; NLopt's
// multi-start cross-checks a sample of cells (every posture it finds must be one of the homotopy's).
// Double precision (a map of ~800 solves).
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_numeric.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/render/plot.hpp"
#include "soma/studies/study.hpp"

#include <fmt/format.h>

#include <map>

namespace soma::studies::gf11map::SOMA_UNITY_ID {  // this file's own names in a unity batch
namespace {

using S = double;
namespace rd = soma::render;

// GF §11.5.4, GF-11.5.4-stewart-forty; SOMA-11.5.4-stewart-real-map
void realMap(Context& c) {
  const StewartPlatform<S> P0 = io::readPlatform<S>(sourceRoot() / "studies/platforms/general.json");
  const int nx = 33, ny = 25;
  const double s0 = -0.5, s1 = 0.9, d0 = -0.2, d1 = 0.45;
  std::vector<int> real(std::size_t(nx) * ny, 0);
  int certified = 0, odd = 0, escalated = 0, multiple = 0, nloptChecked = 0, nloptOutside = 0, nloptSame = 0;
  std::map<int, int> histogram;
  StewartNumericOptions no;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double s = s0 + (s1 - s0) * (i + 0.5) / nx, d = d0 + (d1 - d0) * (j + 0.5) / ny;
      StewartPlatform<S> P = P0;
      for (int k = 0; k < 6; ++k) P.legs[k] = P0.legs[k] + s + (k % 2 == 0 ? d : -d);
      const auto sol = solveStewartForward<S>(P);
      int r = 0;
      for (std::size_t k = 0; k < sol.count(); ++k) r += sol.posture_multiplicity[k];
      real[std::size_t(j) * nx + i] = r;
      ++histogram[r];
      certified += sol.complexCount() == 40;
      odd += r % 2;
      escalated += sol.paths_escalated > 0;
      multiple += sol.distinctCount() < sol.complexCount();
      if ((i + j * nx) % 16 == 0) {  // NLopt multi-start on every 16th cell
        const auto n = solveStewartForwardNlopt(P, no);
        ++nloptChecked;
        nloptSame += n.count() == sol.count();
        for (const auto& g : n.postures) {
          bool known = false;
          for (const auto& h : sol.postures) known = known || (g.matrix() - h.matrix()).norm() <= Tolerance<S>::precision(2);
          nloptOutside += !known;
        }
      }
    }
  const int cells = nx * ny;
  c.checkEqual(fmt::format("cells of the {}×{} map with 40 complex solutions (with multiplicity)", nx, ny), cells, certified);
  c.checkEqual("… cells with an odd number of real postures (non-real solutions come in conjugate pairs)", 0, odd);
  c.checkEqual(fmt::format("NLopt (256 starts) on {} cells: its postures outside the homotopy's real set", nloptChecked), 0,
               nloptOutside);
  c.checkEqual("… cells where NLopt finds as many real postures as the homotopy (two independent methods)", nloptChecked,
               nloptSame);
  c.checkEqual("… the unchanged platform (s = d = 0 lies between cells): general.json's 8 real postures",
               8, static_cast<long long>(solveStewartForward<S>(P0).count()));
  std::string hist;
  int most = 0;
  for (const auto& [r, n] : histogram) {
    hist += fmt::format("{} real: {} cells; ", r, n);
    most = std::max(most, r);
  }
  c.note(fmt::format("Real postures over the map: {}most {}. NLopt found the same number in {} of {} sampled cells "
                     "(a multi-start search may miss postures; it never found one the homotopy lacks). {} cells were "
                     "re-solved in a wider scalar, {} had a multiple root.",
                     hist, most, nloptSame, nloptChecked, escalated, multiple));
  if (!c.makeFigures()) return;
  rd::Plot plot;
  plot.title = "Real postures of the general.json platform as its legs change (of 40 complex)";
  plot.x.label = "s: every leg extended by s";
  plot.y.label = "d: legs 1, 3, 5 extended by d, legs 2, 4, 6 shortened by d";
  plot.x.min = s0;
  plot.x.max = s1;
  plot.y.min = d0;
  plot.y.max = d1;
  rd::PlotCells cl;
  cl.x0 = s0;
  cl.x1 = s1;
  cl.y0 = d0;
  cl.y1 = d1;
  cl.nx = nx;
  cl.ny = ny;
  const auto colorOf = [&](int r) { return r == 0 ? rd::palette::lightGrey : rd::colorMap(double(r) / std::max(most, 1)); };
  for (int r : real) cl.cells.push_back(colorOf(r));
  plot.cells.push_back(cl);
  for (const auto& [r, n] : histogram) plot.legendSwatches.emplace_back(fmt::format("{} real", r), colorOf(r));
  plot.legend = rd::LegendCorner::TopRight;
  rd::PlotSeries origin;
  origin.name = "general.json (8 real)";
  origin.x = {0.0};
  origin.y = {0.0};
  origin.line = false;
  origin.markers = true;
  origin.c = rd::palette::vermillion;
  plot.series.push_back(origin);
  const std::string f = "SOMA-11.5.4-stewart-real-map.png";
  rd::renderPlotPng(plot, c.figurePath(f), 1200, 850);
  c.figure(f, fmt::format("The number of real assembly modes of one 6-6 platform (studies/platforms/general.json) over "
                          "a {}×{} grid of leg lengths L_i = L_i⁰ + s + (−1)^i d; every cell has 40 complex solutions "
                          "(homotopy), the real ones counted with multiplicity. Between regions the count changes by 2 "
                          "where two real postures merge (a singular configuration) and leave as a conjugate pair.",
                          nx, ny));
}

SOMA_STUDY({.id = "SOMA-11.5.4-stewart-real-map",
            .title = "Real postures of a Stewart platform over a two-parameter family of leg lengths (a map)",
            .source = "GF §11.5.4",
            .chapter = "GF 11 — The Study quadric",
            .scalarGeneric = false,
            .run = realMap,
            .whyDouble = "a map of ~800 homotopy solves; the solver's scalars are tested in tests/geometry/parallel"});

}  // namespace
}  // namespace soma::studies::gf11map::SOMA_UNITY_ID
