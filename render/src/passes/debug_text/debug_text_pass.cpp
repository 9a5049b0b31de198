#include "passes/debug_text/debug_text_pass.h"

#include <algorithm>
#include <cstring>

#include "passes/debug_text/bitmap_font.h"
#include "passes/debug_text/debug_text_bindings.h"
#include "shaders/debug_text.comp.spv.h"

namespace candela::render {

std::vector<GlyphInstance> layoutText(std::span<const TextLine> lines, std::uint32_t width,
                                      std::uint32_t height, std::size_t maxGlyphs) {
    std::vector<GlyphInstance> glyphs;
    for (const TextLine& line : lines) {
        const std::uint32_t scale = std::clamp(line.scale, 1u, kTextMaxScale);
        // 64-bit positions: a line placed near the int32 limits must not overflow.
        const std::int64_t s = scale;
        std::int64_t x = line.x;
        std::int64_t y = line.y;
        for (char c : line.text) {
            if (c == '\n') {
                x = line.x;
                y += kTextLineAdvance * s;
                continue;
            }
            const bool visible = x + 6 * s > 0 && y + 8 * s > 0 && x - s < std::int64_t(width) &&
                                 y - s < std::int64_t(height);
            if (c != ' ' && visible) {
                if (glyphs.size() == maxGlyphs) return glyphs;
                glyphs.push_back({std::int32_t(x),
                                  std::int32_t(y),
                                  glyphIndex(c),
                                  scale,
                                  {line.color[0], line.color[1], line.color[2], 1.0f}});
            }
            x += kTextAdvance * s;
        }
    }
    return glyphs;
}

DebugTextPass::DebugTextPass(GpuContext& context)
    : buffer_(context, kFontWords * sizeof(std::uint32_t) + kMaxGlyphs * sizeof(GlyphInstance),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible) {
    const DescriptorBinding bindings[] = {
        {DEBUG_TEXT_BINDING_LDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {DEBUG_TEXT_BINDING_TEXT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, debug_text_comp_spv, bindings, sizeof(std::uint32_t));
    // The font never changes: written once, at the front of the buffer.
    auto* bytes = static_cast<std::byte*>(buffer_.mapped());
    std::memset(bytes, 0, kFontWords * sizeof(std::uint32_t));
    std::span<const GlyphBits> font = fontGlyphs();
    std::memcpy(bytes, font.data(), font.size_bytes());
}

std::uint32_t DebugTextPass::prepare(std::span<const TextLine> lines, std::uint32_t width,
                                     std::uint32_t height) {
    const std::vector<GlyphInstance> glyphs = layoutText(lines, width, height, kMaxGlyphs);
    auto* bytes = static_cast<std::byte*>(buffer_.mapped()) + kFontWords * sizeof(std::uint32_t);
    std::memcpy(bytes, glyphs.data(), glyphs.size() * sizeof(GlyphInstance));
    maxScale_ = 1;
    for (const GlyphInstance& g : glyphs)
        maxScale_ = std::max(maxScale_, g.scale);
    return std::uint32_t(glyphs.size());
}

void DebugTextPass::record(VkCommandBuffer cmd, const ImageRef& ldr,
                           std::uint32_t glyphCount) const {
    if (glyphCount == 0) return;
    VkDescriptorImageInfo image{VK_NULL_HANDLE, ldr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo text{buffer_.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {storageImageWrite(DEBUG_TEXT_BINDING_LDR, &image),
                                           storageBufferWrite(DEBUG_TEXT_BINDING_TEXT, &text)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &glyphCount, sizeof(glyphCount));
    // The largest glyph's cell with its border: 7 x 9 texels.
    vkCmdDispatch(cmd, (7 * maxScale_ + 7) / 8, (9 * maxScale_ + 7) / 8, glyphCount);
}

}  // namespace candela::render
