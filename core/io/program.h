#pragma once
// The format-independent face of io/: probe the format of an input, load it into a toolpath
// while keeping the document its writer needs, and write it back with new orientations.

#include "core/base/error.h"
#include "core/base/forward_text.h"
#include "core/io/cl/apt_reader.h"
#include "core/io/nc/gcode_reader.h"
#include "core/io/read_options.h"
#include "core/io/read_watch.h"
#include "core/io/table/point_table.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <variant>

namespace bladeaxis::io {

enum class ProgramFormat { Gcode, Apt, Table };

const char* toString(ProgramFormat format);

struct ProbedFormat {
    ProgramFormat format = ProgramFormat::Gcode;
    std::optional<std::string> warning; // the extension said otherwise
};

// The format of a program, decided by its content: the first meaningful lines (comments and
// blank lines skipped) are G-code blocks ("N10 G1 X1."), APT/CLSF statements ("GOTO/1,2,3",
// "PARTNO", "$$ comment") or rows of numbers with at most a header line (a point table). The
// extension (.nc .ngc .tap .gcode .mpf .spf .iso, .cl .cls .apt .aptsource .clsf, .txt .csv
// .xyz) only breaks a tie; when the content contradicts it, the content wins with a warning.
// Errors (ErrorCode::Parse, file:line): binary data, or text in none of the formats.
Result<ProbedFormat> detectFormat(const std::filesystem::path& path, std::string_view text);

// The format detectFormat finds, or the extension's when the content is not recognised.
ProgramFormat probeFormat(const std::filesystem::path& path, std::string_view text);

struct LoadedProgram {
    std::variant<nc::GcodeProgram, cl::AptProgram, table::TableProgram> document;
    // The options the program was read with, as resolved by the reader (a detected angle unit
    // is recorded here): the written program is read back with the same ones.
    ReadOptions options;
    // The file a G-code program's text is read again from by its rewrite, once the text was
    // dropped (dropTextKeptInItsFile); empty while the text is in memory.
    std::optional<FileSnapshot> textFile;

    const toolpath::Toolpath& path() const;
    // For the checks that normalise the input before scheduling (B noise snapped to its median).
    toolpath::Toolpath& mutablePath();
    // The program as read, byte for byte; empty once released (releaseRewriteSources) or
    // dropped (dropTextKeptInItsFile).
    const std::string& text() const;
    ProgramFormat format() const;
    std::optional<NcDialect> dialect() const; // of a G-code family program

    // Frees what only a rewrite reads: the text and where each record's words stand in it
    // (for G-code 61 bytes of text and 24 of source per block on a typical program). A job
    // calls it once the program is rewritten: a million-block job then holds 85 MB less
    // while it reads the written program back. The records, the warnings, the dialect and the
    // read options stay; the program can no longer be rewritten, and which records are
    // programmed as the tool tip is no longer known (programsToolTip answers false).
    void releaseRewriteSources();
    // Gives back, while a G-code rewrite runs, what it has read for the last time: the whole
    // pages of the text before `textEnd` and of the block sources before `blockEnd`
    // (returnWholePagesToTheSystem). They read as zeros afterwards, so only a caller that
    // releases the rewrite sources once the rewrite ends (or fails) may call it; a
    // million-block job then holds up to 85 MB less at the rewrite's end. Other formats: nothing.
    void releaseRewriteSourcesBefore(std::size_t textEnd, std::size_t blockEnd);
    // Frees a G-code program's text (61 bytes per block on a typical program), which only its
    // rewrite reads: the rewrite reads it again from `file`, the file it was parsed from, and
    // refuses a file written since. Other formats keep their text (their rewriters read it
    // whole); so does a program whose file changed while it was read.
    void dropTextKeptInItsFile(const FileSnapshot& file);
};

// Whether the records [first, first + count) are programmed as the tool tip in the workpiece
// frame (Sinumerik TRAORI, Heidenhain M128 / FUNCTION TCPM); empty when some are and some are
// not. CL data and ISO programs: false; so is a program whose rewrite sources were released.
std::optional<bool> programsToolTip(const LoadedProgram& program, std::size_t first,
                                    std::size_t count);

// CL data, point tables and CAD models give the tool in the program's workpiece frame, whose
// table axis is X or Y as the machine's table turns; the engine's frame has it along x. These
// turn records' tips and tool axes from one frame to the other (nothing to do on a table-A
// machine).
void toEngineFrame(std::span<toolpath::ClRecord> records, const kinematics::MachineModel& machine);
void toProgramFrame(std::span<toolpath::ClRecord> records, const kinematics::MachineModel& machine);

// Detects the format of text read from `path` and parses it; a contradicting extension becomes
// the first warning of the toolpath.
Result<LoadedProgram> readProgramText(std::string_view text, const std::filesystem::path& path,
                                      const kinematics::MachineModel& machine,
                                      const ReadOptions& options = {}, const ReadWatch& watch = {});

// Reads and parses a program. G-code needs the machine (its axes are turned into CL by FK).
// The `watch` hears how far a G-code read has come and may stop any read (ErrorCode::Cancelled):
// G-code within a few thousand blocks, CL data and point tables once they are parsed.
Result<LoadedProgram> loadProgram(const std::filesystem::path& path,
                                  const kinematics::MachineModel& machine,
                                  const ReadOptions& options = {}, const ReadWatch& watch = {});

// parseProgram of text the loaded program then keeps: a G-code program's text is not copied.
Result<LoadedProgram> parseOwnedProgram(std::string text, std::string_view fileName,
                                        ProgramFormat format,
                                        const kinematics::MachineModel& machine,
                                        const ReadOptions& options = {},
                                        const ReadWatch& watch = {});

// Reads a program of `format` and hands its records (in the engine's frame, as parseProgram
// gives them) to `consume` in order; returns their number. G-code is streamed and its records
// are not kept (nc::streamGcodeRecords); CL data and point tables are parsed whole and handed
// on at once (`readUpTo` is then told nothing).
Result<std::size_t>
streamProgramRecords(std::string_view text, std::string_view fileName, ProgramFormat format,
                     const kinematics::MachineModel& machine, const ReadOptions& options,
                     const nc::RecordChunkConsumer& consume, const nc::TextReadUpTo& readUpTo = {});

// Parses text already in memory (the demo program is generated, never read from disk).
Result<LoadedProgram> parseProgram(std::string_view text, std::string_view fileName,
                                   ProgramFormat format, const kinematics::MachineModel& machine,
                                   const ReadOptions& options = {});

} // namespace bladeaxis::io
