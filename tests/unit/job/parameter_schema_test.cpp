#include "core/job/job_file.h"
#include "core/job/parameter_schema.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

namespace bladeaxis::job {
namespace {

namespace fs = std::filesystem;

TEST(ParameterSchema, KeysAreUniqueAndEveryValueRoundTrips) {
    std::set<std::string> keys;
    for (const ParameterInfo& info : scheduleParameterSchema()) {
        EXPECT_TRUE(keys.insert(info.key).second) << "duplicate key " << info.key;
        for (const auto& preset : {scheduling::bestPreset(), scheduling::faithfulPreset()}) {
            scheduling::ScheduleParameters copy = scheduling::bestPreset();
            const std::string text = info.get(preset);
            ASSERT_TRUE(info.set(copy, text).has_value()) << info.key << " = " << text;
            EXPECT_EQ(info.get(copy), text) << info.key;
        }
    }
    EXPECT_GE(keys.size(), 25u);
}

TEST(ParameterSchema, MarginIsGivenInDegreesAndStoredInRadians) {
    scheduling::ScheduleParameters parameters;
    ASSERT_TRUE(findParameter("margin_deg")->set(parameters, "6"));
    EXPECT_NEAR(parameters.marginRad, 6.0 * 3.141592653589793 / 180.0, 1e-15);
    EXPECT_EQ(findParameter("margin_deg")->get(parameters), "6");
}

TEST(ParameterSchema, ValuesOutsideTheirDomainAreRejectedWithTheKey) {
    scheduling::ScheduleParameters parameters;
    const auto margin = findParameter("margin_deg")->set(parameters, "-1");
    ASSERT_FALSE(margin.has_value());
    EXPECT_NE(margin.error().message.find("margin_deg: expected a number from 0 to 45, got '-1'"),
              std::string::npos);
    EXPECT_FALSE(findParameter("eps_rule")->set(parameters, "fast").has_value());
    EXPECT_FALSE(findParameter("threads")->set(parameters, "1.5").has_value());
    EXPECT_FALSE(findParameter("despike")->set(parameters, "yes").has_value());
    EXPECT_FALSE(findParameter("lead_fraction")->set(parameters, "nan").has_value());
}

TEST(ParameterSchema, PresetsDifferInTheirEpsilonRule) {
    EXPECT_EQ(findParameter("eps_rule")->get(*presetParameters("faithful")), "paper");
    EXPECT_EQ(findParameter("eps_rule")->get(*presetParameters("best")), "exact");
    EXPECT_FALSE(presetParameters("fastest").has_value());
}

TEST(JobFile, WrittenJobReadsBackToTheSameSpec) {
    const fs::path dir = fs::temp_directory_path() / "bladeaxis_job_file";
    JobSpec spec;
    spec.program = dir / "blade.nc";
    spec.machineFile = dir / "machines" / "m.json";
    spec.toolRadius = 6.0;
    spec.parameters = scheduling::faithfulPreset();
    spec.presetName = "faithful";
    ASSERT_TRUE(findParameter("margin_deg")->set(spec.parameters, "4.5"));
    ASSERT_TRUE(findParameter("adjust")->set(spec.parameters, "shift"));
    ASSERT_TRUE(findParameter("lead_band")->set(spec.parameters, "true"));
    ASSERT_TRUE(findParameter("lead_band_min_deg")->set(spec.parameters, "-20"));
    ASSERT_TRUE(findParameter("allow_nonmonotone")->set(spec.parameters, "true"));
    spec.analysis.feedReference = analysis::FeedReference::Centre;
    spec.analysis.feedOverride = 40.0;
    spec.analysis.method = analysis::DerivativeMethod::Filtered;
    spec.analysis.filterSeconds = 0.012;
    spec.cad.tool.stickOut = 42.5;
    spec.cad.tool.holderRadius = 16.0;
    spec.cad.tool.holderLength = 75.0;
    spec.outputProgram = dir / "out.nc";
    const std::string text = jobJsonText(spec, dir);
    JobSpec back;
    ASSERT_TRUE(parseJobJson(text, dir / "job.json", back).has_value()) << text;
    EXPECT_EQ(back.program.lexically_normal(), spec.program.lexically_normal());
    EXPECT_EQ(back.machineFile.lexically_normal(), spec.machineFile.lexically_normal());
    EXPECT_EQ(back.outputProgram.lexically_normal(), spec.outputProgram.lexically_normal());
    EXPECT_EQ(back.toolRadius, 6.0);
    EXPECT_EQ(back.presetName, "faithful");
    for (const ParameterInfo& info : scheduleParameterSchema()) {
        EXPECT_EQ(info.get(back.parameters), info.get(spec.parameters)) << info.key;
    }
    EXPECT_EQ(back.parameters.adjust, scheduling::Adjust::Shift);
    EXPECT_TRUE(back.parameters.leadBand);
    EXPECT_NEAR(back.parameters.leadBandMinRad, -20.0 * 3.141592653589793 / 180.0, 1e-15);
    EXPECT_TRUE(back.parameters.allowNonmonotone);
    EXPECT_EQ(back.analysis.feedReference, analysis::FeedReference::Centre);
    EXPECT_DOUBLE_EQ(back.analysis.feedOverride, 40.0);
    EXPECT_EQ(back.analysis.method, analysis::DerivativeMethod::Filtered);
    EXPECT_DOUBLE_EQ(back.analysis.filterSeconds, 0.012);
    EXPECT_DOUBLE_EQ(back.cad.tool.stickOut, 42.5);
    EXPECT_DOUBLE_EQ(back.cad.tool.holderRadius, 16.0);
    EXPECT_DOUBLE_EQ(back.cad.tool.holderLength, 75.0);
}

TEST(JobFile, AnOutputOutsideTheJobsFolderIsRefusedNamingTheKey) {
    const auto dir = std::filesystem::temp_directory_path() / "bladeaxis_job_confined";
    std::filesystem::create_directories(dir);
    for (const char* output : {"\"../../../.bashrc\"", "\"/tmp/elsewhere.nc\""}) {
        const std::string text = "{\n \"schema\": \"bladeaxis-job/1\",\n \"program\": \"in.nc\",\n "
                                 "\"output_program\": " +
                                 std::string(output) + "\n}";
        JobSpec spec;
        const auto status = parseJobJson(text, dir / "job.json", spec);
        ASSERT_FALSE(status.has_value()) << output;
        EXPECT_NE(status.error().message.find("output_program: a job file writes only inside"),
                  std::string::npos)
            << status.error().toString();
        EXPECT_EQ(status.error().where.line, 4);
    }
}

TEST(JobFile, AnOutputThroughADanglingLinkOutOfTheFolderIsRefused) {
    namespace fs = std::filesystem;
    const auto base = fs::temp_directory_path() / "bladeaxis_job_dangling_link";
    fs::remove_all(base);
    fs::create_directories(base / "job");
    fs::create_symlink("../elsewhere/.bash_login", base / "job" / "out.nc");
    const std::string text = R"({"schema": "bladeaxis-job/1", "program": "in.nc",
  "output_program": "out.nc"})";
    JobSpec spec;
    const auto status = parseJobJson(text, base / "job" / "job.json", spec);
    ASSERT_FALSE(status.has_value());
    EXPECT_NE(status.error().message.find("output_program: a job file writes only inside"),
              std::string::npos)
        << status.error().toString();
    EXPECT_FALSE(fs::exists(base / "elsewhere"));
    fs::remove_all(base);
}

