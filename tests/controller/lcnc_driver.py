#!/usr/bin/python3
"""The headless DISPLAY program of the controller check (run by the `linuxcnc` script).

LinuxCNC starts it as `lcnc_driver.py -ini INI` once HAL, motion, task and io are up. It takes
the program and the output folder from the environment (LCNC_CHECK_PROGRAM, LCNC_CHECK_OUT),
because the linuxcnc script passes its own arguments only. It records the HAL sampler through
halsampler while it switches the machine on, homes, runs the program in AUTO mode and waits for
the interpreter to finish, then writes OUT/driver.json and exits, which shuts LinuxCNC down.

Exit codes: 0 program ran to the end; 2 LinuxCNC reported an error for the program;
3 the controller stopped answering (milltask died or never came up: worth a retry).
"""

import json
import os
import subprocess
import sys
import time

import linuxcnc

PROGRAM = os.environ["LCNC_CHECK_PROGRAM"]
OUT = os.environ["LCNC_CHECK_OUT"]
# Whole-program bound: real time, so a long program takes long; the caller sets it.
RUN_TIMEOUT_S = float(os.environ.get("LCNC_CHECK_TIMEOUT", "1800"))

stat = linuxcnc.stat()
command = linuxcnc.command()
errors = linuxcnc.error_channel()
messages = []


class Unresponsive(Exception):
    """Task does not answer: the caller restarts LinuxCNC."""


def poll():
    stat.poll()
    while True:
        e = errors.poll()
        if not e:
            break
        kind, text = e
        messages.append({"kind": kind, "text": text})


def wait_for(predicate, timeout, what):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        poll()
        if predicate():
            return
        time.sleep(0.01)
    raise Unresponsive(f"timed out waiting for {what}")


def send(call, *args):
    """Sends one command and waits for task to acknowledge it (-1 means no answer)."""
    call(*args)
    if command.wait_complete(10.0) == -1:
        raise Unresponsive(f"no answer to {call.__name__}{args}")


def task_alive():
    """Whether milltask still runs: when it dies, stat keeps its last state and gives no sign."""
    for pid in os.listdir("/proc"):
        try:
            with open(f"/proc/{pid}/comm") as f:
                if f.read().strip() == "milltask":
                    return True
        except (OSError, ValueError):
            continue
    return False


def run():
    wait_for(lambda: stat.task_state != 0, 20.0, "task to publish its status")
    if not task_alive():
        raise Unresponsive("milltask is not running")
    send(command.state, linuxcnc.STATE_ESTOP_RESET)
    send(command.state, linuxcnc.STATE_ON)
    wait_for(lambda: stat.task_state == linuxcnc.STATE_ON, 10.0, "machine on")
    send(command.mode, linuxcnc.MODE_MANUAL)
    send(command.teleop_enable, 0)
    send(command.home, -1)
    wait_for(lambda: all(stat.homed[j] for j in range(5)), 10.0, "homing")
    send(command.mode, linuxcnc.MODE_AUTO)
    send(command.program_open, PROGRAM)
    started = time.monotonic()
    # Not send(): task acknowledges AUTO_RUN only when the program has ended.
    command.auto(linuxcnc.AUTO_RUN, 0)
    # Done when the interpreter is idle again with nothing queued; an error also ends the run
    # (task aborts). A short program can be over before the first poll, so the start is not
    # awaited; the first half second only lets task take the run command.
    time.sleep(0.5)
    last_check = time.monotonic()
    while True:
        poll()
        if stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0:
            break
        if time.monotonic() - last_check > 1.0:
            last_check = time.monotonic()
            if not task_alive():
                raise Unresponsive("milltask died during the run")
        if time.monotonic() - started > RUN_TIMEOUT_S:
            raise Unresponsive("program did not finish within the time bound")
        time.sleep(0.02)
    return time.monotonic() - started


def main():
    # The linuxcnc script hides the display's output in a temporary file it deletes.
    log = open(os.path.join(OUT, "driver.log"), "w")
    os.dup2(log.fileno(), 2)
    samples = open(os.path.join(OUT, "samples.txt"), "w")
    # -t tags each line with the sample number, so any lost sample would show as a gap.
    sampler = subprocess.Popen(["halsampler", "-t"], stdout=samples)
    result = {"program": PROGRAM}
    code = 0
    try:
        result["wall_s"] = run()
        errs = [m for m in messages if m["kind"] in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR)]
        if errs:
            code = 2
    except Unresponsive as e:
        result["failure"] = str(e)
        code = 3
    # Let the sampler drain the last samples of the move before stopping it.
    time.sleep(0.3)
    sampler.terminate()
    sampler.wait()
    samples.close()
    result["messages"] = messages
    result["exit"] = code
    with open(os.path.join(OUT, "driver.json"), "w") as f:
        json.dump(result, f, indent=1)
    return code


if __name__ == "__main__":
    sys.exit(main())
