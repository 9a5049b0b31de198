// The cluster grid's tile size at large frames: the cluster bounds (CLUSTER_BOUNDS_FLOATS per
// cluster) must fit a device's maxStorageBufferRange, 128 MiB on lavapipe and many drivers,
// which 16 px tiles and 64 slices pass at about 4.5 Mpx.
#include <gtest/gtest.h>

#include "clustered/cluster_grid.h"
#include "common/light_list_entry.h"

using candela::render::ClusterGrid;

namespace {

constexpr uint64_t kBoundsBytes = CLUSTER_BOUNDS_FLOATS * sizeof(float);
constexpr uint64_t k128MiB = uint64_t(128) << 20;

uint64_t boundsBytes(uint32_t tile, uint32_t width, uint32_t height) {
    return uint64_t((width + tile - 1) / tile) * ((height + tile - 1) / tile) * 64 * kBoundsBytes;
}

}  // namespace

TEST(ClusterGrid, TilesStayAtTheirSizeWhileTheBoundsFit) {
    EXPECT_EQ(ClusterGrid::tileSizeFitting(16, 64, 1280, 720, kBoundsBytes, k128MiB), 16u);
    EXPECT_EQ(ClusterGrid::tileSizeFitting(16, 64, 2560, 1440, kBoundsBytes, k128MiB), 16u);
    // A device that binds any size keeps 16 px at 4K.
    EXPECT_EQ(ClusterGrid::tileSizeFitting(16, 64, 3840, 2160, kBoundsBytes, ~uint64_t(0)), 16u);
}

TEST(ClusterGrid, TilesGrowUntilTheBoundsFitTheDeviceRange) {
    for (auto [width, height] :
         {std::pair{3840u, 2160u}, std::pair{3072u, 2304u}, std::pair{7680u, 4320u}}) {
        ASSERT_GT(boundsBytes(16, width, height), k128MiB) << width;
        const uint32_t tile =
            ClusterGrid::tileSizeFitting(16, 64, width, height, kBoundsBytes, k128MiB);
        EXPECT_LE(boundsBytes(tile, width, height), k128MiB) << width;
        EXPECT_GT(boundsBytes(tile / 2, width, height), k128MiB) << width << ": not the smallest";
    }
}
