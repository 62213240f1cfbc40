#!/usr/bin/env python3
"""Writes the Sinumerik and Heidenhain versions of tests/data/programs/naca_weak_3rev.nc.

The ISO program positions the tool tip in machine coordinates on the default blade machine
(table A about X, no offsets, tip-programmed). The Sinumerik version switches TRAORI on, so its
X Y Z are the tip in the workpiece frame, O_W = Rx(-A) P, and writes A as A=DC(a mod 360). The
Heidenhain version keeps machine coordinates and writes A mod 360 under M126 (shortest path).
All three describe the same cut: tests compare what BladeAxis makes of them.
"""
import math
import pathlib
import re

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parent / "programs" / "naca_weak_3rev.nc"
MOVE = re.compile(r"N(\d+) G1 X(\S+) Y(\S+) Z(\S+) A(\S+) B(\S+)(?: F(\S+))?$")


def moves():
    for line in SOURCE.read_text().splitlines():
        match = MOVE.match(line)
        if match:
            n, x, y, z, a, b, f = match.groups()
            yield int(n), float(x), float(y), float(z), float(a), float(b), f


def to_workpiece(x, y, z, a_deg):
    a = math.radians(a_deg)
    c, s = math.cos(a), math.sin(a)
    # Rx(-a) applied to (x, y, z)
    return x, c * y + s * z, -s * y + c * z


def modulo(a_deg):
    value = a_deg % 360.0
    return 0.0 if round(value, 4) >= 360.0 else value


def sinumerik():
    out = ["%_N_NACA_WEAK_3REV_MPF", ";$PATH=/_N_MPF_DIR",
           "; BladeAxis synthetic blade program [naca-weak, seed 3], Sinumerik 840D",
           "; ball end R=8 mm, B=5 deg, lead 15 deg, 3 revolutions",
           "N2 G71 G90 G94 G17", "N4 T=\"BALL_R8\" D1", "N6 M6",
           "N8 CYCLE832(0.01,_ORI_FINISH,1)", "N9 MSG(\"FINISH; BLADE\")",
           "N10 G642 SOFT FFWON ORIWKS", "N12 TRAORI"]
    for n, x, y, z, a, b, f in moves():
        wx, wy, wz = to_workpiece(x, y, z, a)
        words = f"N{n} G1 X{wx:.4f} Y{wy:.4f} Z{wz:.4f} A=DC({modulo(a):.4f}) B{b:.4f}"
        out.append(words + (f" F{f}" if f else ""))
    out += ["N7072 TRAFOOF", "N7074 G0 Z100.", "N7080 M30"]
    return "\n".join(out) + "\n"


def heidenhain():
    out = ["0 BEGIN PGM NACA_WEAK_3REV MM",
           "1 ; BladeAxis synthetic blade program [naca-weak, seed 3], TNC 640",
           "2 BLK FORM 0.1 Z X-10 Y-30 Z-30", "3 BLK FORM 0.2 X+80 Y+30 Z+30",
           "4 TOOL DEF 1 L+0 R+8", "5 TOOL CALL 1 Z S12000 F3000 DR+0",
           "6 CYCL DEF 32.0 TOLERANCE", "7 CYCL DEF 32.1 T0.01",
           "8 * - FINISH", "9 L M126"]
    number = 10
    for _, x, y, z, a, b, f in moves():
        words = f"{number} L X{x:+.4f} Y{y:+.4f} Z{z:+.4f} A{modulo(a):+.4f} B{b:+.4f} R0"
        out.append(words + (" FAUTO M3" if f else ""))
        number += 1
    out += [f"{number} L Z+100 R0 FMAX M127", f"{number + 1} END PGM NACA_WEAK_3REV MM"]
    return "\n".join(out) + "\n"


(HERE / "naca_weak_3rev.mpf").write_text(sinumerik())
(HERE / "naca_weak_3rev.h").write_text(heidenhain())
