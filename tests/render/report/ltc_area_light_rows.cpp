// Rows: sphere and tube lights by the representative point and by linearly transformed cosines
// (issue 15, --area-lights), both with the energy-conserving BRDF's lobe (GGX D x height-
// correlated Smith x NoL, F = 1: the lobe render/ltc/'s table is fitted to), against that lobe
// integrated over the light in double, on the grid roughness x light size x view of the
// representative-point rows (area_light_rows.cpp); cost against a point light shaded the same
// way. Heat maps of each shape and mode over roughness x size go to the report's figures.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "area_light_reference.h"
#include "ltc_ggx_table.inc"
#include "report_context.h"
#include "shader_values.h"
#include "svg_figures.h"

namespace candela::report {

namespace {

constexpr double kPi = std::numbers::pi;

// The table's M^-1 entries (00, 02, 20, 22) and magnitude at (roughness, cos theta_v), bilinear
// between cells as a linear sampler would read them (render/ltc/ltc_fit.h gives the axes).
struct LtcLookup {
    std::array<float, 4> inverse;
    double magnitude;
};

LtcLookup lookupLtc(double roughness, double cosView) {
    const int n = kLtcTableSize;
    const double r = std::clamp((roughness - 0.02) / (1.0 - 0.02), 0.0, 1.0) * (n - 1);
    const double c = std::sqrt(std::clamp(1.0 - cosView, 0.0, 1.0)) * (n - 1);
    const int r0 = std::min(int(r), n - 2), c0 = std::min(int(c), n - 2);
    const double fr = r - r0, fc = c - c0;
    LtcLookup out{};
    for (int k = 0; k < 5; ++k) {
        auto at = [&](int row, int column) { return double(kLtcTable[row * n + column][k]); };
        const double top = at(r0, c0) * (1 - fc) + at(r0, c0 + 1) * fc;
        const double bottom = at(r0 + 1, c0) * (1 - fc) + at(r0 + 1, c0 + 1) * fc;
        const double v = top * (1 - fr) + bottom * fr;
        if (k < 4)
            out.inverse[size_t(k)] = float(v);
        else
            out.magnitude = v;
    }
    return out;
}

struct ModeSweep {
    std::vector<std::vector<double>> cells;  // [roughness][size]: relative L1 over the views
    double worst = -1.0, mean = 0.0, worstView = 0.0;
    std::string where;
};

struct ShapeSweep {
    ModeSweep representative, ltc;
};

ShapeSweep sweep(ReportContext& context, bool sphere, const std::vector<double>& sizes,
                 int referenceResolution) {
    std::vector<ValueSample> samples;
    std::vector<double> magnitudes, references;
    const auto views = sphere ? sphereViews : tubeViews;
    for (double roughness : kAreaLightRoughness) {
        const double alpha = stability::reference::alphaFromRoughness(roughness);
        for (double size : sizes) {
            for (const AreaLightView& g : views(size)) {
                const Vec3 V = viewFor(g);
                const LtcLookup ltc = lookupLtc(roughness, V[2]);
                ValueSample s;
                s.a = {float(kLightCentre[0]), float(kLightCentre[1]), float(kLightCentre[2]),
                       sphere ? float(size) : 0.0f};
                s.b = {float(V[0]), float(V[1]), float(V[2]), sphere ? 0.0f : float(size)};
                s.c = {float(roughness), float(kLightAlong[0]), float(kLightAlong[1]),
                       float(kLightAlong[2])};
                s.d = ltc.inverse;
                s.e = {float(ltc.magnitude), 0.0f, 0.0f, 0.0f};
                samples.push_back(s);
                magnitudes.push_back(ltc.magnitude);
                references.push_back(sphere
                                         ? sphereSpecularReference(kLightCentre, size, V, alpha,
                                                                   referenceResolution, true)
                                         : tubeSpecularReference(kLightCentre, kLightAlong, size, V,
                                                                 alpha, referenceResolution, true));
            }
        }
    }
    const auto device = evaluateOnDevice(context.harness, ValueFunction::AreaLightLtc, samples);
    ShapeSweep out;
    size_t k = 0;
    size_t cellCount = 0;
    for (double roughness : kAreaLightRoughness) {
        out.representative.cells.emplace_back();
        out.ltc.cells.emplace_back();
        for (double size : sizes) {
            double errorLtc = 0.0, errorRepresentative = 0.0, sum = 0.0;
            double worstViewLtc = 0.0, worstViewRepresentative = 0.0;
            for (size_t v = 0; v < views(size).size(); ++v, ++k) {
                const double reference = references[k];
                const double ltc = device[k][0] * magnitudes[k];
                const double representative = device[k][1];
                errorLtc += std::fabs(ltc - reference);
                errorRepresentative += std::fabs(representative - reference);
                sum += reference;
                worstViewLtc = std::max(worstViewLtc, std::fabs(ltc - reference) / reference);
                worstViewRepresentative = std::max(
                    worstViewRepresentative, std::fabs(representative - reference) / reference);
            }
            ++cellCount;
            auto record = [&](ModeSweep& mode, double error, double worstView) {
                const double cell = error / sum;
                mode.cells.back().push_back(cell);
                mode.mean += cell;
                mode.worstView = std::max(mode.worstView, worstView);
                if (!(cell <= mode.worst)) {
                    mode.worst = cell;
                    char text[96];
                    std::snprintf(text, sizeof(text), "roughness %.2f, %s %.2f%s", roughness,
                                  sphere ? "sin(sigma)" : "length", size,
                                  sphere ? "" : " m at 1 m");
                    mode.where = text;
                }
            };
            record(out.ltc, errorLtc, worstViewLtc);
            record(out.representative, errorRepresentative, worstViewRepresentative);
        }
    }
    out.ltc.mean /= double(cellCount);
    out.representative.mean /= double(cellCount);
    return out;
}

// Tubes of radius `radius` against the Lambertian capsule they are (capsuleSpecularReference):
// the representative point (with the radius, as the renderer widens it), the bare segment's
// LTC (ltcLineIntegral, the renderer's tube before the capsule) and the capsule's LTC
// (ltcTubeIntegral, the renderer's now), on the tube grid.
struct CapsuleSweep {
    ModeSweep representative, segment, capsule;
};

CapsuleSweep capsuleSweep(ReportContext& context, double radius, const std::vector<double>& lengths,
                          double spacingScale) {
    std::vector<ValueSample> samples;
    std::vector<double> magnitudes, references;
    for (double roughness : kAreaLightRoughness) {
        const double alpha = stability::reference::alphaFromRoughness(roughness);
        // A quarter of the lobe's angular width at 1 m between points (alpha 0.01: 2.5 mm), at
        // most 2 cm (the capsule's own curvature: 8 points around a 0.3 m cylinder were 5 % off).
        const double spacing = spacingScale * std::min(std::max(alpha, 0.004) / 4.0, 0.02);
        for (double length : lengths) {
            for (const AreaLightView& g : tubeViews(length)) {
                const Vec3 V = viewFor(g);
                const LtcLookup ltc = lookupLtc(roughness, V[2]);
                for (double sampleRadius : {radius, -1.0}) {
                    ValueSample s;
                    s.a = {float(kLightCentre[0]), float(kLightCentre[1]), float(kLightCentre[2]),
                           float(sampleRadius)};
                    s.b = {float(V[0]), float(V[1]), float(V[2]), float(length)};
                    s.c = {float(roughness), float(kLightAlong[0]), float(kLightAlong[1]),
                           float(kLightAlong[2])};
                    s.d = ltc.inverse;
                    s.e = {float(ltc.magnitude), 0.0f, 0.0f, 0.0f};
                    samples.push_back(s);
                }
                magnitudes.push_back(ltc.magnitude);
                references.push_back(capsuleSpecularReference(kLightCentre, kLightAlong, length,
                                                              radius, V, alpha, spacing, true));
            }
        }
    }
    const auto device = evaluateOnDevice(context.harness, ValueFunction::AreaLightLtc, samples);
    CapsuleSweep out;
    ModeSweep* modes[] = {&out.representative, &out.segment, &out.capsule};
    size_t k = 0, cellCount = 0;
    for (double roughness : kAreaLightRoughness) {
        for (ModeSweep* mode : modes)
            mode->cells.emplace_back();
        for (double length : lengths) {
            double error[3] = {0, 0, 0}, worstView[3] = {0, 0, 0}, sum = 0.0;
            for (size_t v = 0; v < tubeViews(length).size(); ++v, ++k) {
                const double reference = references[k];
                const double value[3] = {device[2 * k][1], device[2 * k + 1][0] * magnitudes[k],
                                         device[2 * k][0] * magnitudes[k]};
                sum += reference;
                for (int m = 0; m < 3; ++m) {
                    error[m] += std::fabs(value[m] - reference);
                    worstView[m] =
                        std::max(worstView[m], std::fabs(value[m] - reference) / reference);
                }
            }
            ++cellCount;
            for (int m = 0; m < 3; ++m) {
                ModeSweep& mode = *modes[m];
                const double cell = error[m] / sum;
                mode.cells.back().push_back(cell);
                mode.mean += cell;
                mode.worstView = std::max(mode.worstView, worstView[m]);
                if (!(cell <= mode.worst)) {
                    mode.worst = cell;
                    char text[96];
                    std::snprintf(text, sizeof(text), "roughness %.2f, length %.2f m at 1 m",
                                  roughness, length);
                    mode.where = text;
                }
            }
        }
    }
    for (ModeSweep* mode : modes)
        mode->mean /= double(cellCount);
    return out;
}

// The tube's diffuse against the capsule's irradiance (capsuleIrradianceReference): the LTC
// mode's (ltcTubeIntegrals with M^-1 = identity) and the representative mode's (lineIrradiance,
// the isotropic segment of the same lumens), over lengths 0.25..2 m, centres 0, 30, 60 and 80
// degrees off the normal, axes across the plane of incidence, in it, end-on and 15 degrees off
// end-on (centre 1 m away; end-on, the nearer cap 0.5 m away).
struct DiffuseError {
    double worst = -1.0, mean = 0.0;
    std::string where;
};

std::array<DiffuseError, 2> diffuseSweep(ReportContext& context, double radius,
                                         const std::vector<double>& lengths, double spacing) {
    std::vector<ValueSample> samples;
    std::vector<double> references;
    std::vector<std::string> labels;
    const char* axisNames[] = {"across", "in the plane of incidence", "end-on",
                               "15 deg off end-on"};
    for (double length : lengths) {
        for (double elevation : {0.0, 30.0, 60.0, 80.0}) {
            const double theta = elevation * kPi / 180.0;
            const Vec3 toward = {std::sin(theta), 0.0, std::cos(theta)};
            const Vec3 inPlane = {std::cos(theta), 0.0, -std::sin(theta)};
            const double tilt = 15.0 * kPi / 180.0;
            const Vec3 axes[] = {kLightAlong, inPlane, toward,
                                 std::cos(tilt) * toward + std::sin(tilt) * kLightAlong};
            for (int a = 0; a < 4; ++a) {
                const double distance = a >= 2 ? 0.5 + 0.5 * length + radius : 1.0;
                const Vec3 centre = distance * toward;
                ValueSample s;
                s.a = {float(centre[0]), float(centre[1]), float(centre[2]), float(radius)};
                s.b = {0.0f, 0.0f, 1.0f, float(length)};
                s.c = {0.0f, float(axes[a][0]), float(axes[a][1]), float(axes[a][2])};
                samples.push_back(s);
                references.push_back(
                    capsuleIrradianceReference(centre, axes[a], length, radius, spacing));
                char text[96];
                std::snprintf(text, sizeof(text), "length %.2f m, %.0f deg off N, axis %s", length,
                              elevation, axisNames[a]);
                labels.push_back(text);
            }
        }
    }
    const auto device = evaluateOnDevice(context.harness, ValueFunction::TubeDiffuse, samples);
    std::array<DiffuseError, 2> out;
    for (size_t i = 0; i < samples.size(); ++i) {
        for (int m = 0; m < 2; ++m) {
            const double error = std::fabs(device[i][m] / references[i] - 1.0);
            out[m].mean += error / double(samples.size());
            if (error > out[m].worst) {
                out[m].worst = error;
                out[m].where = labels[i];
            }
        }
    }
    return out;
}

std::string percent(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f %%", 100.0 * value);
    return text;
}

// The table of one shape: a row per roughness, "representative / ltc" per size.
ReportTable sweepTable(const ShapeSweep& s, const std::vector<std::string>& sizeLabels) {
    ReportTable table;
    table.header = {"roughness"};
    for (const std::string& label : sizeLabels)
        table.header.push_back(label);
    for (size_t r = 0; r < s.ltc.cells.size(); ++r) {
        std::vector<std::string> row = {formatNumber(kAreaLightRoughness[r])};
        for (size_t c = 0; c < s.ltc.cells[r].size(); ++c) {
            row.push_back(percent(s.representative.cells[r][c]) + " / " +
                          percent(s.ltc.cells[r][c]));
        }
        table.rows.push_back(row);
    }
    return table;
}

HeatMap heatMap(const std::string& title, const ModeSweep& mode,
                const std::vector<std::string>& sizeLabels, const std::string& sizeAxis) {
    HeatMap map;
    map.title = title;
    map.xAxis = sizeAxis;
    map.yAxis = "roughness";
    map.columns = sizeLabels;
    for (double roughness : kAreaLightRoughness)
        map.rows.push_back(formatNumber(roughness));
    map.values = mode.cells;
    return map;
}

}  // namespace

void addLtcAreaLightRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const int sphereGrid = quick ? 96 : 480;
    const int tubeSamples = quick ? 4096 : 65536;
    const uint32_t iterations = context.budget.iterations(4096);
    std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::PointLight, iterations},
        {CostFunction::SphereRepresentative, iterations},
        {CostFunction::SphereLtc, iterations},
        {CostFunction::TubeRepresentative, iterations},
        {CostFunction::TubeLtc, iterations},
        {CostFunction::TubeCapsuleLtc, iterations},
        {CostFunction::TubeSegmentLtc, iterations},
        {CostFunction::TubeCapsuleLtcShading, iterations},
        {CostFunction::TubeRepresentativeShading, iterations},
        {CostFunction::PointLightShading, iterations},
    });
    // Diffuse + specular against a point light's diffuse + specular.
    auto relativeShadingCost = [&](const Cost& c) {
        std::string text =
            formatShaderCost(c) + " diffuse + specular vs point light " + formatShaderCost(ns[9]);
        if (c.ns > c.spread && ns[9].ns > ns[9].spread) {
            text += " (" + formatNumber(c.ns / ns[9].ns) + "x the point light)";
        }
        return text;
    };
    // "x ns vs point light y ns (r x)": cost relative to a point light shaded the same way.
    auto relativeCost = [&](const Cost& c) {
        std::string text = formatShaderCost(c) + " vs point light " + formatShaderCost(ns[0]);
        if (c.ns > c.spread && ns[0].ns > ns[0].spread) {
            text += " (" + formatNumber(c.ns / ns[0].ns) + "x the point light)";
        }
        return text;
    };
    auto measuredNs = [](const Cost& c) { return c.ns > c.spread ? c.ns : 0.0; };

    const std::vector<double> sinSigma = {0.05, 0.1, 0.2, 0.4};
    const std::vector<double> lengths = {0.25, 0.5, 1.0, 2.0};
    const ShapeSweep sphere = sweep(context, true, sinSigma, sphereGrid);
    const ShapeSweep tube = sweep(context, false, lengths, tubeSamples);

    std::vector<std::string> sphereLabels, tubeLabels;
    for (double s : sinSigma) {
        char text[64];
        std::snprintf(text, sizeof(text), "sin(sigma) %.2f (%.3f sr)", s,
                      2.0 * kPi * (1.0 - std::sqrt(1.0 - s * s)));
        sphereLabels.push_back(text);
    }
    for (double length : lengths) {
        char text[64];
        std::snprintf(text, sizeof(text), "length %.2f m (%.0f deg)", length,
                      2.0 * std::atan(0.5 * length) * 180.0 / kPi);
        tubeLabels.push_back(text);
    }

    const std::string reference = "energy-conserving specular integrated over the light (double)";
    auto metric = [](const ModeSweep& m, const char* grid) {
        return std::string("relative L1 over 6 views, worst cell of ") + grid + "; mean cell " +
               percent(m.mean) + ", worst single view " + percent(m.worstView);
    };
    const char* sphereGridText = "roughness 0.1..1 x sin(sigma) 0.05..0.4";
    const char* tubeGridText = "roughness 0.1..1 x length 0.25..2 m at 1 m";
    ReportRow rows[] = {
        {"Sphere light, --area-lights representative (eq. 10-14, correlated Smith)", reference,
         metric(sphere.representative, sphereGridText), sphere.representative.worst, "rel",
         sphere.representative.where, relativeCost(ns[1]), measuredNs(ns[1])},
        {"Sphere light, --area-lights ltc (disk facing the point)", reference,
         metric(sphere.ltc, sphereGridText), sphere.ltc.worst, "rel", sphere.ltc.where,
         relativeCost(ns[2]), measuredNs(ns[2])},
        {"Tube light, --area-lights representative (eq. 16-20, correlated Smith)", reference,
         metric(tube.representative, tubeGridText), tube.representative.worst, "rel",
         tube.representative.where, relativeCost(ns[3]), measuredNs(ns[3])},
        {"Tube light of radius 0, --area-lights ltc (Lambertian line) against the isotropic "
         "segment",
         reference, metric(tube.ltc, tubeGridText), tube.ltc.worst, "rel", tube.ltc.where,
         relativeCost(ns[4]), measuredNs(ns[4])},
    };
    for (ReportRow& row : rows)
        context.report.rows.push_back(row);

    // Tubes of real radius against the Lambertian capsule (radius / distance 0.02, 0.1, 0.3).
    const double capsuleSpacingScale = quick ? 4.0 : 1.0;
    const std::string capsuleReference =
        "energy-conserving specular integrated over the Lambertian capsule (cylinder + 2 "
        "hemispherical caps, the tube's lumens over its area; double)";
    for (double radius : {0.02, 0.1, 0.3}) {
        const CapsuleSweep capsule = capsuleSweep(context, radius, lengths, capsuleSpacingScale);
        char label[64];
        std::snprintf(label, sizeof(label), "Tube light of radius %.2f m", radius);
        const std::string name = label;
        const ReportRow capsuleRows[] = {
            {name + ", --area-lights representative (eq. 16-20 + sphere widening)",
             capsuleReference, metric(capsule.representative, tubeGridText),
             capsule.representative.worst, "rel", capsule.representative.where, relativeCost(ns[3]),
             measuredNs(ns[3])},
            {name + ", bare segment LTC (ltcLineIntegral: the tube before the capsule)",
             capsuleReference, metric(capsule.segment, tubeGridText), capsule.segment.worst, "rel",
             capsule.segment.where, relativeCost(ns[6]), measuredNs(ns[6])},
            {name + ", --area-lights ltc (ltcTubeIntegral: the cone's outline, tangent edges + cap "
                    "arcs; x ltcTubeLobeCorrection)",
             capsuleReference, metric(capsule.capsule, tubeGridText), capsule.capsule.worst, "rel",
             capsule.capsule.where, relativeCost(ns[5]), measuredNs(ns[5])},
        };
        for (const ReportRow& row : capsuleRows)
            context.report.rows.push_back(row);
        const auto diffuse = diffuseSweep(context, radius, lengths, quick ? 0.02 : 0.005);
        const std::string diffuseReference =
            "irradiance integrated over the Lambertian capsule (the tube's lumens over its area; "
            "double)";
        const std::string diffuseGrid =
            "relative error, worst of length 0.25..2 m x centre 0..80 deg off N x axis across, "
            "in the plane, end-on, 15 deg off end-on; mean ";
        const ReportRow diffuseRows[] = {
            {name + ", --area-lights representative, diffuse (lineIrradiance: the isotropic "
                    "segment)",
             diffuseReference, diffuseGrid + percent(diffuse[1].mean), diffuse[1].worst, "rel",
             diffuse[1].where, relativeShadingCost(ns[8]), measuredNs(ns[8])},
            {name + ", --area-lights ltc, diffuse (ltcTubeIntegrals, M^-1 = identity: the "
                    "capsule's irradiance)",
             diffuseReference, diffuseGrid + percent(diffuse[0].mean), diffuse[0].worst, "rel",
             diffuse[0].where, relativeShadingCost(ns[7]), measuredNs(ns[7])},
        };
        for (const ReportRow& row : diffuseRows)
            context.report.rows.push_back(row);
        ReportTable table;
        table.title = name + ": representative / bare segment LTC / capsule LTC";
        table.header = {"roughness"};
        for (const std::string& text : tubeLabels)
            table.header.push_back(text);
        for (size_t r = 0; r < capsule.capsule.cells.size(); ++r) {
            std::vector<std::string> row = {formatNumber(kAreaLightRoughness[r])};
            for (size_t c = 0; c < capsule.capsule.cells[r].size(); ++c) {
                row.push_back(percent(capsule.representative.cells[r][c]) + " / " +
                              percent(capsule.segment.cells[r][c]) + " / " +
                              percent(capsule.capsule.cells[r][c]));
            }
            table.rows.push_back(row);
        }
        table.intro =
            "The tube grid (centre 1 m away, 30 degrees off the normal, axis across the plane of "
            "incidence, six views) for a tube of this radius, against the Lambertian capsule of "
            "the same lumens (luminance lumens / (pi A)), integrated by midpoint quadrature over "
            "its surface (points a quarter of the lobe width apart, at most 2 cm" +
            std::string(quick ? ", 4x coarser in --quick" : "") +
            "). Cell: relative L1 over the views.";
        context.report.tables.push_back(table);
    }

    context.report.notes.push_back(
        "Area-light cost anchor (issue 15): Drobot's PS4 ALU counts for Killzone Shadow Fall's "
        "lights, point 222, sphere 252 (1.14x), disk 361 (1.63x), rectangle 382 (1.72x), "
        "textured rectangle 405 (1.82x). The LTC rows' device times exclude the table fetch (two "
        "texture reads in a renderer; the report passes M^-1 in).");
    ReportTable sphereTable = sweepTable(sphere, sphereLabels);
    sphereTable.title = "Sphere lights: representative point / LTC, energy-conserving BRDF";
    sphereTable.intro =
        "The sphere-light geometry and views of the representative-point table, shaded with the "
        "energy-conserving BRDF's lobe (height-correlated Smith, F = 1). Cell: relative L1 error "
        "over the six views, representative point / LTC (the disk through the centre facing the "
        "point, the table's M^-1 and magnitude read bilinearly on the host). Reference: " +
        std::to_string(sphereGrid) + "^2-point quadrature over the cone in double.";
    context.report.tables.push_back(sphereTable);
    ReportTable tubeTable = sweepTable(tube, tubeLabels);
    tubeTable.title = "Tube lights: representative point / LTC, energy-conserving BRDF";
    tubeTable.intro =
        "The tube geometry and views of the representative-point table, energy-conserving lobe. "
        "Cell: relative L1 error over the six views, representative point / LTC (ltcTubeIntegral "
        "at radius 0: the thin Lambertian tube's closed-form line, 4 / pi brighter across the "
        "axis than this isotropic reference; the capsule tables below measure it against the "
        "light it stands for). Reference: " +
        std::to_string(tubeSamples) + " midpoints along the segment in double.";
    context.report.tables.push_back(tubeTable);

    const std::pair<const char*, const ModeSweep*> maps[] = {
        {"sphere_representative", &sphere.representative},
        {"sphere_ltc", &sphere.ltc},
        {"tube_representative", &tube.representative},
        {"tube_ltc", &tube.ltc},
    };
    for (const auto& [name, mode] : maps) {
        const bool isSphere = std::string(name).rfind("sphere", 0) == 0;
        const std::string title =
            std::string(isSphere ? "Sphere" : "Tube") + " light, " +
            (std::string(name).find("ltc") != std::string::npos ? "--area-lights ltc"
                                                                : "--area-lights representative") +
            ": specular relative L1 error";
        context.report.figures.push_back(
            {std::string("area_light_") + name + ".svg", title,
             heatMapSvg(heatMap(title, *mode, isSphere ? sphereLabels : tubeLabels,
                                isSphere ? "sphere size" : "tube length"))});
    }
}

}  // namespace candela::report
