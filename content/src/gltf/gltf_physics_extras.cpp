#include "gltf_physics_extras.h"

#include <nlohmann/json.hpp>

#include <span>

#include "candela/content/scene_file.h"

namespace candela::content {

// The scene reader does the reading: the two objects become the one entity of a scene, and
// its messages are renamed from that entity to the node.
PhysicsExtras readPhysicsExtras(const std::string& extrasJson, const std::string& file,
                                const std::string& element, Diagnostics& diagnostics) {
    PhysicsExtras out;
    if (extrasJson.find("rigidBody") == std::string::npos &&
        extrasJson.find("collider") == std::string::npos) {
        return out;
    }
    const nlohmann::json extras = nlohmann::json::parse(extrasJson, nullptr, false);
    if (!extras.is_object()) return out;
    nlohmann::json entity = nlohmann::json::object();
    for (const char* key : {"rigidBody", "collider"}) {
        if (auto it = extras.find(key); it != extras.end()) entity[key] = *it;
    }
    if (entity.empty()) return out;
    const nlohmann::json scene = {{"format", "candela.scene"},
                                  {"version", kSceneFileVersion},
                                  {"entities", nlohmann::json::array({entity})}};
    const std::string text = scene.dump();
    Diagnostics said;
    const std::optional<SceneDocument> read =
        parseSceneJson(std::as_bytes(std::span(text)), file, said);
    static const std::string kEntity = "/entities/0/";
    for (Diagnostic& d : said.messages) {
        if (d.element.rfind(kEntity, 0) == 0) {
            d.element = element + ".extras/" + d.element.substr(kEntity.size());
        }
        diagnostics.messages.push_back(std::move(d));
    }
    if (read && !read->entities.empty()) {
        out.rigidBody = read->entities[0].rigidBody;
        out.collider = read->entities[0].collider;
    }
    return out;
}

}  // namespace candela::content
