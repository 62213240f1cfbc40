// The default axis figures hold (docs/figures.md): over the generated blade family and a
// compressor-like blade with sharp edges, a post that inserts chords of 1-5 um every 3-5 points
// on the straight move between two CL points changes no default figure (peak and 99.9th
// percentile velocity and acceleration of every axis, T1) by more than 5 %, on the original and
// on the re-scheduled program; and the default peaks agree within 20 % with an evaluation written
// here, independently of the library: the tip path at the programmed constant feed, each axis
// smoothed by a Gaussian of the same time scale as an 8 ms controller (two 8 ms moving averages
// have a standard deviation of 8 / sqrt(6) ms), on its own 0.5 ms grid, differentiated through
// the kernel's analytic derivatives.

#include "core/blade/presets.h"
#include "core/kinematics/kinematics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;
using kinematics::AxisId;

struct Program {
    std::string name;
    toolpath::Toolpath path;
    double toolRadius = 0.0;
    double feed = 0.0; // mm/s
};

// Like a compressor blade finishing pass: a thin, low-camber section whose edges are sharp
// (leading-edge radius about 0.1 mm), a 4 mm ball, 0.5 mm pitch and 0.2-0.25 mm chords.
Result<Program> compressorLike(int revolutions) {
    blade::BladeSpec spec;
    spec.profile = blade::NacaProfile{0.05, 0.40, 0.05};
    spec.spanStart = 0.0;
    spec.spanEnd = 40.0;
    spec.chordStart = 40.0;
    spec.chordEnd = 36.0;
    spec.staggerStart = units::degToRad(30.0);
    spec.staggerEnd = units::degToRad(40.0);
    spec.pointsPerSide = 600;
    auto model = blade::Blade::create(spec);
    if (!model) {
        return std::unexpected(model.error());
    }
    blade::HelicalPathSpec path;
    path.toolRadius = 4.0;
    path.pitch = 0.5;
    path.revolutions = revolutions;
    path.xStart = 10.0;
    path.chordalTolerance = 0.002;
    path.maxStep = 0.25;
    path.roundTipTo = 1e-3;
    auto generated = blade::generateHelicalPath(*model, path);
    if (!generated) {
        return std::unexpected(generated.error());
    }
    return Program{"compressor-like", std::move(generated->path), path.toolRadius, path.feed};
}

std::uint64_t environmentNumber(const char* name, std::uint64_t fallback) {
    const char* value = std::getenv(name);
    return value != nullptr ? std::strtoull(value, nullptr, 10) : fallback;
}

const std::vector<Program>& programs() {
    static const std::vector<Program> all = [] {
        std::vector<Program> out;
        const auto count = static_cast<int>(environmentNumber("BLADEAXIS_FIGURES_FAMILY", 6));
        auto family =
            blade::syntheticFamily(environmentNumber("BLADEAXIS_PROPERTY_SEED", 2022), count);
        if (!family) {
            ADD_FAILURE() << family.error().message;
            return out;
        }
        for (const blade::FamilyMember& member : *family) {
            auto model = blade::Blade::create(member.blade);
            auto generated = model ? blade::generateHelicalPath(*model, member.path)
                                   : Result<blade::GeneratedPath>(std::unexpected(model.error()));
            if (!generated) {
                ADD_FAILURE() << member.name << ": " << generated.error().message;
                continue;
            }
            out.push_back({member.name, std::move(generated->path), member.path.toolRadius,
                           member.path.feed});
        }
        auto compressor = compressorLike(4);
        if (!compressor) {
            ADD_FAILURE() << compressor.error().message;
        } else {
            out.push_back(std::move(*compressor));
        }
        return out;
    }();
    return all;
}

Result<JobResult> runOn(const Program& program, const toolpath::Toolpath& path,
                        const std::string& tag, bool reschedule = true) {
    const fs::path file =
        fs::temp_directory_path() / ("bladeaxis_default_figures_" + program.name + tag + ".cl");
    std::ofstream(file, std::ios::binary)
        << aptText(path, program.toolRadius, units::perSecondToPerMinute(program.feed));
    JobSpec spec;
    spec.program = file;
    spec.reschedule = reschedule;
    auto result = runQuietly(spec);
    fs::remove(file);
    return result;
}

// --- The independent evaluation -------------------------------------------------------------

