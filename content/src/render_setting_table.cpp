#include "candela/content/render_setting_table.h"

namespace candela::content {

RenderSettings resolveRenderSettings(QualityLevel level,
                                     std::initializer_list<const RenderSettingChoices*> choices) {
    RenderSettings settings;
    forEachRenderSetting([&](const auto& row) {
        settings.*row.value = row.presets[static_cast<std::size_t>(level)];
        for (const RenderSettingChoices* source : choices) {
            if (source && (source->*row.choice)) {
                settings.*row.value = *(source->*row.choice);
                break;
            }
        }
    });
    return settings;
}

}  // namespace candela::content
