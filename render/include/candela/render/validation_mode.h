#pragma once
// Whether the Khronos validation layer runs. Apart from gpu_context.h so application options
// name it without Vulkan.

namespace candela::render {

enum class ValidationMode {
    Off,        // no layer
    IfPresent,  // enable the Khronos layer when it is installed
    Required,   // fail to start without it (tests)
};

}  // namespace candela::render
