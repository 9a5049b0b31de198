#pragma once
// GLFW key and button codes to the runtime's own (public headers stay free of GLFW).
#include <optional>

#include "candela/runtime/input_state.h"

namespace candela::runtime {

std::optional<Key> keyFromGlfw(int glfwKey);
std::optional<MouseButton> mouseButtonFromGlfw(int glfwButton);

}  // namespace candela::runtime
