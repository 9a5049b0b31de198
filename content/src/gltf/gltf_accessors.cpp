#include "gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace candela::content::gltf {
namespace {

std::uint32_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;  // INT and DOUBLE are not valid in glTF accessors
    }
}

// A checked window into a buffer: `length` bytes starting at `data`.
struct ByteRange {
    const std::uint8_t* data = nullptr;
    std::uint64_t length = 0;
};

std::string locateBufferView(const tinygltf::Model& document, int index, ByteRange& range) {
    if (index < 0 || static_cast<std::size_t>(index) >= document.bufferViews.size()) {
        return "bufferView " + std::to_string(index) + " does not exist";
    }
    const tinygltf::BufferView& view = document.bufferViews[static_cast<std::size_t>(index)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= document.buffers.size()) {
        return "bufferViews[" + std::to_string(index) + "] names missing buffer " +
               std::to_string(view.buffer);
    }
    const std::vector<unsigned char>& bytes =
        document.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::uint64_t offset = view.byteOffset;
    const std::uint64_t length = view.byteLength;
    if (offset > bytes.size() || length > bytes.size() - offset) {
        return "bufferViews[" + std::to_string(index) + "] (offset " + std::to_string(offset) +
               ", length " + std::to_string(length) + ") lies outside buffer " +
               std::to_string(view.buffer) + " of " + std::to_string(bytes.size()) + " bytes";
    }
    range.data = bytes.data() + offset;
    range.length = length;
    return {};
}

// Where element i of a strided array lives, with the whole array checked to fit once.
struct StridedElements {
    const std::uint8_t* data = nullptr;
    std::uint64_t stride = 0;
    std::uint64_t count = 0;
};

std::string locateElements(const tinygltf::Model& document, int bufferViewIndex,
                           std::uint64_t byteOffset, std::uint64_t count, std::uint64_t elementSize,
                           bool allowStride, StridedElements& elements) {
    ByteRange view;
    if (std::string error = locateBufferView(document, bufferViewIndex, view); !error.empty()) {
        return error;
    }
    std::uint64_t stride = elementSize;
    if (allowStride) {
        const std::uint64_t declared =
            document.bufferViews[static_cast<std::size_t>(bufferViewIndex)].byteStride;
        if (declared != 0) {
            if (declared < elementSize || declared > 252) {
                return "byteStride " + std::to_string(declared) + " is invalid for " +
                       std::to_string(elementSize) + "-byte elements";
            }
            stride = declared;
        }
    }
    // count and stride are bounded (32-bit count checked by the caller, stride <= 252), so
    // the products below cannot overflow 64 bits.
    if (count > std::numeric_limits<std::uint32_t>::max()) {
        return "count " + std::to_string(count) + " is absurd";
    }
    const std::uint64_t needed = count == 0 ? 0 : stride * (count - 1) + elementSize;
    if (byteOffset > view.length || needed > view.length - byteOffset) {
        return std::to_string(count) + " elements of " + std::to_string(elementSize) +
               " bytes (stride " + std::to_string(stride) + ") at offset " +
               std::to_string(byteOffset) + " overrun bufferView " +
               std::to_string(bufferViewIndex) + " of " + std::to_string(view.length) + " bytes";
    }
    elements = {view.data + byteOffset, stride, count};
    return {};
}

float componentAsFloat(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? static_cast<float>(*p) / 255.0f : static_cast<float>(*p);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<float>(static_cast<std::int8_t>(*p));
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? static_cast<float>(v) / 65535.0f : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f)
                              : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return static_cast<float>(v);
        }
        default:
            return 0.0f;
    }
}

std::uint32_t componentAsUint(const std::uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return *p;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default:
            return 0;
    }
}

const tinygltf::Accessor* findAccessor(const tinygltf::Model& document, int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= document.accessors.size()) return nullptr;
    return &document.accessors[static_cast<std::size_t>(index)];
}

