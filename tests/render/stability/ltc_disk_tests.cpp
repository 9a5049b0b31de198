// The shared LTC disk integral (render/shaders/common/ltc_disk.glsl) on the device: with
// M^-1 = identity it is the diffuse form factor of the disk, checked against the closed form for
// disks parallel to the floor; with the checked-in table's M^-1 it is the transformed cosine's
// integral over the disk, checked against quadrature of that density; disks below the horizon
// or seen from behind give exactly 0 (issue 15).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <vector>

#include "error_stats.h"
#include "form_factors.h"
#include "light_accuracy.h"
#include "ltc_fit.h"
#include "ltc_ggx_table.inc"

using namespace candela::stability;
using candela::ltc::Vec3;

namespace {

constexpr double kPi = std::numbers::pi;

struct Disk {
    Vec3 center, u, v;  // lit side towards u x v
};

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// Midpoint quadrature over the disk's area (n rings x 4n sectors) of density(w) dw, dw =
// cos(emitter) dA / d^2, one-sided (only where the point sees the lit side).
double integrateOverDisk(const Disk& d, int n, const std::function<double(const Vec3&)>& density) {
    const Vec3 normal = cross(d.u, d.v);
    const double area = std::sqrt(dot(normal, normal));  // |u x v|: the area is pi |u x v|
    double sum = 0.0;
    const int sectors = 4 * n;
    for (int i = 0; i < n; ++i) {
        const double r0 = double(i) / n, r1 = double(i + 1) / n;
        const double rMid = std::sqrt(0.5 * (r0 * r0 + r1 * r1));  // splits the ring's area
        const double ringArea = kPi * (r1 * r1 - r0 * r0) * area / sectors;
        for (int j = 0; j < sectors; ++j) {
            const double t = 2.0 * kPi * (j + 0.5) / sectors;
            const double c = rMid * std::cos(t), s = rMid * std::sin(t);
            const Vec3 p{d.center.x + c * d.u.x + s * d.v.x, d.center.y + c * d.u.y + s * d.v.y,
                         d.center.z + c * d.u.z + s * d.v.z};
            const double d2 = dot(p, p);
            const double cosEmitter = -dot(p, normal) / (area * std::sqrt(d2));
            if (cosEmitter <= 0.0) continue;
            const double invLength = 1.0 / std::sqrt(d2);
            const Vec3 w{p.x * invLength, p.y * invLength, p.z * invLength};
            sum += density(w) * cosEmitter / d2 * ringArea;
        }
    }
    return sum;
}

double clampedCosine(const Vec3& w) {
    return w.z > 0.0 ? w.z / kPi : 0.0;
}

// Whether the ray from the origin along w crosses the disk (orthogonal u, v of equal length).
bool rayHitsDisk(const Vec3& w, const Disk& d) {
    const Vec3 n = cross(d.u, d.v);
    const double wn = dot(w, n);
    if (wn == 0.0) return false;
    const double t = dot(d.center, n) / wn;
    if (t <= 0.0) return false;
    const Vec3 p{t * w.x - d.center.x, t * w.y - d.center.y, t * w.z - d.center.z};
    const double x = dot(p, d.u) / dot(d.u, d.u), y = dot(p, d.v) / dot(d.v, d.v);
    return x * x + y * y <= 1.0;
}

// The transformed cosine's mass over the disk: the fraction of its n x n stratified samples
// (importance sampling by the lobe itself, so sharp lobes are resolved) whose ray hits it.
double lobeMassOverDisk(const candela::ltc::TransformedCosine& lobe, const Disk& d, int n) {
    long hits = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            hits += rayHitsDisk(lobe.sample((i + 0.5) / n, (j + 0.5) / n), d) ? 1 : 0;
    }
    return double(hits) / (double(n) * n);
}

LightSample diskSample(const Disk& d, const std::array<double, 4>& inverse) {
    LightSample s;
    s.a = {float(d.center.x), float(d.center.y), float(d.center.z), float(inverse[0])};
    s.b = {float(d.u.x), float(d.u.y), float(d.u.z), float(inverse[1])};
    s.c = {float(d.v.x), float(d.v.y), float(d.v.z), float(inverse[2])};
    s.d = {0.0f, 0.0f, 0.0f, float(inverse[3])};
    return s;
}

constexpr std::array<double, 4> kIdentity = {1.0, 0.0, 0.0, 1.0};

