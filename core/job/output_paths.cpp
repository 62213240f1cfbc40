#include "core/job/output_paths.h"

#include "core/base/output_set.h"
#include "core/job/demo_program.h"

namespace bladeaxis::job {

std::vector<std::string> reportFolderFiles(const JobSpec& spec) {
    std::vector<std::string> files;
    if (spec.demo) {
        files.insert(files.end(), {kDemoProgramName, "demo_blade.step"});
    }
    files.emplace_back("axes.csv");
    if (spec.reschedule) {
        files.emplace_back("layers.csv");
    }
    if (spec.compare) {
        files.insert(files.end(), {"compare.json", "compare.csv", "report.html"});
    }
    files.emplace_back("report.json");
    return files;
}

Status refuseSharedPaths(const JobSpec& spec, const PathNames& names) {
    std::vector<NamedPath> outputs{{names.outputProgram, spec.outputProgram},
                                   {names.outputCl, spec.outputCl}};
    if (hasNulCharacter(spec.outputDir)) {
        outputs.push_back({names.outputDir, spec.outputDir});
    } else if (!spec.outputDir.empty()) {
        for (const std::string& file : reportFolderFiles(spec)) {
            outputs.push_back({names.outputDir + " (" + file + ")", spec.outputDir / file});
        }
    }
    const std::vector<NamedPath> inputs{{names.program, spec.demo ? "" : spec.program},
                                        {names.machine, spec.machineFile},
                                        {names.cad, spec.cad.file},
                                        {names.jobFile, spec.jobFile}};
    return refuseSharedFiles(outputs, inputs);
}

} // namespace bladeaxis::job
