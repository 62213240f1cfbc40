#pragma once
// The stable entry point for plug-in authors and the Python module: read a program, run a job,
// write the program and reports, with progress and cancel callbacks and errors as values.
//
// Installed as <bladeaxis/bladeaxis.h> by the bladeaxis-dev package (find_package(BladeAxis),
// target bladeaxis::bladeaxis). It exposes nothing of the engine's types but the one error type
// and the cancel token, so the engine can change behind it. A job is described as a job file
// describes it (docs/job-file.md): the batch front end, the window and this facade all run the
// same core/job API and give identical results.

#include "core/base/error.h"
#include "core/base/progress.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::api {

// Called on the job's thread. fraction in [0, 1] of the whole job; stage names it ("reading").
struct Callbacks {
    std::function<void(double fraction, std::string_view stage)> progress;
    std::function<void(std::string_view message)> warning;
    // Polled between steps; a cancelled job returns ErrorCode::Cancelled.
    const CancelToken* cancel = nullptr;
};

// One layer of the re-scheduled pass in the S-theta plane: S (mm) along the layer's cutter path,
// theta (rad) relative to the layer's junction angle. Both schedules, and the feasible channel
// [thetaMin, thetaMax] the new one stays inside.
struct LayerCurve {
    std::size_t firstRecord = 0, lastRecord = 0; // records of the cutting pass (0-based)
    std::vector<double> s, thetaOriginal, thetaRescheduled, thetaMin, thetaMax;
    double junctionAngleRad = 0.0;
    bool keptOriginal = false; // no monotone path: the layer keeps its original orientation
};

class JobOutcome {
  public:
    // report.json's content (docs/report-format.md, docs/report.schema.json).
    std::string reportJson() const;
    // The summary `bladeaxis --batch` prints.
    std::string summary() const;
    std::vector<std::string> warnings() const;
    // Empty when the job only analysed the program.
    std::vector<LayerCurve> layers() const;
    bool rescheduled() const;
    // The whole re-scheduled program (InvalidArgument when the job only analysed).
    Result<std::string> programText() const;
    // Writes the re-scheduled program atomically; refuses to overwrite the input program.
    Status writeProgram(const std::filesystem::path& path) const;
    // Writes what the job names: output_program, output_cl and the report folder (output_dir).
    Status writeOutputs() const;

    struct State;
    explicit JobOutcome(std::shared_ptr<const State> state);

  private:
    std::shared_ptr<const State> m_state;
};

// Runs the job a job file describes; paths inside it resolve relative to the file.
Result<JobOutcome> runJobFile(const std::filesystem::path& jobFile,
                              const Callbacks& callbacks = {});

// Runs the job given as a job file's JSON text; relative paths inside it resolve relative to
// baseDirectory. `{"schema": "bladeaxis-job/1", "program": "blade.nc", "tool_radius": 3}`
Result<JobOutcome> runJobJson(std::string_view jobJson, const std::filesystem::path& baseDirectory,
                              const Callbacks& callbacks = {});

// The exit code `bladeaxis --batch` gives for this error (docs/cam-integration.md).
int exitCodeFor(const Error& error);

// "0.1.0"
std::string_view version();

} // namespace bladeaxis::api
