#include "core/io/nc/detail/modal_interpreter.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/nc/detail/axis_motion.h"
#include "core/io/nc/detail/number_style.h"
#include "core/kinematics/kinematics.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::io::nc::detail {

namespace {

constexpr std::array<char, 5> kAxisLetters = kinematics::kProgramLetters;
// Letters that have no meaning in a four-axis Fanuc program (arc centres, extra axes...).
constexpr std::string_view kUnsupportedLetters = "EIJKUVW";
// The same as ScannedBlock::present bits, to pass a block that has none with one test.
constexpr std::uint32_t kUnsupportedLetterBits = [] {
    std::uint32_t bits = 0;
    for (const char letter : kUnsupportedLetters) {
        bits |= 1u << (letter - 'A');
    }
    return bits;
}();

bool isRotaryIndex(std::size_t axis) {
    return axis >= 3;
}

bool hasExponent(std::string_view number) {
    return std::any_of(number.begin(), number.end(), [](char c) { return c == 'e' || c == 'E'; });
}

} // namespace

// The steps of apply() are defined inline: they run for every block of a program, and as calls
// they cost a tenth of the reader's time. The library is built position-independent, where GCC
// inlines no function that is exported and not inline; these are only used in this file.

ModalInterpreter::ModalInterpreter(GcodeProgram& program, const kinematics::MachineModel& machine,
                                   ErrorList& errors, std::optional<AngleUnit> angleUnit)
    : m_program(program), m_machine(machine), m_errors(errors), m_angleUnit(angleUnit) {
    m_integerWords = machine.numbers.integerWords;
    // Positions are kept per program word; the engine's axes are mapped from them per record.
    for (const kinematics::AxisId axis : kinematics::kAllAxes) {
        m_words[static_cast<std::size_t>(axis)] = machine.programWord(axis);
    }
    m_tableWord = m_words[3].index;
    m_tiltBit = static_cast<std::uint8_t>(1u << m_words[4].index);
    m_requiredAxes = static_cast<std::uint8_t>(0x1F & ~m_tiltBit);
    if (program.dialect != NcDialect::Iso) {
        m_angleUnit = AngleUnit::Degrees;
        m_integerWords = kinematics::IntegerWords::Units;
    }
}

bool ModalInterpreter::fail(const Context& at, std::uint32_t offset, std::string message) {
    m_errors.add(at.lineNumber, static_cast<int>(offset) + 1, std::move(message));
    return false;
}

void ModalInterpreter::apply(const ScannedBlock& block, std::string_view line,
                             std::uint32_t lineBegin, int lineNumber) {
    if (!block.hasWords) {
        return;
    }
    const Context at{block, line, lineBegin, lineNumber};
    if (block.subprogramWord != kNoOffset) {
        fail(at, block.subprogramWord,
             "subprogram " +
                 std::string(line.substr(block.subprogramWord, 3) == "M99" ||
                                     line.substr(block.subprogramWord, 3) == "m99"
                                 ? "return M99"
                                 : "call M98") +
                 (block.has('P') ? " P" + std::string(block.word('P').text(line)) : "") +
                 ": BladeAxis reads one flat program and would miss the subprogram's moves; "
                 "have the post-processor expand subprograms");
        return;
    }
    BlockCodes codes;
    if (!applyControls(at) || !readGCodes(at, codes) || !checkLetters(at) || !applyFeedWord(at) ||
        !applyCWord(at)) {
        return;
    }
    std::uint8_t axisWords = 0;
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        if (block.has(kAxisLetters[axis])) {
            axisWords = static_cast<std::uint8_t>(axisWords | (1u << axis));
        }
    }
    if (codes.motion) {
        m_motion = codes.motion;
    }
    if (codes.oneShot) {
        applyOneShot(at, *codes.oneShot, axisWords);
        return;
    }
    if (axisWords == 0) {
        return;
    }
    if (!m_motion) {
        fail(at, firstAxisOffset(at, axisWords), "expected G0 or G1 before the first axis move");
        return;
    }
    if (!applyAxisWords(at, axisWords)) {
        return;
    }
    if (!allAxesKnown()) {
        if (m_motion == GKind::Linear) {
            fail(at, firstAxisOffset(at, axisWords),
                 std::string("expected X, Y, Z and ") + kAxisLetters[m_tableWord] +
                     " to be programmed before the first feed move");
            return;
        }
        m_outside = static_cast<std::uint8_t>(m_outside | axisWords);
        return;
    }
    if (m_motion == GKind::Linear && !checkFeedAvailable(at)) {
        return;
    }
    addRecord(at, axisWords);
}

