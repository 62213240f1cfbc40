#pragma once
// APT / ISO 4343 CLDATA / Siemens NX CLSF support: reader, minimal-diff rewriter, emitter.

#include "core/io/cl/apt_program.h" // IWYU pragma: export
#include "core/io/cl/apt_reader.h"  // IWYU pragma: export
#include "core/io/cl/apt_writer.h"  // IWYU pragma: export
