#pragma once
// The headless axis-motion analysis (spec §6.4, §8.1-8.3), one include for users.

#include "core/analysis/axis_profile.h"  // IWYU pragma: export
#include "core/analysis/constant_feed.h" // IWYU pragma: export
#include "core/analysis/derivatives.h"   // IWYU pragma: export
#include "core/analysis/reversals.h"     // IWYU pragma: export
