// Light shafts' frame-graph declaration (Renderer::declareScattering, issue 16, Yusov 2014,
// GPU Pro 5, "High Performance Outdoor Light Scattering Using Epipolar Sampling"): the aerial
// perspective into the integrated froxel buffer for blended surfaces and wires, then the epipolar
// passes (coordinates, tree, march/refine/interpolate, unwarp) or the brute-force march over the
// lit HDR target.

#include <cstdint>
#include <memory>

#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "lights/gpu_light_buffer.h"
#include "passes/scattering/scattering_pass.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "renderer_frame_handles.h"
#include "renderer_scene_queries.h"

namespace candela::render {

void Renderer::declareScattering(const FrameInputs& inputs, SceneHandles& h,
                                 const ShadowReads& shadowReads, ResourceHandle* aerialFroxels,
                                 uint32_t fogBoundaries) {
    const bool shadows = shadowReads.shadows;
    scatteringMarched_ = false;
    if (!scatteringDrawn(inputs.scene, options_.scattering)) return;
    ScatteringPass::Inputs in;
    in.frame = ScatteringPass::frameOf(inputs.scene, options_.scatteringSettings, width_, height_);
    FrameGraph& g = *graph_;
    if (!scatteringPass_) scatteringPass_ = std::make_unique<ScatteringPass>(context_);
    scatteringPass_->prepare(options_.scattering, shadows, aerialFroxels != nullptr);
    scatteringMarched_ = true;
    in.camera = &cameraBuffer_;
    in.lights = &lights_->buffer();
    in.lightCapacity = lights_->capacity();
    in.shadowMaps = shadows;
    in.settings = options_.scatteringSettings;
    in.cascadeSize = options_.shadowCascadeSize;
    in.nearPlane = inputs.scene.camera.nearPlane;
    const bool epipolar = options_.scattering == ScatteringMode::Epipolar;
    features_.push_back(epipolar ? "scattering_epipolar" : "scattering_brute_force");
    const SceneHandles ids = h;
    auto readCommon = [&](FrameGraph::PassBuilder& p) {
        p.read(h.camera, Use::Uniform);
        p.read(h.lights, Use::StorageRead);
        if (shadows) {
            p.read(shadowReads.atlas, Use::Sampled);
            p.read(shadowReads.views, Use::StorageRead);
            p.read(shadowReads.lights, Use::StorageRead);
        }
    };
    const ShadowDescriptors shadowDescriptors = shadowReads.descriptors;  // the passes run later
    if (aerialFroxels) {
        // The same air for blended surfaces and wires, drawn after the shafts: a coarse grid
        // of view rays into the integrated froxel buffer, after the fog's grid there.
        features_.push_back("aerial_perspective");
        const bool fogGridThere = fogBoundaries > 0;
        const uint32_t firstBoundary = fogBoundaries;
        const ResourceHandle target = *aerialFroxels;
        auto p = g.addPass(
            "aerial_perspective", PassKind::Device,
            [this, in, shadowDescriptors, target, firstBoundary, fogGridThere](PassContext& ctx) {
                ScatteringPass::Inputs frame = in;
                frame.shadows = &shadowDescriptors;
                scatteringPass_->recordAerialPerspective(ctx.cmd(), frame, ctx.buffer(target),
                                                         firstBoundary, fogGridThere);
            });
        readCommon(p);
        *aerialFroxels = p.write(target, fogGridThere ? Use::StorageReadWrite : Use::StorageWrite);
    }
    ResourceHandle counters =
        g.importBuffer("scattering.counters", &scatteringPass_->counters(), true);
    {
        auto p = g.addPass("scattering_clear", PassKind::Device, [this](PassContext& ctx) {
            scatteringPass_->recordClearCounters(ctx.cmd());
        });
        counters = p.write(counters, Use::TransferDst);
    }
    if (!epipolar) {
        auto p = g.addPass("scattering_brute_force", PassKind::Device,
                           [this, ids, in, shadowDescriptors](PassContext& ctx) {
                               ScatteringPass::Inputs frame = in;
                               frame.depth = ctx.image(ids.depth);
                               frame.hdr = ctx.image(ids.hdr);
                               frame.shadows = &shadowDescriptors;
                               scatteringPass_->recordBruteForce(ctx.cmd(), frame);
                           });
        readCommon(p);
        p.read(h.depth, Use::Sampled);
        counters = p.write(counters, Use::StorageReadWrite);
        h.hdr = p.write(h.hdr, Use::StorageReadWrite);
        return;
    }
    ResourceHandle coordinates =
        g.createImage("scattering.coordinates", ScatteringPass::samplesDesc(in.settings));
    ResourceHandle inscatter =
        g.createImage("scattering.inscatter", ScatteringPass::samplesDesc(in.settings));
    ResourceHandle tree =
        g.createImage("scattering.tree", ScatteringPass::treeDesc(in.settings, in.cascadeSize));
    ResourceHandle slices =
        g.createBuffer("scattering.slices", ScatteringPass::slicesBytes(in.settings),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    {
        auto p =
            g.addPass("scattering_coordinates", PassKind::Device,
                      [this, ids, in, shadowDescriptors, coordinates, slices](PassContext& ctx) {
                          ScatteringPass::Inputs frame = in;
                          frame.depth = ctx.image(ids.depth);
                          frame.shadows = &shadowDescriptors;
                          scatteringPass_->recordCoordinates(
                              ctx.cmd(), frame, ctx.image(coordinates), ctx.buffer(slices));
                      });
        readCommon(p);
        p.read(h.depth, Use::Sampled);
        coordinates = p.write(coordinates, Use::StorageWrite);
        slices = p.write(slices, Use::StorageWrite);
    }
    {
        auto p = g.addPass("scattering_tree", PassKind::Device,
                           [this, in, shadowDescriptors, slices, tree](PassContext& ctx) {
                               ScatteringPass::Inputs frame = in;
                               frame.shadows = &shadowDescriptors;
                               scatteringPass_->recordTree(ctx.cmd(), frame, ctx.buffer(slices),
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
                           [this, in, shadowDescriptors, phase, coordinates, slices, tree,
                            inscatter](PassContext& ctx) {
                               ScatteringPass::Inputs frame = in;
                               frame.shadows = &shadowDescriptors;
                               scatteringPass_->recordSamples(
                                   ctx.cmd(), frame, phase, ctx.image(coordinates),
                                   ctx.buffer(slices), ctx.image(tree), ctx.image(inscatter));
                           });
        readCommon(p);
        p.read(coordinates, Use::StorageRead);
        p.read(slices, Use::StorageRead);
        p.read(tree, Use::Sampled);
        counters = p.write(counters, Use::StorageReadWrite);
        inscatter = p.write(inscatter, phase == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    auto p =
        g.addPass("scattering_unwarp", PassKind::Device,
                  [this, ids, in, shadowDescriptors, slices, tree, inscatter](PassContext& ctx) {
                      ScatteringPass::Inputs frame = in;
                      frame.depth = ctx.image(ids.depth);
                      frame.hdr = ctx.image(ids.hdr);
                      frame.shadows = &shadowDescriptors;
                      scatteringPass_->recordUnwarp(ctx.cmd(), frame, ctx.buffer(slices),
                                                    ctx.image(tree), ctx.image(inscatter));
                  });
    readCommon(p);
    p.read(h.depth, Use::Sampled);
    p.read(slices, Use::StorageRead);
    p.read(tree, Use::Sampled);
    p.read(inscatter, Use::StorageRead);
    counters = p.write(counters, Use::StorageReadWrite);
    h.hdr = p.write(h.hdr, Use::StorageReadWrite);
}

}  // namespace candela::render
