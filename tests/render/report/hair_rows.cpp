// Rows: hair self-shadowing (issue 19, Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time
// Hair Rendering"). A ball of 600 or 2,500 strands (4 segments each) 2.5 m ahead under a casting
// sun, 128x128: the lit hair with self-shadowing from the hair depth map (the fibres in front
// estimated from the depth range behind the first hair), and without self-shadowing, against the
// reference that counts the fibres between every shaded fragment and the sun exactly; with the cost
// of the hair depth map and the resolve, and the depth map's cost per 10,000 strands (10,000
// strands, 40,000 segments, 256x256).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../offscreen_frame.h"
#include "../test_scene.h"
#include "candela/content/hair.h"
#include "candela/content/procedural_mesh.h"
#include "median.h"
#include "passes/hair/hair_bindings.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct HairRun {
    CapturedFrame frame;
    double shadowDepthMs = 0.0;
    double resolveMs = 0.0;
};

// The median GPU times of hair_shadow_depth and hair_resolve over `repetitions` frames after
// two (pipelines, shadow maps), and the last frame.
HairRun run(GpuContext& gpu, HairSelfShadow mode, uint32_t strands, uint32_t size,
            uint32_t repetitions) {
    RendererOptions options;
    options.hairSelfShadow = mode;
    SceneResources resources(gpu);
    FrameSequence frames(gpu, size, size, options);
    candela::content::Hair hair = candela::content::generateHair(
        candela::content::makeSphere(0.5f, 12, 6), strands, 0.3f, 19);
    for (auto& p : hair.positions)
        p[2] -= 2.5f;
    candela::content::HairStyle style;
    style.rootRadius = 0.004f;
    style.tipRadius = 0.001f;
    style.color = {0.6f, 0.4f, 0.25f};
    const std::vector<HairDraw> draws{{&hair, &style, glm::mat4(1.0f)}};
    std::vector<LightInstance> sun(1);
    sun[0].light.type = candela::content::LightType::Directional;
    sun[0].light.lux = 3.0f;
    sun[0].light.castShadows = true;
    sun[0].direction = glm::normalize(glm::vec3(0.5f, -1.0f, -0.4f));
    FrameInputs inputs;
    inputs.scene.camera.projection = reverseZPerspective(glm::radians(60.0f), 1.0f, 0.05f);
    inputs.scene.camera.nearPlane = 0.05f;
    inputs.scene.hair = draws;
    inputs.scene.lights = sun;
    HairRun out;
    std::vector<double> depthMs, resolveMs;
    for (uint32_t r = 0; r < repetitions + 2; ++r) {
        RendererStats stats;
        out.frame = frames.render(inputs, resources, &stats);
        if (r < 2) continue;
        for (const auto& [name, t] : stats.passMs) {
            if (name == "hair_shadow_depth") depthMs.push_back(t);
            if (name == "hair_resolve") resolveMs.push_back(t);
        }
    }
    out.shadowDepthMs = depthMs.empty() ? 0.0 : median(depthMs);
    out.resolveMs = resolveMs.empty() ? 0.0 : median(resolveMs);
    return out;
}

// Mean and worst |a - b| over the pixels the reference lights, relative to its mean there.
struct Difference {
    double mean = 0.0;
    double worst = 0.0;
    double signedMean = 0.0;  // mean (a - b) / the reference's mean: > 0 brighter
};
Difference relativeDifference(const CapturedFrame& a, const CapturedFrame& reference) {
    double sum = 0.0, total = 0.0, worst = 0.0, signedSum = 0.0;
    uint32_t count = 0;
    for (size_t i = 0; i < reference.hdrRgb.size(); ++i) {
        if (!(reference.hdrRgb[i] > 0.0f) && !(a.hdrRgb[i] > 0.0f)) continue;
        const double d = std::abs(double(a.hdrRgb[i]) - double(reference.hdrRgb[i]));
        sum += d;
        signedSum += double(a.hdrRgb[i]) - double(reference.hdrRgb[i]);
        worst = std::max(worst, d);
        total += reference.hdrRgb[i];
        ++count;
    }
    if (count == 0 || total <= 0.0) return {};
    const double meanReference = total / count;
    return {sum / count / meanReference, worst / meanReference, signedSum / count / meanReference};
}

}  // namespace

void addHairRows(ReportContext& context) {
    GpuContext& gpu = context.harness.context();
    const uint32_t repetitions = context.budget.quick ? 1 : 5;
    const HairRun big = run(gpu, HairSelfShadow::DepthMap, 10000, 256, repetitions);
    const std::string referenceName =
        "every fibre between the fragment and the sun counted (each lets 1 - 0.35 through)";
    // A sparse ball and a denser one (the reference tests every segment per fragment:
    // lavapipe's loop limit keeps it under about 12,000 segments).
    // The smoke test's quick run: the sparse ball only (the denser one's reference takes seconds
    // a frame on lavapipe).
    const std::vector<uint32_t> balls =
        context.budget.quick ? std::vector<uint32_t>{600u} : std::vector<uint32_t>{600u, 2500u};
    for (uint32_t strands : balls) {
        const HairRun reference = run(gpu, HairSelfShadow::Reference, strands, 128, repetitions);
        const HairRun map = run(gpu, HairSelfShadow::DepthMap, strands, 128, repetitions);
        const HairRun off = run(gpu, HairSelfShadow::Off, strands, 128, repetitions);
        const Difference mapError = relativeDifference(map.frame, reference.frame);
        const Difference offError = relativeDifference(off.frame, reference.frame);
        char metric[300], worst[240], cost[300], name[200];
        std::snprintf(metric, sizeof(metric),
                      "mean |radiance - reference| over the hair's pixels / the reference's mean "
                      "there, a ball of %u strands (%u segments) under a casting sun, 128x128",
                      strands, 4 * strands);
        std::snprintf(worst, sizeof(worst), "worst pixel %.3g x the mean; signed mean %+.3g%%",
                      mapError.worst, 100.0 * mapError.signedMean);
        std::snprintf(cost, sizeof(cost),
                      "hair depth map %s ms + resolve %s ms (reference resolve %s ms); depth map "
                      "%s ms per 10,000 strands (40,000 segments, 4 cascades, 256x256)",
                      formatNumber(map.shadowDepthMs).c_str(), formatNumber(map.resolveMs).c_str(),
                      formatNumber(reference.resolveMs).c_str(),
                      formatNumber(big.shadowDepthMs).c_str());
        std::snprintf(name, sizeof(name),
                      "Hair self-shadowing: hair depth map, (1 - 0.35)^(depth range / (%g x "
                      "radius)) (Martin et al. 2014, GPU Pro 5), %u strands",
                      double(HAIR_FIBRE_SPACING), strands);
        context.report.rows.push_back(
            {name, referenceName, metric, 100.0 * mapError.mean, "% mean", worst, cost});
        std::snprintf(worst, sizeof(worst), "worst pixel %.3g x the mean; signed mean %+.3g%%",
                      offError.worst, 100.0 * offError.signedMean);
        std::snprintf(cost, sizeof(cost), "resolve %s ms", formatNumber(off.resolveMs).c_str());
        std::snprintf(name, sizeof(name), "Hair without self-shadowing, %u strands", strands);
        context.report.rows.push_back(
            {name, referenceName, metric, 100.0 * offError.mean, "% mean", worst, cost});
    }
}

}  // namespace candela::report
