#!/usr/bin/env python3
"""How much fewer, longer blocks would buy on a control that plans every rotary block alone.

    merge_study.py PROGRAM BALL_RADIUS_MM TOLERANCE_MM...

For a table-A / head-B program (X Y Z A B words, the default blade machine's chain: pivot 0,
A about +X, B about +Y), drops programmed points greedily while the ball centre of the merged
block, as the control interpolates the axes linearly, stays within the tolerance of the CL
chords it replaces (both ways: every dropped centre near the new block's path, every point of
the new block near the old chords). Prints the block count and the block-by-block model's time
(the rules of core/analysis/block_planner.cpp, default blade machine limits) before and after.
A study for docs/results.md, not a product path.
"""

import math
import sys

import numpy as np

sys.path.insert(0, __import__("os").path.dirname(__file__))
from gcode_blocks import parse_blocks  # noqa: E402

LIMITS = {"lin_v": 500.0, "lin_a": 3000.0, "rot_v": 360.0, "rot_a": 1800.0}


def centres(q, radius):
    x, y, z = q[:, 0], q[:, 1], q[:, 2]
    a, b = np.radians(q[:, 3]), np.radians(q[:, 4])
    p = np.stack([x + radius * np.sin(b), y, z + radius * np.cos(b)], 1)
    ca, sa = np.cos(-a), np.sin(-a)
    return np.stack([p[:, 0], ca * p[:, 1] - sa * p[:, 2], sa * p[:, 1] + ca * p[:, 2]], 1)


def distance_to_polyline(point, polyline):
    a, b = polyline[:-1], polyline[1:]
    d = b - a
    length2 = np.maximum((d * d).sum(1), 1e-300)
    t = np.clip(((point - a) * d).sum(1) / length2, 0, 1)
    return np.min(np.linalg.norm(point - (a + t[:, None] * d), axis=1))


def interpolated(qa, qb, samples, radius):
    t = np.linspace(0, 1, samples)[:, None]
    return centres(qa[None, :5] * (1 - t) + qb[None, :5] * t, radius)


def merge(q, radius, tolerance, longest=64):
    c = centres(q[:, :5], radius)
    keep, i = [0], 0
    while i < len(q) - 1:
        best = i + 1
        while best + 1 < len(q) and best + 1 - i <= longest:
            j = best + 1
            path = interpolated(q[i], q[j], 6 * (j - i) + 1, radius)
            if any(distance_to_polyline(c[k], path) > tolerance for k in range(i + 1, j)):
                break
            if any(distance_to_polyline(p, c[i:j + 1]) > tolerance for p in path[1:-1]):
                break
            best = j
        keep.append(best)
        i = best
    return keep


def block_time(q):
    blocks = []
    for i in range(1, len(q)):
        d = np.abs(q[i, :5] - q[i - 1, :5])
        d[d < 1e-7] = 0
        length = math.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2) or math.hypot(d[3], d[4])
        if length == 0:
            continue
        tv = max(max(d[:3]) / LIMITS["lin_v"], max(d[3:]) / LIMITS["rot_v"])
        ta = max(max(d[:3]) / LIMITS["lin_a"], max(d[3:]) / LIMITS["rot_a"])
        v = min(q[i, 5] / 60.0, length / tv)
        a = 0.5 * length / ta
        peak = min(v, math.sqrt(a * length))
        duration = 2 * peak / a if peak < v else length / v + v / a
        blocks.append((length, a, peak, duration))
    total = 0.0
    for k, (length, a, peak, duration) in enumerate(blocks):
        total += duration
        if k + 1 < len(blocks):
            length2, a2, peak2, _ = blocks[k + 1]
            blend = min(peak, min(min(length / peak, length2 / peak2), max(peak / a, peak2 / a2)) * a)
            total -= blend / a
    return total


def main():
    program, radius = sys.argv[1], float(sys.argv[2])
    blocks = [b for b in parse_blocks(program) if b["motion"] == "G1"]
    q = np.array([[b["x"], b["y"], b["z"], b["a"], b["b"], b["f"]] for b in blocks])
    print(f"{program}: {len(q) - 1} blocks, model {block_time(q):.1f} s")
    for tolerance in map(float, sys.argv[3:]):
        kept = merge(q, radius, tolerance)
        print(f"  merged within {1000 * tolerance:g} um: {len(kept) - 1} blocks, "
              f"model {block_time(q[kept]):.1f} s")


if __name__ == "__main__":
    main()
