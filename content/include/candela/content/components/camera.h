#pragma once
// Camera component: perspective projection plus physical exposure (EV100).
namespace candela::content {

enum class ExposureMode { Physical, Manual };
enum class Projection { Perspective, Orthographic };

struct Camera {
    Projection projection = Projection::Perspective;
    float verticalFov = 0.8726646f;  // radians (50 degrees)
    float nearPlane = 0.05f;         // metres
    float farPlane = 500.0f;         // metres; reverse-Z keeps precision, far only bounds clusters
    float orthographicHalfHeight = 1.0f;  // metres; used when projection == Orthographic
    ExposureMode exposureMode = ExposureMode::Physical;
    float aperture = 16.0f;  // f-stops
    float shutterSeconds = 1.0f / 100.0f;
    float iso = 100.0f;
    float manualEv100 = 0.0f;  // used when exposureMode == Manual
    float exposureCompensation = 0.0f;
};

}  // namespace candela::content
