#include "app/batch/man_page.h"

#include <CLI/CLI.hpp>

#include <sstream>

namespace bladeaxis::app {

namespace {

// roff treats a leading '.' or '\'' as a request and '\' as an escape; '-' must be "\-" to stay
// a hyphen-minus that can be searched and pasted.
std::string escaped(std::string_view text) {
    std::string out;
    bool lineStart = true;
    for (const char c : text) {
        if (lineStart && (c == '.' || c == '\'')) {
            out += "\\&";
        }
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else {
            out += c;
        }
        lineStart = c == '\n';
    }
    return out;
}

// "-o,--output" -> "\fB\-o\fR, \fB\-\-output\fR \fITEXT\fR"
std::string optionTerm(const CLI::Option& option) {
    std::string term;
    std::stringstream names(option.get_name(false, true));
    std::string name;
    while (std::getline(names, name, ',')) {
        term += (term.empty() ? "" : ", ") + std::string("\\fB") + escaped(name) + "\\fR";
    }
    if (option.get_expected_min() > 0) {
        std::string value = option.get_type_name();
        for (int k = 1; k < option.get_expected_min(); ++k) {
            value += " " + option.get_type_name();
        }
        term += " \\fI" + escaped(value) + "\\fR";
    }
    return term;
}

// An option group repeats the main --help flag; it is listed once, with the main options.
void writeOptions(std::ostream& out, const CLI::App& app, bool isGroup) {
    for (const CLI::Option* option : app.get_options()) {
        if ((isGroup && option == app.get_help_ptr()) || option->get_positional()) {
            continue;
        }
        out << ".TP\n" << optionTerm(*option) << '\n' << escaped(option->get_description()) << '\n';
    }
}

// The text after a heading line of --help's footer ("Exit codes:\n  0  success ...") as an
// indented, unfilled block, so the table's columns survive.
void writeVerbatim(std::ostream& out, std::string_view block) {
    const auto firstNewline = block.find('\n', block.find_first_not_of('\n'));
    out << ".nf\n" << escaped(block.substr(firstNewline + 1)) << "\n.fi\n";
}

} // namespace

std::string manPage(const CLI::App& cli, const ManPageText& text) {
    std::ostringstream out;
    out << ".TH BLADEAXIS 1 \"\" \"BladeAxis " << escaped(text.version) << "\" \"User Commands\"\n"
        << ".SH NAME\nbladeaxis \\- re\\-schedule the rotary A axis of four\\-axis blade "
           "programs\n"
        << ".SH SYNOPSIS\n"
        << ".B bladeaxis\n[\\fIPROGRAM\\fR | \\fIJOB.json\\fR]\n.br\n"
        << ".B bladeaxis\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIPROGRAM\\fR]\n.br\n"
        << ".B bladeaxis \\-\\-batch\n[\\fIOPTIONS\\fR] [\\fIPROGRAM\\fR]\n"
        << ".SH DESCRIPTION\n"
        << escaped(cli.get_description()) << '\n'
        << ".PP\nWithout a command or \\fB\\-\\-batch\\fR, the desktop window opens (with the "
           "program or job file given, if any). Headless, BladeAxis reads a posted NC program "
           "(ISO G\\-code, Sinumerik, Heidenhain), CL data (APT/CLSF) or a point table, "
           "re\\-schedules the tool orientation of the helical cutting pass so the A axis turns "
           "monotonically and smoothly while the ball centres stay where they were, writes the "
           "new program and reports the axis motion before and after. A program it does not "
           "understand is refused with the file, line and reason, never rewritten.\n"
        << ".SH COMMANDS\n";
    writeVerbatim(out, text.commands);
    out << ".SH OPTIONS\n";
    for (const CLI::Option* option : cli.get_options()) {
        if (option->get_positional()) {
            out << ".TP\n\\fI" << escaped(option->get_name()) << "\\fR\n"
                << escaped(option->get_description()) << '\n';
        }
    }
    writeOptions(out, cli, false);
    for (const CLI::App* group : cli.get_subcommands([](const CLI::App*) { return true; })) {
        out << ".SS " << escaped(group->get_group()) << "\n"
            << escaped(group->get_description()) << '\n';
        writeOptions(out, *group, true);
    }
    out << ".SH STANDARD OUTPUT\n"
        << "Standard output carries only what a script reads: the program (\\fB\\-o \\-\\fR), "
           "the CL data (\\fB\\-\\-cl\\-output \\-\\fR), the JSON report "
           "(\\fB\\-\\-json\\fR), or else the summary; two of the three are refused (exit 2). "
           "Errors, warnings, the progress line, and the summary when standard output carries "
           "the program or CL data, go to standard error. With "
           "\\fB\\-\\-json\\fR a refusal is also printed to standard output as a JSON object "
           "{\"error\": {\"code\", \"exit_code\", \"file\", \"line\", \"column\", "
           "\"message\", \"more\"}} (docs/cam\\-integration.md).\n";
    out << ".SH EXIT STATUS\n";
    writeVerbatim(out, text.exitCodes);
    out << ".SH FILES\n"
        << ".TP\n\\fI/usr/share/bladeaxis/machines/*.json\\fR\n"
           "Machine files shipped with BladeAxis (give one with \\fB\\-\\-machine\\fR).\n"
        << ".TP\n\\fI/usr/share/doc/bladeaxis/\\fR\n"
           "The documentation: user guide, method, file formats, CAM integration.\n"
        << ".SH EXAMPLES\n"
        << ".nf\nbladeaxis reschedule blade.nc \\-o blade_rescheduled.nc \\-\\-out report/\n"
           "bladeaxis analyse blade.nc \\-\\-tool\\-radius 3\n"
           "bladeaxis \\-\\-batch \\- \\-\\-tool\\-radius 3 \\-o \\- < in.nc > out.nc\n"
           "bladeaxis \\-\\-batch \\-\\-job blade.json\n.fi\n"
        << ".SH SEE ALSO\n"
           "The user guide, /usr/share/doc/bladeaxis/user\\-guide.md.\n";
    return out.str();
}

} // namespace bladeaxis::app