TEST(JobFile, AJobNamedWithoutAFolderWritesInsideTheCurrentFolder) {
    const auto dir = std::filesystem::temp_directory_path() / "bladeaxis_job_bare_name";
    std::filesystem::create_directories(dir);
    const auto previous = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    JobSpec spec;
    const auto status = parseJobJson(
        R"({"schema": "bladeaxis-job/1", "demo": true, "output_program": "new.nc",
            "output_dir": "report"})",
        "job.json", spec);
    std::filesystem::current_path(previous);
    EXPECT_TRUE(status.has_value()) << status.error().toString();
}

TEST(JobFile, ADemoJobMayReplaceItsEarlierOutputProgram) {
    const auto dir = std::filesystem::temp_directory_path() / "bladeaxis_job_demo_twice";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "new.nc") << "(an earlier run's output)\n";
    JobSpec spec;
    const auto status =
        parseJobJson(R"({"schema": "bladeaxis-job/1", "demo": true, "output_program": "new.nc"})",
                     dir / "job.json", spec);
    EXPECT_TRUE(status.has_value()) << status.error().toString();
}

TEST(JobFile, MoreLayerEditsThanAnyProgramHasLayersAreRefusedNamingTheCount) {
    std::string edits;
    for (std::size_t i = 0; i <= kMaxLayerEdits; ++i) {
        edits += (i == 0 ? "{\"layer\": " : ", {\"layer\": ") + std::to_string(i % 50) + "}";
    }
    const std::string text =
        "{\"schema\": \"bladeaxis-job/1\", \"program\": \"in.nc\", \"layer_edits\": [" + edits +
        "]}";
    JobSpec spec;
    const auto status = parseJobJson(text, "job.json", spec);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(status.error().message.find("at most 100000 layer edits"), std::string::npos)
        << status.error().message;
}

