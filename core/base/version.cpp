#include "core/base/version.h"

namespace bladeaxis {

std::string_view projectVersion() {
    return BLADEAXIS_VERSION;
}

std::string_view projectRevision() {
    return BLADEAXIS_REVISION;
}

} // namespace bladeaxis
