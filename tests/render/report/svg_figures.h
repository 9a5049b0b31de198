#pragma once
// The report's figures as SVG, written by our own small writer (no dependencies): a log-log
// scatter of error against cost, one point per row, and a heat map of a grid of values (a light
// shape and mode over roughness x light size). Pure functions of their data: tested on their own
// (tests/render/report/svg_figures_tests.cpp).
#include <string>
#include <vector>

namespace candela::report {

// A decade-aligned logarithmic axis: value v maps to pixel
//   pixelLow + (log10 v - log10 low) / (log10 high - log10 low) * (pixelHigh - pixelLow).
struct LogAxis {
    double low = 1.0, high = 10.0;  // powers of ten enclosing the data
    double pixelLow = 0.0, pixelHigh = 1.0;

    // The smallest decade range holding every positive value (one decade if there is none).
    static LogAxis enclosing(const std::vector<double>& values, double pixelLow, double pixelHigh);
    double map(double value) const;
};

struct ScatterPoint {
    std::string label;        // listed in the legend under the point's number
    double x = 0.0, y = 0.0;  // > 0 (others are left out)
};

struct LogLogPlot {
    std::string title, xAxis, yAxis;
    std::vector<ScatterPoint> points;
};

// Plot area: x from kPlotLeft to kPlotRight, y from kPlotBottom (low values) up to kPlotTop.
inline constexpr double kPlotLeft = 70.0, kPlotRight = 610.0, kPlotTop = 40.0, kPlotBottom = 400.0;

std::string logLogScatterSvg(const LogLogPlot& plot);

// values[row][column], relative errors (fractions), drawn on a logarithmic colour scale from
// 0.1 % (green) through 5 % to 100 % and over (red); each cell also prints its value in %.
struct HeatMap {
    std::string title, xAxis, yAxis;
    std::vector<std::string> columns, rows;
    std::vector<std::vector<double>> values;
};

std::string heatMapSvg(const HeatMap& map);

// Text with &, <, >, " escaped for XML.
std::string xmlEscape(const std::string& text);

}  // namespace candela::report
