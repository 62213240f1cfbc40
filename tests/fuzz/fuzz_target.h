#pragma once
// What every fuzz target checks on any input: the reader returns a result or an error that
// names what it expected, and never crashes, hangs, throws or reports an internal error (exit
// 1 of the command line). A violation aborts, which libFuzzer and the replay both report.

#include "core/base/error.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

namespace bladeaxis::fuzz {

template <class T>
void expectNoInternalError(const Result<T>& result, std::string_view target) {
    if (!result && result.error().code == ErrorCode::Internal) {
        std::fprintf(stderr, "%.*s: internal error: %s\n", static_cast<int>(target.size()),
                     target.data(), result.error().toString().c_str());
        std::abort();
    }
}

// Runs `read` and turns an escaping exception into an abort with its message.
template <class Read>
void withoutExceptions(std::string_view target, Read&& read) {
    try {
        read();
    } catch (const std::exception& exception) {
        std::fprintf(stderr, "%.*s: exception escaped: %s\n", static_cast<int>(target.size()),
                     target.data(), exception.what());
        std::abort();
    }
}

} // namespace bladeaxis::fuzz
