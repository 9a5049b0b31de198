#pragma once
// Reading glTF accessors with every offset, stride and count checked against the real buffer
// sizes (tinygltf parses these fields but does not validate them). Each function returns an
// empty string on success, else the problem, for the caller to attach to its element name.
#include <tiny_gltf.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace candela::content::gltf {

struct AccessorLimits {
    // Accessors without a bufferView are all zeros (plus sparse values); nothing in the file
    // bounds their size, so we do.
    std::uint64_t maxElementsWithoutBufferView = 1u << 20;
};

// Number of components per element for an accessor type (SCALAR 1 ... MAT4 16), 0 if unknown.
std::uint32_t componentCount(int accessorType);

// Decodes a numeric accessor into floats, `componentsPerElement` per element (the accessor
// type must have exactly that many). Normalized integers map to [0,1] or [-1,1].
std::string readFloats(const tinygltf::Model& document, int accessorIndex,
                       std::uint32_t componentsPerElement, std::vector<float>& out,
                       const AccessorLimits& limits);

// Decodes a SCALAR unsigned byte/short/int accessor (glTF indices).
std::string readIndices(const tinygltf::Model& document, int accessorIndex,
                        std::vector<std::uint32_t>& out, const AccessorLimits& limits);

// The bytes of a bufferView, checked to lie inside its buffer.
std::string bufferViewBytes(const tinygltf::Model& document, int bufferViewIndex,
                            std::span<const std::uint8_t>& bytes);

// Element count of an accessor after checking its index; out-of-range gives an error.
std::string accessorCount(const tinygltf::Model& document, int accessorIndex, std::uint64_t& count);

}  // namespace candela::content::gltf
