#pragma once
// A host-visible storage buffer of T that a pass refills every frame (the wire and hair
// segments): it grows by doubling when a frame needs more, and the frame may overwrite it
// because only one frame is in flight at a time (the one before has completed).
#include <algorithm>
#include <cstddef>

#include "candela/render/gpu_buffer.h"

namespace candela::render {

template <class T>
T* reserveHostStorageArray(GpuContext& context, GpuBuffer& buffer, size_t count) {
    if (count * sizeof(T) > buffer.size()) {
        const VkDeviceSize capacity = std::max<VkDeviceSize>(count, 2 * buffer.size() / sizeof(T));
        buffer = GpuBuffer(context, capacity * sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                           MemoryLocation::HostVisible);
    }
    return static_cast<T*>(buffer.mapped());
}

}  // namespace candela::render
