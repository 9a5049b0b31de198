// The names of the renderer's own option values (renderer_options.h), as --stats and the
// reports spell them; the user-facing settings' names are their table's
// (content/render_setting_table.h, renderSettingName).

#include "candela/render/renderer_options.h"

namespace candela::render {

const char* iblModeName(IblMode mode) {
    switch (mode) {
        case IblMode::SplitSum:
            return "split_sum";
        case IblMode::Mobile:
            return "mobile";
        case IblMode::Reference:
            return "reference";
    }
    return "unknown";
}

}  // namespace candela::render
