#include "core/base/error.h"

#include <algorithm>

namespace bladeaxis {

const char* codeName(ErrorCode code) {
    switch (code) {
    case ErrorCode::InvalidArgument:
        return "InvalidArgument";
    case ErrorCode::FileNotFound:
        return "FileNotFound";
    case ErrorCode::FileUnreadable:
        return "FileUnreadable";
    case ErrorCode::Parse:
        return "Parse";
    case ErrorCode::MachineFile:
        return "MachineFile";
    case ErrorCode::Geometry:
        return "Geometry";
    case ErrorCode::Infeasible:
        return "Infeasible";
    case ErrorCode::CheckFailed:
        return "CheckFailed";
    case ErrorCode::WriteFailed:
        return "WriteFailed";
    case ErrorCode::Cancelled:
        return "Cancelled";
    case ErrorCode::Internal:
        return "Internal";
    }
    return "Internal";
}

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

namespace {

constexpr std::size_t kListedRepeats = 8;

void flatten(const Error& error, std::vector<const Error*>& out) {
    out.push_back(&error);
    for (const Error& other : error.more) {
        flatten(other, out);
    }
}

bool alike(const Error& a, const Error& b) {
    return a.code == b.code && a.message == b.message && a.where.file == b.where.file;
}

std::string headline(const Error& error) {
    std::string text;
    if (!error.where.empty()) {
        text = error.where.toString() + ": ";
    }
    return text + toString(error.code) + ": " + error.message;
}

// " (and 19 more lines like it: 13, 14, ...)" for the repeats of one message.
std::string repeatsNote(const std::vector<const Error*>& repeats) {
    const bool lines = std::all_of(repeats.begin(), repeats.end(),
                                   [](const Error* error) { return error->where.line > 0; });
    std::string text = " (and " + std::to_string(repeats.size()) + " more " +
                       (lines ? (repeats.size() == 1 ? "line" : "lines") : "like it");
    if (!lines) {
        return text + ")";
    }
    text += " like it: ";
    for (std::size_t i = 0; i < repeats.size() && i < kListedRepeats; ++i) {
        text += (i > 0 ? ", " : "") + std::to_string(repeats[i]->where.line);
    }
    return text + (repeats.size() > kListedRepeats ? ", ...)" : ")");
}

} // namespace

// One line per distinct message: a message repeated on many lines (a column of bad numbers, a
// feed missing from every GOTO) is named once with the lines it repeats on, so the first
// distinct problems are not buried under copies of one.
std::string Error::toString() const {
    std::vector<const Error*> all;
    flatten(*this, all);
    std::vector<bool> used(all.size(), false);
    std::string text;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (used[i]) {
            continue;
        }
        std::vector<const Error*> repeats;
        for (std::size_t j = i + 1; j < all.size(); ++j) {
            if (!used[j] && alike(*all[i], *all[j])) {
                used[j] = true;
                repeats.push_back(all[j]);
            }
        }
        text += (text.empty() ? "" : "\n") + headline(*all[i]);
        if (!repeats.empty()) {
            text += repeatsNote(repeats);
        }
    }
    return text;
}

} // namespace bladeaxis
