// Rows: rect and disk lights (issue 15, render/shaders/common/area_lights.glsl), Drobot's (2014,
// GPU Pro 5, "Physically Based Area Lights") representative point and the LTC mode, diffuse and
// specular against the same BRDF integrated over the light in double, on a grid of roughness x
// light size x view; cost against a point light's shading on the device.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include "../stability/brdf_reference.h"
#include "../stability/light_reference.h"
#include "report_context.h"
#include "shader_cost.h"
#include "shaders/area_shape_values.comp.spv.h"
#include "svg_figures.h"

#include "../../../render/ltc/ltc_ggx_table.inc"

namespace candela::report {

namespace {

namespace ref = stability::reference;
using Vec3 = ref::Vec3;
using ref::operator+;
using ref::operator-;
using ref::operator*;
constexpr double kPi = std::numbers::pi;

Vec3 unit(const Vec3& v) {
    return (1.0 / ref::length(v)) * v;
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The light's centre 1 m away, 30 degrees from the normal N = +Z, facing the surface point.
constexpr double kElevation = kPi / 6.0;
const Vec3 kCentre = {std::sin(kElevation), 0.0, std::cos(kElevation)};
const Vec3 kAcross = {std::cos(kElevation), 0.0, -std::sin(kElevation)};  // the light's X
const Vec3 kNormal = {-kCentre[0], -kCentre[1], -kCentre[2]};             // emitting side
const Vec3 kAxisY = cross(kAcross, kNormal);                              // the light's Y
constexpr double kRoughness[] = {0.1, 0.25, 0.5, 0.75, 1.0};
constexpr double kSizes[] = {0.1, 0.3, 0.6, 1.2};  // rect side, disk diameter (m at 1 m)

// The view whose mirror direction leaves the centre by `across` and `along` radians.
Vec3 viewFor(double across, double along) {
    const Vec3 R = unit(kCentre + std::tan(across) * kAcross + std::tan(along) * kAxisY);
    return {-R[0], -R[1], R[2]};
}

// R through the centre, 0.5, 1 and 2 half-sizes off it in the plane of incidence, 0.5 and 1.5
// across it; views under 0.1 above the horizon (R past grazing for the largest light) left out.
std::vector<std::array<double, 2>> viewsFor(double size) {
    const double half = std::atan(0.5 * size);
    std::vector<std::array<double, 2>> views;
    for (const std::array<double, 2>& v : std::initializer_list<std::array<double, 2>>{
             {0, 0}, {0.5 * half, 0}, {half, 0}, {2 * half, 0}, {0, 0.5 * half}, {0, 1.5 * half}}) {
        if (viewFor(v[0], v[1])[2] >= 0.1) views.push_back(v);
    }
    return views;
}

// The textured rect's images (shaders/report_light_texture.glsl), in the rect's (u, v): image 1
// quadrants of luminance (u < 1/2 ? 1.5 : 0.5) x (v < 1/2 ? 1.5 : 0.5); image 2 the same steps
// (contrast 3, average 1) at 0.35, off the halves where every mip level has a texel edge.
double reportTexture(int image, double u, double v) {
    const double cut = image == 2 ? 0.35 : 0.5;
    const double lo = 1.0 / (1.0 + 2.0 * cut);
    return (u < cut ? 3.0 * lo : lo) * (v < cut ? 3.0 * lo : lo);
}

// Diffuse irradiance and specular D Vis(height-correlated Smith) NoL, F0 = 1, per unit
// luminance, integrated over the light by the midpoint rule (n x n points: the rect's grid, the
// disk's radius x angle); a textured rect's luminance times its image `image` at each point (n
// a multiple of 20: no point on either image's edges). A constant-intensity light (Drobot's
// variant): per unit intensity per square metre, the luminance towards the point 1 / cos
// theta_o.
std::array<double, 2> reference(bool disk, int image, bool constantIntensity, double size,
                                const Vec3& V, double alpha, int n) {
    double diffuse = 0.0, specular = 0.0;
    const double half = 0.5 * size;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double u, v, area;
            if (disk) {
                const double r = (i + 0.5) / n * half, phi = (j + 0.5) / n * 2.0 * kPi;
                u = r * std::cos(phi), v = r * std::sin(phi);
                area = r * (half / n) * (2.0 * kPi / n);
            } else {
                u = ((i + 0.5) / n - 0.5) * size, v = ((j + 0.5) / n - 0.5) * size;
                area = (size / n) * (size / n);
            }
            if (image > 0) area *= reportTexture(image, (i + 0.5) / n, (j + 0.5) / n);
            const Vec3 p = kCentre + u * kAcross + v * kAxisY;
            const double distanceSq = ref::dot(p, p);
            const Vec3 L = unit(p);
            const double cosLight = -ref::dot(L, kNormal);
            const double NoL = L[2];
            if (cosLight <= 0.0 || NoL <= 0.0) continue;
            const double luminance = constantIntensity ? 1.0 / cosLight : 1.0;
            const double solidAngle = luminance * area * cosLight / distanceSq;
            diffuse += NoL * solidAngle;
            if (V[2] > 0.0) {
                const Vec3 H = unit(V + L);
                specular += ref::ggxDistribution(alpha, H[2]) *
                            ref::smithGgxCorrelatedVisibility(alpha, V[2], NoL) * NoL * solidAngle;
            }
        }
    }
    return {diffuse, specular};
}

struct AreaShapeSample {
    std::array<float, 4> a{}, b{}, c{}, d{};
};

enum Mode { kRepresentative = 0, kRepresentativeUnclamped = 1, kLtc = 2 };

std::vector<std::array<float, 2>> evaluate(stability::ComputeHarness& harness,
                                           const std::vector<AreaShapeSample>& samples) {
    std::vector<std::array<float, 4>> table;
    for (const auto& cell : kLtcTable) {
        table.push_back({cell[0], cell[1], cell[2], cell[3]});
        table.push_back({cell[4], cell[5], 0.0f, 0.0f});
    }
    render::GpuBuffer in = harness.upload(std::span<const AreaShapeSample>(samples));
    render::GpuBuffer tableBuffer = harness.upload(std::span<const std::array<float, 4>>(table));
    render::GpuBuffer out = harness.buffer(samples.size() * sizeof(float) * 2);
    render::Pipeline pipeline = harness.pipeline(area_shape_values_comp_spv, 3, 8);
    const std::array<uint32_t, 2> job = {0u, uint32_t(samples.size())};
    harness.dispatch(pipeline, {&in, &out, &tableBuffer}, job.data(), sizeof(job),
                     uint32_t((samples.size() + 63) / 64));
    return harness.read<std::array<float, 2>>(out, samples.size());
}

struct Errors {
    double worst = -1.0, sum = 0.0;
    int cells = 0;
    std::string where;
    void add(double e, const std::string& at) {
        sum += e;
        ++cells;
        if (!(e <= worst)) worst = e, where = at;
    }
    std::string text() const {
        char t[96];
        std::snprintf(t, sizeof(t), "max %.1f %%, mean %.1f %%", 100.0 * worst,
                      100.0 * sum / std::max(cells, 1));
        return t;
    }
};

}  // namespace

void addAreaLightShapeRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const int grid = quick ? 60 : 320;
    struct Variant {
        const char* name;
        bool disk;
        Mode mode;
        int image = 0;  // a textured rect's image (reportTexture); 0 untextured
        // A constant-intensity light (its own reference); `factors`: shaded with Drobot's
        // pre-integrated factors (else as a Lambertian light of luminance I_A, to show what the
        // factors buy).
        bool constantIntensity = false;
        bool factors = false;
    };
    const Variant variants[] = {
        {"Rect light: representative point (Drobot 2014, GPU Pro 5)", false, kRepresentative},
        {"Rect light: representative, unclamped p' / p'' (diffuse)", false,
         kRepresentativeUnclamped},
        {"Rect light: LTC (polygon integral, fitted specular)", false, kLtc},
        {"Disk light: representative point (Drobot 2014, GPU Pro 5)", true, kRepresentative},
        {"Disk light: representative, unclamped p' / p'' (diffuse)", true,
         kRepresentativeUnclamped},
        {"Disk light: LTC (Heitz-Hill disk integral, fitted specular)", true, kLtc},
        {"Textured rect light: representative point, image at the sample", false, kRepresentative,
         1},
        {"Textured rect light: LTC, exact integral per image cell (8 x 8 specular, 4 x 4 diffuse)",
         false, kLtc, 1},
        {"Constant-intensity rect light: representative point x pre-integrated factors (Drobot "
         "2014, GPU Pro 5)",
         false, kRepresentative, 0, true, true},
        {"Constant-intensity rect light: LTC x pre-integrated factors", false, kLtc, 0, true, true},
        {"Constant-intensity rect light: representative point without the factors (luminance "
         "I_A)",
         false, kRepresentative, 0, true, false},
        {"Constant-intensity disk light: representative point x pre-integrated factors (Drobot "
         "2014, GPU Pro 5)",
         true, kRepresentative, 0, true, true},
        {"Constant-intensity disk light: LTC x pre-integrated factors", true, kLtc, 0, true, true},
        // The textured rows again on an image whose edges fall off the halves, where the mip
        // chain's texels have edges at every level: nothing tuned to the first image's cut.
        {"Textured rect light (steps at 0.35): representative point, image at the sample", false,
         kRepresentative, 2},
        {"Textured rect light (steps at 0.35): LTC, exact integral per image cell (8 x 8 specular, "
         "4 x 4 diffuse)",
         false, kLtc, 2},
    };
    // Which reference set a variant reads: rect, disk, textured rect, constant-intensity rect
    // and disk (in the order of their first, representative, variants).
    const auto referenceSet = [](const Variant& v) {
        if (v.constantIntensity) return v.disk ? 4 : 3;
        if (v.image == 2) return 5;
        return v.image == 1 ? 2 : v.disk ? 1 : 0;
    };
    // The references, once per shape: [disk][roughness][size][view] -> (diffuse, specular).
    std::vector<AreaShapeSample> samples;
    std::vector<std::array<double, 2>> references;
    int setsDone = 0;
    for (const Variant& variant : variants) {
        const bool firstOfSet = referenceSet(variant) == setsDone;  // computes the set
        for (double roughness : kRoughness) {
            for (double size : kSizes) {
                for (const auto& view : viewsFor(size)) {
                    const Vec3 V = viewFor(view[0], view[1]);
                    AreaShapeSample s;
                    s.a = {float(kCentre[0]), float(kCentre[1]), float(kCentre[2]),
                           variant.disk ? 1.0f : 0.0f};
                    s.b = {float(V[0]), float(V[1]), float(V[2]), float(roughness)};
                    s.c = {float(kAcross[0]), float(kAcross[1]), float(kAcross[2]),
                           float(0.5 * size)};
                    s.d = {float(0.5 * size), float(variant.mode), float(variant.image),
                           variant.factors ? 1.0f : 0.0f};
                    samples.push_back(s);
                    if (firstOfSet) {
                        references.push_back(reference(variant.disk, variant.image,
                                                       variant.constantIntensity, size, V,
                                                       ref::alphaFromRoughness(roughness), grid));
                    }
                }
            }
        }
        if (firstOfSet) ++setsDone;
    }
    const auto device = evaluate(context.harness, samples);

    const uint32_t iterations = context.budget.iterations(64);  // LTC: ~1 us each on lavapipe
    // The textured rect's LTC is 64 cell integrals per lobe (~40 us here): 4 iterations keep its
    // timing to seconds and each invocation under lavapipe's loop limiter (65,535 iterations of
    // every loop together; ~1,300 per evaluation).
    const uint32_t texturedLtcIterations = context.budget.iterations(4);
    const std::vector<Cost> ns = context.cost.nsPerEvaluation({
        {CostFunction::PointLightShading, iterations},
        {CostFunction::RectRepresentative, iterations},
        {CostFunction::RectLtc, iterations},
        {CostFunction::DiskRepresentative, iterations},
        {CostFunction::DiskLtc, iterations},
        {CostFunction::TexturedRectRepresentative, iterations},
        {CostFunction::TexturedRectLtc, texturedLtcIterations},
        {CostFunction::RectRepresentativeConstantIntensity, iterations},
        {CostFunction::RectLtcConstantIntensity, iterations},
        {CostFunction::DiskRepresentativeConstantIntensity, iterations},
        {CostFunction::DiskLtcConstantIntensity, iterations},
    });
    const Cost* costOf[] = {&ns[1], &ns[1], &ns[2], &ns[3], &ns[3],  &ns[4], &ns[5], &ns[6],
                            &ns[7], &ns[8], &ns[1], &ns[9], &ns[10], &ns[5], &ns[6]};
    static_assert(std::size(costOf) == std::size(variants));

    ReportTable table;
    table.title = "Rect and disk lights: error by roughness and size";
    table.intro =
        "A rect (side s) or disk (diameter s) light centred 1 m from the surface, 30 degrees "
        "from its normal and facing it, for up to six views (R through the centre, 0.5, 1 and 2 "
        "half-sizes off it in the plane of incidence, 0.5 and 1.5 across it; views closer than "
        "0.1 to the horizon left out). Cell: relative L1 error over the views (sum |approx - "
        "reference| / sum reference), diffuse / specular. Reference: the same BRDF (GGX D, "
        "height-correlated Smith, F0 = 1) "
        "and the irradiance integrated over the light by the midpoint rule in double (" +
        std::to_string(grid) +
        "^2 points). LTC reads the checked-in table (fp32, bilinear). "
        "Textured rect: an image of four quadrants of luminance 2.25, 0.75, 0.75, 0.25 (average "
        "1) on the rect, and the same steps (contrast 3) at 0.35 of each side instead of 1/2, "
        "integrated times the BRDF over the light; the approximations read it pre-filtered over "
        "the lobe's footprint as the renderer's 256-texel mip chain holds it (aligned 2 x 2 box "
        "levels, bilinear, trilinear between levels; in closed form here). Constant-intensity "
        "lights (the variant in Drobot 2014, GPU Pro 5, \"Physically Based Area Lights\"; "
        "`emission` \"constantIntensity\"): every element radiates intensity I_A in "
        "every direction in front, so the luminance towards the point is I_A / cos theta_o; the "
        "reference integrates that, the approximations multiply the constant-luminance results "
        "by Drobot's pre-integrated factors (the mean of |x - P| / h over the light for "
        "diffuse, over the specular cone's intersection with it for specular, in closed form).";
    table.header = {"variant", "roughness"};
    for (double size : kSizes) {
        char text[64];
        std::snprintf(text, sizeof(text), "s = %.1f m", size);
        table.header.push_back(text);
    }
    // The heat maps (specular over roughness x size) for each shape and mode; none for
    // the unclamped diffuse variant or the constant-intensity lights.
    const char* const heatMapFiles[] = {"rect_representative",
                                        nullptr,
                                        "rect_ltc",
                                        "disk_representative",
                                        nullptr,
                                        "disk_ltc",
                                        "textured_rect_representative",
                                        "textured_rect_ltc",
                                        nullptr,
                                        nullptr,
                                        nullptr,
                                        nullptr,
                                        nullptr,
                                        "textured_rect_steps_035_representative",
                                        "textured_rect_steps_035_ltc"};
    static_assert(std::size(heatMapFiles) == std::size(variants));
    const size_t perVariant = samples.size() / std::size(variants);
    for (size_t v = 0; v < std::size(variants); ++v) {
        const Variant& variant = variants[v];
        const size_t shapeBase = size_t(referenceSet(variant)) * perVariant;
        Errors diffuse, specular;
        HeatMap map;
        map.title = std::string(variant.name) + ": specular relative L1 error";
        map.xAxis = variant.disk ? "disk diameter at 1 m" : "rect side at 1 m";
        map.yAxis = "roughness";
        for (double size : kSizes)
            map.columns.push_back(formatNumber(size) + " m");
        size_t k = 0;
        for (double roughness : kRoughness) {
            map.rows.push_back(formatNumber(roughness));
            map.values.emplace_back();
            std::vector<std::string> row = {variant.name, formatNumber(roughness)};
            for (double size : kSizes) {
                double diffuseError = 0, diffuseSum = 0, specularError = 0, specularSum = 0;
                for (size_t view = 0; view < viewsFor(size).size(); ++view, ++k) {
                    const auto& r = references[shapeBase + k];
                    const auto& a = device[v * perVariant + k];
                    diffuseError += std::fabs(a[0] - r[0]);
                    diffuseSum += r[0];
                    specularError += std::fabs(a[1] - r[1]);
                    specularSum += r[1];
                }
                char at[96];
                std::snprintf(at, sizeof(at), "roughness %.2f, size %.1f m at 1 m", roughness,
                              size);
                const double d = diffuseError / diffuseSum, s = specularError / specularSum;
                diffuse.add(d, at);
                map.values.back().push_back(s);
                if (variant.mode != kRepresentativeUnclamped) specular.add(s, at);
                char cell[64];
                std::snprintf(cell, sizeof(cell), "%.1f %% / %.1f %%", 100.0 * d, 100.0 * s);
                row.push_back(cell);
            }
            if (variant.mode != kRepresentativeUnclamped) table.rows.push_back(row);
        }
        // Cost relative to a point light (its incidence + GGX along one direction).
        std::string cost =
            formatShaderCost(*costOf[v]) + " vs point light " + formatShaderCost(ns[0]);
        if (costOf[v]->ns > costOf[v]->spread && ns[0].ns > ns[0].spread) {
            char ratio[48];
            std::snprintf(ratio, sizeof(ratio), " (%.1fx a point light)", costOf[v]->ns / ns[0].ns);
            cost += ratio;
        }
        context.report.rows.push_back(
            {std::string(variant.name) + ", diffuse",
             "irradiance integrated over the light (double)",
             "relative L1 over the views; roughness 0.1..1 x size 0.1..1.2 m at 1 m: " +
                 diffuse.text(),
             diffuse.worst, "rel", diffuse.where, cost});
        if (variant.mode != kRepresentativeUnclamped) {
            context.report.rows.push_back(
                {std::string(variant.name) + ", specular",
                 "specular integrated over the light (double)",
                 "relative L1 over the views; roughness 0.1..1 x size 0.1..1.2 m at 1 m: " +
                     specular.text(),
                 specular.worst, "rel", specular.where, cost});
        }
        if (heatMapFiles[v] != nullptr) {
            context.report.figures.push_back({std::string("area_light_") + heatMapFiles[v] + ".svg",
                                              map.title, heatMapSvg(map)});
        }
    }
    context.report.tables.push_back(table);
}

}  // namespace candela::report
