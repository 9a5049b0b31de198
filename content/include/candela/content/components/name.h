#pragma once
// Name component: what the editor shows and what scene files and glTF nodes call an entity.
#include <string>

namespace candela::content {

struct Name {
    std::string value;
};

}  // namespace candela::content
