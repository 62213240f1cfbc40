#pragma once
// The million-block G-code program of the end-to-end benchmarks: the tile of million_tile.h
// repeated millionTiles() times along x, emitted through the default blade machine. It is made in
// a child process, so that the benchmark process's peak memory belongs to the benchmarks alone,
// and kept in the temporary folder between runs.

#include "core/base/file_io.h"
#include "core/blade/helical_path.h"
#include "core/io/nc/gcode.h"
#include "core/kinematics/machine_model.h"
#include "tests/bench/million_tile.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sys/wait.h>
#include <unistd.h>

namespace bladeaxis::bench {

[[noreturn]] inline void fail(const char* what, const Error& error) {
    std::fprintf(stderr, "%s: %s\n", what, error.toString().c_str());
    std::exit(1);
}

inline toolpath::Toolpath tiledRecordPath(int tiles) {
    auto bladeModel = blade::Blade::create(twistFreeDemoBlade());
    if (!bladeModel) {
        fail("blade", bladeModel.error());
    }
    const blade::HelicalPathSpec pathSpec = fineTilePath();
    auto tile = blade::generateHelicalPath(*bladeModel, pathSpec);
    if (!tile) {
        fail("path", tile.error());
    }
    const double advance = pathSpec.pitch * pathSpec.revolutions;
    toolpath::Toolpath path;
    path.sourceFile = "million.nc";
    const auto& records = tile->path.records;
    for (int t = 0; t < tiles; ++t) {
        // The closing record of a tile is the first record of the next one.
        const std::size_t count = records.size() - (t + 1 < tiles ? 1 : 0);
        for (std::size_t i = 0; i < count; ++i) {
            toolpath::ClRecord record = records[i];
            record.tip.x() += advance * t;
            path.records.push_back(record);
        }
    }
    return path;
}

// Writes the program of `tiles` tiles (millionTiles() by default) to `file` (in a child
// process) and returns the path.
inline std::filesystem::path writeMillionProgram(const std::filesystem::path& file,
                                                 int tiles = millionTiles()) {
    const pid_t child = fork();
    if (child == 0) {
        auto text =
            io::nc::emitGcode(tiledRecordPath(tiles), kinematics::defaultBladeMachine(), {});
        if (!text) {
            fail("emit", text.error());
        }
        std::_Exit(writeFileAtomically(file, *text) ? 0 : 1);
    }
    int status = 0;
    if (child < 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "could not generate %s\n", file.c_str());
        std::exit(1);
    }
    return file;
}

} // namespace bladeaxis::bench
