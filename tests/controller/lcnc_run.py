#!/usr/bin/env python3
"""Runs one G-code program through LinuxCNC's real trajectory planner, headless and in real
time, and writes the time it spent on each block.

  lcnc_run.py MACHINE.json PROGRAM OUT.json [--startup "G21 G90 G94 G64 P0.01"] [--retries 5]

A simulator configuration is generated from the machine file (lcnc_config.py), `linuxcnc` runs
it with lcnc_driver.py as its display, and the HAL sampler records motion.program-line, the
motion type, the planner velocity and the five joint commands every 1 ms servo period. The time
of a block is the number of servo periods its line was the active one, between the first and
the last period in which any joint moved (the cycle time). milltask has been seen to die in
about one start in ten: such runs are detected and retried.
"""

import argparse
import json
import os
import pwd
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from gcode_blocks import parse_blocks  # noqa: E402
from lcnc_config import write_config  # noqa: E402

SERVO_PERIOD_S = 0.001
RT_USER = "lcnc"


def rt_user_env(fifo_dir):
    """As root, rtapi_app must drop to an unprivileged user (RTAPI_UID) and put its socket
    (RTAPI_FIFO_PATH) in a folder that user owns; the user is created once if absent."""
    env = {}
    if os.geteuid() == 0:
        try:
            user = pwd.getpwnam(RT_USER)
        except KeyError:
            subprocess.run(["useradd", "-r", "-M", "-s", "/usr/sbin/nologin", RT_USER], check=True)
            user = pwd.getpwnam(RT_USER)
        os.chown(fifo_dir, user.pw_uid, user.pw_gid)
        env["RTAPI_UID"] = str(user.pw_uid)
    env["RTAPI_FIFO_PATH"] = os.path.join(fifo_dir, "rtapi_fifo")
    return env


def short_fifo_dir():
    """rtapi_app's socket is a Unix socket, whose path holds at most 107 bytes: one under a
    deep build tree (a CI checkout, a long program name) makes linuxcnc exit 255 without a
    word. A fresh folder directly in /tmp keeps the path short wherever the run lives."""
    return tempfile.mkdtemp(prefix="lcnc-", dir="/tmp")


def log_tail(path, lines=15):
    try:
        with open(path, errors="replace") as f:
            tail = f.read().splitlines()[-lines:]
    except OSError:
        return ""
    return "\n".join(tail) if tail else "(linuxcnc printed nothing)"


def run_linuxcnc(ini, run_dir, program, timeout_s):
    """One start of LinuxCNC; returns the driver's result (driver.json) or a failure dict."""
    out = os.path.join(run_dir, "attempt")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    fifo_dir = short_fifo_dir()
    try:
        return start_once(ini, run_dir, out, program, timeout_s, fifo_dir)
    finally:
        shutil.rmtree(fifo_dir, ignore_errors=True)


def start_once(ini, run_dir, out, program, timeout_s, fifo_dir):
    env = dict(os.environ, LCNC_CHECK_PROGRAM=program, LCNC_CHECK_OUT=out,
               LCNC_CHECK_TIMEOUT=str(timeout_s), **rt_user_env(fifo_dir))
    env.pop("DISPLAY", None)  # no X server; the linuxcnc script must not look for one
    with open(os.path.join(out, "linuxcnc.log"), "w") as log:
        # Own session: on a hang the whole tree (script, task, io, rtapi_app) is ended by its
        # process group, which is only ours.
        proc = subprocess.Popen(["linuxcnc", ini], cwd=run_dir, env=env, stdin=subprocess.DEVNULL,
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            proc.wait(timeout=timeout_s + 120)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGTERM)
            try:
                proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
            return {"exit": 3, "failure": "linuxcnc did not finish"}
    result_path = os.path.join(out, "driver.json")
    if not os.path.exists(result_path):
        log = log_tail(os.path.join(out, "linuxcnc.log"))
        return {"exit": 3,
                "failure": f"linuxcnc exited {proc.returncode} before the driver finished",
                "log": log}
    with open(result_path) as f:
        return json.load(f)


