"""The bladeaxis Python module (app/python, docs/python.md) against the command line and its own
promises. Run by ctest as python.module with PYTHONPATH on the built module, BLADEAXIS_EXE the
built bladeaxis and BLADEAXIS_TEST_DATA the tests/data folder."""

import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import threading

import numpy as np
import pytest

import bladeaxis

TEST_DATA = pathlib.Path(os.environ["BLADEAXIS_TEST_DATA"])
DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"
# A real blade pass: tests/data/nc holds reader fixtures, none of them a helical blade pass.
# Its header states R=8 in prose, not in a post's (T1 D=.. CR=..) comment, so the job names it.
BLADE_PROGRAM = TEST_DATA / "programs" / "naca_weak_3rev.nc"
BLADE_TOOL_RADIUS_MM = 8
# A reader fixture: read fine, refused as "not a helical blade pass" (exit code 5).
NOT_A_BLADE_PROGRAM = TEST_DATA / "nc" / "fanuc_basic.nc"


def without_timing(value):
    """The report without its wall times, which differ between any two runs."""
    if isinstance(value, dict):
        return {key: without_timing(item) for key, item in value.items() if key != "timing"}
    if isinstance(value, list):
        return [without_timing(item) for item in value]
    return value


@pytest.fixture(scope="module")
def demo():
    """The demo job, run once for the tests that only read its outcome, with its progress."""
    calls = []
    outcome = bladeaxis.run_job({"demo": True},
                                progress=lambda fraction, stage: calls.append((fraction, stage)))
    return outcome, calls


def test_demo_report_is_the_command_lines(demo):
    outcome, _ = demo
    printed = subprocess.run([os.environ["BLADEAXIS_EXE"], "--batch", "--demo", "--json"],
                             check=True, capture_output=True, text=True).stdout
    assert without_timing(outcome.report) == without_timing(json.loads(printed))
    assert outcome.report["bladeaxis_version"] == bladeaxis.__version__


def test_demo_outcome(demo):
    outcome, _ = demo
    assert outcome.rescheduled is True
    assert isinstance(outcome.summary, str) and "A reversals" in outcome.summary
    assert outcome.warnings == outcome.report["warnings"]
    assert outcome.report is outcome.report  # converted once


def test_layers_are_monotone_inside_the_channel(demo):
    outcome, _ = demo
    layers = outcome.layers
    assert len(layers) == len(outcome.report["rescheduled"]["layers"])
    scheduled = [layer for layer in layers if not layer.kept_original]
    assert scheduled, "the demo re-schedules at least one layer"
    for layer in scheduled:
        theta = layer.theta_rescheduled
        for array in (layer.s, layer.theta_original, theta, layer.theta_min, layer.theta_max):
            assert isinstance(array, np.ndarray) and array.dtype == np.float64
            assert array.shape == layer.s.shape
            assert not array.flags.writeable
        steps = np.diff(theta)
        assert np.all(steps >= 0) or np.all(steps <= 0), f"{layer} is not monotone"
        assert np.all(theta >= layer.theta_min) and np.all(theta <= layer.theta_max), layer
        assert np.all(np.diff(layer.s) > 0)
        assert 0 <= layer.first_record < layer.last_record
        assert isinstance(layer.junction_angle_rad, float)
    assert layers[0].first_record == 0
    for before, after in zip(layers, layers[1:]):
        assert after.first_record == before.last_record


def test_progress_fractions_do_not_decrease(demo):
    _, calls = demo
    fractions = [fraction for fraction, _ in calls]
    assert fractions == sorted(fractions)
    assert fractions[0] == 0.0 and fractions[-1] == 1.0
    assert all(isinstance(stage, str) and stage for _, stage in calls)


def test_write_program_writes_program_text(demo, tmp_path):
    outcome, _ = demo
    target = tmp_path / "demo_rescheduled.nc"
    outcome.write_program(target)
    assert target.read_bytes() == outcome.program_text.encode("utf-8", "surrogateescape")
    outcome.write_program(str(tmp_path / "as_str.nc"))
    assert (tmp_path / "as_str.nc").read_bytes() == target.read_bytes()


