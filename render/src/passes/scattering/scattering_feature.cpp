#include "passes/scattering/scattering_feature.h"

#include <cstdint>
#include <memory>

#include "candela/render/frame_inputs.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/scattering/scattering_pass.h"
#include "passes/shadows/shadow_frame.h"
#include "passes/volumetrics/integrated_froxels.h"
#include "renderer_scene_queries.h"

namespace candela::render {

namespace {

// What the passes read besides the graph's resources: the frame's sun and air, the lit inputs'
// buffers and the sampling the settings choose.
ScatteringPass::Inputs inputsFor(const FeatureFrame& frame, const LitFrame& lit, bool shadows) {
    const RendererOptions& options = frame.options;
    ScatteringPass::Inputs in;
    in.frame = ScatteringPass::frameOf(frame.inputs.scene, options.scatteringSettings, frame.width,
                                       frame.height);
    in.camera = lit.inputs.camera;
    in.lights = lit.inputs.lights;
    in.lightCapacity = lit.lightCapacity;
    in.shadowMaps = shadows;
    in.settings = options.scatteringSettings;
    in.slices = options.scatteringSlices;
    in.samplesPerSlice = options.scatteringSamples;
    in.cascadeSize = options.shadowCascadeSize;
    in.nearPlane = frame.inputs.scene.camera.nearPlane;
    return in;
}

}  // namespace

ScatteringFeature::ScatteringFeature(GpuContext& context) : context_(context) {}

ScatteringFeature::~ScatteringFeature() = default;

bool ScatteringFeature::active(const FeatureFrame& frame) const {
    return scatteringDrawn(frame.inputs.scene, frame.options.scattering);
}

void ScatteringFeature::declare(FeatureFrame& frame) {
    marched_ = false;
    const RendererOptions& options = frame.options;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const LitFrame& lit = frame.board.get<LitFrame>();
    const ShadowFrame* shadowFrame = frame.board.find<ShadowFrame>();
    const bool shadows = shadowFrame != nullptr;
    IntegratedFroxels& froxels = frame.board.get<IntegratedFroxels>();
    const ScatteringPass::Inputs in = inputsFor(frame, lit, shadows);
    FrameGraph& g = frame.graph;
    if (!pass_) pass_ = std::make_unique<ScatteringPass>(context_);
    ScatteringPass* pass = pass_.get();
    pass->prepare(options.scattering, shadows, froxels.airFroxels);
    marched_ = true;
    const bool epipolar = options.scattering == ScatteringMode::Epipolar;
    frame.features.push_back(epipolar ? "scattering_epipolar" : "scattering_brute_force");
    const ResourceHandle hdr = targets.hdr;
    const ResourceHandle depth = targets.depth;
    auto readCommon = [&](FrameGraph::PassBuilder& p) {
        p.read(targets.camera, Use::Uniform);
        p.read(lit.reads.lights, Use::StorageRead);
        if (shadowFrame) {
            p.read(shadowFrame->atlas, Use::Sampled);
            p.read(shadowFrame->views, Use::StorageRead);
            p.read(shadowFrame->lights, Use::StorageRead);
        }
    };
    const ShadowDescriptors shadowDescriptors = lit.inputs.shadows;  // the passes run later
    if (froxels.airFroxels) {
        // The same air for blended surfaces and wires, drawn after the shafts: a coarse grid
        // of view rays into the integrated froxel buffer, after the fog's grid there.
        frame.features.push_back("aerial_perspective");
        const bool fogGridThere = froxels.fogBoundaries > 0;
        const uint32_t firstBoundary = froxels.fogBoundaries;
        const ResourceHandle target = *froxels.buffer;
        auto p = g.addPass(
            "aerial_perspective", PassKind::Device,
            [pass, in, shadowDescriptors, target, firstBoundary, fogGridThere](PassContext& ctx) {
                ScatteringPass::Inputs passInputs = in;
                passInputs.shadows = &shadowDescriptors;
                pass->recordAerialPerspective(ctx.cmd(), passInputs, ctx.buffer(target),
                                              firstBoundary, fogGridThere);
            });
        readCommon(p);
        froxels.buffer = p.write(target, fogGridThere ? Use::StorageReadWrite : Use::StorageWrite);
    }
    ResourceHandle counters = g.importBuffer("scattering.counters", &pass->counters(), true);
    {
        auto p = g.addPass("scattering_clear", PassKind::Device,
                           [pass](PassContext& ctx) { pass->recordClearCounters(ctx.cmd()); });
        counters = p.write(counters, Use::TransferDst);
    }
    if (!epipolar) {
        auto p = g.addPass("scattering_brute_force", PassKind::Device,
                           [pass, hdr, depth, in, shadowDescriptors](PassContext& ctx) {
                               ScatteringPass::Inputs passInputs = in;
                               passInputs.depth = ctx.image(depth);
                               passInputs.hdr = ctx.image(hdr);
                               passInputs.shadows = &shadowDescriptors;
                               pass->recordBruteForce(ctx.cmd(), passInputs);
                           });
        readCommon(p);
        p.read(targets.depth, Use::Sampled);
        counters = p.write(counters, Use::StorageReadWrite);
        targets.hdr = p.write(targets.hdr, Use::StorageReadWrite);
        return;
    }
    ResourceHandle coordinates = g.createImage(
        "scattering.coordinates", ScatteringPass::samplesDesc(in.slices, in.samplesPerSlice));
    ResourceHandle inscatter = g.createImage(
        "scattering.inscatter", ScatteringPass::samplesDesc(in.slices, in.samplesPerSlice));
    ResourceHandle tree =
        g.createImage("scattering.tree", ScatteringPass::treeDesc(in.slices, in.cascadeSize));
    ResourceHandle slices =
        g.createBuffer("scattering.slices", ScatteringPass::slicesBytes(in.slices),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    {
        auto p =
            g.addPass("scattering_coordinates", PassKind::Device,
                      [pass, depth, in, shadowDescriptors, coordinates, slices](PassContext& ctx) {
                          ScatteringPass::Inputs passInputs = in;
                          passInputs.depth = ctx.image(depth);
                          passInputs.shadows = &shadowDescriptors;
                          pass->recordCoordinates(ctx.cmd(), passInputs, ctx.image(coordinates),
                                                  ctx.buffer(slices));
                      });
        readCommon(p);
        p.read(targets.depth, Use::Sampled);
        coordinates = p.write(coordinates, Use::StorageWrite);
        slices = p.write(slices, Use::StorageWrite);
    }
    {
        auto p = g.addPass("scattering_tree", PassKind::Device,
                           [pass, in, shadowDescriptors, slices, tree](PassContext& ctx) {
                               ScatteringPass::Inputs passInputs = in;
                               passInputs.shadows = &shadowDescriptors;
                               pass->recordTree(ctx.cmd(), passInputs, ctx.buffer(slices),
                                                ctx.image(tree));
                           });
        readCommon(p);
        p.read(slices, Use::StorageRead);
        tree = p.write(tree, Use::StorageWrite);
    }
    constexpr const char* kPhases[] = {"scattering_march", "scattering_refine",
                                       "scattering_interpolate"};
    for (uint32_t phase = 0; phase < 3; ++phase) {
        auto p = g.addPass(kPhases[phase], PassKind::Device,
                           [pass, in, shadowDescriptors, phase, coordinates, slices, tree,
                            inscatter](PassContext& ctx) {
                               ScatteringPass::Inputs passInputs = in;
                               passInputs.shadows = &shadowDescriptors;
                               pass->recordSamples(ctx.cmd(), passInputs, phase,
                                                   ctx.image(coordinates), ctx.buffer(slices),
                                                   ctx.image(tree), ctx.image(inscatter));
                           });
        readCommon(p);
        p.read(coordinates, Use::StorageRead);
        p.read(slices, Use::StorageRead);
        p.read(tree, Use::Sampled);
        counters = p.write(counters, Use::StorageReadWrite);
        inscatter = p.write(inscatter, phase == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    auto p = g.addPass(
        "scattering_unwarp", PassKind::Device,
        [pass, hdr, depth, in, shadowDescriptors, slices, tree, inscatter](PassContext& ctx) {
            ScatteringPass::Inputs passInputs = in;
            passInputs.depth = ctx.image(depth);
            passInputs.hdr = ctx.image(hdr);
            passInputs.shadows = &shadowDescriptors;
            pass->recordUnwarp(ctx.cmd(), passInputs, ctx.buffer(slices), ctx.image(tree),
                               ctx.image(inscatter));
        });
    readCommon(p);
    p.read(targets.depth, Use::Sampled);
    p.read(slices, Use::StorageRead);
    p.read(tree, Use::Sampled);
    p.read(inscatter, Use::StorageRead);
    counters = p.write(counters, Use::StorageReadWrite);
    targets.hdr = p.write(targets.hdr, Use::StorageReadWrite);
}

void ScatteringFeature::collectStats(RendererStats& stats, bool declared) const {
    stats.scatteringMs = passMilliseconds(stats, "scattering_");
    stats.aerialPerspectiveMs = passMilliseconds(stats, "aerial_perspective");
    stats.scatteringSamples = 0;
    stats.scatteringSteps = 0;
    stats.work.scatteringSteps = 0;
    if (!declared || !marched_) return;
    const ScatteringPass::Counts c = pass_->readCounters();
    stats.scatteringSamples = c.rays;
    stats.scatteringSteps = c.steps;
    stats.work.scatteringSteps = c.steps;
}

}  // namespace candela::render
