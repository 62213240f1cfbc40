// Layer edits kept with a job: saved in the job file exactly, applied by every run, and the
// batch front end running the saved job writes the same program as the job API.
#include "app/batch/batch_runner.h"
#include "core/base/file_io.h"
#include "core/base/units.h"
#include "core/job/job.h"
#include "core/job/job_file.h"
#include "core/scheduling/layer_edit.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

Result<JobResult> run(const JobSpec& spec) {
    NullProgressSink progress;
    CancelToken cancel;
    return runJob(spec, progress, cancel);
}

// An interior key point of `layer` moved a little, as a drag in the editor would.
std::vector<Vec2> draggedKeyPoints(const scheduling::LayerResult& layer) {
    for (const double step : {0.02, -0.02, 0.01, -0.01, 0.005, -0.005}) {
        for (std::size_t v = 1; v + 1 < layer.polyline.size(); ++v) {
            std::vector<Vec2> points = layer.polyline;
            points[v].y() += step;
            if (scheduling::resmoothLayer(layer, points, scheduling::bestPreset())) {
                return points;
            }
        }
    }
    return {};
}

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("bladeaxis_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

TEST(LayerEditsJobFile, EditsRoundTripExactly) {
    JobSpec spec;
    spec.demo = true;
    scheduling::LayerOverride edit;
    edit.layer = 3;
    edit.preset = scheduling::Preset::Faithful;
    edit.marginRad = 0.0349;
    edit.epsilonRule = scheduling::EpsilonRule::Paper;
    edit.leadFraction = 0.2;
    edit.keyPoints = {{0.0, 0.0}, {12.345678901234567, 0.1 / 3.0}, {80.125, 6.283185307179586}};
    scheduling::LayerOverride marginOnly;
    marginOnly.layer = 5;
    marginOnly.marginRad = 0.01;
    spec.layerEdits = {edit, marginOnly};

    JobSpec read;
    const Status parsed = parseJobJson(jobJsonText(spec, "/tmp"), "/tmp/job.json", read);
    ASSERT_TRUE(parsed.has_value()) << parsed.error().toString();
    EXPECT_TRUE(read.demo);
    ASSERT_EQ(read.layerEdits.size(), 2u);
    EXPECT_EQ(read.layerEdits[0].keyPoints, edit.keyPoints); // bit for bit
    EXPECT_EQ(read.layerEdits[0].preset, edit.preset);
    EXPECT_EQ(read.layerEdits[0].epsilonRule, edit.epsilonRule);
    EXPECT_EQ(read.layerEdits[0].leadFraction, edit.leadFraction);
    EXPECT_NEAR(*read.layerEdits[0].marginRad, *edit.marginRad, 1e-15);
    EXPECT_EQ(read.layerEdits[1].layer, 5u);
    EXPECT_FALSE(read.layerEdits[1].preset.has_value());
}

// Issue 41: the desktop recognises a job file by its content (packaging/bladeaxis-mime.xml looks
// for "schema": "bladeaxis-job/ in the first 256 bytes), so a saved job, however many edits and
// keys it holds, starts with its schema; before, the keys were sorted and it came last but one.
TEST(JobFile, Issue41SavedJobStartsWithItsSchema) {
    JobSpec spec;
    spec.program = "/data/blade.nc";
    spec.cad.file = "/data/cad/blade.step";
    spec.compare = true;
    spec.reschedule = false;
    for (std::size_t layer = 0; layer < 40; ++layer) {
        scheduling::LayerOverride edit;
        edit.layer = layer;
        edit.keyPoints = {{0.0, 0.0}, {1.0, 0.5}, {2.0, 1.0}};
        spec.layerEdits.push_back(edit);
    }
    const std::string text = jobJsonText(spec, "/data");
    EXPECT_EQ(text.rfind("{\n  \"schema\": \"bladeaxis-job/", 0), 0u) << text.substr(0, 256);
    JobSpec read;
    const Status parsed = parseJobJson(text, "/data/job.json", read);
    ASSERT_TRUE(parsed.has_value()) << parsed.error().toString();
    EXPECT_EQ(jobJsonText(read, "/data"), text);
}

TEST(JobFile, BladeCadAndItsPlacementRoundTrip) {
    JobSpec spec;
    spec.program = "/data/blade.nc";
    spec.cad.file = "/data/cad/blade.step";
    spec.cad.placement.translation = {1.5, -2.0, 0.25};
    JobSpec read;
    const Status parsed = parseJobJson(jobJsonText(spec, "/data"), "/data/job.json", read);
    ASSERT_TRUE(parsed.has_value()) << parsed.error().toString();
    EXPECT_EQ(read.cad.file, fs::path("/data/cad/blade.step"));
    EXPECT_EQ(read.cad.placement.translation, spec.cad.placement.translation);
    EXPECT_NE(jobJsonText(spec, "/data").find("\"cad\": \"cad/blade.step\""), std::string::npos);
}

// The rotation is written in degrees as given, so a saved job places the blade the same.
TEST(JobFile, BladeCadRotationRoundTripsInDegrees) {
    JobSpec spec;
    spec.cad.file = "/data/cad/blade.step";
    spec.cad.placement.rotationXyz = {units::degToRad(90.0), units::degToRad(-12.5), 0.0};
    const std::string text = jobJsonText(spec, "/data");
    const nlohmann::json written = nlohmann::json::parse(text)["cad_rotate_deg"];
    ASSERT_EQ(written.size(), 3u) << text;
    EXPECT_NEAR(written[0].get<double>(), 90.0, 1e-12);
    EXPECT_NEAR(written[1].get<double>(), -12.5, 1e-12);
    EXPECT_EQ(written[2].get<double>(), 0.0);
    JobSpec read;
    const Status parsed = parseJobJson(text, "/data/job.json", read);
    ASSERT_TRUE(parsed.has_value()) << parsed.error().toString();
    EXPECT_TRUE(read.cad.placement.rotationXyz.isApprox(spec.cad.placement.rotationXyz, 1e-15));
    EXPECT_EQ(jobJsonText(read, "/data"), text); // a second save writes the same file
}

TEST(JobFile, MalformedCadRotationNamesTheKeyAndItsLine) {
    JobSpec spec;
    const std::string text =
        "{\n  \"schema\": \"bladeaxis-job/1\",\n  \"cad_rotate_deg\": [90, 0]\n}\n";
    const Status parsed = parseJobJson(text, "rotated.json", spec);
    ASSERT_FALSE(parsed.has_value());
    EXPECT_EQ(parsed.error().where.line, 3);
    EXPECT_NE(parsed.error().message.find("cad_rotate_deg: expected [rx, ry, rz] in degrees"),
              std::string::npos)
        << parsed.error().message;
}

TEST(LayerEditsJobFile, MalformedKeyPointsNameTheLine) {
    JobSpec spec;
    const std::string text = "{\n  \"schema\": \"bladeaxis-job/1\",\n  \"layer_edits\": [\n"
                             "    {\"layer\": 1,\n     \"key_points\": [[0, \"x\"]]}\n  ]\n}\n";
    const Status parsed = parseJobJson(text, "edits.json", spec);
    ASSERT_FALSE(parsed.has_value());
    EXPECT_EQ(parsed.error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(parsed.error().where.line, 5);
    EXPECT_NE(parsed.error().message.find("key_points"), std::string::npos);
}

TEST(LayerEditsJobFile, EditWithoutALayerNumberIsRefused) {
    JobSpec spec;
    const Status parsed = parseJobJson(
        R"({"schema": "bladeaxis-job/1", "layer_edits": [{"margin_deg": 2}]})", "e.json", spec);
    ASSERT_FALSE(parsed.has_value());
    EXPECT_NE(parsed.error().message.find("layer"), std::string::npos);
}

TEST(LayerEditsJob, SavedEditRunsToTheSameProgramInBatch) {
    JobSpec spec;
    spec.demo = true;
    const auto plain = run(spec);
    ASSERT_TRUE(plain.has_value()) << plain.error().toString();
    const auto& layers = plain->rescheduled->schedule.layers;
    scheduling::LayerOverride edit;
    for (std::size_t k = 1; k + 1 < layers.size() && edit.keyPoints.empty(); ++k) {
        edit.layer = k;
        edit.keyPoints = draggedKeyPoints(layers[k]);
    }
    ASSERT_FALSE(edit.keyPoints.empty()) << "no demo layer has a movable key point";
    spec.layerEdits = {edit};
    const auto edited = run(spec);
    ASSERT_TRUE(edited.has_value()) << edited.error().toString();
    EXPECT_NE(edited->rescheduled->programText, plain->rescheduled->programText);
    EXPECT_EQ(edited->rescheduled->schedule.layers[edit.layer].polyline.size(),
              edit.keyPoints.size());
    EXPECT_EQ(edited->rescheduled->schedule.check.reversals, 0u);

    const fs::path folder = freshFolder("layer_edits_job");
    ASSERT_TRUE(writeFileAtomically(folder / "edited.json", jobJsonText(spec, folder)));
    std::ostringstream out, err;
    const std::string output = (folder / "edited.nc").string();
    const int code = app::runBatchCommandLine({"bladeaxis", "--batch", "--quiet", "--job",
                                               (folder / "edited.json").string(), "-o", output},
                                              out, err);
    ASSERT_EQ(code, 0) << err.str();
    const auto written = readTextFile(output);
    ASSERT_TRUE(written.has_value());
    EXPECT_EQ(*written, edited->rescheduled->programText);
    EXPECT_NE(reportJsonText(*edited, &spec).find("\"edited_layers\""), std::string::npos);
}

TEST(LayerEditsJob, AComparisonShowsTheEditedScheduleBesideThePresets) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = true;
    spec.compareOptimum = false;
    const auto plain = run(spec);
    ASSERT_TRUE(plain.has_value()) << plain.error().toString();
    EXPECT_EQ(plain->comparison->find(kEditedMethod), nullptr);
    const auto& layers = plain->rescheduled->schedule.layers;
    scheduling::LayerOverride edit;
    for (std::size_t k = 1; k + 1 < layers.size() && edit.keyPoints.empty(); ++k) {
        edit.layer = k;
        edit.keyPoints = draggedKeyPoints(layers[k]);
    }
    ASSERT_FALSE(edit.keyPoints.empty());
    spec.layerEdits = {edit};
    auto edited = run(spec);
    ASSERT_TRUE(edited.has_value()) << edited.error().toString();
    const compare::MethodResult* row = edited->comparison->find(kEditedMethod);
    ASSERT_NE(row, nullptr);
    // Evaluated like every method: the same motion as the job's own analysis of its program.
    EXPECT_NEAR(row->t1.time, edited->rescheduled->constantFeed.time,
                1e-6 * edited->rescheduled->constantFeed.time);
    EXPECT_EQ(row->profile.aReversals.count, 0);

    // Undone, the row goes: a comparison never shows an edit the program does not have.
    spec.layerEdits.clear();
    ASSERT_TRUE(appendEditedMethod(*edited, spec));
    EXPECT_EQ(edited->comparison->find(kEditedMethod), nullptr);
}

TEST(LayerEditsJob, EditThatNoLongerFitsFailsTheJob) {
    JobSpec spec;
    spec.demo = true;
    scheduling::LayerOverride edit;
    edit.layer = 1;
    edit.keyPoints = {{0.0, 0.0}, {1.0, 50.0}, {2.0, 0.0}};
    spec.layerEdits = {edit};
    const auto result = run(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(result.error().message.find("layer 1"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::job
