#include "core/blade/presets.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/blade/random.h"

#include <cmath>

namespace bladeaxis::blade {
namespace {

using units::degToRad;

enum class Kind { CamberedNaca, SymmetricNaca, Turbine };

Kind kindOf(int index) {
    switch (index % 5) {
    case 3:
        return Kind::SymmetricNaca;
    case 4:
        return Kind::Turbine;
    default:
        return Kind::CamberedNaca;
    }
}

// Draws the profile and returns the name of the member.
std::string drawProfile(Kind kind, int index, Random& random, BladeSpec& spec) {
    const std::string prefix = "family-" + std::to_string(index) + "-";
    if (kind == Kind::Turbine) {
        TurbineProfile profile;
        profile.turning = degToRad(random.uniform(60.0, 110.0));
        profile.maxThickness = random.uniform(0.10, 0.15);
        profile.leRadius = random.uniform(0.015, 0.03);
        profile.teRadius = random.uniform(0.006, 0.012);
        spec.profile = profile;
        return prefix + "turbine-" + formatTrimmed(units::radToDeg(profile.turning), 1);
    }
    NacaProfile profile;
    profile.camber = kind == Kind::SymmetricNaca ? 0.0 : random.uniform(0.06, 0.10);
    profile.camberPosition = random.uniform(0.35, 0.50);
    profile.thickness = random.uniform(0.10, 0.15);
    spec.profile = profile;
    return prefix + "naca-" + formatTrimmed(profile.camber, 3) + "-" +
           formatTrimmed(profile.camberPosition, 2) + "-" + formatTrimmed(profile.thickness, 3);
}

void drawBlade(Random& random, BladeSpec& spec) {
    spec.spanStart = 0.0;
    spec.spanEnd = random.uniform(15.0, 30.0);
    spec.chordStart = random.uniform(50.0, 80.0);
    spec.chordEnd = spec.chordStart * random.uniform(0.85, 1.0);
    spec.staggerStart = degToRad(random.uniform(15.0, 30.0));
    spec.staggerEnd = spec.staggerStart + degToRad(random.uniform(-5.0, 15.0));
    spec.staggerBow = random.chance(0.3) ? degToRad(random.uniform(-3.0, 3.0)) : 0.0;
    spec.leanMm = random.chance(0.5) ? random.uniform(-2.0, 2.0) : 0.0;
    spec.bowMm = random.chance(0.3) ? random.uniform(-1.5, 1.5) : 0.0;
    spec.pointsPerSide = 200 + 50 * random.index(5);
}

void drawPath(Random& random, const BladeSpec& blade, std::uint64_t seed, HelicalPathSpec& path) {
    const double span = blade.spanEnd - blade.spanStart;
    path.pitch = random.uniform(0.2, 1.0);
    path.revolutions = 2 + random.index(4);
    path.xStart = blade.spanStart + random.uniform(0.0, span - path.pitch * path.revolutions);
    path.leadAngle = degToRad(random.uniform(10.0, 20.0));
    path.chordalTolerance = random.uniform(0.005, 0.02);
    path.maxStep = random.uniform(0.5, 2.0);
    path.leadNoise = random.chance(0.3) ? degToRad(random.uniform(0.05, 0.5)) : 0.0;
    path.roundTipTo = random.chance(0.3) ? 1e-3 : 0.0;
    path.seed = seed;
}

} // namespace

BladeSpec demoBladeSpec() {
    BladeSpec spec;
    spec.profile = NacaProfile{0.10, 0.45, 0.12};
    spec.spanStart = 0.0;
    spec.spanEnd = 20.0;
    spec.chordStart = 70.0;
    spec.chordEnd = 70.0;
    spec.staggerStart = degToRad(20.0);
    spec.staggerEnd = degToRad(30.0);
    spec.pointsPerSide = 300;
    return spec;
}

Result<Blade> demoBlade() {
    return Blade::create(demoBladeSpec());
}

HelicalPathSpec demoPathSpec() {
    HelicalPathSpec spec;
    spec.toolRadius = 8.0;
    spec.pitch = 2.0;
    spec.revolutions = 8;
    spec.xStart = 2.0;
    spec.tiltB0 = degToRad(5.0);
    spec.leadAngle = degToRad(15.0);
    spec.chordalTolerance = 0.01;
    spec.maxStep = 1.0;
    spec.feed = units::perMinuteToPerSecond(3000.0);
    return spec;
}

Result<std::vector<FamilyMember>> syntheticFamily(std::uint64_t seed, int count) {
    if (count < 0 || count > 10000) {
        return makeError(ErrorCode::InvalidArgument,
                         "family size = " + std::to_string(count) + " is outside [0, 10000]");
    }
    Random random(seed);
    std::vector<FamilyMember> family;
    for (int index = 0; index < count; ++index) {
        FamilyMember member;
        member.name = drawProfile(kindOf(index), index, random, member.blade);
        drawBlade(random, member.blade);
        drawPath(random, member.blade, seed + static_cast<std::uint64_t>(index), member.path);
        Result<Blade> blade = Blade::create(member.blade);
        if (!blade) {
            return std::unexpected(blade.error());
        }
        const double x0 = *member.path.xStart;
        const double x1 = x0 + member.path.pitch * member.path.revolutions;
        member.minConcaveRadius = blade->minConcaveRadius(x0, x1);
        // R in {4, 8} when feasible with a 10 % margin; 8 on half of the members that allow it.
        const double limit = 0.9 * member.minConcaveRadius;
        if (limit > 8.0 && random.chance(0.5)) {
            member.path.toolRadius = 8.0;
        } else if (limit > 4.0) {
            member.path.toolRadius = 4.0;
        } else {
            member.path.toolRadius = 0.5 * member.minConcaveRadius;
        }
        family.push_back(std::move(member));
    }
    return family;
}

} // namespace bladeaxis::blade
