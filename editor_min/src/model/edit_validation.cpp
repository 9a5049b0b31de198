#include "model/edit_validation.h"

#include <array>

#include "candela/content/component_validation.h"

namespace candela::editor {

namespace {

// "lumens: must not be negative, got -1; attenuationRadius: ..." with the refusals first.
EditCheck fromProblems(const content::ValueProblems& problems) {
    EditCheck check;
    check.accepted = !content::anyRejected(problems);
    for (bool clamped : {false, true}) {
        for (const content::ValueProblem& p : problems) {
            if (p.clamped != clamped) continue;
            if (!check.notice.empty()) check.notice += "; ";
            check.notice += p.field + ": " + p.message;
        }
    }
    return check;
}

}  // namespace

EditCheck checkEdit(content::Light& value) {
    return fromProblems(content::validateLight(value));
}

EditCheck checkEdit(content::Camera& value) {
    return fromProblems(content::validateCamera(value));
}

EditCheck checkEdit(content::Fog& value) {
    return fromProblems(content::validateFog(value));
}

EditCheck checkEdit(content::Atmosphere& value) {
    return fromProblems(content::validateAtmosphere(value));
}

EditCheck checkEdit(content::RigidBody& value) {
    return fromProblems(content::validateRigidBody(value));
}

EditCheck checkEdit(content::Collider& value) {
    return fromProblems(content::validateCollider(value));
}

EditCheck checkEdit(content::AudioSource& value) {
    return fromProblems(content::validateAudioSource(value));
}

EditCheck checkEdit(content::AudioListener& value) {
    return fromProblems(content::validateAudioListener(value));
}

EditCheck checkEdit(ecs::LocalTransform& value) {
    const ecs::Quat& q = value.rotation;
    return fromProblems(content::validateRotation(std::array<float, 4>{q.x, q.y, q.z, q.w}));
}

EditCheck checkEdit(content::Material& value) {
    content::ValueProblems problems = content::validateMaterialFactors(value);
    for (content::ValueProblem& p : content::validateEmission(value))
        problems.push_back(std::move(p));
    return fromProblems(problems);
}

}  // namespace candela::editor
