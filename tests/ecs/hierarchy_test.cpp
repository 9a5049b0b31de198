#include <gtest/gtest.h>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/registry.h>

namespace candela::ecs {
namespace {

TEST(Hierarchy, SetParentLinksChildrenInOrder) {
    Registry registry;
    const Entity root = registry.create();
    const Entity a = registry.create(), b = registry.create(), c = registry.create();
    ASSERT_EQ(setParent(registry, a, root), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, b, root), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, c, b), ReparentResult::Ok);
    EXPECT_EQ(childrenOf(registry, root), (std::vector<Entity>{a, b}));
    EXPECT_EQ(parentOf(registry, c), b);
    EXPECT_EQ(parentOf(registry, root), kNullEntity);
    EXPECT_EQ(depthOf(registry, root), 0u);
    EXPECT_EQ(depthOf(registry, c), 2u);
    EXPECT_TRUE(isAncestorOf(registry, root, c));
    EXPECT_FALSE(isAncestorOf(registry, a, c));
    EXPECT_EQ(descendantsOf(registry, root), (std::vector<Entity>{a, b, c}));
}

TEST(Hierarchy, ReparentUpdatesDepthOfWholeSubtree) {
    Registry registry;
    const Entity r1 = registry.create(), r2 = registry.create();
    const Entity mid = registry.create(), leaf = registry.create();
    ASSERT_EQ(setParent(registry, mid, r1), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, leaf, mid), ReparentResult::Ok);
    const Entity deep = registry.create();
    ASSERT_EQ(setParent(registry, r2, deep), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, mid, r2), ReparentResult::Ok);
    EXPECT_TRUE(childrenOf(registry, r1).empty());
    EXPECT_EQ(depthOf(registry, mid), 2u);
    EXPECT_EQ(depthOf(registry, leaf), 3u);
    ASSERT_EQ(setParent(registry, mid, kNullEntity), ReparentResult::Ok);
    EXPECT_EQ(depthOf(registry, mid), 0u);
    EXPECT_EQ(depthOf(registry, leaf), 1u);
    EXPECT_TRUE(childrenOf(registry, r2).empty());
}

TEST(Hierarchy, CycleIsRejectedAndNothingChanges) {
    Registry registry;
    const Entity a = registry.create(), b = registry.create(), c = registry.create();
    ASSERT_EQ(setParent(registry, b, a), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, c, b), ReparentResult::Ok);
    const std::uint64_t version = hierarchyVersion(registry);
    EXPECT_EQ(setParent(registry, a, c), ReparentResult::WouldCreateCycle);
    EXPECT_EQ(setParent(registry, a, b), ReparentResult::WouldCreateCycle);
    EXPECT_EQ(setParent(registry, a, a), ReparentResult::WouldCreateCycle);
    EXPECT_EQ(hierarchyVersion(registry), version);
    EXPECT_EQ(parentOf(registry, a), kNullEntity);
    EXPECT_EQ(parentOf(registry, c), b);
    // Moving a node under its own sibling subtree's other branch is fine.
    EXPECT_EQ(setParent(registry, c, a), ReparentResult::Ok);
    EXPECT_EQ(setParent(registry, b, c), ReparentResult::Ok);
    EXPECT_EQ(depthOf(registry, b), 2u);
}

TEST(Hierarchy, StaleHandlesAreRejected) {
    Registry registry;
    const Entity a = registry.create(), b = registry.create();
    registry.destroy(b);
    EXPECT_EQ(setParent(registry, a, b), ReparentResult::StaleParent);
    EXPECT_EQ(setParent(registry, b, a), ReparentResult::StaleChild);
}

TEST(Hierarchy, DestroyingAParentOrphansItsChildren) {
    Registry registry;
    const Entity root = registry.create(), mid = registry.create();
    const Entity leaf1 = registry.create(), leaf2 = registry.create();
    ASSERT_EQ(setParent(registry, mid, root), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, leaf1, mid), ReparentResult::Ok);
    ASSERT_EQ(setParent(registry, leaf2, mid), ReparentResult::Ok);
    registry.destroy(mid);
    EXPECT_TRUE(childrenOf(registry, root).empty());
    EXPECT_EQ(parentOf(registry, leaf1), kNullEntity);
    EXPECT_EQ(depthOf(registry, leaf2), 0u);
    EXPECT_EQ(registry.get<HierarchyNode>(root).childCount, 0u);
}

TEST(Hierarchy, DestroyingAMiddleSiblingKeepsTheListIntact) {
    Registry registry;
    const Entity root = registry.create();
    std::vector<Entity> kids;
    for (int i = 0; i < 5; ++i) {
        kids.push_back(registry.create());
        ASSERT_EQ(setParent(registry, kids.back(), root), ReparentResult::Ok);
    }
    registry.destroy(kids[2]);
    registry.destroy(kids[0]);
    registry.destroy(kids[4]);
    EXPECT_EQ(childrenOf(registry, root), (std::vector<Entity>{kids[1], kids[3]}));
    EXPECT_EQ(registry.get<HierarchyNode>(root).childCount, 2u);
}

TEST(Hierarchy, DestroyWithDescendants) {
    Registry registry;
    const Entity root = registry.create(), keep = registry.create();
    Entity parent = root;
    std::vector<Entity> chain;
    for (int i = 0; i < 10; ++i) {
        const Entity e = registry.create();
        ASSERT_EQ(setParent(registry, e, parent), ReparentResult::Ok);
        chain.push_back(e);
        parent = e;
    }
    ASSERT_EQ(setParent(registry, keep, root), ReparentResult::Ok);
    destroyWithDescendants(registry, chain[0]);
    for (Entity e : chain)
        EXPECT_FALSE(registry.valid(e));
    EXPECT_EQ(childrenOf(registry, root), (std::vector<Entity>{keep}));
}

}  // namespace
}  // namespace candela::ecs