struct Peaks {
    std::array<double, 5> velocity{}, acceleration{}; // per axis, mm or rad, s
};

// The machine axes `axes` (one per pass record) run at the constant tip feed `feed` along the
// tips of the forward kinematics, each axis smoothed by a Gaussian of standard deviation
// sigma (s) on a grid of `step` s; velocity and acceleration are the axis convolved with the
// Gaussian's first and second derivatives. Outside the pass the axis goes on at its end slope.
Peaks independentPeaks(const kinematics::MachineModel& machine,
                       std::span<const kinematics::MachineAxes> axes, double feed) {
    constexpr double step = 0.5e-3;
    const double sigma = 0.008 / std::sqrt(6.0);
    std::vector<double> t;
    std::vector<std::size_t> index;
    Vec3 last = kinematics::forwardKinematics(machine.chain, axes[0]).tip;
    double s = 0.0;
    t.push_back(0.0);
    index.push_back(0);
    for (std::size_t i = 1; i < axes.size(); ++i) {
        const Vec3 tip = kinematics::forwardKinematics(machine.chain, axes[i]).tip;
        const double chord = (tip - last).norm();
        if (chord < 1e-9) {
            continue;
        }
        s += chord;
        last = tip;
        t.push_back(s / feed);
        index.push_back(i);
    }
    const double duration = t.back();
    const auto half = static_cast<std::ptrdiff_t>(std::ceil(4.0 * sigma / step));
    std::vector<double> g0, g1, g2; // the unit Gaussian and its d/dt, d2/dt2, times the step
    for (std::ptrdiff_t j = -half; j <= half; ++j) {
        const double u = static_cast<double>(j) * step;
        const double g = std::exp(-0.5 * u * u / (sigma * sigma)) /
                         (sigma * std::sqrt(2.0 * std::numbers::pi)) * step;
        g0.push_back(g);
        g1.push_back(-u / (sigma * sigma) * g);
        g2.push_back((u * u / (sigma * sigma) - 1.0) / (sigma * sigma) * g);
    }
    // The sampled, truncated kernels must differentiate polynomials exactly. The sampled g''
    // does not sum to zero (about -44 /s^2 at 0.5 ms, cut at 4 sigma), so without correction the
    // acceleration reads 44 times the axis's position: 581 rad/s^2 for an A that has turned
    // 13 rad, thousands of mm/s^2 for Y and Z tens of millimetres from the origin. Correct g''
    // within span{g'', g} so that sum g'' = 0 and sum u^2/2 g'' = 1 (its odd moments vanish by
    // symmetry), and scale g' so that sum -u g' = 1.
    {
        double s0 = 0.0, s2 = 0.0, m0 = 0.0, m2 = 0.0, m1 = 0.0;
        for (std::ptrdiff_t j = -half; j <= half; ++j) {
            const auto k = static_cast<std::size_t>(j + half);
            const double u2 = 0.5 * std::pow(static_cast<double>(j) * step, 2);
            s0 += g2[k];
            s2 += u2 * g2[k];
            m0 += g0[k];
            m2 += u2 * g0[k];
            m1 -= static_cast<double>(j) * step * g1[k];
        }
        // alpha g'' + beta g: alpha s0 + beta m0 = 0, alpha s2 + beta m2 = 1
        const double det = s2 * m0 - s0 * m2;
        const double alpha = m0 / det, beta = -s0 / det;
        for (std::size_t k = 0; k < g2.size(); ++k) {
            g2[k] = alpha * g2[k] + beta * g0[k];
            g1[k] /= m1;
        }
    }
    Peaks peaks;
    const auto count = static_cast<std::ptrdiff_t>(std::floor(duration / step)) + 1;
    for (AxisId axis : kinematics::kAllAxes) {
        std::vector<double> q(t.size());
        for (std::size_t k = 0; k < t.size(); ++k) {
            q[k] = axes[index[k]][axis];
        }
        const double startSlope = (q[1] - q[0]) / (t[1] - t[0]);
        const double endSlope = (q.back() - q[q.size() - 2]) / (t.back() - t[t.size() - 2]);
        std::vector<double> grid(static_cast<std::size_t>(count + 2 * half));
        std::size_t segment = 0;
        for (std::ptrdiff_t k = -half; k < count + half; ++k) {
            const double at = static_cast<double>(k) * step;
            double value = 0.0;
            if (at <= 0.0) {
                value = q.front() + startSlope * at;
            } else if (at >= duration) {
                value = q.back() + endSlope * (at - duration);
            } else {
                while (t[segment + 1] < at) {
                    ++segment;
                }
                const double f = (at - t[segment]) / (t[segment + 1] - t[segment]);
                value = q[segment] + f * (q[segment + 1] - q[segment]);
            }
            grid[static_cast<std::size_t>(k + half)] = value;
        }
        double peakV = 0.0, peakA = 0.0;
        for (std::ptrdiff_t k = 0; k < count; ++k) {
            double v = 0.0, a = 0.0;
            for (std::ptrdiff_t j = -half; j <= half; ++j) {
                // (q * g')(t) = sum q(t - u) g'(u)
                const double value = grid[static_cast<std::size_t>(k + half - j)];
                v += value * g1[static_cast<std::size_t>(j + half)];
                a += value * g2[static_cast<std::size_t>(j + half)];
            }
            peakV = std::max(peakV, std::abs(v));
            peakA = std::max(peakA, std::abs(a));
        }
        peaks.velocity[static_cast<std::size_t>(axis)] = peakV;
        peaks.acceleration[static_cast<std::size_t>(axis)] = peakA;
    }
    return peaks;
}

