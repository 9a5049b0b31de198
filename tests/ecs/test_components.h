#pragma once
// Plain component structs shared by the ECS tests.
#include <string>

namespace candela::ecs::test {

struct Position {
    float x = 0, y = 0, z = 0;
};
struct Velocity {
    float x = 0, y = 0, z = 0;
};
struct Health {
    int value = 100;
};
struct Frozen {};
// Not trivially copyable: exercises the relocate/destroy paths of the storage.
struct Name {
    std::string text;
};

}  // namespace candela::ecs::test
