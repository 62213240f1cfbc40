#pragma once
// The tool a post-processor states in a comment, so that a program that says which cutter it was
// posted for needs no --tool-radius. Read: the Autodesk post convention (Fusion, HSM, Inventor
// CAM, used by many Fanuc, Haas and Heidenhain posts): "(T1 D=8. CR=4. TAPER=0deg - ball end
// mill)", D the diameter and CR the corner radius, in the program's linear unit; and the header
// BladeAxis's own generator writes, "(ball end R=8 mm, B=5 deg, ...)": R= in a comment that says
// "ball". D and CR only count together; "D1" (an offset number), a lone "R4" or an "R=" in a
// comment that does not name a ball are never read as a tool.

#include <optional>
#include <string_view>

namespace bladeaxis::io::nc::detail {

struct ToolComment {
    double diameter = 0.0;     // in the program's linear unit
    double cornerRadius = 0.0; // the same unit
    bool isBallEnd() const;    // CR = D / 2 within 1e-6 relative
};

// The tool of the comment in `line` (text in parentheses or after ';'), if it states one.
std::optional<ToolComment> toolInComment(std::string_view line);

} // namespace bladeaxis::io::nc::detail
