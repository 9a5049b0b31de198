#pragma once
// Screen-space debug text for games (a score, a hint): print it from a system every frame it
// should show; the frame draws it over the tonemapped image, in a window and headless alike
// (so --capture FILE.png shows it), and starts the next frame with an empty list.
//
//   runtime::debugText(world).print(16, 16, "SCORE " + std::to_string(score));
//
// The font is the engine's 5x7 bitmap (render/text_overlay.h lists its characters).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "candela/render/text_overlay.h"

namespace candela::runtime {

class SceneWorld;

struct DebugText {
    // (x, y): the first character's top-left pixel; scale: pixels per font texel (1..8).
    void print(std::int32_t x, std::int32_t y, std::string text,
               std::array<float, 3> color = {1, 1, 1}, std::uint32_t scale = 2) {
        lines.push_back({x, y, scale, color, std::move(text)});
    }
    std::vector<render::TextLine> lines;  // this frame's, taken by frame extraction
};

// The world's debug text (a registry resource, made on first use).
DebugText& debugText(SceneWorld& world);

}  // namespace candela::runtime
