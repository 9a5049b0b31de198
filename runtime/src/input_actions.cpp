#include "candela/runtime/input_actions.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "candela/content/file_bytes.h"

namespace candela::runtime {
namespace {

constexpr std::uint64_t kMaxBindingsBytes = 1024 * 1024;  // a file a person edits

const char* const kSpellings =
    "key:<A-Z, 0-9, Space, Left, ...>, mouse:left|right|middle, pad:<A, B, X, Y, DpadUp, ...>";

std::vector<InputBinding> parseAll(const std::vector<std::string_view>& spellings) {
    std::vector<InputBinding> out;
    for (std::string_view spelling : spellings) {
        const std::optional<InputBinding> binding = parseInputBinding(spelling);
        if (!binding) {
            throw std::invalid_argument("InputActions: '" + std::string(spelling) +
                                        "' is not a binding (" + kSpellings + ")");
        }
        out.push_back(*binding);
    }
    return out;
}

bool anyDown(const std::vector<InputBinding>& bindings, const InputState& input) {
    return std::any_of(bindings.begin(), bindings.end(),
                       [&](const InputBinding& b) { return b.down(input); });
}

std::optional<GamepadAxis> parseStick(std::string_view spelling) {
    if (!spelling.starts_with("pad:")) return std::nullopt;
    return gamepadAxisFromName(spelling.substr(4));
}

}  // namespace

std::optional<InputBinding> parseInputBinding(std::string_view spelling) {
    const auto colon = spelling.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    const std::string_view device = spelling.substr(0, colon);
    const std::string_view name = spelling.substr(colon + 1);
    if (device == "key") {
        if (auto key = keyFromName(name)) {
            return InputBinding{InputBinding::Device::Key, std::uint8_t(*key)};
        }
    } else if (device == "mouse") {
        if (auto button = mouseButtonFromName(name)) {
            return InputBinding{InputBinding::Device::Mouse, std::uint8_t(*button)};
        }
    } else if (device == "pad") {
        if (auto button = gamepadButtonFromName(name)) {
            return InputBinding{InputBinding::Device::Pad, std::uint8_t(*button)};
        }
    }
    return std::nullopt;
}

bool InputBinding::down(const InputState& input) const {
    switch (device) {
        case Device::Key:
            return input.down(Key(index));
        case Device::Mouse:
            return input.down(MouseButton(index));
        case Device::Pad:
            return input.down(GamepadButton(index));
    }
    return false;
}

bool InputBinding::pressed(const InputState& input) const {
    switch (device) {
        case Device::Key:
            return input.pressed(Key(index));
        case Device::Mouse:
            return input.pressed(MouseButton(index));
        case Device::Pad:
            return input.pressed(GamepadButton(index));
    }
    return false;
}

void InputActions::bindButton(std::string name, std::vector<std::string_view> bindings) {
    std::vector<InputBinding> parsed = parseAll(bindings);
    std::erase_if(buttons_, [&](const Button& b) { return b.name == name; });
    buttons_.push_back({std::move(name), std::move(parsed)});
}

void InputActions::bindAxis(std::string name, std::vector<std::string_view> negative,
                            std::vector<std::string_view> positive, std::string_view stick,
                            float deadZone) {
    Axis axis{std::move(name), parseAll(negative), parseAll(positive), std::nullopt, deadZone};
    if (!stick.empty()) {
        axis.stick = parseStick(stick);
        if (!axis.stick) {
            throw std::invalid_argument("InputActions: '" + std::string(stick) +
                                        "' is not a stick (pad:LeftX, pad:LeftY, ...)");
        }
    }
    if (!(deadZone >= 0.0f && deadZone < 1.0f)) {
        throw std::invalid_argument("InputActions: a dead zone lies in [0, 1)");
    }
    std::erase_if(axes_, [&](const Axis& a) { return a.name == axis.name; });
    axes_.push_back(std::move(axis));
}

std::string InputActions::loadBindings(const std::filesystem::path& path) {
    const content::FileBytes file = content::readFileBytes(path, kMaxBindingsBytes);
    if (!file.error.empty()) return path.string() + ": cannot read bindings: " + file.error;
    return parseBindings(
        std::string_view(reinterpret_cast<const char*>(file.bytes.data()), file.bytes.size()),
        path.string());
}

std::string InputActions::parseBindings(std::string_view text, const std::string& source) {
    const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
    if (!root.is_object()) return source + ": not a bindings file (a JSON object)";
    // Read everything into copies first: a file with any problem changes nothing.
    std::vector<Button> buttons = buttons_;
    std::vector<Axis> axes = axes_;
    const auto list = [&](const nlohmann::json& j, const std::string& where,
                          std::vector<InputBinding>& out) -> std::string {
        if (!j.is_array()) return source + ": " + where + ": expected a list of bindings";
        out.clear();
        for (const nlohmann::json& item : j) {
            const std::optional<InputBinding> binding =
                item.is_string() ? parseInputBinding(item.get<std::string>()) : std::nullopt;
            if (!binding) {
                return source + ": " + where + ": '" +
                       (item.is_string() ? item.get<std::string>() : item.dump()) +
                       "' is not a binding (" + kSpellings + ")";
            }
            out.push_back(*binding);
        }
        return {};
    };
    const auto names = [](const auto& all) {
        std::string out;
        for (const auto& a : all)
            out += (out.empty() ? "" : ", ") + a.name;
        return out;
    };
    for (const auto& [key, value] : root.items()) {
        if (key != "buttons" && key != "axes") {
            return source + ": unknown key '" + key + "' (buttons, axes)";
        }
        if (!value.is_object()) return source + ": " + key + ": expected an object";
    }
    if (auto it = root.find("buttons"); it != root.end()) {
        for (const auto& [name, value] : it->items()) {
            auto button = std::find_if(buttons.begin(), buttons.end(),
                                       [&](const Button& b) { return b.name == name; });
            if (button == buttons.end()) {
                return source + ": buttons: unknown action '" + name + "' (" + names(buttons) + ")";
            }
            if (std::string e = list(value, "buttons/" + name, button->bindings); !e.empty())
                return e;
        }
    }
    if (auto it = root.find("axes"); it != root.end()) {
        for (const auto& [name, value] : it->items()) {
            auto axis = std::find_if(axes.begin(), axes.end(),
                                     [&](const Axis& a) { return a.name == name; });
            if (axis == axes.end()) {
                return source + ": axes: unknown action '" + name + "' (" + names(axes) + ")";
            }
            const std::string where = "axes/" + name;
            if (!value.is_object()) return source + ": " + where + ": expected an object";
            for (const auto& [field, entry] : value.items()) {
                if (field == "negative" || field == "positive") {
                    auto& target = field == "negative" ? axis->negative : axis->positive;
                    if (std::string e = list(entry, where + "/" + field, target); !e.empty())
                        return e;
                } else if (field == "stick") {
                    const auto stick =
                        entry.is_string() ? parseStick(entry.get<std::string>()) : std::nullopt;
                    if (!stick) {
                        return source + ": " + where + "/stick: '" +
                               (entry.is_string() ? entry.get<std::string>() : entry.dump()) +
                               "' is not a stick (pad:LeftX, pad:LeftY, pad:RightX, pad:RightY, "
                               "pad:LeftTrigger, pad:RightTrigger)";
                    }
                    axis->stick = stick;
                } else if (field == "deadZone") {
                    const double zone = entry.is_number() ? entry.get<double>() : -1.0;
                    if (!(zone >= 0.0 && zone < 1.0)) {
                        return source + ": " + where + "/deadZone: expected a number in [0, 1)";
                    }
                    axis->deadZone = float(zone);
                } else {
                    return source + ": " + where + ": unknown key '" + field +
                           "' (negative, positive, stick, deadZone)";
                }
            }
        }
    }
    buttons_ = std::move(buttons);
    axes_ = std::move(axes);
    return {};
}

const InputActions::Button* InputActions::findButton(std::string_view name) const {
    for (const Button& b : buttons_)
        if (b.name == name) return &b;
    return nullptr;
}

const InputActions::Axis* InputActions::findAxis(std::string_view name) const {
    for (const Axis& a : axes_)
        if (a.name == name) return &a;
    return nullptr;
}

bool InputActions::down(std::string_view button, const InputState& input) const {
    const Button* b = findButton(button);
    return b && anyDown(b->bindings, input);
}

bool InputActions::pressed(std::string_view button, const InputState& input) const {
    const Button* b = findButton(button);
    return b && std::any_of(b->bindings.begin(), b->bindings.end(),
                            [&](const InputBinding& binding) { return binding.pressed(input); });
}

float InputActions::axis(std::string_view name, const InputState& input) const {
    const Axis* a = findAxis(name);
    if (!a) return 0.0f;
    float value = float(anyDown(a->positive, input)) - float(anyDown(a->negative, input));
    if (a->stick) {
        const float raw = input.axis(*a->stick);
        const float tilt = std::fabs(raw);
        if (tilt > a->deadZone) {
            value +=
                std::copysign((std::min(tilt, 1.0f) - a->deadZone) / (1.0f - a->deadZone), raw);
        }
    }
    return std::clamp(value, -1.0f, 1.0f);
}

}  // namespace candela::runtime
