#include "core/base/json_key_lines.h"

#include <algorithm>
#include <vector>

namespace bladeaxis {

namespace {

// One open object or array while the text is scanned.
struct Container {
    bool isObject = false;
    bool expectingKey = false; // in an object: the next string is a key, not a value
    std::size_t index = 0;     // in an array: the element being read
    std::string key;           // in an object: the key whose value is being read
};

// Reads the string starting at text[at] == '"'; returns its decoded text (escapes other than
// \uXXXX resolved, which no key BladeAxis knows needs) and moves `at` past the closing quote.
std::string readString(std::string_view text, std::size_t& at, int& line) {
    std::string value;
    for (++at; at < text.size() && text[at] != '"'; ++at) {
        if (text[at] == '\\' && at + 1 < text.size()) {
            ++at;
            value += text[at] == 'n' ? '\n' : text[at] == 't' ? '\t' : text[at];
        } else {
            line += text[at] == '\n' ? 1 : 0;
            value += text[at];
        }
    }
    ++at;
    return value;
}

bool pathIs(const std::vector<Container>& open, std::string_view key,
            std::span<const std::string> path) {
    if (open.size() != path.size() || path.back() != key) {
        return false;
    }
    // Container i is reached through segment i - 1; the last segment is the key itself.
    for (std::size_t i = 1; i < open.size(); ++i) {
        const Container& parent = open[i - 1];
        const std::string segment = parent.isObject ? parent.key : std::to_string(parent.index);
        if (segment != path[i - 1]) {
            return false;
        }
    }
    return true;
}

} // namespace

int lineOfJsonKey(std::string_view text, std::span<const std::string> path) {
    if (path.empty()) {
        return 0;
    }
    std::vector<Container> open;
    int line = 1;
    int found = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        const char c = text[at];
        if (c == '"') {
            const int keyLine = line;
            std::string value = readString(text, at, line);
            if (!open.empty() && open.back().isObject && open.back().expectingKey) {
                if (pathIs(open, value, path)) {
                    found = keyLine;
                }
                open.back().key = std::move(value);
                open.back().expectingKey = false;
            }
            continue;
        }
        if (c == '{' || c == '[') {
            open.push_back({c == '{', c == '{', 0, {}});
        } else if ((c == '}' || c == ']') && !open.empty()) {
            open.pop_back();
        } else if (c == ',' && !open.empty()) {
            open.back().expectingKey = open.back().isObject;
            open.back().index += open.back().isObject ? 0 : 1;
        } else if (c == '\n') {
            ++line;
        }
        ++at;
    }
    return found;
}

std::string jsonKeyPathText(std::span<const std::string> path) {
    std::string text;
    for (const std::string& segment : path) {
        const bool index = !segment.empty() && std::ranges::all_of(segment, [](char c) {
            return c >= '0' && c <= '9';
        });
        text += index ? "[" + segment + "]" : (text.empty() ? "" : ".") + segment;
    }
    return text;
}

} // namespace bladeaxis
