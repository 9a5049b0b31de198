// Environment layout detection and resampling into Vulkan cube faces. OpenEXR's own cube
// layout is resolved with OpenEXR's CubeMap functions, so its face orientation is never
// re-derived by hand.
#include "candela/content/environment_map.h"

#include <OpenEXR/ImfEnvmap.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace candela::content {
namespace {

// Bilinear sample of `image` at continuous texel position (x, y), clamped to the rectangle
// [x0, x1] x [y0, y1] (one cube face inside a strip), writing RGBA to out.
void sampleClamped(const FloatImage& image, float x, float y, int x0, int y0, int x1, int y1,
                   float* out) {
    x = std::clamp(x, static_cast<float>(x0), static_cast<float>(x1));
    y = std::clamp(y, static_cast<float>(y0), static_cast<float>(y1));
    const int ix = std::min(static_cast<int>(x), x1);
    const int iy = std::min(static_cast<int>(y), y1);
    const int jx = std::min(ix + 1, x1);
    const int jy = std::min(iy + 1, y1);
    const float fx = x - static_cast<float>(ix);
    const float fy = y - static_cast<float>(iy);
    const auto at = [&](int px, int py) {
        return image.texel(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py));
    };
    for (int c = 0; c < 4; ++c) {
        const float top = at(ix, iy)[c] * (1 - fx) + at(jx, iy)[c] * fx;
        const float bottom = at(ix, jy)[c] * (1 - fx) + at(jx, jy)[c] * fx;
        out[c] = top * (1 - fy) + bottom * fy;
    }
}

FloatImage blankFace(std::uint32_t size) {
    FloatImage face;
    face.width = face.height = size;
    face.rgba.assign(std::size_t{size} * size * 4, 0.0f);
    return face;
}

// OpenEXR's cube layout: a w x 6w strip whose faces OpenEXR orients its own way.
std::array<FloatImage, 6> facesFromOpenExrCube(const FloatImage& strip) {
    const std::uint32_t size = strip.width;
    const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(static_cast<int>(strip.width) - 1,
                                                           static_cast<int>(strip.height) - 1));
    std::array<FloatImage, 6> faces;
    for (int f = 0; f < 6; ++f) {
        faces[static_cast<std::size_t>(f)] = blankFace(size);
        for (std::uint32_t j = 0; j < size; ++j) {
            for (std::uint32_t i = 0; i < size; ++i) {
                const auto d =
                    cubeFaceDirection(static_cast<CubeFace>(f),
                                      (static_cast<float>(i) + 0.5f) / static_cast<float>(size),
                                      (static_cast<float>(j) + 0.5f) / static_cast<float>(size));
                Imf::CubeMapFace sourceFace;
                Imath::V2f inFace;
                Imf::CubeMap::faceAndPixelPosition(Imath::V3f(d[0], d[1], d[2]), window, sourceFace,
                                                   inFace);
                const Imath::V2f position = Imf::CubeMap::pixelPosition(sourceFace, window, inFace);
                const Imath::Box2i faceWindow = Imf::CubeMap::dataWindowForFace(sourceFace, window);
                sampleClamped(strip, position.x, position.y, faceWindow.min.x, faceWindow.min.y,
                              faceWindow.max.x, faceWindow.max.y,
                              faces[static_cast<std::size_t>(f)].texel(i, j));
            }
        }
    }
    return faces;
}

// Copies an N x N block at block coordinates (bx, by), optionally rotated 180 degrees.
FloatImage cutFace(const FloatImage& image, std::uint32_t size, std::uint32_t bx, std::uint32_t by,
                   bool rotate180) {
    FloatImage face = blankFace(size);
    for (std::uint32_t j = 0; j < size; ++j) {
        for (std::uint32_t i = 0; i < size; ++i) {
            const std::uint32_t si = rotate180 ? size - 1 - i : i;
            const std::uint32_t sj = rotate180 ? size - 1 - j : j;
            std::copy_n(image.texel(bx * size + si, by * size + sj), 4, face.texel(i, j));
        }
    }
    return face;
}

}  // namespace

std::array<float, 3> cubeFaceDirection(CubeFace face, float s, float t) {
    const float u = 2 * s - 1;
    const float v = 2 * t - 1;
    std::array<float, 3> d{};
    switch (face) {  // inverse of the Vulkan spec's cube face selection table
        case CubeFace::PositiveX:
            d = {1, -v, -u};
            break;
        case CubeFace::NegativeX:
            d = {-1, -v, u};
            break;
        case CubeFace::PositiveY:
            d = {u, 1, v};
            break;
        case CubeFace::NegativeY:
            d = {u, -1, -v};
            break;
        case CubeFace::PositiveZ:
            d = {u, -v, 1};
            break;
        case CubeFace::NegativeZ:
            d = {-u, -v, -1};
            break;
    }
    const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (float& c : d)
        c /= length;
    return d;
}