def test_write_outputs_writes_what_the_job_names(tmp_path):
    outcome = bladeaxis.run_job({"demo": True, "output_program": "out/demo.nc",
                                 "output_dir": "out/report"}, base_dir=tmp_path)
    assert not (tmp_path / "out").exists()  # run_job itself writes nothing
    outcome.write_outputs()
    assert (tmp_path / "out" / "demo.nc").read_text() == outcome.program_text
    report = json.loads((tmp_path / "out" / "report" / "report.json").read_text())
    assert without_timing(report) == without_timing(outcome.report)


def test_output_cl_is_written_as_documented(tmp_path):
    outcome = bladeaxis.run_job({"demo": True, "output_cl": "demo.cl"}, base_dir=tmp_path)
    outcome.write_outputs()
    assert "GOTO/" in (tmp_path / "demo.cl").read_text()


def test_an_unknown_key_is_refused_with_the_nearest_known_one():
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        bladeaxis.run_job({"demo": True, "output_programm": "x.nc"})
    assert raised.value.exit_code == 2 and raised.value.code == "InvalidArgument"
    assert 'did you mean "output_program"?' in str(raised.value)


def test_a_bytes_path_is_read_as_a_path(tmp_path):
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        bladeaxis.run_job({"program": os.fsencode(tmp_path / "no_such_blade.nc"),
                           "tool_radius_mm": 4})
    assert raised.value.exit_code == 3 and raised.value.code == "FileNotFound"


def test_a_path_that_is_not_utf8_is_refused_naming_its_key(tmp_path):
    name = pathlib.Path(os.fsdecode(os.fsencode(tmp_path) + b"/blade\xff.nc"))
    with pytest.raises(ValueError) as raised:
        bladeaxis.run_job({"program": name, "tool_radius_mm": 4})
    assert "job['program']" in str(raised.value) and "not UTF-8" in str(raised.value)


def test_missing_program_is_exit_code_3(tmp_path):
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        bladeaxis.run_job({"program": "no_such_blade.nc", "tool_radius_mm": 4}, base_dir=tmp_path)
    error = raised.value
    assert isinstance(error, Exception)
    assert error.exit_code == 3 and error.code == "FileNotFound"
    assert "no_such_blade.nc" in str(error)
    assert pathlib.Path(error.file) == tmp_path / "no_such_blade.nc"


def test_bad_value_is_exit_code_2():
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        bladeaxis.run_job({"demo": True, "tool_radius_mm": -1})
    assert raised.value.exit_code == 2 and raised.value.code == "InvalidArgument"
    assert "tool_radius_mm" in str(raised.value)


def test_not_a_blade_pass_is_exit_code_5_with_its_line():
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        bladeaxis.run_job({"program": NOT_A_BLADE_PROGRAM, "tool_radius_mm": 5})
    error = raised.value
    assert error.exit_code == 5 and error.code == "Geometry"
    assert error.file == str(NOT_A_BLADE_PROGRAM) and error.line > 0 and error.column is None
    assert str(error).startswith(f"{NOT_A_BLADE_PROGRAM}:{error.line}: ")


def test_analyse_only_has_no_program():
    outcome = bladeaxis.run_job({"demo": True, "analyse_only": True})
    assert outcome.rescheduled is False
    assert outcome.layers == []
    assert "rescheduled" not in outcome.report
    with pytest.raises(bladeaxis.BladeAxisError) as raised:
        outcome.program_text
    assert raised.value.exit_code == 2


def test_job_file_path(tmp_path):
    job = {"schema": "bladeaxis-job/1", "program": str(BLADE_PROGRAM),
           "tool_radius_mm": BLADE_TOOL_RADIUS_MM, "output_program": "blade_rescheduled.nc"}
    job_file = tmp_path / "blade.json"
    job_file.write_text(json.dumps(job))
    by_path = bladeaxis.run_job(job_file)
    by_str = bladeaxis.run_job(str(job_file))
    assert by_path.rescheduled and by_path.program_text == by_str.program_text
    assert by_path.report["tool_radius_mm"] == BLADE_TOOL_RADIUS_MM
    by_path.write_outputs()  # output_program is relative to the job file
    assert (tmp_path / "blade_rescheduled.nc").read_text() == by_path.program_text


