#pragma once
// Core messages name the command line's options ("give --angle-unit rad", "use --force to write
// it anyway"): right for the batch, which prints them. In the window the same advice must name
// the window's control instead, so the error dialogs pass every core message through
// windowWording. The core's wording stays the batch's; the mapping lives here, next to the
// controls it names.

#include "core/base/error.h"

#include <QString>

namespace bladeaxis::ui {

// The names of the window's controls the messages point to, one place for the dialogs, the
// controls' own labels and the tests.
namespace controls {
inline constexpr const char* kJobSettings = "Job settings";           // the dock (View menu)
inline constexpr const char* kAngleUnit = "Angle unit";               // in Job settings
inline constexpr const char* kBTolerance = "B tolerance";             // in Job settings
inline constexpr const char* kChannelTolerance = "Channel tolerance"; // in Job settings
inline constexpr const char* kPreset = "Preset";                      // in Job settings
inline constexpr const char* kApply = "Apply and re-run";             // in Job settings
inline constexpr const char* kReviewTab = "Review";                   // the dashboard's tab
inline constexpr const char* kAcknowledge = "Export although the tool gouges or collides here";
inline constexpr const char* kToolRadius = "Tool radius"; // the tool bar's radius box
} // namespace controls

// `message` with each command-line advice replaced by the window's control that does the same
// ("give --angle-unit rad" -> choose "radians" under Angle unit in the Job settings panel and
// press Apply and re-run). A message without such advice comes back unchanged.
QString windowWording(const QString& message);
// The error as the dialogs show it: "file:line: kind: message", worded for the window.
QString windowWording(const Error& error);

} // namespace bladeaxis::ui
