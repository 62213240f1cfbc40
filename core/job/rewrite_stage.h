#pragma once
// The verification stage of a re-scheduling: the written program read back (reschedule.h has
// the stages before it).

#include "core/base/error.h"
#include "core/base/file_io.h"
#include "core/base/progress.h"
#include "core/job/reschedule.h"

#include <string_view>
#include <vector>

namespace bladeaxis::job {

// The written program as read back: how far its ball centres are from the input's, and the
// tip feed of each pass record as the control will run it.
struct WrittenProgram {
    double maxCentreDeviationMm = 0.0;
    int maxCentreDeviationLine = 0; // the input line of the block where it is largest
    std::vector<double> passFeeds;  // mm/s, when asked for (keepFeeds)
};

// Reads back the written program, `text` or the `staged` file's content when given.
Result<WrittenProgram> readBackWritten(const PassToRewrite& pass, std::string_view text,
                                       const StagedFile* staged, bool keepFeeds,
                                       const CancelToken& cancel);

} // namespace bladeaxis::job