def test_dict_paths_resolve_against_base_dir():
    job = {"program": pathlib.Path("programs") / BLADE_PROGRAM.name,
           "tool_radius_mm": BLADE_TOOL_RADIUS_MM}
    outcome = bladeaxis.run_job(job, base_dir=TEST_DATA)
    assert outcome.rescheduled
    assert "schema" not in job  # the caller's dict is not changed


def test_arguments_of_the_wrong_kind():
    with pytest.raises(TypeError):
        bladeaxis.run_job(42)
    with pytest.raises(TypeError):
        bladeaxis.run_job({"demo": True}, progress="not callable")
    with pytest.raises(ValueError):
        bladeaxis.run_job("job.json", base_dir=".")
    with pytest.raises(ValueError):
        bladeaxis.run_job({"demo": True, "feed_mm_min": float("nan")})


class Stop(Exception):
    pass


def test_exception_in_progress_cancels_and_propagates():
    calls = []

    def progress(fraction, stage):
        calls.append(fraction)
        if fraction >= 0.3:
            raise Stop(stage)

    with pytest.raises(Stop, match="analysing"):
        bladeaxis.run_job({"demo": True}, progress=progress)
    assert calls[-1] == 0.3  # never called again: the job was cancelled


# CL data that states its ball (CUTTER/16,8) run with another radius: one warning.
WARNING_JOB = {"program": TEST_DATA / "programs" / "turbine_2rev.cls", "tool_radius_mm": 5}


def test_warnings_are_reported_as_found():
    messages = []
    outcome = bladeaxis.run_job(WARNING_JOB, warning=messages.append)
    assert messages == outcome.warnings == outcome.report["warnings"]
    assert len(messages) == 1 and "replaces the file's 8 mm" in messages[0]


def test_exception_in_warning_propagates():
    def warning(message):
        raise Stop(message)

    with pytest.raises(Stop, match="replaces the file's 8 mm"):
        bladeaxis.run_job(WARNING_JOB, warning=warning)


def test_ctrl_c_stops_the_job():
    """A SIGINT that arrives while the engine runs is noticed at the next stage."""
    calls = []
    reading = threading.Event()

    def progress(fraction, stage):
        calls.append(fraction)
        if fraction > 0.0:
            reading.set()

    def interrupt():
        reading.wait()
        os.kill(os.getpid(), signal.SIGINT)

    # As in an interactive Python: a test runner started in the background by a shell inherits
    # SIGINT ignored, and Python then installs no handler of its own.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    sender = threading.Thread(target=interrupt)
    sender.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            bladeaxis.run_job({"demo": True}, progress=progress)
    finally:
        reading.set()
        sender.join()
        signal.signal(signal.SIGINT, previous)
    assert 1.0 not in calls


def python_snippets():
    """The ```python blocks of docs/python.md, each to be run as it stands."""
    return re.findall(r"```python\n(.*?)```", DOCS.read_text(), re.DOTALL)


@pytest.mark.parametrize("index", range(len(python_snippets())))
def test_documentation_snippets_run(index, tmp_path, monkeypatch, capsys):
    """Each block runs as a script in an empty folder. The post-processing hook gets a folder
    "posted" with a blade program and a program BladeAxis refuses, and the arguments the page
    shows (a ball radius of 8 mm)."""
    posted = tmp_path / "posted"
    posted.mkdir()
    blade, bracket = posted / "blade_7.nc", posted / "bracket.nc"
    shutil.copyfile(BLADE_PROGRAM, blade)
    shutil.copyfile(NOT_A_BLADE_PROGRAM, bracket)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(sys, "argv", ["reschedule_posted.py", "posted", "8"])
    snippet = python_snippets()[index]
    exec(compile(snippet, f"{DOCS.name} block {index}", "exec"), {"__name__": "__main__"})
    printed = capsys.readouterr().out
    if "def reschedule_folder" in snippet:
        assert "blade_7.nc: re-scheduled, A reversals " in printed
        assert blade.read_bytes() != BLADE_PROGRAM.read_bytes()
        assert (posted / "blade_7.nc.orig").read_bytes() == BLADE_PROGRAM.read_bytes()
        assert "bracket.nc: kept as posted, refused for the geometry" in printed
        assert bracket.read_bytes() == NOT_A_BLADE_PROGRAM.read_bytes()
        assert sorted(path.name for path in posted.iterdir()) == [
            "blade_7.nc", "blade_7.nc.orig", "bracket.nc"]
