#include "passes/output/output_stage.h"

#include "candela/render/gpu_context.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/debug_text/debug_text_pass.h"
#include "passes/fxaa/fxaa_pass.h"
#include "passes/tonemap/tonemap_pass.h"
#include "passes/upscale/upscale_pass.h"

namespace candela::render {

OutputStage::OutputStage(GpuContext& context, const RendererOptions& options)
    : context_(context), tonemap_(std::make_unique<TonemapPass>(context)) {
    if (options.aa == AntiAliasing::Fxaa) fxaa_ = std::make_unique<FxaaPass>(context);
}

OutputStage::~OutputStage() = default;

void OutputStage::setUpscales(bool upscales) {
    if (!upscales) {
        upscale_.reset();
    } else if (!upscale_) {
        upscale_ = std::make_unique<UpscalePass>(context_);
    }
}

ResourceHandle OutputStage::declareUpscale(FrameGraph& g, ResourceHandle hdr,
                                           ResourceHandle outputHdr,
                                           std::vector<std::string>& features) {
    features.push_back("upscale");
    auto p = g.addPass("upscale", PassKind::Device, [this, hdr, outputHdr](PassContext& ctx) {
        upscale_->record(ctx.cmd(), ctx.image(hdr), ctx.image(outputHdr));
    });
    p.read(hdr, Use::Sampled);
    return p.write(outputHdr, Use::StorageWrite);
}

ResourceHandle OutputStage::declareDisplay(FrameGraph& g, ResourceHandle hdr, ResourceHandle ldr,
                                           float exposure, const std::vector<TextLine>& text,
                                           uint32_t outputWidth, uint32_t outputHeight,
                                           std::vector<std::string>& features) {
    features.push_back("tonemap_aces");
    // FXAA reads the tonemapped image from a transient and writes the LDR target.
    ResourceHandle tonemapped = ldr;
    if (fxaa_) {
        tonemapped = g.createImage("fxaa.input",
                                   {VK_FORMAT_R8G8B8A8_UNORM, outputWidth, outputHeight, 1, false,
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
    }
    auto p =
        g.addPass("tonemap", PassKind::Device, [this, hdr, tonemapped, exposure](PassContext& ctx) {
            tonemap_->record(ctx.cmd(), ctx.image(hdr), ctx.image(tonemapped), exposure);
        });
    p.read(hdr, Use::StorageRead);
    tonemapped = p.write(tonemapped, Use::StorageWrite);
    if (fxaa_) {
        features.push_back("fxaa");
        auto f = g.addPass("fxaa", PassKind::Device, [this, tonemapped, ldr](PassContext& ctx) {
            fxaa_->record(ctx.cmd(), ctx.image(tonemapped), ctx.image(ldr));
        });
        f.read(tonemapped, Use::Sampled);
        ldr = f.write(ldr, Use::StorageWrite);
    } else {
        ldr = tonemapped;
    }
    if (text.empty()) return ldr;
    if (!debugText_) debugText_ = std::make_unique<DebugTextPass>(context_);
    const uint32_t glyphs = debugText_->prepare(text, outputWidth, outputHeight);
    if (glyphs == 0) return ldr;
    features.push_back("debug_text");
    const ResourceHandle glyphBuffer = g.importBuffer("debug_text.glyphs", &debugText_->buffer());
    auto d = g.addPass("debug_text", PassKind::Device, [this, ldr, glyphs](PassContext& ctx) {
        debugText_->record(ctx.cmd(), ctx.image(ldr), glyphs);
    });
    d.read(glyphBuffer, Use::StorageRead);
    // Draws over the tonemapped pixels; passes after it (ExtraPass) draw over the text.
    return d.write(ldr, Use::StorageReadWrite);
}

}  // namespace candela::render
