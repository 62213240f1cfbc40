"""Runs bladeaxis_freecad_test.py in a headless FreeCAD (freecadcmd) and turns its outcome into
ctest's: 0 passed, 1 failed, 77 skipped because FreeCAD is not installed.

    run_freecad_test.py PYTHON_MODULE_DIR PLUGIN_DIR BLADEAXIS_EXE

freecadcmd exits 0 even when the script raises, so a pass also needs the script's PASS line.
FreeCAD's settings go to a scratch HOME, never the user's.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bladeaxis_freecad_test.py")


def main(module_dir, plugin_dir, bladeaxis_exe):
    freecadcmd = shutil.which("freecadcmd")
    if freecadcmd is None:
        print("SKIPPED: freecadcmd is not installed (Debian package freecad; "
              "`bash packaging/install-deps.sh` or `make test` installs it)")
        return SKIP
    with tempfile.TemporaryDirectory(prefix="bladeaxis-freecad-home-") as home:
        env = dict(os.environ, HOME=home, QT_QPA_PLATFORM="offscreen",
                   PYTHONDONTWRITEBYTECODE="1", BLADEAXIS_EXE=bladeaxis_exe,
                   BLADEAXIS_FREECAD_PLUGIN=plugin_dir,
                   PYTHONPATH=os.pathsep.join([module_dir, plugin_dir]))
        env.pop("DISPLAY", None)
        run = subprocess.run([freecadcmd, SCRIPT], env=env, cwd=home, stdin=subprocess.DEVNULL,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             errors="replace", timeout=240)
    print(readable(run.stdout))
    if run.returncode == 0 and "BLADEAXIS-FREECAD-TEST: PASS" in run.stdout:
        return 0
    print(f"FAILED: freecadcmd exited {run.returncode}"
          + ("" if "BLADEAXIS-FREECAD-TEST:" in run.stdout else " without running the tests"))
    return 1


def readable(output):
    """FreeCAD's output without its progress counters ("Recompute......", "(25 %)" in tabs),
    which would bury the test's lines in the ctest log."""
    output = re.sub(r"\t*\(\s*\d+ %\)\t*|[A-Z][a-z ]+\.{6}", "", output)
    return "\n".join(line for line in output.splitlines() if line.strip())


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
