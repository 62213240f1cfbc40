#pragma once
// Escaping shared by the HTML page and its SVG figures.

#include <string>

namespace bladeaxis::report {

// Text made safe for XML/HTML element content and attribute values.
std::string escapeMarkup(const std::string& text);

} // namespace bladeaxis::report
