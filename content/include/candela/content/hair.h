#pragma once
// Hair (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair Rendering", TressFX-style
// strands): polylines from root to tip, drawn by the hair pass as camera-facing quads into a
// per-pixel linked list, sorted and blended per pixel. Made from a glTF LINES / LINE_STRIP
// primitive whose material's extras has a `hair` object (Material::hair, content/README.md), or
// generated on a mesh's surface (generateHair, for scene files and the demo).
#include <array>
#include <cstdint>
#include <vector>

namespace candela::content {

struct Primitive;

struct Hair {
    std::vector<std::array<float, 3>> positions;  // mesh space
    std::vector<std::uint32_t> segments;          // index pairs into positions, root end first
    // Each position's place along its strand, 0 at the root, 1 at the tip (by arc length): the
    // radius runs from the style's root radius to its tip radius along it.
    std::vector<float> rootToTip;
    std::int32_t material = -1;  // into Model::materials; -1: the default (no hair style)
};

// rootToTip for `positions` joined by `segments` (index pairs, each pointing from root toward
// tip): a position no segment ends at is a root; arc length from it over the strand's length.
// A lone position (no segment) gets 0.
std::vector<float> strandParameters(const std::vector<std::array<float, 3>>& positions,
                                    const std::vector<std::uint32_t>& segments);

// `count` strands rooted at random points of `surface`'s triangles (area-weighted, from
// `seed`: the same seed gives the same hair), each `length` metres long along the surface
// normal, bent by a small deterministic random lean, in `pointsPerStrand` - 1 segments.
// Empty when the surface has no triangle of positive area.
Hair generateHair(const Primitive& surface, std::uint32_t count, float length, std::uint32_t seed,
                  std::uint32_t pointsPerStrand = 5);

}  // namespace candela::content