inline bool ModalInterpreter::applyControls(const Context& at) {
    const std::uint16_t controls = at.block.controls;
    if (controls & (kToolTipOn | kToolTipOff)) {
        m_toolTip = (controls & kToolTipOn) != 0;
    }
    if (controls & (kShortestPathOn | kShortestPathOff)) {
        m_shortestA = (controls & kShortestPathOn) != 0;
    }
    if (controls & (kToolDef | kToolCall)) {
        noteStatedTool(at.block);
    }
    if (controls & kFeedAuto) {
        if (!m_autoFeed) {
            return fail(at, 0, "FAUTO without a feed: expected F in the TOOL CALL before it");
        }
        m_feedPerMinuteMm = *m_autoFeed;
    }
    return true;
}

// Heidenhain: TOOL DEF states a tool's radius, TOOL CALL selects it (its DR added) and the feed
// FAUTO blocks use. The ball radius is that of the tool called before the first move.
void ModalInterpreter::noteStatedTool(const ScannedBlock& block) {
    const StatedToolData& tool = block.tool;
    if (block.controls & kToolDef) {
        if (tool.radius) {
            m_toolRadii.emplace_back(tool.number, *tool.radius);
        }
        return;
    }
    if (tool.feed) {
        m_autoFeed = *tool.feed;
    }
    m_definedRadius.reset();
    for (auto it = m_toolRadii.rbegin(); it != m_toolRadii.rend(); ++it) {
        if (it->first == tool.number) {
            m_definedRadius = it->second + tool.deltaRadius.value_or(0.0);
            break;
        }
    }
}

inline bool ModalInterpreter::readGCodes(const Context& at, BlockCodes& codes) {
    for (int i = 0; i < at.block.gCount; ++i) {
        if (!applyGCode(at, at.block.gCodes[static_cast<std::size_t>(i)], codes)) {
            return false;
        }
    }
    return true;
}

inline bool ModalInterpreter::applyGCode(const Context& at, const WordSpan& word,
                                         BlockCodes& codes) {
    const int code = gCodeTimesTen(word.value);
    if (code == kNotAGCode) {
        return fail(at, word.valueBegin,
                    "expected a G code number, found 'G" + std::string(word.text(at.line)) + "'");
    }
    const GCodeInfo info = m_program.dialect == NcDialect::Sinumerik ? classifySinumerikGCode(code)
                                                                     : classifyGCode(code);
    switch (info.kind) {
    case GKind::Rapid:
    case GKind::Linear:
        if (codes.motion && *codes.motion != info.kind) {
            return fail(at, word.letter, "two motion codes (G0 and G1) in one block");
        }
        codes.motion = info.kind;
        return true;
    case GKind::Dwell:
    case GKind::ReferenceReturn:
    case GKind::MachineCoordinates:
        codes.oneShot = info.kind;
        return true;
    case GKind::Inch:
    case GKind::Metric:
        m_inch = info.kind == GKind::Inch;
        return true;
    case GKind::Absolute:
    case GKind::Incremental:
        m_incremental = info.kind == GKind::Incremental;
        return true;
    case GKind::InverseTime:
    case GKind::PerMinute:
        m_inverseTime = info.kind == GKind::InverseTime;
        return true;
    case GKind::ToolTipOn:
    case GKind::ToolTipOff:
        // Fanuc's G43.4 means what Sinumerik's TRAORI and Heidenhain's M128 mean.
        m_toolTip = info.kind == GKind::ToolTipOn;
        return true;
    case GKind::NoOp:
        return true;
    case GKind::Unsupported:
        break;
    }
    const std::string name = gCodeName(code);
    return fail(at, word.letter,
                info.reason != nullptr
                    ? std::string(info.reason)
                    : "unsupported G code " + name + ": expected G0, G1 and modal settings only");
}

