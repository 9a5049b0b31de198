#pragma once
// tinygltf converts `extras` and `extensions` into its Value tree recursively, so a document
// nested thousands of levels deep would overflow the stack. We measure the nesting before
// parsing, without recursion and without building a tree.
#include <cstddef>
#include <string_view>

namespace candela::content::gltf {

inline constexpr std::size_t kMaxJsonNesting = 128;

// Deepest [ / { nesting in `text`, ignoring brackets inside strings.
std::size_t jsonNestingDepth(std::string_view text);

}  // namespace candela::content::gltf
