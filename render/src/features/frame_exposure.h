#pragma once
// The exposure the frame is tonemapped with (1 / (1.2 x 2^EV100), the camera's or the adapted
// one): TAA clips its history in this frame's exposed values.
namespace candela::render {

struct FrameExposure {
    float exposure = 1.0f;
};

}  // namespace candela::render