inline bool ModalInterpreter::checkLetters(const Context& at) {
    if ((at.block.present & kUnsupportedLetterBits) == 0) {
        return true;
    }
    for (char letter : kUnsupportedLetters) {
        if (at.block.has(letter)) {
            return fail(at, at.block.word(letter).letter,
                        std::string("unsupported word '") + letter +
                            "': expected G, X, Y, Z, A, B, C, F, N, M, S, T, D, H, O, P, Q, R "
                            "or L words");
        }
    }
    return true;
}

inline bool ModalInterpreter::applyFeedWord(const Context& at) {
    m_blockInverseTime.reset();
    if (!at.block.has('F')) {
        return true;
    }
    const WordSpan& word = at.block.word('F');
    if (!(word.value > 0.0)) {
        return fail(at, word.valueBegin,
                    "expected a positive feed, found 'F" + std::string(word.text(at.line)) + "'");
    }
    if (m_inverseTime) {
        m_blockInverseTime = word.value;
    } else {
        m_feedPerMinuteMm = m_inch ? units::inchToMm(word.value) : word.value;
    }
    return true;
}

inline bool ModalInterpreter::applyCWord(const Context& at) {
    if (!at.block.has('C')) {
        return true;
    }
    const WordSpan& word = at.block.word('C');
    const double c = m_incremental ? m_c.value_or(0.0) + word.value : word.value;
    if (m_c && *m_c != c) {
        return fail(at, word.letter,
                    "C changes from " + formatTrimmed(*m_c, 6) + " to " + formatTrimmed(c, 6) +
                        ": expected a constant C (four-axis programs do not move C)");
    }
    m_c = c;
    return true;
}

void ModalInterpreter::applyOneShot(const Context& at, GKind kind, std::uint8_t axisWords) {
    if (kind == GKind::Dwell) {
        if ((axisWords & ~1u) != 0) {
            fail(at, firstAxisOffset(at, static_cast<std::uint8_t>(axisWords & ~1u)),
                 "expected only X or P (the dwell time) in a G4 block");
        }
        return;
    }
    // G28/G30 go to a reference point, G53 to machine coordinates: the named axes end up at
    // positions this reader cannot know in the workpiece frame, so they must be programmed again.
    m_known = static_cast<std::uint8_t>(m_known & ~axisWords);
    if (axisWords & m_tiltBit) {
        m_bProgrammed = true;
    }
}

inline bool ModalInterpreter::applyAxisWords(const Context& at, std::uint8_t axisWords) {
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        const std::uint8_t bit = static_cast<std::uint8_t>(1u << axis);
        if (!(axisWords & bit)) {
            continue;
        }
        const WordSpan& word = at.block.word(kAxisLetters[axis]);
        const WordTextStyle style =
            word.plainStyle ? *word.plainStyle : styleOfWord(word.text(at.line));
        noteAxisWord(m_program.axisStyles[axis], style);
        // "10." and "1e3" are decimal numbers to the control, "10" a whole number it may scale.
        // A plain decimal has no exponent.
        const bool decimal =
            style.hasPoint || (!word.plainStyle && hasExponent(word.text(at.line)));
        const double value = axisWordValue(at, axis, word, decimal);
        if (bit == m_tiltBit && !m_machine.hasB() && value != 0.0) {
            // One refusal says it all: every later tilt word is the same mismatch, and listing
            // each (with its own value) would bury the cause under twenty lines.
            if (m_fixedHeadRefused) {
                return false;
            }
            m_fixedHeadRefused = true;
            const std::string tilt(1, kAxisLetters[axis]);
            return fail(at, word.letter,
                        tilt + std::string(word.text(at.line)) + ": the machine '" +
                            m_machine.name + "' has a fixed head (no " + tilt +
                            " axis); expected no " + tilt + " word or " + tilt +
                            "0, or the machine file of the machine this program was posted for "
                            "(the first such word; later ones are not listed)");
        }
        const RotaryForm form = effectiveForm(word, axis);
        const bool relative =
            form == RotaryForm::Incremental || (form == RotaryForm::Plain && m_incremental);
        if (relative && !(m_known & bit)) {
            const std::string name(1, kAxisLetters[axis]);
            const bool g91 = form == RotaryForm::Plain;
            return fail(at, word.letter,
                        "incremental " + std::string(g91 ? "(G91) " : "") + name +
                            " move before any absolute " + name + " position: expected " + name +
                            " to be programmed " + (g91 ? "in G90" : "absolute") + " first");
        }
        if (word.form == RotaryForm::Shortest || word.form == RotaryForm::Positive ||
            word.form == RotaryForm::Negative) {
            if (value < 0.0 || value >= units::kTwoPi * (1.0 + 1e-12)) {
                return fail(at, word.valueBegin,
                            "DC, ACP and ACN take a position in [0, 360) deg, found " +
                                std::string(word.text(at.line)));
            }
        }
        if (isRotaryIndex(axis)) {
            m_lastForms[axis - 3] = form;
        }
        m_position[axis] = reachedBy(form, axis, value);
        m_known = static_cast<std::uint8_t>(m_known | bit);
        if (bit == m_tiltBit) {
            m_bProgrammed = true;
        }
    }
    return true;
}

