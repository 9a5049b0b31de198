// glTF entry points: container checks, tinygltf parsing with our file and image hooks,
// required-extension policy, then the conversion steps in dependency order.
#include "candela/content/gltf_loader.h"

#include <array>
#include <sstream>

#include "candela/content/file_bytes.h"
#include "glb_container.h"
#include "gltf_context.h"
#include "gltf_image_callback.h"
#include "json_nesting.h"

namespace candela::content {
namespace {

constexpr std::array kSupportedExtensions = {
    "KHR_lights_punctual",     "KHR_materials_emissive_strength", "KHR_materials_unlit",
    "KHR_texture_transform",   "KHR_materials_specular",          "KHR_materials_anisotropy",
    "KHR_materials_clearcoat",
};

bool isSupported(const std::string& extension) {
    for (const char* supported : kSupportedExtensions) {
        if (extension == supported) return true;
    }
    return false;
}

// tinygltf's file hooks: bounded reads, no shell-style path expansion, and no file access at
// all when the options forbid it.
struct FileAccess {
    bool allowed = true;
    std::uint64_t maxBytes = 0;
};

bool fileExists(const std::string& path, void* user) {
    const auto& access = *static_cast<FileAccess*>(user);
    std::error_code ec;
    return access.allowed && std::filesystem::is_regular_file(path, ec);
}

std::string expandFilePath(const std::string& path, void*) {
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                   void* user) {
    const auto& access = *static_cast<FileAccess*>(user);
    if (!access.allowed) {
        if (error) *error += "external file '" + path + "' not allowed\n";
        return false;
    }
    FileBytes file = readFileBytes(path, access.maxBytes);
    if (!file.error.empty()) {
        if (error) *error += "'" + path + "': " + file.error + "\n";
        return false;
    }
    const auto* begin = reinterpret_cast<const unsigned char*>(file.bytes.data());
    out->assign(begin, begin + file.bytes.size());
    return true;
}

bool writeWholeFile(std::string* error, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    if (error) *error += "the loader never writes files\n";
    return false;
}

void addLines(Diagnostics& diagnostics, const std::string& file, const std::string& text,
              Severity severity) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty()) continue;
        if (severity == Severity::Error)
            diagnostics.error(file, "", "glTF parser: " + line);
        else
            diagnostics.warning(file, "", "glTF parser: " + line);
    }
}

// Parses bytes (GLB or JSON) into a tinygltf document. Returns false with messages added.
bool parseDocument(std::span<const std::byte> bytes, const std::filesystem::path& path,
                   const GltfLoadOptions& options, gltf::ImageCallbackState& images,
                   Diagnostics& diagnostics, tinygltf::Model& document) {
    const std::string file = path.string();
    FileAccess access{options.allowExternalFiles, options.maxFileBytes};
    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(gltf::decodeImageFromUri, &images);
    parser.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, writeWholeFile, &access});
    // The extras' text too: tinygltf's value tree drops empty objects ("hair": {}).
    parser.SetStoreOriginalJSONForExtrasAndExtensions(true);
    std::string error;
    std::string warning;
    const std::string baseDir = path.parent_path().string();
    bool parsed = false;
    try {
        const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
        std::string_view jsonText(reinterpret_cast<const char*>(data), bytes.size());
        std::uint64_t glbLength = 0;
        const bool isGlb = gltf::looksLikeGlb(bytes);
        if (isGlb) {
            if (std::string problem = gltf::checkGlbContainer(bytes, glbLength); !problem.empty()) {
                diagnostics.error(file, "", problem);
                return false;
            }
            jsonText = jsonText.substr(20, gltf::glbJsonLength(bytes));
        }
        if (gltf::jsonNestingDepth(jsonText) > gltf::kMaxJsonNesting) {
            diagnostics.error(
                file, "",
                "JSON is nested deeper than " + std::to_string(gltf::kMaxJsonNesting) + " levels");
            return false;
        }
        if (isGlb) {
            const std::uint64_t length = glbLength;
            parsed = parser.LoadBinaryFromMemory(&document, &error, &warning, data,
                                                 static_cast<unsigned int>(length), baseDir);
        } else {
            parsed = parser.LoadASCIIFromString(&document, &error, &warning,
                                                reinterpret_cast<const char*>(data),
                                                static_cast<unsigned int>(bytes.size()), baseDir);
        }
    } catch (const std::exception& e) {
        error += std::string("exception: ") + e.what() + "\n";
        parsed = false;
    }
    addLines(diagnostics, file, warning, Severity::Warning);
    if (!parsed) {
        addLines(diagnostics, file, error.empty() ? "unknown error\n" : error, Severity::Error);
        return false;
    }
    return true;
}

bool checkAssetAndExtensions(const tinygltf::Model& document, const std::string& file,
                             Diagnostics& diagnostics) {
    if (document.asset.version.empty() || document.asset.version[0] != '2') {
        diagnostics.error(file, "asset.version",
                          "'" + document.asset.version + "' is not glTF 2.x");
        return false;
    }
    bool usable = true;
    for (const std::string& extension : document.extensionsRequired) {
        if (!isSupported(extension)) {
            diagnostics.error(file, "extensionsRequired",
                              "required extension " + extension + " is not supported");
            usable = false;
        }
    }
    for (const std::string& extension : document.extensionsUsed) {
        if (!isSupported(extension)) {
            diagnostics.warning(file, "extensionsUsed",
                                "extension " + extension + " is not supported; ignored");
        }
    }
    return usable;
}

}  // namespace

std::optional<Model> loadGltfFromMemory(std::span<const std::byte> bytes,
                                        const std::filesystem::path& path, Diagnostics& diagnostics,
                                        const GltfLoadOptions& options) {
    const std::string file = path.string();
    if (bytes.empty()) {
        diagnostics.error(file, "", "file is empty");
        return std::nullopt;
    }
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
        diagnostics.error(file, "", "file is over 4 GiB");
        return std::nullopt;
    }
    gltf::ImageCallbackState images;
    images.limits.maxDimension = options.maxImageDimension;
    tinygltf::Model document;
    if (!parseDocument(bytes, path, options, images, diagnostics, document)) return std::nullopt;
    if (!checkAssetAndExtensions(document, file, diagnostics)) return std::nullopt;

    Model model;
    model.sourcePath = path;
    gltf::Context context{document, file, diagnostics, options, model};
    try {
        gltf::convertImages(context, images);
        gltf::convertTextures(context);
        gltf::convertMaterials(context);
        gltf::convertLightsAndCameras(context);
        gltf::convertMeshes(context);
        gltf::convertNodes(context);
        gltf::convertSkins(context);
        gltf::convertAnimations(context);
    } catch (const std::bad_alloc&) {
        diagnostics.error(file, "", "out of memory while converting");
        return std::nullopt;
    }
    return model;
}

std::optional<Model> loadGltf(const std::filesystem::path& path, Diagnostics& diagnostics,
                              const GltfLoadOptions& options) {
    FileBytes file = readFileBytes(path, options.maxFileBytes);
    if (!file.error.empty()) {
        diagnostics.error(path.string(), "", file.error);
        return std::nullopt;
    }
    return loadGltfFromMemory(file.bytes, path, diagnostics, options);
}

}  // namespace candela::content
