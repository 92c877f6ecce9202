#include "bench/svg_plot.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace hullpack {
namespace {

// A small XML well-formedness check: one root element, every tag closed in order, attribute values
// quoted, only the five predefined entities (or numeric ones), no stray '<' or '&'. Returns "" when
// well-formed, else what is wrong.
std::string XmlProblem(const std::string& xml) {
  std::vector<std::string> open;
  size_t i = 0, roots = 0;
  auto check_text = [&](size_t from, size_t to) -> std::string {
    for (size_t k = from; k < to; ++k) {
      if (xml[k] == '&') {
        const size_t semi = xml.find(';', k);
        if (semi == std::string::npos || semi > to) return "unterminated entity";
        const std::string name = xml.substr(k + 1, semi - k - 1);
        if (name != "amp" && name != "lt" && name != "gt" && name != "quot" && name != "apos" &&
            (name.empty() || name[0] != '#')) {
          return "unknown entity &" + name + ";";
        }
      }
    }
    return "";
  };
  if (xml.compare(0, 5, "<?xml") == 0) {
    i = xml.find("?>");
    if (i == std::string::npos) return "unterminated declaration";
    i += 2;
  }
  while (i < xml.size()) {
    const size_t lt = xml.find('<', i);
    const std::string text_problem = check_text(i, lt == std::string::npos ? xml.size() : lt);
    if (!text_problem.empty()) return text_problem;
    if (lt == std::string::npos) break;
    if (open.empty()) {
      for (size_t k = i; k < lt; ++k) {
        if (!std::isspace(static_cast<unsigned char>(xml[k])))
          return "text outside the root element";
      }
    }
    const size_t gt = xml.find('>', lt);
    if (gt == std::string::npos) return "unterminated tag";
    std::string tag = xml.substr(lt + 1, gt - lt - 1);
    if (tag.find('<') != std::string::npos) return "'<' inside a tag";
    if (!tag.empty() && tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (open.empty() || open.back() != name) return "closing " + name + " does not match";
      open.pop_back();
    } else {
      const bool self_closing = !tag.empty() && tag.back() == '/';
      if (self_closing) tag.pop_back();
      const size_t space = tag.find_first_of(" \n\t");
      const std::string name = tag.substr(0, space);
      if (name.empty()) return "empty tag name";
      // Attributes: name="value" pairs.
      size_t k = space == std::string::npos ? tag.size() : space;
      while (k < tag.size()) {
        while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
        if (k >= tag.size()) break;
        const size_t eq = tag.find('=', k);
        if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
          return "unquoted attribute in " + name;
        const size_t end = tag.find('"', eq + 2);
        if (end == std::string::npos) return "unterminated attribute in " + name;
        if (tag.substr(eq + 2, end - eq - 2).find('<') != std::string::npos)
          return "'<' in an attribute";
        k = end + 1;
      }
      if (open.empty()) ++roots;
      if (!self_closing) open.push_back(name);
    }
    i = gt + 1;
  }
  if (!open.empty()) return "unclosed <" + open.back() + ">";
  if (roots != 1) return "expected one root element, found " + std::to_string(roots);
  return "";
}

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The (cx, cy) of every data marker (markers carry a <title>; legend markers do not).
std::vector<std::pair<double, double>> Markers(const std::string& svg) {
  std::vector<std::pair<double, double>> out;
  for (size_t at = svg.find("<circle cx=\""); at != std::string::npos;
       at = svg.find("<circle cx=\"", at + 1)) {
    const size_t close = svg.find('>', at);
    if (svg.compare(close + 1, 7, "<title>") != 0) continue;
    const double cx = std::strtod(svg.c_str() + at + 12, nullptr);
    const size_t cy_at = svg.find("cy=\"", at);
    out.push_back({cx, std::strtod(svg.c_str() + cy_at + 4, nullptr)});
  }
  return out;
}

Plot TwoSeries() {
  Plot p;
  p.title = "error <against> time & \"size\"";
  p.x = {"time (ms)", true};
  p.y = {"error (fraction)", true};
  PlotSeries a, b;
  a.name = "bunny & 'friends'";
  a.points = {{1, 1e-3}, {10, 1e-4}, {100, 1e-5}};
  b.name = "igea";
  b.points = {{2, 5e-3}, {20, 5e-4}, {200, 5e-5}, {2000, 4e-5}};
  p.series = {a, b};
  p.note = "one point per setting <ok>";
  return p;
}

TEST(SvgPlot, WellFormedWithOneMarkerPerPoint) {
  size_t drawn = 0;
  const std::string svg = RenderSvg(TwoSeries(), &drawn);
  EXPECT_EQ(XmlProblem(svg), "");
  EXPECT_EQ(drawn, 7u);
  EXPECT_EQ(Markers(svg).size(), 7u);
  EXPECT_EQ(Count(svg, "<polyline"), 2u);
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  // Names, title and labels are escaped, and the legend names both series.
  EXPECT_NE(svg.find("bunny &amp; &apos;friends&apos;"), std::string::npos);
  EXPECT_NE(svg.find("error &lt;against&gt; time &amp; &quot;size&quot;"), std::string::npos);
  EXPECT_NE(svg.find(">igea</text>"), std::string::npos);
  EXPECT_NE(svg.find("time (ms), log scale"), std::string::npos);
}

TEST(SvgPlot, MarkersInsideThePlotAreaAndOrderedLikeTheData) {
  const std::string svg = RenderSvg(TwoSeries());
  const auto m = Markers(svg);
  ASSERT_EQ(m.size(), 7u);
  for (const auto& [x, y] : m) {
    EXPECT_GE(x, 80.0);
    EXPECT_LE(x, 590.0);
    EXPECT_GE(y, 46.0);
    EXPECT_LE(y, 420.0);
  }
  // Series a: x grows and error falls, so the markers go right and down the page (y grows).
  EXPECT_LT(m[0].first, m[1].first);
  EXPECT_LT(m[0].second, m[1].second);
  // Log axes: equal ratios are equal distances.
  EXPECT_NEAR(m[1].first - m[0].first, m[2].first - m[1].first, 0.02);
  EXPECT_NEAR(m[1].second - m[0].second, m[2].second - m[1].second, 0.02);
}

TEST(SvgPlot, PointsALogAxisCannotShowAreLeftOut) {
  Plot p;
  p.x = {"x", true};
  p.y = {"y", false};
  PlotSeries s;
  s.name = "s";
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  s.points = {{0, 1}, {-1, 2}, {1, 1}, {10, 3}, {nan, 1}, {100, inf}, {1000, -4}};
  p.series = {s};
  size_t drawn = 0;
  const std::string svg = RenderSvg(p, &drawn);
  EXPECT_EQ(XmlProblem(svg), "");
  EXPECT_EQ(drawn, 3u);  // (1,1), (10,3), (1000,-4): a linear y axis shows negative values
  EXPECT_EQ(Markers(svg).size(), 3u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, ReferenceLinesHaveNoMarkers) {
  Plot p = TwoSeries();
  PlotSeries bound;
  bound.name = "bound";
  bound.dashed = true;
  bound.markers = false;
  bound.points = {{1, 1e-2}, {1000, 1e-5}};
  p.series.push_back(bound);
  size_t drawn = 0;
  const std::string svg = RenderSvg(p, &drawn);
  EXPECT_EQ(XmlProblem(svg), "");
  EXPECT_EQ(drawn, 7u);
  EXPECT_EQ(Count(svg, "<polyline"), 3u);
  EXPECT_EQ(Count(svg, "stroke-dasharray"), 2u);  // the line and its legend sample
}

TEST(SvgPlot, EmptyAndSinglePointPlotsAreValid) {
  Plot empty;
  empty.title = "nothing";
  size_t drawn = 5;
  EXPECT_EQ(XmlProblem(RenderSvg(empty, &drawn)), "");
  EXPECT_EQ(drawn, 0u);
  Plot one;
  one.x = {"x", false};
  one.y = {"y", true};
  one.series = {{"only", {{3, 3}}, false, true}};
  const std::string svg = RenderSvg(one, &drawn);
  EXPECT_EQ(XmlProblem(svg), "");
  EXPECT_EQ(drawn, 1u);
  const auto m = Markers(svg);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_TRUE(std::isfinite(m[0].first) && std::isfinite(m[0].second));
}

TEST(SvgPlot, TheCheckerRejectsBrokenXml) {
  EXPECT_NE(XmlProblem("<svg><g></svg>"), "");
  EXPECT_NE(XmlProblem("<svg a=b></svg>"), "");
  EXPECT_NE(XmlProblem("<svg>a & b</svg>"), "");
  EXPECT_NE(XmlProblem("<svg></svg><svg></svg>"), "");
  EXPECT_EQ(XmlProblem("<svg a=\"1\"><g/>x &amp; y</svg>"), "");
}

TEST(SvgPlot, SeriesKeepTheirColourAndLongNotesWrap) {
  Plot p = TwoSeries();
  p.series[0].colour = 1;
  p.series[1].colour = 1;
  p.note = std::string(100, 'a') + " " + std::string(60, 'b');
  const std::string svg = RenderSvg(p);
  EXPECT_EQ(XmlProblem(svg), "");
  // Both series (and their legend lines) in palette colour 1; the note on two lines.
  EXPECT_EQ(Count(svg, "stroke=\"#d62728\""), 4u);
  EXPECT_EQ(Count(svg, std::string(100, 'a') + "</text>"), 1u);
  EXPECT_EQ(Count(svg, ">" + std::string(60, 'b') + "</text>"), 1u);
}

}  // namespace
}  // namespace hullpack
