// candela-editor [--frames N]
#include <cstdlib>
#include <cstring>

#include "editor_window.h"

int main(int argc, char** argv) {
    uint32_t frames = 0;
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0) {
            frames = static_cast<uint32_t>(std::strtoul(argv[i + 1], nullptr, 10));
        }
    }
    return candela::editor::runEditorWindow(frames);
}
