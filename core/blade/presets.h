#pragma once
// Built-in blades and path specifications: the demo (fast, shows the reciprocating original
// orientation) and a seeded family of varied blades for property tests (spec §10.2, §10.4).

#include "core/base/error.h"
#include "core/blade/blade.h"
#include "core/blade/helical_path.h"

#include <cstdint>
#include <string>
#include <vector>

namespace bladeaxis::blade {

// High-camber NACA m = 0.10, p = 0.45, t = 0.12 (as in spec Appendix B, smaller): chord 70 mm,
// span 0..20 mm, stagger 20 -> 30 deg. Its pressure side is concave.
BladeSpec demoBladeSpec();
Result<Blade> demoBlade();

// R = 8 mm, pitch 2 mm, 8 revolutions from x = 2 mm, B0 = 5 deg, lead 15 deg, tolerance 0.01 mm,
// feed 3000 mm/min.
HelicalPathSpec demoPathSpec();

struct FamilyMember {
    std::string name; // e.g. "family-3-naca-0.08-0.42-0.13" (kind and main parameters)
    BladeSpec blade;
    HelicalPathSpec path;
    double minConcaveRadius = 0.0; // of the swept sections, mm (+inf for convex sections)
};

// `count` blades and path specs drawn from `seed`: high-camber NACA (m 0.06-0.10, t 0.10-0.15),
// every 5th symmetric NACA, every 5th turbine-type; varied chord, span, twist, lean, pitch,
// tolerance and lead; R = 8 mm where it is below the minimum concave radius, else 4 mm, else
// half that radius. Some members have lead noise and tip rounding. Deterministic from the seed.
Result<std::vector<FamilyMember>> syntheticFamily(std::uint64_t seed, int count);

} // namespace bladeaxis::blade
