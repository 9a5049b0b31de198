// Rows: the representative-point sphere (eq. 10-14) and tube (eq. 16-20) lights against their
// specular integrated over the light's surface, by roughness and by the light's size; cost
// against Monte Carlo over the surface on the device.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "area_light_reference.h"
#include "report_context.h"
#include "shader_values.h"

namespace candela::report {

namespace {

constexpr double kPi = std::numbers::pi;
const Vec3& kCentre = kLightCentre;
const Vec3& kAlong = kLightAlong;
const auto& kRoughness = kAreaLightRoughness;
using Geometry = AreaLightView;

Vec3 viewFor(double across, double along) {
    return report::viewFor({across, along});
}

struct Cell {
    double l1 = 0.0;      // sum |approx - reference| / sum reference over the views
    double onAxis = 0.0;  // signed relative error with R through the centre
};

std::string cellText(const Cell& cell) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.1f %% (%+.1f %%)", 100.0 * cell.l1, 100.0 * cell.onAxis);
    return text;
}

struct Sweep {
    ReportTable table;
    double worst = -1.0;
    std::string where;
};

// sizes: sphere sin(sigma) or tube length (m), at 1 m. views(size) lists the geometries.
template <class Views, class Reference>
Sweep sweep(ReportContext& context, bool sphere, const std::vector<double>& sizes, Views views,
            Reference reference) {
    std::vector<ValueSample> samples;
    for (double roughness : kRoughness) {
        for (double size : sizes) {
            for (const Geometry& g : views(size)) {
                Vec3 V = viewFor(g.across, g.along);
                ValueSample s;
                s.a = {float(kCentre[0]), float(kCentre[1]), float(kCentre[2]),
                       sphere ? float(size) : 0.0f};
                s.b = {float(V[0]), float(V[1]), float(V[2]), sphere ? 0.0f : float(size)};
                s.c = {float(roughness), float(kAlong[0]), float(kAlong[1]), float(kAlong[2])};
                samples.push_back(s);
            }
        }
    }
    auto device = evaluateOnDevice(context.harness, ValueFunction::AreaLight, samples);
    Sweep out;
    size_t k = 0;
    for (double roughness : kRoughness) {
        std::vector<std::string> row = {formatNumber(roughness)};
        const double alpha = stability::reference::alphaFromRoughness(roughness);
        for (double size : sizes) {
            double sumError = 0.0, sumReference = 0.0;
            Cell cell;
            bool first = true;
            for (const Geometry& g : views(size)) {
                const double r = reference(size, viewFor(g.across, g.along), alpha);
                const double a = device[k++][0];
                sumError += std::fabs(a - r);
                sumReference += r;
                if (first) cell.onAxis = (a - r) / r;
                first = false;
            }
            cell.l1 = sumError / sumReference;
            row.push_back(cellText(cell));
            if (!(cell.l1 <= out.worst)) {
                out.worst = cell.l1;
                char text[96];
                std::snprintf(text, sizeof(text), "roughness %.2f, %s %.2f%s", roughness,
                              sphere ? "sin(sigma)" : "length", size, sphere ? "" : " m at 1 m");
                out.where = text;
            }
        }
        out.table.rows.push_back(row);
    }
    return out;
}

}  // namespace

void addAreaLightRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const int sphereGrid = quick ? 96 : 640;
    const int tubeSamples = quick ? 4096 : 65536;
    const uint32_t monteCarloSamples = 64;
    const uint32_t monteCarloIterations = context.budget.iterations(16);
    const uint32_t iterations = context.budget.iterations(4096);
    std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::SphereRepresentative, iterations},
        {CostFunction::SphereMonteCarlo, monteCarloIterations, monteCarloSamples},
        {CostFunction::TubeRepresentative, iterations},
        {CostFunction::TubeMonteCarlo, monteCarloIterations, monteCarloSamples},
    });
    const std::string monteCarloCost =
        " (Monte Carlo: " + std::to_string(monteCarloSamples) + " stratified samples, device)";

    // Sphere and tube views: sphereViews, tubeViews (area_light_reference.h).
    const std::vector<double> sinSigma = {0.05, 0.1, 0.2, 0.4};
    Sweep sphere =
        sweep(context, true, sinSigma, sphereViews, [&](double s, const Vec3& V, double alpha) {
            return sphereSpecularReference(kCentre, s, V, alpha, sphereGrid);
        });
    sphere.table.title = "Sphere lights: representative point against the integral over the sphere";
    sphere.table.intro =
        "Specular (D Vis NoL E, F0 = 1) of a sphere light 1 m away, 30 degrees from the normal, "
        "for six views: R through the centre, at 0.5, 1 and 2 angular radii off it in the plane "
        "of incidence, 0.5 and 1.5 across it. Cell: relative L1 error over the six views "
        "(sum |approx - reference| / sum reference), and in brackets the signed relative error "
        "with R through the centre. Reference: midpoint quadrature over the subtended cone in "
        "double (" +
        std::to_string(sphereGrid) + "^2 points).";
    sphere.table.header = {"roughness"};
    for (double s : sinSigma) {
        char text[64];
        std::snprintf(text, sizeof(text), "sin(sigma) %.2f (%.3f sr)", s,
                      2.0 * kPi * (1.0 - std::sqrt(1.0 - s * s)));
        sphere.table.header.push_back(text);
    }
    context.report.rows.push_back(
        {"Sphere light: representative point + (alpha / alpha')^2 (eq. 10-14)",
         "specular integrated over the sphere (double)",
         "relative L1 over 6 views (roughness 0.1..1 x sin(sigma) 0.05..0.4, see the table below)",
         sphere.worst, "rel", sphere.where, formatShaderCost(ns[0], ns[1]) + monteCarloCost,
         plottedNs(ns[0])});
    context.report.tables.push_back(sphere.table);

    const std::vector<double> lengths = {0.25, 0.5, 1.0, 2.0};
    Sweep tube =
        sweep(context, false, lengths, tubeViews, [&](double length, const Vec3& V, double alpha) {
            return tubeSpecularReference(kCentre, kAlong, length, V, alpha, tubeSamples);
        });
    tube.table.title = "Tube lights: representative point against the integral along the tube";
    tube.table.intro =
        "Specular (F0 = 1) of a tube light (radius 0) centred 1 m away, 30 degrees from the "
        "normal, its axis perpendicular to the plane of incidence, for six views: R through the "
        "centre, along the axis to 0.5, 1 and 1.5 half-lengths, and 0.1 rad across it at 0 and "
        "0.5 half-lengths. Cell: relative L1 error over the six views, in brackets the signed "
        "error with R through the centre. Reference: " +
        std::to_string(tubeSamples) +
        " midpoints along the segment in double, each a point light carrying its share of the "
        "intensity.";
    tube.table.header = {"roughness"};
    for (double length : lengths) {
        char text[64];
        std::snprintf(text, sizeof(text), "length %.2f m (%.0f deg)", length,
                      2.0 * std::atan(0.5 * length) * 180.0 / kPi);
        tube.table.header.push_back(text);
    }
    context.report.rows.push_back(
        {"Tube light: closest point to R + alpha / alpha' (eq. 16-20)",
         "specular integrated along the tube (double)",
         "relative L1 over 6 views (roughness 0.1..1 x length 0.25..2 m at 1 m, see the table "
         "below)",
         tube.worst, "rel", tube.where, formatShaderCost(ns[2], ns[3]) + monteCarloCost,
         plottedNs(ns[2])});
    context.report.tables.push_back(tube.table);
}

}  // namespace candela::report
