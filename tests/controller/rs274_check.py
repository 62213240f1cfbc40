#!/usr/bin/env python3
"""Checks ISO/Fanuc programs with LinuxCNC's standalone interpreter rs274.

For each program: rs274 must exit 0 and print nothing but canonical calls (any other text is an
interpreter error), emit one STRAIGHT_TRAVERSE/STRAIGHT_FEED per motion block of the program
(gcode_blocks.py) and end each at the block's X Y Z A B. rs274 prints positions with four
decimals in the program's length units (mm after G21, inch after G20; degrees for A B) as
STRAIGHT_FEED(x, y, z, a, b, c), so an end point matches when it is within half a unit of the
fourth decimal of the block's value.

  rs274_check.py PROGRAM...           check the programs
  rs274_check.py --self-test          prove the check fails on a wrong expectation
  rs274_check.py suite --bladeaxis BIN --work DIR [--also GLOB...]
                                      generate programs with bladeaxis into DIR, check them and
                                      every existing file matching the globs
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from gcode_blocks import AXES, ProgramError, parse_blocks  # noqa: E402

_CANON = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z][A-Z0-9_]*)\((.*)\)\s*$")
_MOVES = ("STRAIGHT_FEED", "STRAIGHT_TRAVERSE", "ARC_FEED")
# rs274 rounds to 4 decimals: half a unit of the last digit, plus a hair for binary rounding.
TOLERANCE = 0.5e-4 + 1e-9


def run_rs274(program):
    """Runs rs274 on program; returns (exit code, canonical moves [(name, [values])], errors)."""
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        # rs274 creates its parameter file in the working folder: keep it out of the sources.
        proc = subprocess.run(
            ["rs274", "-i", os.path.join(HERE, "rs274.ini"), "-t", os.path.join(HERE, "tool.tbl"),
             "-g", os.path.abspath(program)],
            cwd=tmp, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=600)
    moves, errors = [], []
    for line in (proc.stdout + proc.stderr).splitlines():
        if not line.strip() or line.strip() == "executing":
            continue
        m = _CANON.match(line)
        if not m:
            errors.append(line.strip())
        elif m.group(1) in _MOVES:
            moves.append((m.group(1), [float(v) for v in m.group(2).split(",")]))
    return proc.returncode, moves, errors


def compare(blocks, moves):
    """Differences between the program's motion blocks and rs274's canonical moves (a list of
    messages, empty when they agree)."""
    problems = []
    if len(moves) != len(blocks):
        problems.append(f"{len(moves)} canonical moves for {len(blocks)} motion blocks")
    for block, (name, values) in zip(blocks, moves):
        want = "STRAIGHT_TRAVERSE" if block["motion"] == "G0" else "STRAIGHT_FEED"
        if name != want:
            problems.append(f"line {block['line']}: {name}, expected {want}")
            continue
        for i, axis in enumerate(AXES):
            if abs(values[i] - block[axis.lower()]) > TOLERANCE:
                problems.append(f"line {block['line']}: {axis} {values[i]:.4f} from rs274, "
                                f"{block[axis.lower()]} in the program")
        if len(problems) > 20:
            problems.append("...")
            break
    return problems


def check(program):
    """Checks one program; returns a list of problems (empty: it passed)."""
    try:
        blocks = parse_blocks(program)
    except ProgramError as e:
        return [str(e)]
    code, moves, errors = run_rs274(program)
    problems = [f"rs274 exit code {code}"] if code != 0 else []
    problems += [f"rs274: {e}" for e in errors[:10]]
    problems += compare(blocks, moves)
    return problems


def check_all(programs):
    failed = 0
    for program in programs:
        problems = check(program)
        n = len(parse_blocks(program)) if not problems else "?"
        if problems:
            failed += 1
            print(f"FAIL {program}")
            for p in problems:
                print(f"     {p}")
        else:
            print(f"ok   {program} ({n} motion blocks)")
    return failed


def self_test():
    """The check must fail on a wrong word, a missing block and an interpreter error, and pass on
    the right program; otherwise a passing suite would prove nothing."""
    with tempfile.TemporaryDirectory(prefix="rs274-self-") as tmp:
        good = os.path.join(tmp, "good.nc")
        with open(good, "w") as f:
            f.write("(self test)\nN10 G21 G90 G94\nN20 G0 X10 Y2.5 Z3 A0 B15\n"
                    "N30 G1 X12.3456 Y-3.21 Z4.5 A370.5 B14.25 F1500\nN40 X13 A380.125\nN50 M30\n")
        results = {}
        results["right program passes"] = not check(good)
        blocks = parse_blocks(good)
        _, moves, _ = run_rs274(good)
        wrong = [dict(b) for b in blocks]
        wrong[1]["x"] += 0.001  # one word differs by a unit of the third decimal
        results["a wrong X is found"] = any("X " in p for p in compare(wrong, moves))
        wrong = [dict(b) for b in blocks]
        wrong[2]["a"] += 0.0002  # A differs by two units of the fourth decimal
        results["a wrong A is found"] = any("A " in p for p in compare(wrong, moves))
        results["a missing block is found"] = any("canonical moves" in p
                                                  for p in compare(blocks[:-1], moves))
        results["a G0 taken for G1 is found"] = bool(
            compare([dict(blocks[0], motion="G1")] + blocks[1:], moves))
        bad = os.path.join(tmp, "bad.nc")
        with open(bad, "w") as f:
            f.write("G21 G90\nG1 X1 Y2 F100\nG1 G0 X2\nM30\n")  # two motions in one block
        results["an interpreter error is found"] = any("rs274" in p for p in check(bad))
    for name, passed in results.items():
        print(f"{'ok  ' if passed else 'FAIL'} {name}")
    return 0 if all(results.values()) else 1


def suite(bladeaxis, work, globs):
    """Generates programs with bladeaxis (so the test does not depend on the golden tests having
    run) and checks them together with the existing programs matching globs."""
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    runs = [
        ["--batch", "--demo", "--out", f"{work}/demo", "-o", f"{work}/demo/demo_blade_rescheduled.nc"],
        ["generate", f"{work}/turbine_s5.nc", "--profile", "turbine", "--revolutions", "1", "--seed", "5"],
        ["generate", f"{work}/naca_s7.nc", "--profile", "naca-high-camber", "--revolutions", "1",
         "--seed", "7"],
        ["reschedule", f"{work}/turbine_s5.nc", "--tool-radius", "8", "-o", f"{work}/turbine_s5_rs.nc"],
        ["reschedule", f"{work}/naca_s7.nc", "--tool-radius", "8", "--preset", "faithful",
         "-o", f"{work}/naca_s7_rs.nc"],
    ]
    for args in runs:
        proc = subprocess.run([bladeaxis] + args, capture_output=True, text=True, timeout=600)
        if proc.returncode != 0:
            print(f"FAIL bladeaxis {' '.join(args)}: exit {proc.returncode}\n{proc.stderr}")
            return 1
    programs = sorted(glob.glob(f"{work}/**/*.nc", recursive=True))
    generated = len(programs)
    for pattern in globs:
        programs += sorted(p for p in glob.glob(pattern, recursive=True) if p not in programs)
    print(f"{generated} generated programs, {len(programs) - generated} found")
    if generated < 6:  # demo original + re-scheduled, two generated, two re-scheduled
        print(f"FAIL only {generated} programs generated")
        return 1
    return 1 if check_all(programs) else 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--self-test":
        return self_test()
    if len(sys.argv) > 1 and sys.argv[1] == "suite":
        parser = argparse.ArgumentParser(prog="rs274_check.py suite")
        parser.add_argument("--bladeaxis", required=True)
        parser.add_argument("--work", required=True)
        parser.add_argument("--also", nargs="*", default=[])
        args = parser.parse_args(sys.argv[2:])
        return suite(args.bladeaxis, os.path.abspath(args.work), args.also)
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 2
    return 1 if check_all(sys.argv[1:]) else 0


if __name__ == "__main__":
    sys.exit(main())
