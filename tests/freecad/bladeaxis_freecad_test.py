"""The BladeAxis post and summary (resources/freecad/BladeAxis) inside a headless FreeCAD 0.20.

Run by run_freecad_test.py as `freecadcmd bladeaxis_freecad_test.py` with PYTHONPATH on the
built bladeaxis module and the add-on folder, BLADEAXIS_EXE the built bladeaxis (it generates
the blade program) and HOME a scratch folder. A Path job is built here the way a user builds one:
a ball end mill tool controller and a Custom operation whose G-code is a helical four-axis blade
pass with A words; it is posted through FreeCAD's own Post Process code with the post
'bladeaxis', found on FreeCAD's post search path.

freecadcmd exits 0 even when a script raises, so the outcome is the exit status set here and
the line BLADEAXIS-FREECAD-TEST: PASS, which the driver requires.
"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import traceback
import unittest

import FreeCAD
from PathScripts import PathCustom, PathJob, PathPreferences, PathToolBit, PathToolController

PLUGIN_DIR = os.environ["BLADEAXIS_FREECAD_PLUGIN"]
BALL_BIT = os.path.join(FreeCAD.getHomePath(), "Mod", "Path", "Tools", "Bit", "6mm_Ball_End.fctb")
ARGUMENTS = "--post=linuxcnc --no-show-editor --precision=4"


def generated_blade_program(folder):
    """A helical four-axis blade pass (B fixed, A reversing twice a revolution) from
    bladeaxis --generate, with a 3 mm ball like the 6 mm ball end mill of the job."""
    path = os.path.join(folder, "generated.nc")
    subprocess.run([os.environ["BLADEAXIS_EXE"], "--batch", "--generate", path,
                    "--tool-radius", "3", "--revolutions", "4", "-q"], check=True)
    with open(path, encoding="utf-8") as program:
        return program.read()


def path_gcode(program):
    """The program's motion blocks as FreeCAD Path G-code: no comments, block numbers or M
    codes, and F in mm/s, the unit of FreeCAD's Path commands (the post writes mm/min)."""
    lines, motion = [], None
    for block in program.splitlines():
        words = re.findall(r"([A-Z])(-?[0-9.]+)", re.sub(r"\(.*?\)", "", block.upper()))
        motion = next((f"G{int(float(v))}" for k, v in words
                       if k == "G" and float(v) in (0, 1)), motion)
        axes = [(k, float(v)) for k, v in words if k in "XYZABF"]
        if motion and any(k in "XYZAB" for k, _ in axes):
            lines.append(" ".join([motion] + [f"{k}{v / 60 if k == 'F' else v:g}"
                                              for k, v in axes]))
    return lines


def a_words(text):
    """The A values of a posted program, in order."""
    return [float(value) for value in re.findall(r"\bA(-?[0-9.]+)", text)]


def reversals(values):
    """Direction changes of a sequence, as BladeAxis counts A reversals (zero steps skipped)."""
    signs = [1 if b > a else -1 for a, b in zip(values, values[1:]) if b != a]
    return sum(1 for s, t in zip(signs, signs[1:]) if s != t)


def make_job(doc, name, ball, gcode, output):
    """A Path job on a box with one tool controller (a ball end mill when ball, else FreeCAD's
    default flat end mill) and a Custom operation carrying gcode, posted with bladeaxis."""
    box = doc.addObject("Part::Box", f"{name}Model")
    doc.recompute()
    job = PathJob.Create(name, [box])
    if ball:
        default = job.Tools.Group[0]
        bit = PathToolBit.Factory.CreateFrom(BALL_BIT, f"{name}Ball")
        controller = PathToolController.Create(f"{name}TC", bit, 2)
        job.Proxy.addToolController(controller)
        job.Tools.removeObject(default)
        doc.removeObject(default.Tool.Name)
        doc.removeObject(default.Name)
    operation = PathCustom.Create(f"{name}Blade", parentJob=job)
    operation.Gcode = gcode
    job.PostProcessor = "bladeaxis"
    job.PostProcessorArgs = ARGUMENTS
    job.PostProcessorOutputFile = output
    doc.recompute()
    return job


def post(job):
    """Posts the job with FreeCAD's own Post Process code (what Path > Post Process runs);
    returns the G-code of the last file."""
    from PathScripts import PathPost

    command = PathPost.CommandPathPost()
    gcode = None
    for objects in command.buildPostList(job):
        failed, gcode, _ = command.exportObjectsWith(objects, job)
        assert not failed, "FreeCAD did not find the post or the file name"
    return gcode


