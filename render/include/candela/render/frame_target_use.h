#pragma once
// How a pass added from outside the renderer (an overlay, a debug draw: FrameLayer in the
// runtime) uses the frame's two targets. The frame graph turns these into barriers and layout
// transitions, so the pass records none itself. Vulkan-free: games name these too.
#include <cstdint>

namespace candela::render {

enum class FrameTarget : std::uint8_t {
    Hdr,  // RGBA32F scene radiance (what EXR captures read)
    Ldr,  // RGBA8 tonemapped, sRGB-encoded values (what the window shows, PNG captures)
};

// What both targets are created for (storage, colour attachment, transfer source); sampling
// either or copying into it would need usage flags they do not have.
enum class TargetUse : std::uint8_t {
    StorageRead,       // storage image read in a compute shader (imageLoad)
    StorageWrite,      // storage image written in a compute shader (previous contents discarded)
    StorageReadWrite,  // read and written in a compute shader
    ColorAttachment,   // drawn onto (loaded, blended, stored)
    TransferSrc,       // copied from
};

struct TargetAccess {
    FrameTarget target = FrameTarget::Ldr;
    TargetUse use = TargetUse::ColorAttachment;
};

}  // namespace candela::render
