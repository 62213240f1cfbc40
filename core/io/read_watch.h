#pragma once
// How a caller follows a long read: the token it stops on and the share of the text read so
// far. A five-million-block program takes over a second to read.

#include "core/base/progress.h"

#include <functional>

namespace bladeaxis::io {

struct ReadWatch {
    // Looked at every 4,096 G-code blocks, and once CL data or a point table is parsed: once it
    // is set, the read ends with ErrorCode::Cancelled.
    const CancelToken* cancel = nullptr;
    // Called every 4,096 G-code blocks with the share of the text read so far, in [0, 1].
    std::function<void(double fractionRead)> progress;
};

} // namespace bladeaxis::io
