#!/usr/bin/env python3
"""Mutation run over the golden inputs: the batch tool on thousands of damaged programs and
machine files must refuse each with a documented exit code, never exit 1 (an internal error),
never end by a signal, never run past its time limit and never grow past the memory bound.

    mutation_run.py BLADEAXIS [--cases 20000] [--seed 1] [--jobs 2] [--work DIR]
                    [--max-rss-mb 2048] [--timeout 60]

Inputs are the programs and machine files the golden tests read (tests/data). Each case takes
one of them, applies one to three mutations (a flipped or deleted byte, a line deleted,
duplicated or swapped, a number replaced by an extreme, NaN, an empty or a huge value, a line
of garbage, a truncation) and runs `bladeaxis --batch` on it, writing into a folder of its
own. The run prints a table of exit codes and lists every failing case, with the mutated input
kept in DIR/failures so it can be replayed. Exit status 0 when no case failed.
"""

import argparse
import collections
import concurrent.futures
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
PROGRAMS = [
    "programs/naca_weak_3rev.nc", "programs/turbine_2rev.cls", "dialects/naca_weak_3rev.mpf",
    "dialects/naca_weak_3rev.h", "awkward/points_with_feed.csv", "awkward/goto_only.cl",
    "awkward/radians_2rev.nc", "awkward/b_noise_large.nc", "cl/classic_apt.apt",
    "cl/nx_clsf_crlf.cls", "nc/compact_lowercase.nc",
]
MACHINES = ["resources/machines/blade_ab.json", "resources/machines/table_a.json",
            "resources/machines/table_b.json", "tests/data/machines/short_z_travel.json"]
# Exit codes the tool documents for bad input (core/base/exit_codes.h); 1 is a bug.
DOCUMENTED = {0, 2, 3, 4, 5, 6}
EXTREMES = ["1e308", "-1e308", "nan", "inf", "", "0", "-0", "1e-320", "3000000", "99999999999",
            "1.2.3", "--5", "+", "0x10", "1e7"]
NUMBER = re.compile(rb"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")


def mutate_bytes(data: bytes, rng: random.Random) -> bytes:
    lines = data.split(b"\n")
    kind = rng.randrange(9)
    if kind == 0 and data:  # flip a byte
        i = rng.randrange(len(data))
        return data[:i] + bytes([data[i] ^ (1 << rng.randrange(8))]) + data[i + 1:]
    if kind == 1 and data:  # delete a byte
        i = rng.randrange(len(data))
        return data[:i] + data[i + 1:]
    if kind == 2 and len(lines) > 1:  # delete a line
        del lines[rng.randrange(len(lines))]
    elif kind == 3 and lines:  # duplicate a line
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind == 4 and len(lines) > 1:  # swap two lines
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind == 5:  # a number replaced by an extreme
        numbers = list(NUMBER.finditer(data))
        if numbers:
            m = rng.choice(numbers)
            return data[:m.start()] + rng.choice(EXTREMES).encode() + data[m.end():]
    elif kind == 6 and lines:  # a line of garbage
        garbage = bytes(rng.randrange(1, 256) for _ in range(rng.randrange(1, 40)))
        lines.insert(rng.randrange(len(lines)), garbage)
    elif kind == 7 and data:  # truncation
        return data[:rng.randrange(len(data))]
    elif kind == 8 and lines:  # a block repeated many times
        i = rng.randrange(len(lines))
        lines[i:i + 1] = [lines[i]] * rng.randrange(2, 2000)
    return b"\n".join(lines)


def make_case(index: int, seed: int):
    rng = random.Random(seed * 1_000_003 + index)
    program = DATA / rng.choice(PROGRAMS)
    machine = ROOT / rng.choice(MACHINES)
    target = "machine" if rng.random() < 0.2 else "program"
    data = (machine if target == "machine" else program).read_bytes()
    for _ in range(rng.randint(1, 3)):
        data = mutate_bytes(data, rng)
    extra = rng.choice([[], ["--tool-radius", "4"], ["--analyse-only"], ["--compare"],
                        ["--derivatives", "filter"], ["--angle-unit", "rad"],
                        ["--feed", "600"]])
    return program, machine, target, data, extra


