// Line plots as plain SVG text, so the benchmarks can draw their curves without a plotting
// dependency: linear or log axes with ticks and labels, one polyline with point markers per series,
// a legend, and a tooltip (<title>) on every marker.
#ifndef HULLPACK_TOOLS_BENCH_SVG_PLOT_H_
#define HULLPACK_TOOLS_BENCH_SVG_PLOT_H_

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hullpack {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in this order
  bool dashed = false;  // e.g. a reference bound rather than a measurement
  bool markers = true;
  int colour = -1;  // palette index, so a series keeps its colour across plots; -1: its position
};

struct PlotAxis {
  std::string label;  // with the unit, e.g. "encode + decode time (ms)"
  bool log = false;
};

struct Plot {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::string note;  // one small line under the plot (inputs, what each point is)
};

// The plot as a complete SVG document. Points with a non-finite coordinate, or a coordinate <= 0 on
// a log axis, cannot be drawn and are left out; `drawn` (may be null) gets the number of markers
// drawn (points of series with markers). An empty plot still gives a valid document with its axes.
std::string RenderSvg(const Plot& plot, size_t* drawn = nullptr);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_SVG_PLOT_H_