// A disk of radius r centred at c, facing the origin (lit side towards it).
Disk facingOrigin(const Vec3& c, double r) {
    const double length = std::sqrt(dot(c, c));
    const Vec3 toward{-c.x / length, -c.y / length, -c.z / length};
    // Any unit vector across `toward`, then u x v = toward.
    const Vec3 helper = std::fabs(toward.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    Vec3 u = cross(helper, toward);
    const double ul = std::sqrt(dot(u, u));
    u = {u.x / ul, u.y / ul, u.z / ul};
    const Vec3 v = cross(toward, u);
    return Disk{c, {u.x * r, u.y * r, u.z * r}, {v.x * r, v.y * r, v.z * r}};
}

}  // namespace

// Ceiling disks 1 cm to 40 m across at heights 5 cm to 10 m, straight above the point and off
// to the side: within 1e-5 relative of the closed form where the disk covers at least 1e-3 of
// the hemisphere's cosine (measured 2.1e-7), and within 1e-6 absolute everywhere (1.4e-7).
TEST(LtcDisk, DiffuseDiskMatchesTheClosedForm) {
    ComputeHarness harness;
    std::vector<LightSample> samples;
    std::vector<double> reference;
    for (double h : {0.05, 0.5, 2.0, 10.0}) {
        for (double r : {0.005, 0.3, 1.0, 4.0, 20.0}) {
            for (double offset : {0.0, 0.4, 1.5, 6.0}) {
                // Lit side down: u x v = -z.
                const Disk d{{offset, 0.3 * offset, h}, {r, 0, 0}, {0, -r, 0}};
                samples.push_back(diskSample(d, kIdentity));
                reference.push_back(
                    parallelDiskFormFactor(r, h, offset * std::sqrt(1.0 + 0.3 * 0.3)));
            }
        }
    }
    const auto values = evaluateOnDevice(harness, LightFunction::LtcDisk, samples);
    WorstError relative;
    WorstError absolute;
    for (size_t i = 0; i < samples.size(); ++i) {
        absolute.add(std::fabs(values[i][0] - reference[i]), [&] {
            return "value " + std::to_string(values[i][0]) + " reference " +
                   std::to_string(reference[i]) + " case " + std::to_string(i);
        });
        if (reference[i] < 1e-3) continue;
        relative.add(std::fabs(values[i][0] - reference[i]) / reference[i], [&] {
            return "value " + std::to_string(values[i][0]) + " reference " +
                   std::to_string(reference[i]) + " case " + std::to_string(i);
        });
    }
    relative.print("ltcDiskIntegral, identity", "relative");
    absolute.print("ltcDiskIntegral, identity", "absolute");
    EXPECT_LE(relative.error, 1e-5);
    EXPECT_LE(absolute.error, 1e-6);
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// Tilted disks (walls and disks facing the point) that cross the horizon: the equivalent
// sphere cap clips them approximately (Heitz and Hill 2017), held to the measured bound; disks
// wholly below the horizon, seen from behind, or edge-on give exactly 0.
TEST(LtcDisk, HorizonClippingLetsNoLightThroughFromBelow) {
    ComputeHarness harness;
    std::vector<Disk> disks;
    for (double d : {0.3, 1.0, 3.0}) {
        for (double z : {-0.5, -0.1, 0.0, 0.2, 0.8}) {
            // A wall at x = d facing the point (lit side -x): u x v = -x with u = y, v = z.
            for (double r : {0.25, 1.0})
                disks.push_back(Disk{{d, 0.2, z * r}, {0, -r, 0}, {0, 0, r}});
        }
    }
    const size_t straddling = disks.size();
    disks.push_back(Disk{{1, 0, -1.01}, {0, -1, 0}, {0, 0, 1}});  // wall wholly below
    disks.push_back(Disk{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}});       // ceiling seen from behind
    disks.push_back(Disk{{1, 0, 1}, {0, 1, 0}, {0, 0, 0.5}});     // wall seen from behind
    disks.push_back(Disk{{0, 0, 1}, {1, 0, 0}, {0, 0, 0.5}});     // edge-on
    // Specular M^-1 that tilts the lobe: a disk just below the horizon stays dark.
    const std::array<double, 4> tilted = {1.0, -0.6, 0.3, 0.5};
    std::vector<LightSample> samples;
    for (const Disk& d : disks)
        samples.push_back(diskSample(d, kIdentity));
    samples.push_back(diskSample(disks[straddling], tilted));
    const auto values = evaluateOnDevice(harness, LightFunction::LtcDisk, samples);
    WorstError relative;
    for (size_t i = 0; i < straddling; ++i) {
        const double reference = integrateOverDisk(disks[i], 300, clampedCosine);
        if (reference < 1e-3) {
            EXPECT_NEAR(values[i][0], reference, 2e-3) << "disk " << i;
            continue;
        }
        relative.add(std::fabs(values[i][0] - reference) / reference, [&] {
            return "disk " + std::to_string(i) + " value " + std::to_string(values[i][0]) +
                   " reference " + std::to_string(reference);
        });
    }
    relative.print("ltcDiskIntegral across the horizon", "relative");
    EXPECT_LE(relative.error, 0.25);
    for (size_t i = straddling; i < values.size(); ++i) {
        EXPECT_EQ(values[i][0], 0.0f) << "case " << i - straddling;
    }
    EXPECT_EQ(harness.validationMessages(), 0u);
}

