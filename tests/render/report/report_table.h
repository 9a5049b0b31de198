#pragma once
// The report's content: one row per approximation (its error against a reference and its
// cost against the reference's, both measured in this run), extra tables, and notes; written
// as the markdown page docs/speed-vs-error.md.
#include <string>
#include <vector>

namespace candela::report {

struct ReportRow {
    std::string approximation;
    std::string reference;
    std::string metric;  // how the error is measured, over which inputs
    double error = 0.0;
    std::string errorUnit;  // "abs", "rel", "% energy", ...
    std::string worstCase;  // where the worst error is
    std::string cost;       // approximation vs reference, e.g. "0.8 vs 2.1 ns (2.6x)"
    // Machine-readable cost for the error-against-cost figure: the approximation's device
    // nanoseconds per evaluation (0: not measured per evaluation, or under the timer's noise;
    // such rows are left out of the figure, which lists them).
    double costNs = 0.0;
};

// A figure written beside the page (an SVG file) and embedded in it.
struct ReportFigure {
    std::string file;  // name only: written in the page's folder
    std::string caption;
    std::string svg;
};

struct ReportTable {
    std::string title;
    std::string intro;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

struct Report {
    std::string device;
    std::string budget;
    double seconds = 0.0;
    std::vector<ReportRow> rows;
    std::vector<ReportTable> tables;
    std::vector<std::string> notes;
    std::vector<ReportFigure> figures;
};

std::string formatNumber(double value, int significant = 3);
// "a vs b ns/eval (ratio x)"; negative costs (below the timer's noise) print as "< noise".
std::string formatCost(double approximationNs, double referenceNs, const char* unit = "ns");

std::string toMarkdown(const Report& report);

}  // namespace candela::report
