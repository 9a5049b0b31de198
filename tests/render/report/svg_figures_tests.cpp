// The report's SVG writer (svg_figures.h): its output is well-formed XML (every element
// closed, in order; text escaped), and scatter points sit at their log-log coordinates.
#include "svg_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace candela::report;

namespace {

// Checks that every tag is closed in order (a minimal XML well-formedness check: no
// attributes with '>' inside, which the writer never emits); returns the problem or "".
std::string tagStructureProblem(const std::string& svg) {
    std::vector<std::string> open;
    size_t at = 0;
    while ((at = svg.find('<', at)) != std::string::npos) {
        const size_t end = svg.find('>', at);
        if (end == std::string::npos) return "unterminated tag at " + std::to_string(at);
        const std::string tag = svg.substr(at + 1, end - at - 1);
        at = end + 1;
        if (tag.empty()) return "empty tag";
        if (tag[0] == '?') continue;  // the XML declaration
        if (tag[0] == '/') {
            if (open.empty() || open.back() != tag.substr(1)) return "unexpected </" + tag + ">";
            open.pop_back();
            continue;
        }
        if (tag.back() == '/') continue;  // self-closing
        open.push_back(tag.substr(0, tag.find(' ')));
    }
    if (!open.empty()) return "unclosed <" + open.back() + ">";
    // Text between tags must not hold a raw '&' that is not an entity.
    for (size_t amp = svg.find('&'); amp != std::string::npos; amp = svg.find('&', amp + 1)) {
        const size_t semicolon = svg.find(';', amp);
        if (semicolon == std::string::npos || semicolon - amp > 6) return "raw &";
    }
    return "";
}

// The numeric attribute `name` of the n-th element `element`.
double attribute(const std::string& svg, const std::string& element, int n,
                 const std::string& name) {
    size_t at = 0;
    for (int i = 0; i <= n; ++i) {
        at = svg.find("<" + element + " ", at);
        if (at == std::string::npos) return std::nan("");
        if (i < n) ++at;
    }
    const size_t key = svg.find(" " + name + "=\"", at);
    return std::strtod(svg.c_str() + key + name.size() + 3, nullptr);
}

}  // namespace

TEST(ReportSvg, ScatterIsWellFormedAndPlacesPointsOnLogAxes) {
    LogLogPlot plot;
    plot.title = "error <against> cost & more";
    plot.xAxis = "ns";
    plot.yAxis = "relative";
    plot.points = {{"a & b", 0.5, 2.22}, {"c", 40.0, 0.004}, {"dropped", 0.0, 1.0}};
    const std::string svg = logLogScatterSvg(plot);
    EXPECT_EQ(tagStructureProblem(svg), "") << svg;
    EXPECT_NE(svg.find("error &lt;against&gt; cost &amp; more"), std::string::npos);
    // x spans 0.1 .. 100 (3 decades), y 0.001 .. 10 (4 decades); the zero-cost point is left out.
    EXPECT_EQ(svg.find("dropped"), std::string::npos);
    const double x0 = kPlotLeft + (std::log10(0.5) + 1.0) / 3.0 * (kPlotRight - kPlotLeft);
    const double y0 = kPlotBottom + (std::log10(2.22) + 3.0) / 4.0 * (kPlotTop - kPlotBottom);
    const double x1 = kPlotLeft + (std::log10(40.0) + 1.0) / 3.0 * (kPlotRight - kPlotLeft);
    const double y1 = kPlotBottom + (std::log10(0.004) + 3.0) / 4.0 * (kPlotTop - kPlotBottom);
    EXPECT_NEAR(attribute(svg, "circle", 0, "cx"), x0, 0.01);
    EXPECT_NEAR(attribute(svg, "circle", 0, "cy"), y0, 0.01);
    EXPECT_NEAR(attribute(svg, "circle", 1, "cx"), x1, 0.01);
    EXPECT_NEAR(attribute(svg, "circle", 1, "cy"), y1, 0.01);
    EXPECT_TRUE(std::isnan(attribute(svg, "circle", 2, "cx")));
}

TEST(ReportSvg, LogAxisEnclosesTheDataInWholeDecades) {
    const LogAxis axis = LogAxis::enclosing({0.03, 7.0, -1.0, 0.0}, 0.0, 300.0);
    EXPECT_DOUBLE_EQ(axis.low, 0.01);
    EXPECT_DOUBLE_EQ(axis.high, 10.0);
    EXPECT_NEAR(axis.map(0.1), 100.0, 1e-9);
    EXPECT_NEAR(axis.map(1.0), 200.0, 1e-9);
    const LogAxis single = LogAxis::enclosing({1.0}, 0.0, 1.0);
    EXPECT_GT(single.high, single.low);
}

TEST(ReportSvg, HeatMapHasACellPerValueWithItsLabel) {
    HeatMap map;
    map.title = "Sphere light, ltc";
    map.xAxis = "size";
    map.yAxis = "roughness";
    map.columns = {"0.05", "0.4"};
    map.rows = {"0.1", "1"};
    map.values = {{0.004, 2.22}, {0.01, std::nan("")}};
    const std::string svg = heatMapSvg(map);
    EXPECT_EQ(tagStructureProblem(svg), "") << svg;
    size_t cells = 0;
    for (size_t at = svg.find("<rect x="); at != std::string::npos;
         at = svg.find("<rect x=", at + 1))
        ++cells;
    EXPECT_EQ(cells, 4u);
    EXPECT_NE(svg.find(">222.0 %<"), std::string::npos);
    EXPECT_NE(svg.find(">0.4 %<"), std::string::npos);
    EXPECT_NE(svg.find(">n/a<"), std::string::npos);
}
