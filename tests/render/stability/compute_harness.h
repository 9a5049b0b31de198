#pragma once
// Runs the stability shaders on the real device: one GpuContext with validation required,
// host-visible storage buffers bound to bindings 0..n-1 by push descriptors, one dispatch per
// call, results read straight from the mapped memory.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <span>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/pipeline.h"

namespace candela::stability {

class ComputeHarness {
public:
    ComputeHarness();

    render::GpuContext& context() { return context_; }
    uint32_t validationMessages() const { return context_.validationMessages(); }

    // A zero-filled host-visible storage buffer.
    render::GpuBuffer buffer(size_t bytes);

    template <class T>
    render::GpuBuffer upload(std::span<const T> values) {
        render::GpuBuffer b = buffer(values.size_bytes());
        std::memcpy(b.mapped(), values.data(), values.size_bytes());
        return b;
    }

    template <class T>
    std::vector<T> read(const render::GpuBuffer& b, size_t count) const {
        std::vector<T> values(count);
        std::memcpy(values.data(), b.mapped(), count * sizeof(T));
        return values;
    }

    render::Pipeline pipeline(std::span<const uint32_t> spirv, uint32_t bufferCount,
                              uint32_t pushConstantBytes);

    // Binds `buffers` to bindings 0.. in order, dispatches groupCountX workgroups and waits;
    // a barrier makes the shader writes visible to the host.
    void dispatch(const render::Pipeline& pipeline,
                  std::initializer_list<const render::GpuBuffer*> buffers,
                  const void* pushConstants, uint32_t pushConstantBytes, uint32_t groupCountX);

private:
    render::GpuContext context_;
};

}  // namespace candela::stability
