#pragma once
// The Vulkan surface of a runtime Window: kept out of window.h so that header needs no Vulkan.
#include <vulkan/vulkan.h>

#include "candela/runtime/window.h"

namespace candela::runtime {

// Throws when GLFW cannot create the surface.
VkSurfaceKHR createWindowSurface(Window& window, VkInstance instance);

}  // namespace candela::runtime
