#include "bench/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/xml_escape.h"

namespace hullpack {
namespace {

// Canvas and plot area, in SVG user units; the legend sits right of the plot area.
constexpr double kWidth = 820, kHeight = 500;
constexpr double kLeft = 80, kRight = 590, kTop = 46, kBottom = 420;

// Sixteen colours that stay apart from each other on white (one per corpus mesh and a spare).
const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#393b79", "#637939",
                                "#b5cf6b", "#843c39", "#e7969c", "#000000"};
constexpr size_t kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

std::string Colour(const PlotSeries& s, size_t position) {
  const size_t k = s.colour >= 0 ? static_cast<size_t>(s.colour) : position;
  return kPalette[k % kPaletteSize];
}

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.2f", v);
  return buf;
}

// Tick label: plain decimals in a readable range, otherwise "2e-5" (no exponent padding).
std::string TickLabel(double v) {
  if (v == 0) return "0";
  char buf[32];
  const double a = std::fabs(v);
  if (a >= 1e-3 && a < 1e5) {
    std::snprintf(buf, sizeof(buf), "%.4g", v);
    return buf;
  }
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  std::string s = buf;
  const size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mant = s.substr(0, e), exp = s.substr(e + 1);
  std::string sign;
  if (!exp.empty() && (exp[0] == '-' || exp[0] == '+')) {
    if (exp[0] == '-') sign = "-";
    exp = exp.substr(1);
  }
  while (exp.size() > 1 && exp[0] == '0') exp = exp.substr(1);
  return mant + "e" + sign + exp;
}

bool Drawable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

struct Tick {
  double value;
  bool labelled;
};

// Maps data values on one axis to [0, 1] and lists its ticks.
struct Scale {
  bool log = false;
  double lo = 0, hi = 1;  // in log10 units for a log axis
  std::vector<Tick> ticks;

  double Unit(double v) const {
    const double t = log ? std::log10(v) : v;
    return (t - lo) / (hi - lo);
  }
};

Scale MakeScale(double min, double max, bool log) {
  Scale s;
  s.log = log;
  if (!(min <= max)) min = max = log ? 1.0 : 0.0;  // nothing drawable
  if (log) {
    double lo = std::floor(std::log10(min)), hi = std::ceil(std::log10(max));
    if (hi <= lo) hi = lo + 1;
    s.lo = lo;
    s.hi = hi;
    const double decades = hi - lo;
    const int every = decades > 8 ? 2 : 1;
    for (double k = lo; k <= hi + 1e-9; k += 1) {
      const double base = std::pow(10.0, k);
      s.ticks.push_back({base, static_cast<long>(k - lo) % every == 0});
      if (k >= hi) break;
      if (decades <= 3) {
        for (double m : {2.0, 5.0}) s.ticks.push_back({base * m, decades <= 2});
      }
    }
    return s;
  }
  double span = max - min;
  if (span <= 0) {
    span = std::max(1.0, std::fabs(max));
    min -= span / 2;
    max += span / 2;
  }
  const double raw = span / 6;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  }
  s.lo = std::floor(min / step) * step;
  s.hi = std::ceil(max / step) * step;
  if (s.hi <= s.lo) s.hi = s.lo + step;
  for (double v = s.lo; v <= s.hi + step * 1e-6; v += step)
    s.ticks.push_back({std::fabs(v) < step * 1e-9 ? 0.0 : v, true});
  return s;
}

}  // namespace