// How a rotary word reaches its value: its own form (Sinumerik DC, ACP...), or for the table
// the shortest way while Heidenhain's M126 is on.
inline RotaryForm ModalInterpreter::effectiveForm(const WordSpan& word, std::size_t axis) const {
    if (word.form != RotaryForm::Plain) {
        return word.form;
    }
    return axis == m_tableWord && m_shortestA ? RotaryForm::Shortest : RotaryForm::Plain;
}

// The axis position a word of the given form reaches from the current one. The modulo forms
// (DC, ACP, ACN, M126) turn by less than a full turn; before the axis is known they go to the
// value itself.
inline double ModalInterpreter::reachedBy(RotaryForm form, std::size_t axis, double value) const {
    const double from = m_position[axis];
    switch (form) {
    case RotaryForm::Plain:
        return m_incremental ? from + value : value;
    case RotaryForm::Absolute:
        return value;
    case RotaryForm::Incremental:
        return from + value;
    default:
        return ((m_known >> axis) & 1u) ? reachedByModulo(form, from, value) : value;
    }
}

// The word's value in mm or rad: the control's rule for a number without a decimal point, then
// inch and the angle unit.
inline double ModalInterpreter::axisWordValue(const Context& at, std::size_t axis,
                                              const WordSpan& word, bool hasPoint) {
    double value = word.value;
    if (value != 0.0) {
        int& first = hasPoint ? m_firstPointLine : m_firstIntegerLine;
        first = first == 0 ? at.lineNumber : first;
    }
    const kinematics::NumberRules& rules = m_machine.numbers;
    const bool rotary = isRotaryIndex(axis);
    if (!hasPoint && m_integerWords == kinematics::IntegerWords::Increments) {
        value *= rotary ? rules.incrementDeg : (m_inch ? rules.incrementInch : rules.incrementMm);
    }
    if (rotary) {
        if (std::abs(word.value) > m_largestRotaryWord) {
            m_largestRotaryWord = std::abs(word.value);
            m_largestRotaryLine = at.lineNumber;
            m_largestRotaryColumn = static_cast<int>(word.letter) + 1;
        }
        m_firstRotaryLine = m_firstRotaryLine == 0 ? at.lineNumber : m_firstRotaryLine;
        return m_angleUnit == AngleUnit::Radians ? value : units::degToRad(value);
    }
    return m_inch ? units::inchToMm(value) : value;
}

void ModalInterpreter::noteDeclaredUnit(AngleUnit unit, int lineNumber) {
    if (!m_angleUnit) {
        m_angleUnit = unit;
        m_unitDeclarationLine = lineNumber;
    }
}

