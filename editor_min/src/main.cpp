// candela-editor [<scene>] [--script FILE] [--size WxH] [--frames N] [--validation MODE]
#include <cstdio>

#include "app/editor_app.h"
#include "app/editor_options.h"

int main(int argc, char** argv) {
    std::string error;
    bool help = false;
    std::optional<candela::editor::EditorOptions> options =
        candela::editor::parseEditorOptions(argc, argv, error, help);
    if (!options) {
        if (help) {
            std::printf("%s", error.c_str());
            return candela::editor::kEditorOk;
        }
        std::fprintf(stderr, "candela-editor: %s\n%s", error.c_str(),
                     candela::editor::editorUsage().c_str());
        return candela::editor::kEditorBadArguments;
    }
    return candela::editor::runEditor(*options);
}
