#include "core/job/reproduction.h"

#include <gtest/gtest.h>

namespace bladeaxis::job {
namespace {

TEST(Spread, MedianAndQuartilesInterpolateBetweenOrderStatistics) {
    const Spread spread = spreadOf({5.0, 1.0, 3.0, 2.0, 4.0});
    EXPECT_DOUBLE_EQ(spread.median, 3.0);
    EXPECT_DOUBLE_EQ(spread.q1, 2.0);
    EXPECT_DOUBLE_EQ(spread.q3, 4.0);
    EXPECT_EQ(spread.count, 5u);
    EXPECT_DOUBLE_EQ(spreadOf({1.0, 2.0}).median, 1.5);
    EXPECT_EQ(spreadOf({}).count, 0u);
}

const ReproductionResult& smallStudy() {
    static const ReproductionResult result = [] {
        ReproductionSpec spec;
        spec.blades = 5;
        NullProgressSink progress;
        auto run = runReproduction(spec, progress, CancelToken{});
        EXPECT_TRUE(run.has_value()) << run.error().toString();
        return *run;
    }();
    return result;
}

TEST(Reproduction, EveryBladeIsComparedAndTheEngineNeverReverses) {
    const ReproductionResult& result = smallStudy();
    ASSERT_EQ(result.blades.size(), 5u);
    for (const BladeFigures& blade : result.blades) {
        EXPECT_TRUE(blade.error.empty()) << blade.blade << ": " << blade.error;
        EXPECT_TRUE(blade.missing.empty()) << blade.blade << ": " << blade.missing.front();
        EXPECT_EQ(blade.figures.at("stheta-best").at("a_reversals"), 0.0) << blade.blade;
    }
    // Issue 4: the symmetric member (family-3) used to lose its optimum and thus its gaps.
    EXPECT_EQ(result.summary.at("stheta-best").at("peak_theta_dd_ratio_to_optimal_lp").count, 5u);
    EXPECT_EQ(result.summary.at("stheta-best").at("t2_gain_vs_original").count, 5u);
    const Spread& reduction =
        result.summary.at("stheta-best").at("a_peak_acceleration_reduction_vs_original");
    EXPECT_EQ(reduction.count, 5u);
    EXPECT_GT(reduction.median, 0.5);
    EXPECT_LE(reduction.q1, reduction.median);
    EXPECT_LE(reduction.median, reduction.q3);
}

TEST(Reproduction, SummaryCountsTheBladesOfEachMedianAndNamesWhatIsMissing) {
    ReproductionResult result;
    BladeFigures blade;
    blade.blade = "family-7";
    blade.figures["stheta-best"]["t2_gain_vs_original"] = 0.4;
    blade.missing = {"optimal-qp: layer 2: did not converge"};
    result.blades = {blade, blade};
    result.blades[1].blade = "family-8";
    result.blades[1].missing.clear();
    result.summary["stheta-best"]["t2_gain_vs_original"] = spreadOf({0.4, 0.4});
    const std::string text = reproductionSummary(result);
    EXPECT_NE(text.find("(2 blades)"), std::string::npos) << text;
    EXPECT_NE(text.find("family-7: optimal-qp: layer 2: did not converge"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("family-8:"), std::string::npos) << text;
    const std::string json = reproductionJsonText(result);
    EXPECT_NE(json.find("\"missing_figures\""), std::string::npos);
}

TEST(Reproduction, IsDeterministicForASeed) {
    ReproductionSpec spec;
    spec.blades = 5;
    NullProgressSink progress;
    auto again = runReproduction(spec, progress, CancelToken{});
    ASSERT_TRUE(again.has_value());
    // Every figure but the measured compute-time ratios is bit-identical.
    auto withoutTimings = [](const std::string& csv) {
        std::string kept;
        std::size_t start = 0;
        while (start < csv.size()) {
            const std::size_t end = csv.find('\n', start);
            const std::string line = csv.substr(start, end - start);
            if (line.find("compute_speedup") == std::string::npos) {
                kept += line + "\n";
            }
            start = end == std::string::npos ? csv.size() : end + 1;
        }
        return kept;
    };
    EXPECT_EQ(withoutTimings(reproductionCsv(*again)),
              withoutTimings(reproductionCsv(smallStudy())));
}

TEST(Reproduction, CancelledStudyStops) {
    ReproductionSpec spec;
    spec.blades = 3;
    NullProgressSink progress;
    CancelToken cancel;
    cancel.requestCancel();
    auto result = runReproduction(spec, progress, cancel);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Cancelled);
}

} // namespace
} // namespace bladeaxis::job
