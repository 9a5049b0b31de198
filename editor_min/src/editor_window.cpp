#include "editor_window.h"

#include <GLFW/glfw3.h>

#include <cstdio>

namespace candela::editor {

int runEditorWindow(uint32_t frames) {
    if (!glfwInit()) {
        std::fprintf(stderr, "candela-editor: cannot open a window (no display; try xvfb-run)\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    GLFWwindow* window = glfwCreateWindow(1280, 720, "Candela Editor", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "candela-editor: window creation failed\n");
        glfwTerminate();
        return 1;
    }
    for (uint32_t i = 0; !glfwWindowShouldClose(window) && (frames == 0 || i < frames); ++i) {
        glfwWaitEventsTimeout(1.0 / 60.0);
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace candela::editor
