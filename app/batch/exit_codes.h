#pragma once
// The batch front end's exit codes are the core's table (core/base/exit_codes.h), so a plug-in
// and the command line map every error alike.

#include "core/base/exit_codes.h"
