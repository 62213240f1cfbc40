#!/usr/bin/env python3
"""Lists the motion blocks of an ISO/Fanuc G-code program: line, motion, X Y Z A B end point, F.

The end point is absolute (modal words carried over, G91 increments summed) in the program's
own units, i.e. what the controller is asked to reach at the end of the block; F is the modal
feed in force for the block. This is the per-block key both for the rs274 check (same end
points, same count) and for comparing a timing model with LinuxCNC's measured block times
(`line` is the 1-based file line, which is what LinuxCNC reports as motion.program-line).

CLI: gcode_blocks.py PROGRAM [--json]  prints one block per line (or a JSON list).
"""

import json
import re
import sys

AXES = "XYZAB"
_COMMENT = re.compile(r"\([^)]*\)")
_WORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
# G codes after which axis words are not a move of the modal motion (dwell, data setting,
# offsets): such blocks are not motion blocks.
_NON_MOTION_G = {4.0, 10.0, 92.0, 92.1, 92.2, 92.3}


class ProgramError(ValueError):
    pass


def decimals(text):
    """Digits written after the decimal point ("12.30" -> 2, "7" -> 0)."""
    return len(text.split(".", 1)[1]) if "." in text else 0


def parse_blocks(path):
    """Returns the motion blocks of the program at path as dicts (see the module text)."""
    pos = {a: 0.0 for a in AXES}
    motion = None  # modal group 1: 0 (G0) or 1 (G1); arcs are refused below
    absolute = True
    feed = None
    blocks = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, raw in enumerate(f, start=1):
            text = _COMMENT.sub(" ", raw.upper()).split(";", 1)[0].strip()
            if not text or text == "%":
                continue
            if text.startswith("/"):
                text = text[1:]
            words = _WORD.findall(text)
            gs = [float(v) for letter, v in words if letter == "G"]
            non_motion = any(g in _NON_MOTION_G for g in gs)
            for g in gs:
                if g in (0.0, 1.0):
                    motion = int(g)
                elif g in (2.0, 3.0):
                    raise ProgramError(f"{path}:{number}: arcs (G2/G3) are not handled")
                elif g == 90.0:
                    absolute = True
                elif g == 91.0:
                    absolute = False
            axis_words = {}
            for letter, value in words:
                if letter == "F":
                    feed = float(value)
                elif letter in AXES:
                    axis_words[letter] = value
            if not axis_words or non_motion:
                continue
            if motion is None:
                raise ProgramError(f"{path}:{number}: axis words before any G0/G1")
            for letter, value in axis_words.items():
                pos[letter] = float(value) if absolute else pos[letter] + float(value)
            blocks.append({
                "line": number,
                "motion": f"G{motion}",
                **{a.lower(): pos[a] for a in AXES},
                "f": feed,
                "decimals": {a: decimals(v) for a, v in axis_words.items()},
            })
    return blocks


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) >= 2 else 2
    blocks = parse_blocks(argv[1])
    if "--json" in argv[2:]:
        json.dump(blocks, sys.stdout, indent=None)
        print()
        return 0
    print("line motion X Y Z A B F")
    for b in blocks:
        f = "-" if b["f"] is None else f"{b['f']:g}"
        print(f"{b['line']} {b['motion']} " + " ".join(f"{b[a]:.4f}" for a in "xyzab") + f" {f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
