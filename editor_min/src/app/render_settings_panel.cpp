#include "app/render_settings_panel.h"

#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "candela/content/render_setting_table.h"
#include "model/editor_scene.h"

namespace candela::editor {

namespace {

// A combo of "preset's" and `values`, spelled by the row; true when the choice changed.
template <typename T>
bool drawChoice(const content::RenderSettingRow<T>& row, const char* label,
                const std::vector<T>& values, std::optional<T>& choice) {
    std::vector<std::string> names{"preset's"};
    int current = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        names.push_back(content::renderSettingText(row, values[i]));
        if (choice && *choice == values[i]) current = int(i) + 1;
    }
    bool changed = false;
    if (ImGui::BeginCombo(label, names[std::size_t(current)].c_str())) {
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (ImGui::Selectable(names[i].c_str(), int(i) == current) && int(i) != current) {
                choice = i == 0 ? std::nullopt : std::optional<T>(values[i - 1]);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// A number within the row's range, after a check box that takes it from the preset.
template <typename T>
bool drawNumber(const content::RenderSettingRow<T>& row, const char* label, T presetValue,
                std::optional<T>& choice) {
    bool chosen = choice.has_value();
    const std::string box = std::string("##chosen ") + label;
    bool changed = ImGui::Checkbox(box.c_str(), &chosen);
    if (changed) choice = chosen ? std::optional<T>(presetValue) : std::nullopt;
    ImGui::SameLine();
    if (!choice) {
        ImGui::TextDisabled("%s: preset's %s", label,
                            content::renderSettingText(row, presetValue).c_str());
        return changed;
    }
    T value = *choice;
    if constexpr (std::is_floating_point_v<T>) {
        changed |= ImGui::SliderFloat(label, &value, row.least, row.most);
    } else {
        changed |= ImGui::DragScalar(label, ImGuiDataType_U32, &value, 1.0f, &row.least, &row.most);
    }
    // The scene reader's rules, so what is saved loads back.
    value = std::clamp(value, row.least, row.most);
    choice = value;
    return changed;
}

// Every value a Choice, Toggle or Counts row offers.
template <typename T>
std::vector<T> offeredValues(const content::RenderSettingRow<T>& row) {
    std::vector<T> values;
    for (const content::NamedValue<T>& named : row.names)
        values.push_back(named.value);
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
        if (row.widget == content::SettingWidget::Counts) {
            for (T v = std::max<T>(row.least, 1); v <= row.most; v *= 2)
                values.push_back(v);
        }
    }
    return values;
}

}  // namespace

void drawSceneRenderSettings(EditorScene& scene, InspectorLayout* layout) {
    if (!ImGui::CollapsingHeader("Render settings", ImGuiTreeNodeFlags_DefaultOpen)) return;
    // The preset values shown beside unchosen numbers: the scene's level, else the CPU
    // device's (the editor does not know which device will run the game).
    const content::QualityLevel level =
        scene.sceneQuality().value_or(content::qualityForDevice(true));
    content::RenderSettingChoices settings = scene.sceneRenderSettings();
    bool changed = false;
    content::forEachRenderSetting([&](const auto& row) {
        const std::string label(row.statsName);
        auto& choice = settings.*row.choice;
        switch (row.widget) {
            case content::SettingWidget::Choice:
            case content::SettingWidget::Toggle:
            case content::SettingWidget::Counts:
                changed |= drawChoice(row, label.c_str(), offeredValues(row), choice);
                break;
            case content::SettingWidget::Slider:
            case content::SettingWidget::Count: {
                using T = std::remove_cvref_t<decltype(*choice)>;
                if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
                    changed |= drawNumber(row, label.c_str(),
                                          row.presets[static_cast<std::size_t>(level)], choice);
                }
                break;
            }
        }
        if (layout) (*layout)[label] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
    });
    if (changed) scene.setSceneRenderSettings(settings, true);
    ImGui::TextDisabled("Apply when the scene is next opened");
}

}  // namespace candela::editor