TEST(JobFile, AnEditWithMillionsOfKeyPointsIsRefused) {
    std::string points;
    for (std::size_t i = 0; i <= kMaxKeyPointsPerLayer; ++i) {
        points += (i == 0 ? "[" : ", [") + std::to_string(i) + ", 0]";
    }
    const std::string text = "{\"schema\": \"bladeaxis-job/1\", \"program\": \"in.nc\", "
                             "\"layer_edits\": [{\"layer\": 1, \"key_points\": [" +
                             points + "]}]}";
    JobSpec spec;
    const auto status = parseJobJson(text, "job.json", spec);
    ASSERT_FALSE(status.has_value());
    EXPECT_NE(status.error().message.find("at most 100000 key points"), std::string::npos)
        << status.error().message;
}

TEST(JobFile, AJobFileLargerThanAnyJobIsRefusedBeforeItIsRead) {
    const auto path = std::filesystem::temp_directory_path() /
                      ("bladeaxis_huge_job_" + std::to_string(::getpid()) + ".json");
    {
        std::ofstream out(path, std::ios::binary);
        out << "{\"schema\": \"bladeaxis-job/1\", \"x\": \"";
        out.seekp(static_cast<std::streamoff>(kMaxJobFileBytes) + 16);
        out << "\"}";
    }
    JobSpec spec;
    const auto status = readJobFile(path, spec);
    std::filesystem::remove(path);
    ASSERT_FALSE(status.has_value());
    EXPECT_NE(status.error().message.find("job file too large"), std::string::npos);
}

TEST(JobFile, AnOutputProgramOverAFileThatIsNoProgramIsRefused) {
    const auto dir = std::filesystem::temp_directory_path() / "bladeaxis_job_unrelated";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "notes.txt") << "keep me\n";
    const std::string text = "{\n \"schema\": \"bladeaxis-job/1\",\n \"program\": \"in.nc\",\n "
                             "\"output_program\": \"notes.txt\"\n}";
    JobSpec spec;
    const auto refused = parseJobJson(text, dir / "job.json", spec);
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().message.find("not a program like the input"), std::string::npos);
    std::ofstream(dir / "previous.nc") << "G1 X0\n";
    const std::string previous = "{\n \"schema\": \"bladeaxis-job/1\",\n \"program\": "
                                 "\"in.nc\",\n \"output_program\": \"previous.nc\"\n}";
    EXPECT_TRUE(parseJobJson(previous, dir / "job.json", spec).has_value());
}

