#include "core/base/error.h"

namespace bladeaxis {

const char* toString(ErrorCode code) {
    switch (code) {
    case ErrorCode::InvalidArgument:
        return "invalid argument";
    case ErrorCode::FileNotFound:
        return "file not found";
    case ErrorCode::FileUnreadable:
        return "file unreadable";
    case ErrorCode::Parse:
        return "parse error";
    case ErrorCode::MachineFile:
        return "machine file error";
    case ErrorCode::Geometry:
        return "geometry error";
    case ErrorCode::Infeasible:
        return "infeasible";
    case ErrorCode::CheckFailed:
        return "check failed";
    case ErrorCode::WriteFailed:
        return "write failed";
    case ErrorCode::Cancelled:
        return "cancelled";
    case ErrorCode::Internal:
        return "internal error";
    }
    return "error";
}

std::string SourceLocation::toString() const {
    std::string text = file;
    if (line > 0) {
        text += ":" + std::to_string(line);
        if (column > 0) {
            text += ":" + std::to_string(column);
        }
    }
    return text;
}

std::string Error::toString() const {
    std::string text;
    if (!where.empty()) {
        text = where.toString() + ": ";
    }
    text += bladeaxis::toString(code);
    text += ": ";
    text += message;
    for (const Error& other : more) {
        text += "\n" + other.toString();
    }
    return text;
}

} // namespace bladeaxis