// --- The checks ------------------------------------------------------------------------------

struct Figure {
    std::string name;
    double value = 0.0;
    double floor = 0.0; // an absolute allowance for figures near zero
};

std::vector<Figure> figuresOf(const analysis::AxisProfile& profile,
                              const analysis::ConstantFeedTime& t1) {
    std::vector<Figure> figures;
    for (AxisId axis : kinematics::kAllAxes) {
        if (axis == AxisId::B) {
            continue; // the fixed tilt: its only motion is the CL file's rounding (1e-6 rad/s)
        }
        const auto& series = profile.axis(axis);
        const std::string name = kinematics::axisName(axis);
        // A p99.9 far below its axis's peak is a still stretch's noise: it may move by 1 % of
        // the peak.
        figures.push_back({name + " peak velocity", series.peakVelocity, 0.0});
        figures.push_back({name + " peak acceleration", series.peakAcceleration, 0.0});
        figures.push_back(
            {name + " p99.9 velocity", series.p999Velocity, 0.01 * series.peakVelocity});
        figures.push_back({name + " p99.9 acceleration", series.p999Acceleration,
                           0.01 * series.peakAcceleration});
    }
    figures.push_back({"T1", t1.time, 0.0});
    return figures;
}

void expectHold(const std::string& what, const std::vector<Figure>& before,
                const std::vector<Figure>& after) {
    ASSERT_EQ(before.size(), after.size());
    for (std::size_t k = 0; k < before.size(); ++k) {
        const double a = before[k].value, b = after[k].value;
        EXPECT_LE(std::abs(b - a), 0.05 * std::abs(a) + before[k].floor + 1e-12)
            << what << " " << before[k].name << ": " << a << " -> " << b << " ("
            << 100.0 * (b - a) / a << " %)";
    }
}

void expectAgree(const std::string& what, const analysis::AxisProfile& profile,
                 const Peaks& independent) {
    for (AxisId axis : kinematics::kAllAxes) {
        if (axis == AxisId::B) {
            continue; // the fixed tilt (rounding noise)
        }
        const auto& series = profile.axis(axis);
        const auto k = static_cast<std::size_t>(axis);
        const std::pair<const char*, std::pair<double, double>> pairs[] = {
            {"peak velocity", {series.peakVelocity, independent.velocity[k]}},
            {"peak acceleration", {series.peakAcceleration, independent.acceleration[k]}}};
        for (const auto& [name, values] : pairs) {
            const auto [reported, reference] = values;
            if (reference < 1e-9 && reported < 1e-9) {
                continue; // a still axis (B)
            }
            EXPECT_LE(std::abs(reported - reference), 0.2 * reference)
                << what << " " << kinematics::axisName(axis) << " " << name << ": default "
                << reported << ", independent " << reference;
        }
    }
}

