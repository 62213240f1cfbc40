#include "core/io/cl/apt.h"

#include <gtest/gtest.h>

#include <clocale>
#include <random>
#include <string>

namespace bladeaxis::io::cl {
namespace {

toolpath::Toolpath randomPath(unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-500.0, 500.0);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    std::uniform_int_distribution<int> percent(0, 99);
    toolpath::Toolpath path;
    path.toolRadius = 3.175;
    double feed = 20.0;
    for (int i = 0; i < count; ++i) {
        toolpath::ClRecord record;
        record.tip = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
        Vec3 axis(gaussian(rng), gaussian(rng), gaussian(rng));
        record.axis = axis.norm() > 1e-3 ? axis.normalized() : Vec3::UnitZ();
        if (percent(rng) < 10) {
            record.motion = toolpath::MotionKind::Rapid;
        } else {
            if (percent(rng) < 15) {
                feed = 5.0 + percent(rng);
            }
            record.feed = feed;
        }
        path.records.push_back(record);
    }
    return path;
}

TEST(EmitApt, RoundTripsThroughTheReader) {
    const toolpath::Toolpath path = randomPath(42, 400);
    AptEmitOptions options;
    options.decimals = 10;
    options.comments = {"round trip", "two\nlines $"};
    const std::string text = emitApt(path, options);
    Result<AptProgram> program = parseApt(text, "emitted.cls");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto& records = program->path.records;
    ASSERT_EQ(records.size(), path.records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
        EXPECT_LT((records[i].tip - path.records[i].tip).lpNorm<Eigen::Infinity>(), 1e-9) << i;
        EXPECT_LT((records[i].axis - path.records[i].axis).lpNorm<Eigen::Infinity>(), 1e-9) << i;
        EXPECT_EQ(records[i].motion, path.records[i].motion) << i;
        EXPECT_NEAR(records[i].feed, path.records[i].feed, 1e-9) << i;
    }
    ASSERT_TRUE(program->path.toolRadius.has_value());
    EXPECT_NEAR(*program->path.toolRadius, 3.175, 1e-12);
    EXPECT_TRUE(program->path.warnings.empty());
}

TEST(EmitApt, WritesTheHeaderAndFedratOnlyWhenTheFeedChanges) {
    toolpath::Toolpath path;
    toolpath::ClRecord record;
    record.feed = 10.0;
    path.records = {record, record, record};
    path.records[0].motion = toolpath::MotionKind::Rapid;
    path.records[0].feed = 0.0;
    AptEmitOptions options;
    options.decimals = 3;
    options.toolRadius = 5.0;
    EXPECT_EQ(emitApt(path, options), "PARTNO BLADEAXIS\nUNITS/MM\nCUTTER/10,5\nMULTAX/ON\n"
                                      "RAPID\nGOTO/0.000,0.000,0.000,0.000,0.000,1.000\n"
                                      "FEDRAT/MMPM,600.000\n"
                                      "GOTO/0.000,0.000,0.000,0.000,0.000,1.000\n"
                                      "GOTO/0.000,0.000,0.000,0.000,0.000,1.000\nEND\nFINI\n");
}

// A decimal-comma desktop must not change what is read or written (docs/architecture.md,
// Conventions).
TEST(AptLocale, DecimalCommaLocaleChangesNothing) {
    const toolpath::Toolpath path = randomPath(7, 50);
    const std::string sample = "UNITS/MM\nCUTTER/6.35,3.175\nFEDRAT/MMPM,1234.5\n"
                               "GOTO/1.25,-2.5,3.75,0.6,0,0.8\n";
    const std::string emittedC = emitApt(path, AptEmitOptions{});
    const Result<AptProgram> parsedC = parseApt(sample, "c.cls");
    ASSERT_TRUE(parsedC.has_value());

    const char* previous = std::setlocale(LC_ALL, nullptr);
    const std::string saved = previous ? previous : "C";
    if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr) {
        GTEST_SKIP() << "de_DE.UTF-8 locale not installed";
    }
    const std::string emittedDe = emitApt(path, AptEmitOptions{});
    const Result<AptProgram> parsedDe = parseApt(sample, "c.cls");
    std::setlocale(LC_ALL, saved.c_str());

    EXPECT_EQ(emittedDe, emittedC);
    ASSERT_TRUE(parsedDe.has_value());
    EXPECT_EQ(parsedDe->path.records[0].tip, parsedC->path.records[0].tip);
    EXPECT_EQ(parsedDe->path.records[0].axis, parsedC->path.records[0].axis);
    EXPECT_EQ(parsedDe->path.records[0].feed, parsedC->path.records[0].feed);
    EXPECT_EQ(parsedDe->path.toolRadius, parsedC->path.toolRadius);
}

} // namespace
} // namespace bladeaxis::io::cl