std::string RenderSvg(const Plot& plot, size_t* drawn) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  for (const PlotSeries& s : plot.series) {
    for (const auto& [x, y] : s.points) {
      if (!Drawable(x, plot.x.log) || !Drawable(y, plot.y.log)) continue;
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
      ymin = std::min(ymin, y);
      ymax = std::max(ymax, y);
    }
  }
  const Scale sx = MakeScale(xmin, xmax, plot.x.log), sy = MakeScale(ymin, ymax, plot.y.log);
  auto px = [&](double x) { return kLeft + sx.Unit(x) * (kRight - kLeft); };
  auto py = [&](double y) { return kBottom - sy.Unit(y) * (kBottom - kTop); };

  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + Num(kWidth) + "\" height=\"" +
         Num(kHeight) + "\" viewBox=\"0 0 " + Num(kWidth) + " " + Num(kHeight) +
         "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect x=\"0\" y=\"0\" width=\"" + Num(kWidth) + "\" height=\"" + Num(kHeight) +
         "\" fill=\"white\"/>\n";
  svg += "<text x=\"" + Num(kWidth / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" +
         XmlEscape(plot.title) + "</text>\n";

  // Grid and tick labels.
  svg += "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n";
  for (const Tick& t : sx.ticks) {
    const double x = px(t.value);
    svg += "<line x1=\"" + Num(x) + "\" y1=\"" + Num(kTop) + "\" x2=\"" + Num(x) + "\" y2=\"" +
           Num(kBottom) + "\"/>\n";
  }
  for (const Tick& t : sy.ticks) {
    const double y = py(t.value);
    svg += "<line x1=\"" + Num(kLeft) + "\" y1=\"" + Num(y) + "\" x2=\"" + Num(kRight) +
           "\" y2=\"" + Num(y) + "\"/>\n";
  }
  svg += "</g>\n<g fill=\"#333\">\n";
  for (const Tick& t : sx.ticks) {
    if (!t.labelled) continue;
    svg += "<text x=\"" + Num(px(t.value)) + "\" y=\"" + Num(kBottom + 16) +
           "\" text-anchor=\"middle\">" + XmlEscape(TickLabel(t.value)) + "</text>\n";
  }
  for (const Tick& t : sy.ticks) {
    if (!t.labelled) continue;
    svg += "<text x=\"" + Num(kLeft - 6) + "\" y=\"" + Num(py(t.value) + 4) +
           "\" text-anchor=\"end\">" + XmlEscape(TickLabel(t.value)) + "</text>\n";
  }
  svg += "</g>\n";
  svg += "<rect x=\"" + Num(kLeft) + "\" y=\"" + Num(kTop) + "\" width=\"" + Num(kRight - kLeft) +
         "\" height=\"" + Num(kBottom - kTop) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  svg += "<text x=\"" + Num((kLeft + kRight) / 2) + "\" y=\"" + Num(kBottom + 38) +
         "\" text-anchor=\"middle\">" +
         XmlEscape(plot.x.label + (plot.x.log ? ", log scale" : "")) + "</text>\n";
  svg += "<text x=\"18\" y=\"" + Num((kTop + kBottom) / 2) +
         "\" text-anchor=\"middle\" transform=\"rotate(-90 18 " + Num((kTop + kBottom) / 2) +
         ")\">" + XmlEscape(plot.y.label + (plot.y.log ? ", log scale" : "")) + "</text>\n";

  // Series: a polyline through the drawable points and a marker with a tooltip on each.
  size_t markers = 0;
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const std::string colour = Colour(s, i);
    std::string line, dots;
    for (const auto& [x, y] : s.points) {
      if (!Drawable(x, plot.x.log) || !Drawable(y, plot.y.log)) continue;
      line += (line.empty() ? "" : " ") + Num(px(x)) + "," + Num(py(y));
      if (!s.markers) continue;
      char tip[96];
      std::snprintf(tip, sizeof(tip), ": x = %.4g, y = %.4g", x, y);
      dots += "<circle cx=\"" + Num(px(x)) + "\" cy=\"" + Num(py(y)) + "\" r=\"3\"><title>" +
              XmlEscape(s.name + tip) + "</title></circle>\n";
      ++markers;
    }
    svg += "<g stroke=\"" + std::string(colour) + "\" fill=\"" + colour + "\">\n";
    if (!line.empty()) {
      svg += "<polyline fill=\"none\" stroke-width=\"1.5\"" +
             std::string(s.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"" + line +
             "\"/>\n";
    }
    svg += dots + "</g>\n";
  }

  // Legend, right of the plot area.
  double ly = kTop + 6;
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const std::string colour = Colour(s, i);
    const double lx = kRight + 16;
    svg += "<line x1=\"" + Num(lx) + "\" y1=\"" + Num(ly) + "\" x2=\"" + Num(lx + 22) + "\" y2=\"" +
           Num(ly) + "\" stroke=\"" + colour + "\" stroke-width=\"1.5\"" +
           (s.dashed ? " stroke-dasharray=\"6 4\"" : "") + "/>\n";
    if (s.markers) {
      svg += "<circle cx=\"" + Num(lx + 11) + "\" cy=\"" + Num(ly) + "\" r=\"3\" fill=\"" + colour +
             "\"/>\n";
    }
    std::string name = s.name.size() > 34 ? s.name.substr(0, 31) + "..." : s.name;
    svg += "<text x=\"" + Num(lx + 28) + "\" y=\"" + Num(ly + 4) + "\">" + XmlEscape(name) +
           "</text>\n";
    ly += 17;
  }
  // The note, wrapped at word boundaries into at most two lines.
  std::vector<std::string> note_lines;
  std::string rest = plot.note;
  while (!rest.empty()) {
    constexpr size_t kLine = 118;
    size_t cut = rest.size();
    if (cut > kLine && note_lines.empty()) {
      const size_t space = rest.rfind(' ', kLine);
      cut = space == std::string::npos || space == 0 ? kLine : space;
    }
    note_lines.push_back(rest.substr(0, cut));
    rest = cut < rest.size() ? rest.substr(cut + (rest[cut] == ' ' ? 1 : 0)) : "";
  }
  for (size_t i = 0; i < note_lines.size(); ++i) {
    const double y = kHeight - 12 - 14 * double(note_lines.size() - 1 - i);
    svg += "<text x=\"" + Num(kLeft) + "\" y=\"" + Num(y) + "\" font-size=\"11\" fill=\"#555\">" +
           XmlEscape(note_lines[i]) + "</text>\n";
  }
  svg += "</svg>\n";
  if (drawn) *drawn = markers;
  return svg;
}

}  // namespace hullpack
