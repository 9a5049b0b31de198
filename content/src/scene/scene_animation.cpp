#include "scene_animation.h"

#include <cmath>

#include "candela/content/model.h"

namespace candela::content {
namespace {

std::string clipList(const Model& model) {
    std::string list;
    for (std::size_t i = 0; i < model.animations.size(); ++i)
        list += (i ? ", " : "") + std::to_string(i) + " '" + model.animations[i].name + "'";
    return list.empty() ? "none" : list;
}

// The clip's index, or -1 with `message` set.
std::int32_t resolveClip(const SceneClip& clip, const AnimationPlayer& player,
                         std::string& message) {
    const std::size_t count = player.model->animations.size();
    if (!clip.name.empty()) {
        const std::int32_t index = player.findClip(clip.name);
        if (index < 0) {
            message = "no clip named '" + clip.name + "' (clips: " + clipList(*player.model) + ")";
        }
        return index;
    }
    if (clip.index < 0 || static_cast<std::size_t>(clip.index) >= count) {
        message =
            "no clip " + std::to_string(clip.index) + " (clips: " + clipList(*player.model) + ")";
        return -1;
    }
    return clip.index;
}

SceneClip sceneClip(const AnimationPlayer& player, std::int32_t index) {
    const std::string& name = player.model->animations[static_cast<std::size_t>(index)].name;
    // A name that another clip before it shares would load as that clip: keep the index.
    if (!name.empty() && player.findClip(name) == index) return SceneClip{name, 0};
    return SceneClip{"", index};
}

}  // namespace

std::optional<SceneAnimationProblem> restoreAnimationPlayer(const SceneAnimation& state,
                                                            AnimationPlayer& player) {
    const auto reset = [&](std::string pointer, std::string message) {
        player.play(player.model->animations.empty() ? -1 : 0, true);
        return SceneAnimationProblem{std::move(pointer), std::move(message)};
    };
    // The reader rejects these already; a document built in code may still hold them.
    if (!std::isfinite(state.time)) return reset("/time", "expected a finite number of seconds");
    if (!std::isfinite(state.speed)) return reset("/speed", "expected a finite number");
    if (state.crossfade &&
        (!(state.crossfade->duration > 0) || !std::isfinite(state.crossfade->duration) ||
         !std::isfinite(state.crossfade->time) || !(state.crossfade->elapsed >= 0) ||
         state.crossfade->elapsed > state.crossfade->duration)) {
        return reset("/crossfade", "expected a duration > 0 and 0 <= elapsed <= duration");
    }
    std::string message;
    const std::int32_t clip = resolveClip(state.clip, player, message);
    if (clip < 0) return reset("/clip", message);
    std::int32_t next = -1;
    if (state.crossfade) {
        next = resolveClip(state.crossfade->clip, player, message);
        if (next < 0) return reset("/crossfade/clip", message);
    }
    player.play(clip, state.loop);
    player.time = state.time;
    player.speed = state.speed;
    player.playing = state.playing;
    if (state.crossfade) {
        player.nextClip = next;
        player.nextTime = state.crossfade->time;
        player.fadeDuration = state.crossfade->duration;
        player.fadeElapsed = state.crossfade->elapsed;
    }
    return std::nullopt;
}

std::optional<SceneAnimation> captureAnimationPlayer(const AnimationPlayer& player) {
    const auto valid = [&](std::int32_t clip) {
        return player.model && clip >= 0 &&
               static_cast<std::size_t>(clip) < player.model->animations.size();
    };
    if (!valid(player.clip)) return std::nullopt;
    SceneAnimation state;
    state.clip = sceneClip(player, player.clip);
    state.time = player.time;
    state.speed = player.speed;
    state.loop = player.loop;
    state.playing = player.playing;
    if (valid(player.nextClip) && player.fadeDuration > 0) {
        state.crossfade =
            SceneAnimation::Crossfade{sceneClip(player, player.nextClip), player.nextTime,
                                      player.fadeDuration, player.fadeElapsed};
    }
    return state;
}

}  // namespace candela::content
