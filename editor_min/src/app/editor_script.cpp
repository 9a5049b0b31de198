#include "app/editor_script.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "candela/content/components/light.h"
#include "candela/content/components/name.h"
#include "candela/content/file_bytes.h"
#include "model/editor_scene.h"
#include "model/property_edits.h"
#include "model/set_component_command.h"
#include "model/structure_commands.h"

namespace candela::editor {

namespace {

std::string trim(const std::string& s) {
    const size_t begin = s.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return {};
    const size_t end = s.find_last_not_of(" \t\r");
    return s.substr(begin, end - begin + 1);
}

const std::set<std::string>& knownVerbs() {
    static const std::set<std::string> verbs = {
        "open",     "select", "set",  "rename", "create",     "duplicate", "delete",
        "reparent", "undo",   "redo", "save",   "screenshot", "wait",      "quit"};
    return verbs;
}

}  // namespace

std::optional<EditorScript> EditorScript::load(const std::filesystem::path& path,
                                               std::string& error) {
    content::FileBytes file = content::readFileBytes(path, kMaxFileBytes);
    if (!file.error.empty()) {
        error = path.string() + ": cannot read the script: " + file.error;
        return std::nullopt;
    }
    return parse(std::string(reinterpret_cast<const char*>(file.bytes.data()), file.bytes.size()),
                 path.string(), error);
}

std::optional<EditorScript> EditorScript::parse(const std::string& text, const std::string& source,
                                                std::string& error) {
    EditorScript script;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        ScriptStep step;
        step.where = source + ":" + std::to_string(number);
        const size_t space = line.find_first_of(" \t");
        step.verb = line.substr(0, space);
        step.text = space == std::string::npos ? std::string() : trim(line.substr(space));
        auto fail = [&](const std::string& message) {
            error = step.where + ": " + message;
            return std::nullopt;
        };
        if (!knownVerbs().count(step.verb)) return fail("unknown step '" + step.verb + "'");
        const bool needsText = step.verb == "open" || step.verb == "select" || step.verb == "set" ||
                               step.verb == "rename" || step.verb == "create" ||
                               step.verb == "reparent" || step.verb == "screenshot" ||
                               step.verb == "wait";
        if (needsText && step.text.empty()) return fail(step.verb + " needs an argument");
        if (step.verb == "set") {
            std::istringstream words(step.text);
            words >> step.property;
            std::string word;
            while (words >> word) {
                char* end = nullptr;
                const float value = std::strtof(word.c_str(), &end);
                if (end == word.c_str() || *end != '\0' || !std::isfinite(value)) {
                    return fail("set: '" + word + "' is not a number");
                }
                step.values.push_back(value);
            }
            if (step.values.empty()) return fail("set " + step.property + " needs values");
        } else if (step.verb == "wait") {
            char* end = nullptr;
            const unsigned long frames = std::strtoul(step.text.c_str(), &end, 10);
            if (*end != '\0' || frames > 100000) return fail("wait: bad frame count");
            step.count = uint32_t(frames);
        } else if (step.verb == "create") {
            const std::string kind = step.text.substr(0, step.text.find(' '));
            if (kind != "empty" && kind != "point" && kind != "spot") {
                return fail("create: '" + kind + "' is not empty, point or spot");
            }
        }
        script.steps_.push_back(std::move(step));
    }
    return script;
}

const ScriptStep* EditorScript::nextStep() {
    if (waitFrames_ > 0) {
        --waitFrames_;
        return nullptr;
    }
    if (finished()) return nullptr;
    const ScriptStep* step = &steps_[next_++];
    if (step->verb == "wait") waitFrames_ = step->count;
    return step;
}

bool runModelStep(EditorScene& scene, const ScriptStep& step, bool& handled, std::string& error) {
    handled = true;
    auto fail = [&](const std::string& message) {
        error = step.where + ": " + step.verb + ": " + message;
        return false;
    };
    const ecs::Entity selected = scene.selected();
    if (step.verb == "select") {
        const ecs::Entity e = scene.findByName(step.text);
        if (e == ecs::kNullEntity) return fail("no entity named '" + step.text + "'");
        scene.select(e);
        return true;
    }
    if (step.verb == "undo") return scene.undo() || fail("nothing to undo");
    if (step.verb == "redo") return scene.redo() || fail("nothing to redo");
    if (step.verb == "create") {
        const size_t space = step.text.find(' ');
        const std::string kind = step.text.substr(0, space);
        std::string name = space == std::string::npos ? kind : trim(step.text.substr(space));
        std::optional<content::Light> light;
        if (kind != "empty") {
            light = content::Light{};
            if (kind == "spot") light->type = content::LightType::Spot;
        }
        auto command = std::make_unique<CreateEntityCommand>(scene, selected, name, light);
        const uint64_t id = command->createdId();
        if (!scene.execute(std::move(command))) return fail("could not create");
        scene.selectId(id);
        return true;
    }
    const bool needsSelection = step.verb == "set" || step.verb == "rename" ||
                                step.verb == "duplicate" || step.verb == "delete" ||
                                step.verb == "reparent";
    if (!needsSelection) {
        handled = false;
        return true;
    }
    if (selected == ecs::kNullEntity) return fail("nothing selected");
    std::unique_ptr<EditCommand> command;
    std::string why;
    if (step.verb == "set") {
        std::string notice;
        command = propertyEdit(scene, selected, step.property, step.values, why, &notice);
        if (!command) return fail(why);
        if (!notice.empty()) {
            std::fprintf(stderr, "%s: set: %s: clamped: %s\n", step.where.c_str(),
                         step.property.c_str(), notice.c_str());
        }
    } else if (step.verb == "rename") {
        command = setComponent(scene, selected, content::Name{step.text}, "Rename");
    } else if (step.verb == "duplicate") {
        uint64_t copy = 0;
        command = duplicateEntity(scene, selected, &copy);
        if (!scene.execute(std::move(command))) return fail("could not duplicate");
        scene.selectId(copy);
        return true;
    } else if (step.verb == "delete") {
        command = deleteEntity(scene, selected);
    } else if (step.verb == "reparent") {
        ecs::Entity parent = ecs::kNullEntity;
        if (step.text != "-") {
            parent = scene.findByName(step.text);
            if (parent == ecs::kNullEntity) return fail("no entity named '" + step.text + "'");
        }
        command = reparentEntity(scene, selected, parent);
    }
    if (!command || !scene.execute(std::move(command))) return fail("the edit did not apply");
    return true;
}

}  // namespace candela::editor
