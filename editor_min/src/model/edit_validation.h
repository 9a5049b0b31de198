#pragma once
// The editor's side of the rules the scene loader applies (content/component_validation.h),
// so the editor never saves a value the loader would then drop: an edit the loader would
// reject is refused, and a value the loader would clamp is clamped here, with a notice.
#include <string>

#include "candela/content/components/atmosphere.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/content/components/collider.h"
#include "candela/content/components/fog.h"
#include "candela/content/components/light.h"
#include "candela/content/components/rigid_body.h"
#include "candela/content/material.h"
#include "candela/ecs/transform.h"

namespace candela::editor {

struct EditCheck {
    bool accepted = true;
    std::string notice;  // why it was refused, or what was clamped; empty when neither
};

// May clamp fields of `value`.
EditCheck checkEdit(content::Light& value);
EditCheck checkEdit(content::Camera& value);
EditCheck checkEdit(content::Fog& value);
EditCheck checkEdit(content::Atmosphere& value);
EditCheck checkEdit(ecs::LocalTransform& value);
EditCheck checkEdit(content::Material& value);
EditCheck checkEdit(content::RigidBody& value);
EditCheck checkEdit(content::Collider& value);
EditCheck checkEdit(content::AudioSource& value);
EditCheck checkEdit(content::AudioListener& value);

// Components without rules (names, ...) are always accepted.
template <class T>
EditCheck checkEdit(T&) {
    return {};
}

}  // namespace candela::editor
