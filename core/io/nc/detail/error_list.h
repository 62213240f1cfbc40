#pragma once
// Collects parse errors with their locations, up to kMaxParseErrors; the first one is the main
// error and the rest travel in Error::more (parsers keep going: docs/architecture.md, Conventions).

#include "core/base/error.h"

#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::io::nc::detail {

class ErrorList {
  public:
    ErrorList(std::string_view fileName, int limit) : m_fileName(fileName), m_limit(limit) {}

    void add(int line, int column, std::string message) {
        if (!full()) {
            m_errors.push_back(
                Error{ErrorCode::Parse, std::move(message), {m_fileName, line, column}, {}});
        }
    }
    bool full() const { return static_cast<int>(m_errors.size()) >= m_limit; }
    bool empty() const { return m_errors.empty(); }
    const std::string& fileName() const { return m_fileName; }

    // The first error, carrying the others in `more`. Call only when !empty().
    Error take() {
        Error first = std::move(m_errors.front());
        for (std::size_t i = 1; i < m_errors.size(); ++i) {
            first.more.push_back(std::move(m_errors[i]));
        }
        m_errors.clear();
        return first;
    }

  private:
    std::string m_fileName;
    int m_limit;
    std::vector<Error> m_errors;
};

} // namespace bladeaxis::io::nc::detail