// Found by fuzzing: values of the wrong JSON type used to escape as exceptions (exit 1).
TEST(JobFile, ValuesOfTheWrongTypeAreInvalidArgumentsNamingTheFile) {
    for (const std::string text :
         {"{\"schema\": true}", "{\"schema\": \"bladeaxis-job/1\", \"columns\": 5}",
          "{\"schema\": \"bladeaxis-job/1\", \"layer_edits\": [{\"layer\": -1}]}",
          "{\"schema\": \"bladeaxis-job/1\", \"layer_edits\": [{\"layer\": 1, "
          "\"margin_deg\": \"wide\"}]}"}) {
        JobSpec spec;
        const auto status = parseJobJson(text, "/jobs/job.json", spec);
        ASSERT_FALSE(status.has_value()) << text;
        EXPECT_EQ(status.error().code, ErrorCode::InvalidArgument) << status.error().toString();
        EXPECT_EQ(status.error().where.file, "/jobs/job.json");
    }
}

TEST(JobFile, UnknownDerivativeMethodNamesTheKey) {
    const std::string text = "{\n \"schema\": \"bladeaxis-job/1\",\n \"derivatives\": \"cubic\"\n}";
    JobSpec spec;
    const auto status = parseJobJson(text, "job.json", spec);
    ASSERT_FALSE(status.has_value());
    EXPECT_NE(status.error().message.find("derivatives: expected"), std::string::npos);
    EXPECT_EQ(status.error().where.line, 3);
}

// A job file's text read as job.json.
Status parsedJob(const std::string& text) {
    JobSpec spec;
    return parseJobJson(text, "job.json", spec);
}

TEST(JobFile, UnknownParameterNamesTheKeyAndLine) {
    const std::string text =
        "{\n \"schema\": \"bladeaxis-job/1\",\n \"parameters\": {\n  \"margn_deg\": 3\n }\n}";
    const Status status = parsedJob(text);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().toString(),
              "job.json:4: invalid argument: parameters.margn_deg: unknown key in the scheduling "
              "parameters (docs/job-file.md); did you mean \"margin_deg\"?");
}

// The key is found by its path, not by its first occurrence: a layer edit's preset is not the
// job's, and a value out of range is named as the file names it.
TEST(JobFile, AnErrorInALayerEditNamesTheEditsLineAndKey) {
    const std::string text = "{\n \"schema\": \"bladeaxis-job/1\",\n \"preset\": \"best\",\n"
                             " \"layer_edits\": [\n  { \"layer\": 1 },\n"
                             "  { \"layer\": 2, \"preset\": \"bogus\" }\n ]\n}";
    const Status status = parsedJob(text);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().toString(), "job.json:6: invalid argument: layer_edits[1].preset: "
                                         "expected \"faithful\" or \"best\"");
}

TEST(JobFile, AParameterOutOfRangeIsNamedWithItsSectionAndUnit) {
    const std::string text =
        "{\n \"schema\": \"bladeaxis-job/1\",\n \"parameters\": {\n  \"margin_deg\": 99\n }\n}";
    const Status status = parsedJob(text);
    ASSERT_FALSE(status.has_value());
    EXPECT_EQ(status.error().where.line, 4);
    EXPECT_NE(status.error().message.find("parameters.margin_deg: expected a number from 0 to 45"),
              std::string::npos)
        << status.error().message;
}

TEST(JobFile, BadValuesAreRejected) {
    JobSpec spec;
    EXPECT_FALSE(parseJobJson("{}", "j.json", spec).has_value());
    EXPECT_FALSE(
        parseJobJson("{\"schema\": \"bladeaxis-job/1\", \"tool_radius_mm\": -2}", "j.json", spec));
    EXPECT_FALSE(
        parseJobJson("{\"schema\": \"bladeaxis-job/1\", \"preset\": \"quick\"}", "j.json", spec));
    EXPECT_FALSE(
        parseJobJson("{\"schema\": \"bladeaxis-job/1\", \"parameters\": {\"margin_deg\": \"x\"}}",
                     "j.json", spec));
    EXPECT_FALSE(parseJobJson("not json", "j.json", spec).has_value());
}

