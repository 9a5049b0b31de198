#pragma once
// Scripted editor sessions (tests, demos): a text file of steps, one run per frame, doing what
// the panels do through the same commands.
//
//   # comment
//   open <scene>                 load a scene file or glTF (replaces the open scene)
//   select <name>                the first entity in scene order with that Name
//   set <property> <v>...        e.g. set light.lumens 1600 (model/property_edits.h)
//   rename <name>
//   create empty|point|spot [<name>]   under the selection (or at the root)
//   duplicate | delete           the selection
//   reparent <parent name>|-     the selection under that entity (-: a root)
//   undo | redo
//   save [<path>]                the scene file (default: the opened scene file)
//   screenshot <path>            this frame, UI included, as PNG (or EXR: scene radiance)
//   wait <frames>
//   quit
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace candela::editor {

class EditorScene;

struct ScriptStep {
    std::string where;  // "file:line", for messages
    std::string verb;
    std::string text;           // the rest of the line after the verb, trimmed
    std::vector<float> values;  // `set`: the numbers after the property
    std::string property;       // `set`: the property name
    uint32_t count = 0;         // `wait`
};

class EditorScript {
public:
    // Larger files, and FIFOs, devices or directories, are refused naming the file.
    static constexpr std::uint64_t kMaxFileBytes = 16ull * 1024 * 1024;
    static std::optional<EditorScript> load(const std::filesystem::path& path, std::string& error);
    static std::optional<EditorScript> parse(const std::string& text, const std::string& source,
                                             std::string& error);

    bool finished() const { return next_ >= steps_.size(); }
    // The step to run this frame, or null while waiting / when finished.
    const ScriptStep* nextStep();
    const std::vector<ScriptStep>& steps() const { return steps_; }

private:
    std::vector<ScriptStep> steps_;
    size_t next_ = 0;
    uint32_t waitFrames_ = 0;
};

// Runs the steps that only touch the model (select, set, rename, create, duplicate, delete,
// reparent, undo, redo). Returns false with `error` ("file:line: ...") when the step failed;
// `handled` is false for steps the app runs itself (open, save, screenshot, wait, quit).
bool runModelStep(EditorScene& scene, const ScriptStep& step, bool& handled, std::string& error);

}  // namespace candela::editor