// With the checked-in table's M^-1 (roughness 0.08 to 1, views 0 to 53 degrees), disks facing
// the point around the mirror direction and off it, 2 to 35 degrees of angular radius, above the
// horizon: the integral of the transformed cosine over the disk against the lobe's own mass
// there (600^2 stratified samples of it). Where the moved disk stays above the moved horizon the
// cone's form factor is exact; where it crosses it the equivalent cap clips it.
TEST(LtcDisk, SpecularMatchesTheTransformedCosinesIntegral) {
    using namespace candela::ltc;
    ComputeHarness harness;
    struct Case {
        int row, column;
        double reference;
        bool crossesMovedHorizon;
    };
    std::vector<Case> cases;
    std::vector<LightSample> samples;
    for (int row : {4, 32, 63}) {
        for (int column : {0, 20, 40}) {
            const auto& cell = kLtcTable[row * kLtcTableSize + column];
            const TableCell tableCell{cell[0], cell[1], cell[2], cell[3], cell[4], cell[5]};
            const TransformedCosine lobe =
                TransformedCosine::from(inverse(tableCell.inverseMatrix()));
            const double cosView = tableCosView(column, kLtcTableSize);
            const double sinView = std::sqrt(1.0 - cosView * cosView);
            for (double angle : {0.04, 0.2, 0.7}) {
                for (auto [offset, lift] : {std::pair{0.0, 0.2}, {0.25, 0.2}}) {
                    // Around the mirror direction (-sinView, 0, cosView), raised off the horizon.
                    Vec3 dir{-sinView + offset, 0.1, cosView + lift};
                    const double l = std::sqrt(dot(dir, dir));
                    dir = {dir.x / l, dir.y / l, dir.z / l};
                    const double distance = 2.0;
                    const double radius = distance * std::tan(angle);
                    if (dir.z * distance - radius <= 0.05) continue;  // keep it above
                    const Disk d = facingOrigin(
                        {dir.x * distance, dir.y * distance, dir.z * distance}, radius);
                    const double reference = lobeMassOverDisk(lobe, d, 600);
                    if (reference < 1e-3) continue;
                    samples.push_back(diskSample(d, {cell[0], cell[1], cell[2], cell[3]}));
                    // The moved disk's lowest point: does it dip under the moved horizon?
                    const Mat3 minv = tableCell.inverseMatrix();
                    const Vec3 c = minv * d.center, u = minv * d.u, v = minv * d.v;
                    const bool crosses = c.z - std::sqrt(u.z * u.z + v.z * v.z) < 0.0;
                    cases.push_back({row, column, reference, crosses});
                }
            }
        }
    }
    const auto values = evaluateOnDevice(harness, LightFunction::LtcDisk, samples);
    // The reference counts lobe samples: under ~2 % of them (7,200 hits) its own noise reaches
    // the per-mille level, so those disks are held to a looser bound. (These disks stay above
    // the moved horizon; LtcDisk.HorizonClipping* measures the crossing ones.)
    WorstError above, aboveSmall, crossing;
    double sum = 0.0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const double e = std::fabs(values[i][0] - cases[i].reference) / cases[i].reference;
        sum += e;
        WorstError& bucket = cases[i].crossesMovedHorizon ? crossing
                             : cases[i].reference >= 0.02 ? above
                                                          : aboveSmall;
        bucket.add(e, [&] {
            char text[160];
            std::snprintf(text, sizeof text, "row %d column %d: ltc %.5f lobe %.5f", cases[i].row,
                          cases[i].column, values[i][0], cases[i].reference);
            return std::string(text);
        });
    }
    above.print("ltcDiskIntegral, moved disk above", "relative");
    aboveSmall.print("ltcDiskIntegral, above, mass < 2 %", "relative");
    crossing.print("ltcDiskIntegral, moved disk crossing", "relative");
    std::printf("  mean relative error %.2e over %zu disks\n", sum / double(cases.size()),
                cases.size());
    EXPECT_GT(above.count, 20);  // measured: 28
    EXPECT_LE(above.error, 5e-3);
    EXPECT_LE(aboveSmall.error, 0.08);  // the reference's own noise: 4.6 % measured at 0.15 %
    EXPECT_LE(crossing.error, 0.25);
    EXPECT_EQ(harness.validationMessages(), 0u);
}