def run_measured(command, stderr_path, timeout):
    """Runs `command` in its own session; returns (exit code or -signal, peak RSS in MB, timed
    out). wait4 gives this child's own peak RSS, whatever the other workers do."""
    with open(stderr_path, "wb") as err:
        proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err,
                                stdin=subprocess.DEVNULL, start_new_session=True)
    timed_out = []

    def kill():
        timed_out.append(True)
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    timer = threading.Timer(timeout, kill)
    timer.start()
    try:
        _, status, usage = os.wait4(proc.pid, 0)
    finally:
        timer.cancel()
    proc.returncode = os.waitstatus_to_exitcode(status)  # Popen must not wait again
    return proc.returncode, usage.ru_maxrss / 1024.0, bool(timed_out)


def run_case(args, index):
    program, machine, target, data, extra = make_case(index, args.seed)
    folder = Path(tempfile.mkdtemp(prefix=f"m{index}-", dir=args.work))
    try:
        machine_path = folder / "machine.json"
        program_path = folder / program.name
        if target == "machine":
            machine_path.write_bytes(data)
            shutil.copyfile(program, program_path)
        else:
            shutil.copyfile(machine, machine_path)
            program_path.write_bytes(data)
        command = [args.bladeaxis, "--batch", str(program_path), "--machine", str(machine_path),
                   "-q", "--out", str(folder / "report")] + extra
        if "--analyse-only" not in extra:
            command += ["-o", str(folder / ("out" + program.suffix))]
        code, rss, timed_out = run_measured(command, folder / "stderr.txt", args.timeout)
        failure = None
        if timed_out:
            failure = f"no end within {args.timeout:.0f} s"
        elif code < 0:
            failure = f"ended by signal {-code}"
        elif code not in DOCUMENTED:
            failure = f"exit {code}"
        elif rss > args.max_rss_mb:
            failure = f"peak memory {rss:.0f} MB"
        if failure:
            kept = Path(args.work) / "failures" / f"case{index}_{target}_{program.name}"
            kept.parent.mkdir(parents=True, exist_ok=True)
            kept.write_bytes(data)
            last = (folder / "stderr.txt").read_bytes().decode(errors="replace").strip()
            failure += (f" ({' '.join(extra) or 'no option'}, {target} mutated, input kept as "
                        f"{kept}): {last.splitlines()[-1] if last else ''}")
        return index, code, rss, failure
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def summary(codes) -> str:
    return "exit codes: " + ", ".join(f"{c}: {n}" for c, n in sorted(codes.items()))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bladeaxis")
    parser.add_argument("--cases", type=int, default=20000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--work", default=None)
    parser.add_argument("--max-rss-mb", type=float, default=2048.0)
    parser.add_argument("--timeout", type=float, default=60.0)
    args = parser.parse_args()
    args.work = args.work or tempfile.mkdtemp(prefix="bladeaxis-mutation-")
    Path(args.work).mkdir(parents=True, exist_ok=True)
    codes = collections.Counter()
    failures = []
    peak = 0.0
    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for index, code, rss, failure in pool.map(lambda i: run_case(args, i),
                                                     range(args.cases)):
            codes[code] += 1
            peak = max(peak, rss)
            done = sum(codes.values())
            if done % 1000 == 0:  # a long run's partial figures stay readable
                print(f"{done} cases, {time.monotonic() - started:.0f} s: " + summary(codes) +
                      f"; largest peak {peak:.0f} MB; {len(failures)} failure(s)",
                      file=sys.stderr, flush=True)
            if failure:
                failures.append(f"case {index}: {failure}")
                print(failures[-1], file=sys.stderr, flush=True)
    print(f"{args.cases} cases in {time.monotonic() - started:.0f} s (seed {args.seed}); " +
          summary(codes) +
          f"; largest peak memory of a case {peak:.0f} MB; {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