class BladeAxisFreeCADPost(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix="bladeaxis-freecad-")
        # The add-on folder as the user's macro folder, one of the places FreeCAD 0.20 searches
        # for posts (docs/cam-integration.md, "FreeCAD"), so the job can name the post.
        FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Macro").SetString(
            "MacroPath", PLUGIN_DIR)
        cls.gcode = path_gcode(generated_blade_program(cls.folder))
        cls.doc = FreeCAD.newDocument("BladeAxisTest")

    def test_the_post_is_listed_by_freecad(self):
        self.assertIn("bladeaxis", PathPreferences.allAvailablePostProcessors())

    def test_a_ball_end_job_is_rescheduled_and_its_original_kept(self):
        output = os.path.join(self.folder, "blade.ngc")
        text = post(make_job(self.doc, "Ball", True, self.gcode, output))

        original = os.path.join(self.folder, "blade.original.ngc")
        report_dir = os.path.join(self.folder, "blade.bladeaxis")
        with open(output, encoding="utf-8") as program:
            rescheduled = program.read()
        with open(original, encoding="utf-8") as program:
            posted = program.read()
        self.assertEqual(text, rescheduled)
        self.assertIn("(Post Processor: linuxcnc_post)", posted)
        self.assertRegex(posted, r"G1 X-?\d+\.\d{4} ", "--precision=4 reached linuxcnc")
        before, after = a_words(posted), a_words(rescheduled)
        self.assertGreater(len(after), 500)
        self.assertEqual(len(before), len(after))
        self.assertGreater(reversals(before), 0, "the input must reverse A to test anything")
        self.assertEqual(reversals(after), 0, "A still reverses after re-scheduling")

        with open(os.path.join(report_dir, "report.json"), encoding="utf-8") as stream:
            report = json.load(stream)
        self.assertEqual(report["tool_radius_mm"], 3)
        self.assertLessEqual(report["rescheduled"]["analysis"]["a_reversals"],
                             report["original"]["a_reversals"])
        for name in ("axes.csv", "layers.csv", "summary.txt"):
            self.assertTrue(os.path.isfile(os.path.join(report_dir, name)), name)
        self.assertEqual(glob.glob(os.path.join(self.folder, ".bladeaxis-*")), [])

        import bladeaxis_summary

        self.assertEqual(bladeaxis_summary.last_report_dir(), report_dir)
        summary = bladeaxis_summary.summary_text(report_dir)
        self.assertIn(f"A reversals: {report['original']['a_reversals']} -> 0", summary)
        self.assertIn("Ball radius: 3 mm", summary)
        self.assertTrue(bladeaxis_summary.report_file(report_dir).endswith("report.json"))

    def test_a_job_without_a_ball_end_mill_fails_and_leaves_nothing(self):
        output = os.path.join(self.folder, "flat.ngc")
        with open(output, "w", encoding="utf-8") as stale:
            stale.write("(a program of an earlier run)\n")
        os.mkdir(os.path.join(self.folder, "flat.bladeaxis"))  # its report
        job = make_job(self.doc, "Flat", False, self.gcode, output)
        with self.assertRaises(RuntimeError) as raised:
            post(job)
        error = raised.exception
        self.assertEqual(type(error).__name__, "BladeAxisPostError")
        self.assertEqual((error.exit_code, error.code), (2, "InvalidArgument"))
        self.assertIn("radius", str(error))
        self.assertIn("exit code 2, InvalidArgument", str(error))
        self.assertFalse(os.path.exists(output), "a stale program was left")
        original = os.path.join(self.folder, "flat.original.ngc")
        self.assertEqual(error.file, original, "the message names the post's program")
        self.assertIn(f"{original}: invalid argument", str(error))
        with open(original, encoding="utf-8") as posted:
            self.assertIn("M2", posted.read(), "the post's program is whole")
        self.assertFalse(os.path.exists(os.path.join(self.folder, "flat.bladeaxis")))
        self.assertEqual(glob.glob(os.path.join(self.folder, ".bladeaxis-*")), [])

    def test_an_unknown_delegate_post_is_named(self):
        job = make_job(self.doc, "Typo", True, self.gcode, os.path.join(self.folder, "t.ngc"))
        job.PostProcessorArgs = "--post=linuxcnx"
        with self.assertRaises(RuntimeError) as raised:
            post(job)
        self.assertIn("no FreeCAD post named 'linuxcnx'", str(raised.exception))
        self.assertIn("linuxcnc", str(raised.exception))
        self.assertFalse(os.path.exists(os.path.join(self.folder, "t.ngc")))

    def test_the_summary_without_a_report_says_so(self):
        import bladeaxis_summary

        parameters = FreeCAD.ParamGet(bladeaxis_summary.PARAMETERS)
        kept = parameters.GetString("LastReportDir", "")
        parameters.SetString("LastReportDir", os.path.join(self.folder, "gone.bladeaxis"))
        try:
            with self.assertRaisesRegex(bladeaxis_summary.NoReport, "gone"):
                bladeaxis_summary.last_report_dir()
        finally:
            parameters.SetString("LastReportDir", kept)


def main():
    """Runs the tests and exits with their outcome (freecadcmd itself would exit 0)."""
    try:
        suite = unittest.defaultTestLoader.loadTestsFromTestCase(BladeAxisFreeCADPost)
        result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
        passed = result.wasSuccessful()
    except BaseException:
        traceback.print_exc()
        passed = False
    print(f"BLADEAXIS-FREECAD-TEST: {'PASS' if passed else 'FAIL'}", flush=True)
    sys.stdout.flush()
    os._exit(0 if passed else 1)


main()
