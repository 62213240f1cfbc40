#pragma once
// Starts the desktop application; the batch front end never calls this, so `--batch` needs no
// display.

namespace bladeaxis::ui {

int runGui(int argc, char** argv);

} // namespace bladeaxis::ui
