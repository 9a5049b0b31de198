#pragma once
// candela-editor's command line:
//   candela-editor [<scene>] [--script FILE] [--size WxH] [--frames N]
//                  [--validation off|on|require]
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "candela/render/validation_mode.h"

namespace candela::editor {

struct EditorOptions {
    std::optional<std::filesystem::path> scene;   // a .json scene file, .gltf or .glb
    std::optional<std::filesystem::path> script;  // steps run one per frame (editor_script.h)
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;  // 0: until the window closes (or the script quits)
    render::ValidationMode validation = render::ValidationMode::IfPresent;
    bool physicsDebug = false;  // --physics-debug: colliders drawn as wires (the runtime's flag)
};

// Parses argv; nullopt with `error` set on bad arguments, or when --help was asked (`error`
// then holds the usage text and `helpRequested` is set).
std::optional<EditorOptions> parseEditorOptions(int argc, const char* const* argv,
                                                std::string& error, bool& helpRequested);

std::string editorUsage();

}  // namespace candela::editor
