// One homogeneous step of a ray through the medium, shared by the ray march and the froxel
// integration.
#ifndef CANDELA_VOLUMETRIC_STEP_GLSL
#define CANDELA_VOLUMETRIC_STEP_GLSL

// Integrates a step of length dt with constant medium m (in-scattering, extinction) into the
// running (radiance, transmittance): exact for a homogeneous step (Hillaire 2015).
void integrateStep(vec4 m, float dt, inout vec3 radiance, inout float transmittance) {
    float stepTransmittance = exp(-m.w * dt);
    float weight = m.w > 1e-7 ? (1.0 - stepTransmittance) / m.w : dt;
    radiance += transmittance * m.rgb * weight;
    transmittance *= stepTransmittance;
}

#endif
