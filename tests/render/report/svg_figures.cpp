#include "svg_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela::report {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f", value);
    return text;
}

std::string decadeLabel(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

void text(std::ostringstream& out, double x, double y, const std::string& content,
          const char* anchor = "start", int size = 11) {
    out << "<text x=\"" << number(x) << "\" y=\"" << number(y) << "\" font-size=\"" << size
        << "\" text-anchor=\"" << anchor << "\">" << xmlEscape(content) << "</text>\n";
}

void header(std::ostringstream& out, double width, double height) {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number(width) << "\" height=\""
        << number(height) << "\" viewBox=\"0 0 " << number(width) << " " << number(height)
        << "\" font-family=\"sans-serif\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

// Green (small) to red (large) on log10 of the value between 1e-3 and 1.
std::string errorColour(double value) {
    const double t = std::clamp((std::log10(std::max(value, 1e-6)) + 3.0) / 3.0, 0.0, 1.0);
    const int r = int(std::lround(255.0 * std::min(1.0, 2.0 * t)));
    const int g = int(std::lround(200.0 * std::min(1.0, 2.0 * (1.0 - t))));
    char text[16];
    std::snprintf(text, sizeof(text), "#%02x%02x40", r, g);
    return text;
}

}  // namespace

std::string xmlEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

LogAxis LogAxis::enclosing(const std::vector<double>& values, double pixelLow, double pixelHigh) {
    double lowest = 0.0, highest = 0.0;
    for (double v : values) {
        if (!(v > 0.0) || !std::isfinite(v)) continue;
        lowest = lowest == 0.0 ? v : std::min(lowest, v);
        highest = std::max(highest, v);
    }
    LogAxis axis;
    axis.pixelLow = pixelLow;
    axis.pixelHigh = pixelHigh;
    if (highest > 0.0) {
        axis.low = std::pow(10.0, std::floor(std::log10(lowest)));
        axis.high = std::pow(10.0, std::ceil(std::log10(highest)));
        if (axis.high <= axis.low) axis.high = axis.low * 10.0;
    }
    return axis;
}

double LogAxis::map(double value) const {
    const double t = (std::log10(value) - std::log10(low)) / (std::log10(high) - std::log10(low));
    return pixelLow + t * (pixelHigh - pixelLow);
}

std::string logLogScatterSvg(const LogLogPlot& plot) {
    std::vector<ScatterPoint> points;
    for (const ScatterPoint& p : plot.points) {
        if (p.x > 0.0 && p.y > 0.0 && std::isfinite(p.x) && std::isfinite(p.y)) points.push_back(p);
    }
    std::vector<double> xs, ys;
    for (const ScatterPoint& p : points)
        xs.push_back(p.x), ys.push_back(p.y);
    const LogAxis x = LogAxis::enclosing(xs, kPlotLeft, kPlotRight);
    const LogAxis y = LogAxis::enclosing(ys, kPlotBottom, kPlotTop);
    const double legendTop = kPlotBottom + 50.0;
    const double height = legendTop + 16.0 * double(points.size()) + 20.0;
    std::ostringstream out;
    header(out, 660.0, height);
    text(out, 330.0, 22.0, plot.title, "middle", 14);
    out << "<rect x=\"" << number(kPlotLeft) << "\" y=\"" << number(kPlotTop) << "\" width=\""
        << number(kPlotRight - kPlotLeft) << "\" height=\"" << number(kPlotBottom - kPlotTop)
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double d = x.low; d <= x.high * 1.0001; d *= 10.0) {
        const double px = x.map(d);
        out << "<line x1=\"" << number(px) << "\" y1=\"" << number(kPlotTop) << "\" x2=\""
            << number(px) << "\" y2=\"" << number(kPlotBottom) << "\" stroke=\"#ddd\"/>\n";
        text(out, px, kPlotBottom + 16.0, decadeLabel(d), "middle");
    }
    for (double d = y.low; d <= y.high * 1.0001; d *= 10.0) {
        const double py = y.map(d);
        out << "<line x1=\"" << number(kPlotLeft) << "\" y1=\"" << number(py) << "\" x2=\""
            << number(kPlotRight) << "\" y2=\"" << number(py) << "\" stroke=\"#ddd\"/>\n";
        text(out, kPlotLeft - 6.0, py + 4.0, decadeLabel(d), "end");
    }
    text(out, 0.5 * (kPlotLeft + kPlotRight), kPlotBottom + 34.0, plot.xAxis, "middle", 12);
    out << "<text x=\"16\" y=\"" << number(0.5 * (kPlotTop + kPlotBottom))
        << "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 16 "
        << number(0.5 * (kPlotTop + kPlotBottom)) << ")\">" << xmlEscape(plot.yAxis) << "</text>\n";
    for (size_t i = 0; i < points.size(); ++i) {
        const double px = x.map(points[i].x), py = y.map(points[i].y);
        out << "<circle cx=\"" << number(px) << "\" cy=\"" << number(py)
            << "\" r=\"4\" fill=\"#3060c0\"/>\n";
        text(out, px + 6.0, py - 4.0, std::to_string(i + 1), "start", 10);
        text(out, kPlotLeft, legendTop + 16.0 * double(i),
             std::to_string(i + 1) + ": " + points[i].label, "start", 11);
    }
    out << "</svg>\n";
    return out.str();
}

std::string heatMapSvg(const HeatMap& map) {
    const double left = 90.0, top = 50.0, cellWidth = 130.0, cellHeight = 34.0;
    const double width = left + cellWidth * double(map.columns.size()) + 20.0;
    const double height = top + cellHeight * double(map.rows.size()) + 60.0;
    std::ostringstream out;
    header(out, width, height);
    text(out, 0.5 * width, 22.0, map.title, "middle", 14);
    for (size_t c = 0; c < map.columns.size(); ++c) {
        text(out, left + cellWidth * (double(c) + 0.5), top - 8.0, map.columns[c], "middle", 10);
    }
    for (size_t r = 0; r < map.rows.size(); ++r) {
        const double y = top + cellHeight * double(r);
        text(out, left - 8.0, y + 0.5 * cellHeight + 4.0, map.rows[r], "end");
        for (size_t c = 0; c < map.columns.size(); ++c) {
            const double value =
                r < map.values.size() && c < map.values[r].size() ? map.values[r][c] : std::nan("");
            const double x = left + cellWidth * double(c);
            out << "<rect x=\"" << number(x) << "\" y=\"" << number(y) << "\" width=\""
                << number(cellWidth) << "\" height=\"" << number(cellHeight) << "\" fill=\""
                << (std::isfinite(value) ? errorColour(value) : std::string("#888888"))
                << "\" stroke=\"white\"/>\n";
            char label[32];
            if (std::isfinite(value))
                std::snprintf(label, sizeof(label), "%.1f %%", 100.0 * value);
            else
                std::snprintf(label, sizeof(label), "n/a");
            text(out, x + 0.5 * cellWidth, y + 0.5 * cellHeight + 4.0, label, "middle", 11);
        }
    }
    const double bottom = top + cellHeight * double(map.rows.size());
    text(out, left + 0.5 * cellWidth * double(map.columns.size()), bottom + 20.0, map.xAxis,
         "middle", 12);
    text(out, 10.0, bottom + 44.0,
         map.yAxis + " down the side; colour: log scale, green 0.1 % to red 100 %", "start", 10);
    out << "</svg>\n";
    return out.str();
}

}  // namespace candela::report
