#pragma once
// The one error type of BladeAxis: every fallible core function returns Result<T>.
// Expected failures (bad files, infeasible input) are values, never exceptions.

#include <expected>
#include <string>
#include <utility>
#include <vector>

namespace bladeaxis {

// What went wrong, coarse enough to map to a process exit code (see app/batch/exit_codes.h).
enum class ErrorCode {
    InvalidArgument, // a parameter out of its domain (command line, job file)
    FileNotFound,    // an input path does not exist
    FileUnreadable,  // exists but cannot be opened or read
    Parse,           // malformed NC / CL / point-table text
    MachineFile,     // machine description invalid
    Geometry,        // NaN, degenerate or unreachable geometry
    Infeasible,      // no schedule exists inside the channel
    CheckFailed,     // a post-condition of the result failed
    WriteFailed,     // output could not be written
    Cancelled,       // the user asked to stop
    Internal,        // a bug: an invariant did not hold
};

const char* toString(ErrorCode code);
// The enumerator's own spelling ("FileNotFound"): stable for scripts to compare (the Python
// module's BladeAxisError.code), unlike toString's prose.
const char* codeName(ErrorCode code);

// Where in an input file an error was found. line and column are 1-based; 0 means unknown.
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    bool empty() const { return file.empty() && line == 0; }
    // "file:line:column", "file:line" or "file", depending on what is known.
    std::string toString() const;
};

struct Error {
    ErrorCode code = ErrorCode::Internal;
    std::string message;
    SourceLocation where;
    // Further problems found after the first one (parsers keep going up to a limit).
    std::vector<Error> more;

    // "blade.nc:12:5: parse error: expected a number after 'X'"
    std::string toString() const;
};

template <class T>
using Result = std::expected<T, Error>;

using Status = std::expected<void, Error>;

inline std::unexpected<Error> makeError(ErrorCode code, std::string message,
                                        SourceLocation where = {}) {
    return std::unexpected(Error{code, std::move(message), std::move(where), {}});
}

} // namespace bladeaxis