void ModalInterpreter::finish() {
    m_program.angleUnit = m_angleUnit.value_or(AngleUnit::Degrees);
    // A rotary word beyond 2 pi cannot be radians; below it, a helical blade pass in degrees
    // would turn less than 6.3 deg, so the values alone cannot tell.
    if (!m_angleUnit && m_largestRotaryWord > 0.0 && m_largestRotaryWord <= units::kTwoPi) {
        // Named at the largest word: the one that shows the values could be either unit.
        m_errors.add(m_largestRotaryLine, m_largestRotaryColumn,
                     "the unit of the rotary words is ambiguous: every A and B is at most " +
                         formatTrimmed(m_largestRotaryWord, 6) + " (this word)" +
                         " (<= 2 pi), which reads as radians as well as degrees; give "
                         "--angle-unit deg|rad (job key angle_unit) or a header comment such as "
                         "(ANGLES IN DEGREES)");
    }
    if (m_integerWords == kinematics::IntegerWords::RefuseMixed && m_firstPointLine > 0 &&
        m_firstIntegerLine > 0) {
        m_errors.add(
            m_firstIntegerLine, 1,
            "axis words without a decimal point here, with one at line " +
                std::to_string(m_firstPointLine) +
                ": a Fanuc-style control reads X1000 as 1.000 mm (least input increments), "
                "others as 1000 mm; say which in the machine file (\"integer_words\": "
                "\"increments\" or \"units\", docs/machine-file.md)");
    }
}

inline bool ModalInterpreter::allAxesKnown() const {
    if ((m_known & m_requiredAxes) != m_requiredAxes) {
        return false;
    }
    return (m_known & m_tiltBit) || !m_bProgrammed;
}

inline bool ModalInterpreter::checkFeedAvailable(const Context& at) {
    if (m_inverseTime && !m_blockInverseTime) {
        return fail(at, 0, "expected an F word in every inverse-time (G93) feed block");
    }
    if (!m_inverseTime && !m_feedPerMinuteMm) {
        return fail(at, 0, "expected an F word before the first feed move");
    }
    return true;
}

std::uint32_t ModalInterpreter::firstAxisOffset(const Context& at, std::uint8_t axisWords) const {
    std::uint32_t first = kNoOffset;
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        if (axisWords & (1u << axis)) {
            first = std::min(first, at.block.word(kAxisLetters[axis]).letter);
        }
    }
    return first == kNoOffset ? 0 : first;
}

// The offset of the first axis word whose number begins beyond what RecordSource can point to;
// kNoOffset when all fit.
inline std::uint32_t ModalInterpreter::firstWordBeyondSource(const Context& at,
                                                             std::uint8_t axisWords) const {
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        if ((axisWords & (1u << axis)) && at.block.word(kAxisLetters[axis]).valueBegin >= kNoWord) {
            return at.block.word(kAxisLetters[axis]).valueBegin;
        }
    }
    return kNoOffset;
}

// Filled in place in the vector: a source built on the stack and copied in is read back with
// wide loads from its narrow stores, which the processor cannot forward.
inline void ModalInterpreter::fillSource(RecordSource& source, const Context& at,
                                         std::uint8_t axisWords) {
    source.lineBegin = at.lineBegin;
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        if (axisWords & (1u << axis)) {
            const WordSpan& word = at.block.word(kAxisLetters[axis]);
            source.wordBegin[axis] = static_cast<std::uint16_t>(word.valueBegin);
            source.wordLength[axis] = static_cast<std::uint8_t>(word.valueEnd - word.valueBegin);
        }
    }
    source.flags =
        static_cast<std::uint8_t>((m_incremental ? kIncremental : 0) | (m_inch ? kInch : 0) |
                                  (m_inverseTime ? kInverseTime : 0));
    const bool combined = m_motion == GKind::Linear && readsCombinedFeed();
    source.flags = static_cast<std::uint8_t>(source.flags | (m_toolTip ? kToolTip : 0) |
                                             (combined ? kCombinedFeed : 0));
    source.setOutside = m_outside;
    m_outside = 0;
    for (std::size_t rotary = 0; rotary < 2; ++rotary) {
        const std::size_t axis = 3 + rotary;
        source.rotaryForms[rotary] = (axisWords >> axis) & 1u
                                         ? effectiveForm(at.block.word(kAxisLetters[axis]), axis)
                                     : (axis == m_tableWord && m_shortestA) ? RotaryForm::Shortest
                                                                            : m_lastForms[rotary];
    }
}

