#include <algorithm>

#include "candela/content/components/animation.h"
#include "candela/content/model.h"

namespace candela::content {

void AnimationPlayer::play(std::int32_t clipIndex, bool looping) {
    clip = clipIndex;
    time = 0;
    loop = looping;
    playing = true;
    nextClip = -1;
    fadeElapsed = fadeDuration = nextTime = 0;
}

void AnimationPlayer::crossfade(std::int32_t clipIndex, float seconds) {
    if (clip < 0 || !(seconds > 0)) {
        play(clipIndex, loop);
        return;
    }
    nextClip = clipIndex;
    nextTime = 0;
    fadeDuration = seconds;
    fadeElapsed = 0;
    playing = true;
}

std::int32_t AnimationPlayer::findClip(std::string_view name) const {
    if (model == nullptr) return -1;
    for (std::size_t i = 0; i < model->animations.size(); ++i) {
        if (model->animations[i].name == name) return static_cast<std::int32_t>(i);
    }
    return -1;
}

std::string AnimationPlayer::playByNameOrIndex(const std::string& nameOrIndex) {
    std::int32_t index = findClip(nameOrIndex);
    const std::size_t count = model ? model->animations.size() : 0;
    if (index < 0 && !nameOrIndex.empty() &&
        nameOrIndex.find_first_not_of("0123456789") == std::string::npos &&
        nameOrIndex.size() < 9) {
        const long value = std::stol(nameOrIndex);
        if (value >= 0 && static_cast<std::size_t>(value) < count)
            index = static_cast<std::int32_t>(value);
    }
    if (index >= 0) {
        play(index, true);
        return {};
    }
    std::string available;
    for (std::size_t i = 0; i < count; ++i) {
        available += (i ? ", " : "") + std::to_string(i) + " '" + model->animations[i].name + "'";
    }
    return "no animation '" + nameOrIndex +
           "' (available: " + (available.empty() ? std::string("none") : available) + ")";
}

float AnimationPlayer::fadeWeight() const {
    if (nextClip < 0 || !(fadeDuration > 0)) return 0;
    return std::clamp(fadeElapsed / fadeDuration, 0.0f, 1.0f);
}

}  // namespace candela::content