// Decodes an accessor into `out` as `components` values per element through `convert`,
// including the zero-initialised bufferView-less case and sparse substitution.
template <typename T, typename Convert>
std::string decode(const tinygltf::Model& document, const tinygltf::Accessor& accessor,
                   std::uint32_t components, std::vector<T>& out, const AccessorLimits& limits,
                   Convert convert) {
    const std::uint32_t size = componentSize(accessor.componentType);
    if (size == 0) return "componentType " + std::to_string(accessor.componentType) + " is invalid";
    const std::uint64_t count = accessor.count;
    const std::uint64_t elementSize = std::uint64_t{size} * components;
    if (accessor.bufferView < 0) {
        if (count > limits.maxElementsWithoutBufferView) {
            return "count " + std::to_string(count) +
                   " without a bufferView exceeds the limit of " +
                   std::to_string(limits.maxElementsWithoutBufferView);
        }
        out.assign(count * components, T{});
    } else {
        StridedElements elements;
        if (std::string error = locateElements(document, accessor.bufferView, accessor.byteOffset,
                                               count, elementSize, true, elements);
            !error.empty()) {
            return error;
        }
        out.resize(count * components);
        for (std::uint64_t i = 0; i < count; ++i) {
            const std::uint8_t* element = elements.data + i * elements.stride;
            for (std::uint32_t c = 0; c < components; ++c) {
                out[i * components + c] = convert(element + c * size, accessor.componentType);
            }
        }
    }
    if (!accessor.sparse.isSparse) return {};

    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || static_cast<std::uint64_t>(sparse.count) > count) {
        return "sparse count " + std::to_string(sparse.count) + " is not in [1, " +
               std::to_string(count) + "]";
    }
    const std::uint32_t indexSize = componentSize(sparse.indices.componentType);
    if (indexSize == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) {
        return "sparse indices componentType " + std::to_string(sparse.indices.componentType) +
               " is invalid";
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        return "sparse byteOffset is negative";
    }
    const auto sparseCount = static_cast<std::uint64_t>(sparse.count);
    StridedElements indices;
    StridedElements values;
    if (std::string error = locateElements(document, sparse.indices.bufferView,
                                           static_cast<std::uint64_t>(sparse.indices.byteOffset),
                                           sparseCount, indexSize, false, indices);
        !error.empty()) {
        return "sparse indices: " + error;
    }
    if (std::string error = locateElements(document, sparse.values.bufferView,
                                           static_cast<std::uint64_t>(sparse.values.byteOffset),
                                           sparseCount, elementSize, false, values);
        !error.empty()) {
        return "sparse values: " + error;
    }
    for (std::uint64_t s = 0; s < sparseCount; ++s) {
        const std::uint32_t target =
            componentAsUint(indices.data + s * indices.stride, sparse.indices.componentType);
        if (target >= count) {
            return "sparse index " + std::to_string(target) + " is not below count " +
                   std::to_string(count);
        }
        for (std::uint32_t c = 0; c < components; ++c) {
            out[target * components + c] =
                convert(values.data + s * values.stride + c * size, accessor.componentType);
        }
    }
    return {};
}

}  // namespace

std::uint32_t componentCount(int accessorType) {
    switch (accessorType) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

std::string bufferViewBytes(const tinygltf::Model& document, int bufferViewIndex,
                            std::span<const std::uint8_t>& bytes) {
    ByteRange range;
    std::string error = locateBufferView(document, bufferViewIndex, range);
    if (error.empty()) bytes = {range.data, static_cast<std::size_t>(range.length)};
    return error;
}

std::string accessorCount(const tinygltf::Model& document, int accessorIndex,
                          std::uint64_t& count) {
    const tinygltf::Accessor* accessor = findAccessor(document, accessorIndex);
    if (accessor == nullptr) return "accessor " + std::to_string(accessorIndex) + " does not exist";
    count = accessor->count;
    return {};
}

std::string readFloats(const tinygltf::Model& document, int accessorIndex,
                       std::uint32_t componentsPerElement, std::vector<float>& out,
                       const AccessorLimits& limits) {
    const tinygltf::Accessor* accessor = findAccessor(document, accessorIndex);
    if (accessor == nullptr) return "accessor " + std::to_string(accessorIndex) + " does not exist";
    if (componentCount(accessor->type) != componentsPerElement) {
        return "accessors[" + std::to_string(accessorIndex) + "] has " +
               std::to_string(componentCount(accessor->type)) + " components, expected " +
               std::to_string(componentsPerElement);
    }
    const bool normalized = accessor->normalized;
    std::string error = decode(document, *accessor, componentsPerElement, out, limits,
                               [normalized](const std::uint8_t* p, int type) {
                                   return componentAsFloat(p, type, normalized);
                               });
    return error.empty() ? error : "accessors[" + std::to_string(accessorIndex) + "]: " + error;
}

std::string readIndices(const tinygltf::Model& document, int accessorIndex,
                        std::vector<std::uint32_t>& out, const AccessorLimits& limits) {
    const tinygltf::Accessor* accessor = findAccessor(document, accessorIndex);
    if (accessor == nullptr) return "accessor " + std::to_string(accessorIndex) + " does not exist";
    const int type = accessor->componentType;
    if (accessor->type != TINYGLTF_TYPE_SCALAR || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                                   type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                                   type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        return "accessors[" + std::to_string(accessorIndex) +
               "] is not a scalar of unsigned byte/short/int, so it cannot hold indices";
    }
    std::string error = decode(document, *accessor, 1, out, limits, componentAsUint);
    return error.empty() ? error : "accessors[" + std::to_string(accessorIndex) + "]: " + error;
}

}  // namespace candela::content::gltf
