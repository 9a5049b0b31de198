#pragma once
// Screen-space debug text (render::TextLine) drawn by a compute pass onto the LDR image after
// tonemapping; the frame graph orders it after the tonemap pass and before the capture copy.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "candela/render/text_overlay.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuContext;

// One character as the shader reads it (std430, 32 bytes).
struct GlyphInstance {
    std::int32_t x = 0, y = 0;  // top-left pixel of the 5x7 ink
    std::uint32_t index = 0;    // bitmap_font.h glyph
    std::uint32_t scale = 1;
    std::array<float, 4> color{1, 1, 1, 1};
};
static_assert(sizeof(GlyphInstance) == 32);

// The glyphs `lines` draw on a width x height image: spaces and characters wholly outside the
// image are left out; scale is clamped to 1..kTextMaxScale. At most `maxGlyphs`.
std::vector<GlyphInstance> layoutText(std::span<const TextLine> lines, std::uint32_t width,
                                      std::uint32_t height, std::size_t maxGlyphs);

class DebugTextPass {
public:
    static constexpr std::size_t kMaxGlyphs = 16384;

    explicit DebugTextPass(GpuContext& context);
    // Writes the glyphs into the host-visible buffer the pass reads; returns how many. The
    // buffer is rewritten each frame, as the camera's is: one frame is in flight at a time.
    std::uint32_t prepare(std::span<const TextLine> lines, std::uint32_t width,
                          std::uint32_t height);
    const GpuBuffer& buffer() const { return buffer_; }
    // ldr in GENERAL layout, writable as a storage image.
    void record(VkCommandBuffer cmd, const ImageRef& ldr, std::uint32_t glyphCount) const;

private:
    Pipeline pipeline_;
    GpuBuffer buffer_;
    std::uint32_t maxScale_ = 1;
};

}  // namespace candela::render
