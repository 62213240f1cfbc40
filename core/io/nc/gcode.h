#pragma once
// ISO/Fanuc G-code for four-axis blade programs: read, rewrite with new axes (minimal diff),
// and emit a fresh program from a toolpath.

#include "core/io/nc/gcode_emitter.h"
#include "core/io/nc/gcode_program.h"
#include "core/io/nc/gcode_reader.h"
#include "core/io/nc/gcode_writer.h"
