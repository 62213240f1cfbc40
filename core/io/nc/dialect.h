#pragma once
// Which NC dialect a G-code family program is written in, from its content first and its
// extension second. Content markers: a Heidenhain program opens with "BEGIN PGM" (after an
// optional block number) or moves with "L X+.."; a Sinumerik program uses instructions no ISO
// program has (TRAORI, A=DC(..), CYCLE832, MSG(..), "%_N_" headers...). Without a marker,
// .h is Heidenhain, .mpf/.spf Sinumerik and anything else ISO.

#include "core/io/read_options.h"

#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis::io::nc {

struct DetectedDialect {
    NcDialect dialect = NcDialect::Iso;
    std::optional<std::string> warning; // the extension names another dialect
};

DetectedDialect detectDialect(std::string_view text, std::string_view fileName);

// True for a line of Heidenhain conversational text ("12 L X+1 FMAX", "0 BEGIN PGM A MM"):
// format detection counts these as G-code family lines.
bool looksLikeHeidenhainLine(std::string_view line);

} // namespace bladeaxis::io::nc
