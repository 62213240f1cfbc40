// The command line's commands (bladeaxis analyse ...) and the manual page generated from the
// option table.
#include "app/batch/batch_options.h"
#include "app/subcommands.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

namespace bladeaxis::app {
namespace {

using Arguments = std::vector<std::string>;

TEST(Subcommands, ACommandStandsForItsFlags) {
    EXPECT_EQ(expandSubcommand({"bladeaxis", "analyse", "x.nc"}),
              (Arguments{"bladeaxis", "--batch", "--analyse-only", "x.nc"}));
    EXPECT_EQ(expandSubcommand({"bladeaxis", "analyze", "x.nc"}),
              (Arguments{"bladeaxis", "--batch", "--analyse-only", "x.nc"}));
    EXPECT_EQ(expandSubcommand({"bladeaxis", "reschedule", "x.nc", "-o", "y.nc"}),
              (Arguments{"bladeaxis", "--batch", "x.nc", "-o", "y.nc"}));
    EXPECT_EQ(expandSubcommand({"bladeaxis", "compare", "x.nc"}),
              (Arguments{"bladeaxis", "--batch", "--compare", "x.nc"}));
    EXPECT_EQ(expandSubcommand({"bladeaxis", "generate", "out.nc", "--revolutions", "2"}),
              (Arguments{"bladeaxis", "--batch", "--generate", "out.nc", "--revolutions", "2"}));
}

TEST(Subcommands, GuiOpensTheWindowWithTheRestOfTheLine) {
    EXPECT_EQ(expandSubcommand({"bladeaxis", "gui", "x.nc"}), (Arguments{"bladeaxis", "x.nc"}));
}

TEST(Subcommands, OnlyTheFirstArgumentIsACommand) {
    const Arguments plain{"bladeaxis", "--batch", "analyse"};
    EXPECT_EQ(expandSubcommand(plain), plain);
    const Arguments file{"bladeaxis", "./analyse"};
    EXPECT_EQ(expandSubcommand(file), file);
    EXPECT_EQ(expandSubcommand({"bladeaxis"}), (Arguments{"bladeaxis"}));
}

TEST(Subcommands, AnExpandedCommandParsesToItsMode) {
    const auto generate = parseBatchOptions(expandSubcommand({"bladeaxis", "generate", "out.nc"}));
    ASSERT_TRUE(generate) << generate.error().message;
    EXPECT_EQ(generate->mode, BatchOptions::Mode::Generate);
    const auto analyse = parseBatchOptions(expandSubcommand({"bladeaxis", "analyse", "--demo"}));
    ASSERT_TRUE(analyse) << analyse.error().message;
    EXPECT_EQ(analyse->mode, BatchOptions::Mode::Analyse);
    EXPECT_FALSE(analyse->job.reschedule);
}

TEST(ManPage, ListsEveryOptionOfTheHelpAndTheExitCodes) {
    const auto help = parseBatchOptions({"bladeaxis", "--help"});
    const auto man = parseBatchOptions({"bladeaxis", "--man"});
    ASSERT_TRUE(help && man);
    ASSERT_EQ(man->mode, BatchOptions::Mode::ManPage);
    const std::string& page = man->manPageText;
    EXPECT_EQ(page.rfind(".TH BLADEAXIS 1", 0), 0u);
    for (const char* section : {".SH NAME", ".SH SYNOPSIS", ".SH OPTIONS", ".SH EXIT STATUS",
                                ".SH COMMANDS", ".SH FILES"}) {
        EXPECT_NE(page.find(section), std::string::npos) << section;
    }
    // Every long option --help shows is in the page, written as roff's \-\-name.
    const std::regex longOption("--([a-z][a-z0-9-]+)");
    std::set<std::string> options;
    for (std::sregex_iterator it(help->helpText.begin(), help->helpText.end(), longOption), end;
         it != end; ++it) {
        options.insert((*it)[1]);
    }
    ASSERT_GT(options.size(), 30u);
    for (std::string name : options) {
        std::string roff = "\\-\\-";
        for (const char c : name) {
            roff += c == '-' ? std::string("\\-") : std::string(1, c);
        }
        EXPECT_NE(page.find(roff), std::string::npos) << "--" << name;
    }
    EXPECT_NE(page.find("cancelled (Ctrl+C"), std::string::npos);
}

TEST(ManPage, IsNotListedInTheHelp) {
    const auto help = parseBatchOptions({"bladeaxis", "--help"});
    ASSERT_TRUE(help);
    EXPECT_EQ(help->helpText.find("--man"), std::string::npos);
    EXPECT_NE(help->helpText.find("reschedule PROGRAM -o OUT"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::app