std::array<float, 2> latLongTexelPosition(const std::array<float, 3>& d, std::uint32_t width,
                                          std::uint32_t height) {
    const float pi = std::numbers::pi_v<float>;
    const float longitude = (d[0] == 0 && d[2] == 0) ? 0.0f : std::atan2(d[0], d[2]);
    const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const float latitude = std::asin(std::clamp(d[1] / length, -1.0f, 1.0f));
    return {(0.5f - longitude / (2 * pi)) * static_cast<float>(width),
            (0.5f - latitude / pi) * static_cast<float>(height)};
}

std::array<float, 3> latLongDirection(float column, float row, std::uint32_t width,
                                      std::uint32_t height) {
    const float pi = std::numbers::pi_v<float>;
    const float longitude = (0.5f - column / static_cast<float>(width)) * 2 * pi;
    const float latitude = (0.5f - row / static_cast<float>(height)) * pi;
    return {std::sin(longitude) * std::cos(latitude), std::sin(latitude),
            std::cos(longitude) * std::cos(latitude)};
}

std::optional<EnvironmentMap> environmentFromExr(ExrImage exr, const std::string& name,
                                                 Diagnostics& diagnostics) {
    EnvironmentMap env;
    env.replacedNonFiniteTexels = exr.replacedNonFiniteTexels;
    const std::uint32_t w = exr.image.width;
    const std::uint32_t h = exr.image.height;
    const auto useLatLong = [&](EnvironmentSource source) {
        env.layout = EnvironmentLayout::LatLong;
        env.source = source;
        env.latLong = std::move(exr.image);
        return env;
    };
    const auto useCube = [&](EnvironmentSource source, std::array<FloatImage, 6> faces) {
        env.layout = EnvironmentLayout::Cube;
        env.source = source;
        env.cubeFaces = std::move(faces);
        return env;
    };
    switch (exr.envmap) {
        case ExrEnvmapAttribute::LatLong:
            return useLatLong(EnvironmentSource::LatLongEnvmap);
        case ExrEnvmapAttribute::Cube:
            if (h != 6 * w) {
                diagnostics.error(name, "",
                                  "envmap says cube but the image is " + std::to_string(w) + " x " +
                                      std::to_string(h) + " (need width x 6*width)");
                return std::nullopt;
            }
            return useCube(EnvironmentSource::CubeEnvmap, facesFromOpenExrCube(exr.image));
        case ExrEnvmapAttribute::Absent:
            break;
    }
    if (w == 2 * h) return useLatLong(EnvironmentSource::LatLongByAspect);
    if (h == 6 * w)
        return useCube(EnvironmentSource::VerticalStrip, facesFromOpenExrCube(exr.image));
    if (w == 6 * h) {
        std::array<FloatImage, 6> faces;
        for (std::uint32_t f = 0; f < 6; ++f)
            faces[f] = cutFace(exr.image, h, f, 0, false);
        return useCube(EnvironmentSource::HorizontalStrip, std::move(faces));
    }
    if (3 * w == 4 * h && w % 4 == 0) {
        const std::uint32_t n = w / 4;
        return useCube(EnvironmentSource::HorizontalCross,
                       {cutFace(exr.image, n, 2, 1, false), cutFace(exr.image, n, 0, 1, false),
                        cutFace(exr.image, n, 1, 0, false), cutFace(exr.image, n, 1, 2, false),
                        cutFace(exr.image, n, 1, 1, false), cutFace(exr.image, n, 3, 1, false)});
    }
    if (4 * w == 3 * h && w % 3 == 0) {
        const std::uint32_t n = w / 3;
        return useCube(EnvironmentSource::VerticalCross,
                       {cutFace(exr.image, n, 2, 1, false), cutFace(exr.image, n, 0, 1, false),
                        cutFace(exr.image, n, 1, 0, false), cutFace(exr.image, n, 1, 2, false),
                        cutFace(exr.image, n, 1, 1, false), cutFace(exr.image, n, 1, 3, true)});
    }
    diagnostics.warning(name, "",
                        "no envmap attribute and a " + std::to_string(w) + " x " +
                            std::to_string(h) + " image; treated as lat-long");
    return useLatLong(EnvironmentSource::LatLongAssumed);
}

std::optional<EnvironmentMap> loadEnvironmentExr(const std::filesystem::path& path,
                                                 Diagnostics& diagnostics,
                                                 const ExrLimits& limits) {
    auto exr = readExrImage(path, diagnostics, limits);
    if (!exr) return std::nullopt;
    return environmentFromExr(std::move(*exr), path.string(), diagnostics);
}

}  // namespace candela::content