// The re-scheduled program as a tool path of its own: the job's records with the new poses on
// its pass. Analysed as an input, its figures are those of the re-scheduled program.
toolpath::Toolpath rescheduledPath(const JobResult& result) {
    toolpath::Toolpath path = result.program.path();
    const std::span<const toolpath::ClRecord> pass(path.records.data() + result.pass.first,
                                                   result.pass.count);
    const std::vector<toolpath::ClRecord> rewritten = rescheduledRecords(pass, *result.rescheduled);
    std::ranges::copy(rewritten,
                      path.records.begin() + static_cast<std::ptrdiff_t>(result.pass.first));
    return path;
}

struct Split {
    double chordMm;
    int every;
};

constexpr Split kSplits[] = {{0.001, 3}, {0.003, 5}, {0.005, 4}, {0.002, 5}};

// Micro-chords are added to each program as written: to the CAM's original, and to the
// re-scheduled program (its own points, analysed as it would run). Re-scheduling a chorded
// original is a different question (the schedule itself may move: its lead-in search and key
// points see the new split points); that is printed, not asserted here.
TEST(DefaultFiguresHold, MicroChordsMoveNoFigureAndTheFiguresAgreeWithAnIndependentController) {
    ASSERT_FALSE(programs().empty());
    for (const Program& program : programs()) {
        SCOPED_TRACE(program.name);
        auto clean = runOn(program, program.path, "_clean");
        ASSERT_TRUE(clean) << clean.error().toString();
        ASSERT_TRUE(clean->rescheduled.has_value());
        const RescheduleOutcome& cleanNew = *clean->rescheduled;
        const auto originalFigures = figuresOf(clean->original, clean->constantFeed);
        std::printf("[ measure  ] %s: %zu records; A peak acc. %.0f -> %.0f deg/s^2, T1 %.1f -> "
                    "%.1f s\n",
                    program.name.c_str(), clean->pass.count,
                    units::radToDeg(clean->original.axis(AxisId::A).peakAcceleration),
                    units::radToDeg(cleanNew.profile.axis(AxisId::A).peakAcceleration),
                    clean->constantFeed.time, cleanNew.constantFeed.time);

        expectAgree(program.name + " original", clean->original,
                    independentPeaks(clean->machine, *clean->axes, program.feed));
        expectAgree(program.name + " re-scheduled", cleanNew.profile,
                    independentPeaks(clean->machine, *cleanNew.axes, program.feed));
        const toolpath::Toolpath written = rescheduledPath(*clean);
        auto writtenClean = runOn(program, written, "_written", false);
        ASSERT_TRUE(writtenClean) << writtenClean.error().toString();
        const auto writtenFigures = figuresOf(writtenClean->original, writtenClean->constantFeed);

        for (const Split& split : kSplits) {
            const std::string tag = "_" + std::to_string(static_cast<int>(split.chordMm * 1e3)) +
                                    "um_every_" + std::to_string(split.every);
            auto chorded = runOn(
                program,
                withMicroChords(program.path, program.toolRadius, split.chordMm, split.every), tag);
            ASSERT_TRUE(chorded) << tag << ": " << chorded.error().toString();
            ASSERT_TRUE(chorded->rescheduled.has_value());
            ASSERT_GT(chorded->pass.count, clean->pass.count + clean->pass.count / 6) << tag;
            std::printf(
                "[ measure  ] %s%s: A peak acc. %.0f -> %.0f deg/s^2, T1 %.1f -> %.1f s\n",
                program.name.c_str(), tag.c_str(),
                units::radToDeg(chorded->original.axis(AxisId::A).peakAcceleration),
                units::radToDeg(chorded->rescheduled->profile.axis(AxisId::A).peakAcceleration),
                chorded->constantFeed.time, chorded->rescheduled->constantFeed.time);
            expectHold(program.name + tag + " original", originalFigures,
                       figuresOf(chorded->original, chorded->constantFeed));
            auto writtenChorded = runOn(
                program, withMicroChords(written, program.toolRadius, split.chordMm, split.every),
                tag + "_written", false);
            ASSERT_TRUE(writtenChorded) << tag << ": " << writtenChorded.error().toString();
            expectHold(program.name + tag + " re-scheduled", writtenFigures,
                       figuresOf(writtenChorded->original, writtenChorded->constantFeed));
        }
    }
}

} // namespace
} // namespace bladeaxis::job::test