def read_samples(path):
    """Sampler rows: (sample number, line, motion type, velocity, j0..j4)."""
    rows = []
    with open(path) as f:
        for text in f:
            parts = text.split()
            if len(parts) != 9:
                if "overrun" in text:
                    raise RuntimeError("sampler overrun: samples were lost")
                continue
            rows.append((int(parts[0]), int(parts[1]), int(parts[2]), float(parts[3]),
                         *map(float, parts[4:])))
    return rows


def block_times(rows):
    """Cycle time and per-line times from the sampler rows (see the module text)."""
    for a, b in zip(rows, rows[1:]):
        if b[0] != a[0] + 1:
            raise RuntimeError(f"samples {a[0]}..{b[0]} missing")
    moving = [i for i in range(1, len(rows)) if rows[i][4:] != rows[i - 1][4:]]
    if not moving:
        return 0.0, []
    first, last = moving[0], moving[-1]
    # A sample counts for the line active in it; consecutive samples of one line form one
    # entry (a line seen again later, which a blended planner does not do, gets its own entry).
    per_line = []
    for row in rows[first:last + 1]:
        line, vel = row[1], row[3]
        if per_line and per_line[-1]["line"] == line:
            entry = per_line[-1]
        else:
            entry = {"line": line, "samples": 0, "peak_vel": 0.0, "min_vel": float("inf")}
            per_line.append(entry)
        entry["samples"] += 1
        entry["peak_vel"] = max(entry["peak_vel"], vel)
        entry["min_vel"] = min(entry["min_vel"], vel)
    for e in per_line:
        e["time_s"] = round(e.pop("samples") * SERVO_PERIOD_S, 6)
        # current-vel is the planner's tool-path speed in units/s (XYZ, or A B alone).
        e["peak_vel"] = round(e["peak_vel"], 4)
        e["min_vel"] = round(e["min_vel"], 4)
    return (last - first + 1) * SERVO_PERIOD_S, per_line


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("machine")
    parser.add_argument("program")
    parser.add_argument("output")
    parser.add_argument("--startup", default="G21 G90 G94 G64 P0.01",
                        help="RS274NGC startup code (use plain G64 for no blend tolerance)")
    parser.add_argument("--retries", type=int, default=5)
    parser.add_argument("--timeout", type=float, default=1800.0, help="per run, seconds")
    args = parser.parse_args()
    program = os.path.abspath(args.program)
    blocks = parse_blocks(program)
    run_dir = os.path.abspath(os.path.splitext(args.output)[0] + ".run")
    os.makedirs(run_dir, exist_ok=True)
    ini = write_config(args.machine, run_dir, os.path.join(HERE, "lcnc_driver.py"), args.startup)
    failures = []
    for attempt in range(1, args.retries + 1):
        started = time.monotonic()
        result = run_linuxcnc(ini, run_dir, program, args.timeout)
        if result["exit"] != 3:
            break
        failures.append(result.get("failure", "?"))
        print(f"lcnc_run: attempt {attempt} failed ({failures[-1]}); retrying", file=sys.stderr)
        if result.get("log"):
            print(f"lcnc_run: the end of linuxcnc's output:\n{result['log']}", file=sys.stderr)
    else:
        print(f"lcnc_run: {program}: LinuxCNC failed {args.retries} times: {failures}",
              file=sys.stderr)
        return 3
    if result["exit"] == 2:
        print(f"lcnc_run: {program}: LinuxCNC reported errors: {result['messages']}",
              file=sys.stderr)
        return 2
    cycle, per_line = block_times(read_samples(os.path.join(run_dir, "attempt", "samples.txt")))
    by_line = {b["line"]: b for b in blocks}
    timed_blocks = sum(1 for e in per_line if e["line"] in by_line)
    summary = {
        "program": program,
        "machine": os.path.abspath(args.machine),
        "startup_code": args.startup,
        "attempts": attempt,
        "failed_attempts": failures,
        "wall_s": round(time.monotonic() - started, 3),
        "cycle_time_s": round(cycle, 6),
        "blocks": len(blocks),
        "blocks_timed": timed_blocks,
        "per_block": per_line,
    }
    with open(args.output, "w") as f:
        json.dump(summary, f, indent=1)
    print(f"{os.path.basename(program)}: {len(blocks)} blocks, planner cycle time {cycle:.3f} s "
          f"({timed_blocks} blocks timed, {attempt} start(s))")
    return 0


if __name__ == "__main__":
    sys.exit(main())