void ModalInterpreter::addRecord(const Context& at, std::uint8_t axisWords) {
    if (const std::uint32_t beyond = firstWordBeyondSource(at, axisWords); beyond != kNoOffset) {
        fail(at, beyond, "block too long: expected axis words within 65534 characters");
        return;
    }
    fillSource(m_program.sources.emplace_back(), at, axisWords);
    if (m_recordCount++ == 0 && m_definedRadius) {
        m_program.path.toolRadius = *m_definedRadius;
    }
    if (!(m_known & m_tiltBit) && !m_warnedDefaultB && m_machine.hasB()) {
        m_warnedDefaultB = true;
        const char tilt = kAxisLetters[m_words[4].index];
        m_program.path.warnings.push_back(
            SourceLocation{m_errors.fileName(), at.lineNumber, 0}.toString() + ": " + tilt +
            " is not programmed before the first move: " + tilt + " = 0 assumed");
    }
    const auto word = [this](std::size_t axis) {
        const kinematics::ProgramWord& w = m_words[axis];
        const bool known = (m_known >> w.index) & 1u;
        return known ? w.sign * m_position[w.index] : 0.0;
    };
    kinematics::MachineAxes axes;
    axes.x = word(0);
    axes.y = word(1);
    axes.z = word(2);
    axes.a = word(3);
    axes.b = word(4);
    kinematics::TableAHeadB chain = m_machine.chain;
    chain.tipInWorkpiece = m_toolTip;
    const kinematics::ToolPose pose = kinematics::forwardKinematics(chain, axes);
    const toolpath::MotionKind motion =
        m_motion == GKind::Linear ? toolpath::MotionKind::Feed : toolpath::MotionKind::Rapid;
    m_program.path.records.push_back(toolpath::ClRecord{
        .tip = pose.tip,
        .axis = pose.axis,
        .axes = axes,
        .feed = motion == toolpath::MotionKind::Feed ? feedOfRecord(pose.tip) : 0.0,
        .motion = motion,
        .line = at.lineNumber,
    });
    if (m_program.dialect == NcDialect::Iso &&
        m_machine.feedMeaning == kinematics::FeedMeaning::CombinedAxes) {
        const double fileFeed = m_feedPerMinuteMm.value_or(0.0) / (m_inch ? 25.4 : 1.0);
        m_program.programmedFeeds.push_back(fileFeed);
    }
    m_lastRecordPosition = m_position;
    m_lastTip = pose.tip;
}

// Whether F of a feed block is read over the combined axis move: ISO G94 on a control that
// says so, without tool-tip programming (Sinumerik's FGROUP default and Heidenhain take F along
// the linear path).
inline bool ModalInterpreter::readsCombinedFeed() const {
    return m_program.dialect == NcDialect::Iso && !m_inverseTime && !m_toolTip &&
           m_machine.feedMeaning == kinematics::FeedMeaning::CombinedAxes;
}

// Tip speed in mm/s. G94: F is mm/min, or over the combined move (then the block lasts that
// move / F). G93: F is 1/min, the block lasts 1/F min. Either way the tip speed is the tip chord
// over that time (0, unknown, for a first block without a start point).
inline double ModalInterpreter::feedOfRecord(const Vec3& tip) const {
    if (readsCombinedFeed()) {
        if (!m_lastTip || !m_lastRecordPosition) {
            return 0.0;
        }
        const double fileFeed = *m_feedPerMinuteMm / (m_inch ? 25.4 : 1.0);
        const double minutes =
            combinedAxisMove(*m_lastRecordPosition, m_position, m_inch) / fileFeed;
        return minutes > 0.0 ? units::perMinuteToPerSecond((tip - *m_lastTip).norm() / minutes)
                             : 0.0;
    }
    if (!m_inverseTime) {
        return units::perMinuteToPerSecond(*m_feedPerMinuteMm);
    }
    if (!m_lastTip) {
        return 0.0;
    }
    const double chord = (tip - *m_lastTip).norm();
    return units::perMinuteToPerSecond(chord * *m_blockInverseTime);
}

} // namespace bladeaxis::io::nc::detail
