// findNamed and findAnimationPlayer (issue 47) on a loaded model: the shared Fox.
#include <gtest/gtest.h>

#include <filesystem>

#include "candela/content/asset_cache.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/name.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/model_lookup.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"

namespace candela::content {
namespace {

TEST(ModelLookup, FindsNamedNodesAndTheAnimationPlayerUnderARoot) {
    Diagnostics diagnostics;
    std::optional<Model> fox =
        loadGltf(std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/Fox/Fox.glb", diagnostics);
    ASSERT_TRUE(fox) << diagnostics.toString();
    ecs::Registry registry;
    const ecs::Entity root = registry.create();
    registry.emplace<Name>(root, Name{"fox"});
    registry.emplace<ecs::LocalTransform>(root);
    registry.emplace<ecs::WorldTransform>(root);
    instantiateModel(registry, *fox, root);
    const ecs::Entity elsewhere = registry.create();
    registry.emplace<Name>(elsewhere, Name{"b_Head_05"});  // same name, not under the fox

    const ecs::Entity head = findNamed(registry, root, "b_Head_05");
    ASSERT_NE(head, ecs::kNullEntity);
    EXPECT_NE(head, elsewhere);
    EXPECT_TRUE(ecs::isAncestorOf(registry, root, head));
    EXPECT_EQ(findNamed(registry, root, "fox"), root) << "the root itself counts";
    EXPECT_EQ(findNamed(registry, root, "no such node"), ecs::kNullEntity);

    const ecs::Entity animated = findAnimationPlayer(registry, root);
    ASSERT_NE(animated, ecs::kNullEntity);
    EXPECT_GE(registry.get<AnimationPlayer>(animated).findClip("Run"), 0);
    EXPECT_EQ(findAnimationPlayer(registry, elsewhere), ecs::kNullEntity);
    EXPECT_EQ(findNamed(registry, ecs::kNullEntity, "fox"), ecs::kNullEntity);
}

}  // namespace
}  // namespace candela::content
