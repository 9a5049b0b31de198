#pragma once
// A wire (Persson 2014, GPU Pro 5, "Wire Antialiasing"): a thin cylinder along a polyline, drawn by
// the wire pass as camera-facing ribbons at least a pixel wide whose alpha keeps the real width's
// energy. Made from a glTF LINES / LINE_STRIP / LINE_LOOP primitive whose material's extras gives
// `wireRadius`, or in code (the demo's power lines).
#include <array>
#include <cstdint>
#include <vector>

namespace candela::content {

struct Wire {
    std::vector<std::array<float, 3>> positions;  // mesh space
    std::vector<std::uint32_t> segments;          // index pairs into positions
    float radius = 0;                             // metres (the material's extras.wireRadius)
    std::int32_t material = -1;                   // into Model::materials; -1: the default
};

}  // namespace candela::content
