#pragma once
// Which files a job reads and writes, by the names a person gave them, so that a job whose
// outputs would overwrite each other or an input is refused before it runs.

#include "core/base/error.h"
#include "core/job/job.h"

#include <string>
#include <vector>

namespace bladeaxis::job {

// The name a message gives each of a job's paths: the job file's keys unless a front end
// names its own options (the batch: "-o", "--out", ...).
struct PathNames {
    std::string program = "program";
    std::string machine = "machine";
    std::string cad = "cad";
    std::string jobFile = "the job file";
    std::string outputProgram = "output_program";
    std::string outputCl = "output_cl";
    std::string outputDir = "output_dir";
};

// The files a job writes into spec.outputDir, by name ("report.json", "axes.csv", ...).
std::vector<std::string> reportFolderFiles(const JobSpec& spec);

// Refuses (InvalidArgument, naming both) a job two of whose outputs are the same file
// (`-o OUT/report.json --out OUT`, `-o x --cl-output x`), or an output that is one of its inputs,
// also through links and for names not yet there; and any path with a NUL character.
Status refuseSharedPaths(const JobSpec& spec, const PathNames& names = {});

} // namespace bladeaxis::job
