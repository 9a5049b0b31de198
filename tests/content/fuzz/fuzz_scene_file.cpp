// libFuzzer target: any bytes through the scene-file parser; whatever parses must save and
// parse back to the same text (the round-trip promise).
#include <cstddef>
#include <cstdint>

#include "candela/content/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace candela::content;
    Diagnostics diagnostics;
    auto scene =
        parseSceneJson({reinterpret_cast<const std::byte*>(data), size}, "fuzz.json", diagnostics);
    if (!scene) return 0;
    std::string error;
    const std::string text = sceneToJson(*scene, error);
    if (!error.empty()) return 0;  // e.g. non-finite values cannot be written
    Diagnostics again;
    auto reparsed = parseSceneJson({reinterpret_cast<const std::byte*>(text.data()), text.size()},
                                   "fuzz-resaved.json", again);
    if (!reparsed || again.hasErrors()) __builtin_trap();
    std::string error2;
    if (sceneToJson(*reparsed, error2) != text) __builtin_trap();
    return 0;
}
