#pragma once
// The format-independent face of io/: probe the format of an input, load it into a toolpath
// while keeping the document its writer needs, and write it back with new orientations.

#include "core/base/error.h"
#include "core/io/cl/apt_reader.h"
#include "core/io/nc/gcode_reader.h"
#include "core/io/read_options.h"

#include <filesystem>
#include <variant>

namespace bladeaxis::io {

enum class ProgramFormat { Gcode, Apt };

const char* toString(ProgramFormat format);

// Guesses the format from the file extension (.nc .ngc .tap .gcode .mpf .iso -> G-code;
// .cl .cls .apt .aptsource .clsf -> APT) and, for other names, from the text (a GOTO/ statement
// means APT).
ProgramFormat probeFormat(const std::filesystem::path& path, std::string_view text);

struct LoadedProgram {
    std::variant<nc::GcodeProgram, cl::AptProgram> document;
    // The options the program was read with, as resolved by the reader (a detected angle unit
    // is recorded here): the written program is read back with the same ones.
    ReadOptions options;

    const toolpath::Toolpath& path() const;
    // For the checks that normalise the input before scheduling (B noise snapped to its median).
    toolpath::Toolpath& mutablePath();
    const std::string& text() const; // the program as read, byte for byte
    ProgramFormat format() const;
};

// Reads and parses a program. G-code needs the machine (its axes are turned into CL by FK).
Result<LoadedProgram> loadProgram(const std::filesystem::path& path,
                                  const kinematics::MachineModel& machine,
                                  const ReadOptions& options = {});

// Parses text already in memory (the demo program is generated, never read from disk).
Result<LoadedProgram> parseProgram(std::string_view text, std::string_view fileName,
                                   ProgramFormat format, const kinematics::MachineModel& machine,
                                   const ReadOptions& options = {});

} // namespace bladeaxis::io
