#pragma once
// The meaning of G-code blocks: modal state (motion, units, distance and feed modes, the
// position of every axis) and the CL records it produces. One instance reads one program.

#include "core/geometry/vec.h"
#include "core/io/nc/detail/block_scanner.h"
#include "core/io/nc/detail/error_list.h"
#include "core/io/nc/detail/g_codes.h"
#include "core/io/nc/gcode_program.h"
#include "core/io/read_options.h"
#include "core/kinematics/machine_model.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace bladeaxis::io::nc::detail {

class ModalInterpreter {
  public:
    // `angleUnit`: the unit of rotary words when the user stated it; empty: degrees unless a
    // header comment declares radians, and checked at the end (finish).
    // Sinumerik and Heidenhain programs (program.dialect) state rotary words in degrees and
    // read a number without a decimal point as whole units, whatever the machine file says of
    // ISO programs.
    ModalInterpreter(GcodeProgram& program, const kinematics::MachineModel& machine,
                     ErrorList& errors, std::optional<AngleUnit> angleUnit);

    // Interprets one scanned block. `line` is its text, starting at `lineBegin` in the program.
    void apply(const ScannedBlock& block, std::string_view line, std::uint32_t lineBegin,
               int lineNumber);

    // A comment line before the first rotary word that states the unit of the rotary words
    // ("(ANGLES IN RADIANS)"), unless the user stated it.
    void noteDeclaredUnit(AngleUnit unit, int lineNumber);
    bool rotaryWordSeen() const { return m_firstRotaryLine > 0; }

    // Records made so far. A streamed read hands the program's records on and clears them, so
    // their count is kept here.
    std::size_t recordCount() const { return m_recordCount; }

    // The checks that need the whole program: an angle unit the values cannot decide, axis words
    // with and without a decimal point mixed. Records the unit read in the program.
    void finish();

  private:
    // The non-modal and motion codes of one block.
    struct BlockCodes {
        std::optional<GKind> motion;  // G0 / G1 in this block
        std::optional<GKind> oneShot; // G4 / G28 / G30 / G53 in this block
    };
    // The block being interpreted, for error locations.
    struct Context {
        const ScannedBlock& block;
        std::string_view line;
        std::uint32_t lineBegin;
        int lineNumber;
    };

    bool fail(const Context& at, std::uint32_t offset, std::string message);
    bool applyControls(const Context& at);
    void noteStatedTool(const ScannedBlock& block);
    double reachedBy(RotaryForm form, std::size_t axis, double value) const;
    RotaryForm effectiveForm(const WordSpan& word, std::size_t axis) const;
    bool readGCodes(const Context& at, BlockCodes& codes);
    bool applyGCode(const Context& at, const WordSpan& word, BlockCodes& codes);
    bool checkLetters(const Context& at);
    bool applyFeedWord(const Context& at);
    bool applyCWord(const Context& at);
    void applyOneShot(const Context& at, GKind kind, std::uint8_t axisWords);
    bool applyAxisWords(const Context& at, std::uint8_t axisWords);
    double axisWordValue(const Context& at, std::size_t axis, const WordSpan& word, bool hasPoint);
    bool allAxesKnown() const;
    bool checkFeedAvailable(const Context& at);
    std::uint32_t firstWordBeyondSource(const Context& at, std::uint8_t axisWords) const;
    void fillSource(RecordSource& source, const Context& at, std::uint8_t axisWords);
    void addRecord(const Context& at, std::uint8_t axisWords);
    double feedOfRecord(const Vec3& tip) const;
    bool readsCombinedFeed() const;
    std::uint32_t firstAxisOffset(const Context& at, std::uint8_t axisWords) const;

    GcodeProgram& m_program;
    const kinematics::MachineModel& m_machine;
    ErrorList& m_errors;

    std::optional<GKind> m_motion; // modal G0 / G1; none before the first one
    bool m_inch = false;
    bool m_incremental = false;
    bool m_inverseTime = false;
    std::optional<double> m_feedPerMinuteMm;          // G94 feed in mm/min, once programmed
    std::optional<double> m_blockInverseTime;         // G93 F of the current block (1/min)
    std::array<double, 5> m_position{};               // mm / rad, as programmed, in X Y Z A B order
    std::array<kinematics::ProgramWord, 5> m_words{}; // the program word of each engine axis
    std::size_t m_tableWord = 3;                      // the rotary table's word (A or B)
    std::uint8_t m_tiltBit = 1u << 4;                 // the tilting head's word: may default to 0
    std::uint8_t m_requiredAxes = 0x0F;               // the words a feed move needs
    std::uint8_t m_known = 0;                         // bit per AxisId
    bool m_bProgrammed = false;
    bool m_warnedDefaultB = false;
    std::optional<double> m_c; // deg, the constant C
    std::uint8_t m_outside = 0x1F;
    bool m_toolTip = false;   // TRAORI / M128 / FUNCTION TCPM in effect
    bool m_shortestA = false; // Heidenhain M126 in effect (for the table)
    std::array<RotaryForm, 2> m_lastForms{RotaryForm::Plain, RotaryForm::Plain}; // A, B
    std::optional<double> m_autoFeed;      // mm/min, the feed of FAUTO (Heidenhain TOOL CALL F)
    std::optional<double> m_definedRadius; // Heidenhain TOOL DEF R of the tool called
    std::vector<std::pair<int, double>> m_toolRadii; // TOOL DEF number, R
    kinematics::IntegerWords m_integerWords = kinematics::IntegerWords::RefuseMixed;
    std::optional<Vec3> m_lastTip;
    std::optional<std::array<double, 5>> m_lastRecordPosition; // for the combined-axes time
    std::size_t m_recordCount = 0;

    std::optional<AngleUnit> m_angleUnit; // given or declared; empty: degrees, checked in finish
    int m_unitDeclarationLine = 0;        // the header comment that declared it, if any
    double m_largestRotaryWord = 0.0;     // max |A|, |B| as written
    bool m_fixedHeadRefused = false;      // a tilt word on a fixed-head machine was refused
    int m_largestRotaryLine = 0;          // where it is written (1-based line and column)
    int m_largestRotaryColumn = 0;
    int m_firstRotaryLine = 0;
    int m_firstPointLine = 0;   // first non-zero axis word with a decimal point
    int m_firstIntegerLine = 0; // first non-zero axis word without one
};

} // namespace bladeaxis::io::nc::detail
