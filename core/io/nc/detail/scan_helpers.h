#pragma once
// The lexical pieces every dialect's scanner shares: character classes, numbers, ISO words and
// the messages for what cannot be read.

#include "core/io/nc/detail/block_scanner.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis::io::nc::detail {

inline bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
inline bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
inline bool isLetter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
inline char upper(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

inline ScanIssue issueAt(std::size_t offset, std::string message) {
    return {static_cast<std::uint32_t>(offset), std::move(message)};
}

// Empties `block` for the next line.
void resetBlock(ScannedBlock& block);

// Reads the number starting at `begin` into `word` (its span and value); `letter` names the
// word in the message when there is no number or it is out of range.
std::optional<ScanIssue> readNumber(std::string_view line, std::size_t begin, char letter,
                                    WordSpan& word);

// Scans one ISO word (letter, blanks, number) starting at the letter; advances `i` past it.
std::optional<ScanIssue> scanWord(std::string_view line, std::size_t& i, ScannedBlock& block);

// Stores an axis, feed or other word read by a dialect scanner; refuses a repeated letter.
std::optional<ScanIssue> storeWord(char letter, const WordSpan& word, ScannedBlock& block);

// Control bytes in a comment: binary data, not text.
std::optional<ScanIssue> checkCommentBytes(std::string_view line, std::size_t begin,
                                           std::size_t end);

// The message for a character no word starts with.
ScanIssue unexpectedCharacter(std::string_view line, std::size_t i);

// The upper-case identifier starting at `i` (letters, digits, '_'); advances `i` past it.
std::string readIdentifier(std::string_view line, std::size_t& i);

} // namespace bladeaxis::io::nc::detail