// The job-file schema (resources/schemas/job-file.schema.json) describes each scheduling
// parameter as the reader takes it: the same keys, kinds, ranges and choices.
TEST(JobFileSchema, DescribesEveryParameterAsTheReaderTakesIt) {
    std::ifstream file(std::string(BLADEAXIS_SOURCE_DIR) +
                       "/resources/schemas/job-file.schema.json");
    ASSERT_TRUE(file.good());
    const nlohmann::json schema = nlohmann::json::parse(file);
    const nlohmann::json& described = schema.at("properties").at("parameters").at("properties");
    std::set<std::string> keys;
    for (const ParameterInfo& info : scheduleParameterSchema()) {
        keys.insert(info.key);
        ASSERT_TRUE(described.contains(info.key)) << info.key;
        const nlohmann::json& entry = described.at(info.key);
        switch (info.kind) {
        case ParameterInfo::Kind::Number:
        case ParameterInfo::Kind::Integer:
            EXPECT_EQ(entry.at("type"),
                      info.kind == ParameterInfo::Kind::Number ? "number" : "integer")
                << info.key;
            EXPECT_EQ(entry.at("minimum").get<double>(), info.min) << info.key;
            EXPECT_EQ(entry.at("maximum").get<double>(), info.max) << info.key;
            break;
        case ParameterInfo::Kind::Choice:
            EXPECT_EQ(entry.at("enum").get<std::vector<std::string>>(), info.choices) << info.key;
            break;
        case ParameterInfo::Kind::Flag:
            EXPECT_EQ(entry.at("type"), "boolean") << info.key;
            break;
        }
    }
    for (const auto& [key, unused] : described.items()) {
        EXPECT_TRUE(keys.contains(key)) << key << " is in the schema but not a parameter";
    }
}

// What the window saves is what the schema describes: every key of a written job, with layer
// edits and parameters, is one of its object's properties.
TEST(JobFileSchema, AJobTheProgramWritesHasOnlyTheSchemasKeys) {
    JobSpec spec;
    spec.program = "/data/blade.nc";
    spec.machineFile = "/data/machine.json";
    spec.cad.file = "/data/blade.step";
    spec.outputProgram = "/data/out.nc";
    spec.outputDir = "/data/report";
    spec.toolRadius = 4.0;
    spec.parameters.marginRad = 0.05;
    scheduling::LayerOverride edit;
    edit.layer = 2;
    edit.marginRad = 0.03;
    edit.keyPoints = {{0.0, 0.0}, {5.0, 0.1}};
    spec.layerEdits.push_back(edit);
    const nlohmann::json job = nlohmann::json::parse(jobJsonText(spec, "/data"));
    std::ifstream file(std::string(BLADEAXIS_SOURCE_DIR) +
                       "/resources/schemas/job-file.schema.json");
    const nlohmann::json schema = nlohmann::json::parse(file);
    const auto expectKnown = [](const nlohmann::json& object, const nlohmann::json& objectSchema) {
        for (const auto& [key, unused] : object.items()) {
            EXPECT_TRUE(objectSchema.at("properties").contains(key)) << key;
        }
    };
    expectKnown(job, schema);
    ASSERT_TRUE(job.contains("parameters"));
    expectKnown(job.at("parameters"), schema.at("properties").at("parameters"));
    ASSERT_TRUE(job.contains("layer_edits"));
    for (const nlohmann::json& written : job.at("layer_edits")) {
        expectKnown(written, schema.at("properties").at("layer_edits").at("items"));
    }
}

} // namespace
} // namespace bladeaxis::job
