#pragma once
// Change ticks. Every component write that goes through the registry (emplace, replace, patch,
// markChanged) stamps the row with the registry's current tick; readers ask for rows stamped
// after the tick they last saw. 32 bits wrap after 2^32 advances (828 days at 60 per second).
#include <cstdint>

namespace candela::ecs {

using Tick = std::uint32_t;

// Tick 0 means "before anything happened": changedSince(0) returns every component.
inline constexpr Tick kNeverTick = 0;

}  // namespace candela::ecs
