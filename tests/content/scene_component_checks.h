#pragma once
// What the scene-file tests of single components share: a scene of one entity holding the
// component as JSON, a scene saved and loaded again, and the check that a bad one is left out
// of the loaded scene with an error naming the file, the element and what is wrong.
#include <gtest/gtest.h>

#include <initializer_list>
#include <span>
#include <string>

#include "candela/content/scene_file.h"

namespace candela::content::testing {

inline std::optional<SceneDocument> parseScene(const std::string& text, const char* fileName,
                                               Diagnostics& diagnostics) {
    return parseSceneJson(std::as_bytes(std::span(text)), fileName, diagnostics);
}

// `scene` written as JSON and read back as `fileName`, failing the test on any error or
// message on the way.
inline std::optional<SceneDocument> savedAndLoaded(const SceneDocument& scene,
                                                   const char* fileName) {
    std::string error;
    const std::string text = sceneToJson(scene, error);
    EXPECT_EQ(error, "");
    Diagnostics diagnostics;
    auto loaded = parseScene(text, fileName, diagnostics);
    EXPECT_TRUE(loaded) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    return loaded;
}

// {"entities": [{"name": "air", <otherFields>"<key>": <json>}]}; otherFields ends in ", ".
inline std::string sceneWithComponent(const std::string& key, const std::string& json,
                                      const std::string& otherFields = "") {
    return R"({"format": "candela.scene", "version": 1, "entities": [{"name": "air", )" +
           otherFields + "\"" + key + "\": " + json + "}]}";
}

struct RejectedComponent {
    std::string scene;
    const char* element;     // the JSON pointer the error names
    const char* words = "";  // and what it says is wrong
};

// Each scene loads without its first entity's component (`present` says whether it has one)
// and with an error naming `fileName`, the element and the words.
template <class Present>
void expectEachComponentIsRejected(const char* fileName,
                                   std::initializer_list<RejectedComponent> cases,
                                   Present present) {
    for (const RejectedComponent& c : cases) {
        SCOPED_TRACE(c.scene);
        Diagnostics diagnostics;
        auto loaded = parseScene(c.scene, fileName, diagnostics);
        ASSERT_TRUE(loaded);
        EXPECT_FALSE(present(loaded->entities.at(0))) << "a bad component is left out";
        const std::string text = diagnostics.toString();
        EXPECT_NE(text.find(fileName), std::string::npos) << text;
        EXPECT_NE(text.find(c.element), std::string::npos) << text;
        EXPECT_NE(text.find(c.words), std::string::npos) << text;
    }
}

}  // namespace candela::content::testing
