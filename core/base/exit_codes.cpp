#include "core/base/exit_codes.h"

namespace bladeaxis {

ExitCode exitCodeFor(const Error& error) {
    switch (error.code) {
    case ErrorCode::InvalidArgument:
        return kExitUsage;
    case ErrorCode::FileNotFound:
    case ErrorCode::FileUnreadable:
    case ErrorCode::Parse:
        return kExitInput;
    case ErrorCode::MachineFile:
        return kExitMachine;
    case ErrorCode::Geometry:
    case ErrorCode::Infeasible:
    case ErrorCode::CheckFailed:
        return kExitGeometry;
    case ErrorCode::WriteFailed:
        return kExitWrite;
    case ErrorCode::Cancelled:
        return kExitCancelled;
    case ErrorCode::Internal:
        return kExitInternal;
    }
    return kExitInternal;
}

} // namespace bladeaxis
