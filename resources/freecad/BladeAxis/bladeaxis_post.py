"""BladeAxis post-processor for FreeCAD's Path workbench (FreeCAD 0.20).

An existing FreeCAD post (linuxcnc unless --post names another) writes the program; BladeAxis then
re-schedules the tool orientation of its helical four-axis pass. The program FreeCAD asked for is
replaced by the re-scheduled one only when BladeAxis succeeds: the post's own output is kept
beside it as NAME.original.EXT, and the report (report.json, axes.csv, layers.csv, summary.txt)
goes into the folder NAME.bladeaxis beside it. When BladeAxis refuses the program nothing is
left at NAME (no partial and no stale program; NAME.original.EXT is the post's program the
message's file and line refer to), and the error, with BladeAxis's code, file and line, is
printed to the report view and raised.

Install: see "FreeCAD" in /usr/share/doc/bladeaxis/cam-integration.md (docs/cam-integration.md).
"""
import argparse
import os
import shlex
import shutil
import tempfile

import FreeCAD

TOOLTIP = """
BladeAxis: writes the program with another FreeCAD post (linuxcnc by default) and re-schedules
the tool orientation of its four-axis helical blade pass so that the A axis turns one way.
The ball radius comes from the job's ball end mill, or from --tool-radius.
The post's own program is kept as NAME.original.EXT, the report in the folder NAME.bladeaxis.
"""

# Where the summary command (InitGui.py, BladeAxis_Summary.FCMacro) finds the last job.
PARAMETERS = "User parameter:BaseApp/Preferences/Mod/BladeAxis"

parser = argparse.ArgumentParser(prog="bladeaxis", add_help=False, allow_abbrev=False)
parser.add_argument("--post", default="linuxcnc",
                    help="the FreeCAD post that writes the program, default linuxcnc; every "
                         "argument BladeAxis does not know is passed on to it")
parser.add_argument("--tool-radius", type=float, metavar="MM",
                    help="ball radius R in mm; default: half the diameter of the job's ball end "
                         "mill")
parser.add_argument("--machine", metavar="FILE",
                    help="BladeAxis machine file, e.g. /usr/share/bladeaxis/machines/"
                         "blade_ab.json; default: the built-in blade machine")
parser.add_argument("--preset", choices=("best", "faithful"),
                    help="BladeAxis scheduling rules, default best")
parser.add_argument("--compare", action="store_true",
                    help="also compare every method and write report.html (slower)")

TOOLTIP_ARGS = parser.format_help()


class BladeAxisPostError(RuntimeError):
    """Raised when the program cannot be posted or re-scheduled; FreeCAD shows it in the
    report view and the Path job keeps its last output date, so a refused program is never
    mistaken for a posted one. exit_code, code, file and line are BladeAxis's when it refused."""

    def __init__(self, message, exit_code=None, code=None, file=None, line=None):
        super().__init__(message)
        self.exit_code = exit_code
        self.code = code
        self.file = file
        self.line = line


def export(objectslist, filename, argstring):
    """FreeCAD's post-processor entry point: writes filename ("-": nothing) and returns the
    re-scheduled program's text."""
    options, passed_on = parse_arguments(argstring)
    try:
        return post_and_reschedule(objectslist, filename, options, passed_on)
    except BladeAxisPostError as error:
        FreeCAD.Console.PrintError(f"BladeAxis post: {error}\n")
        raise


def parse_arguments(argstring):
    """Splits the job's post arguments into BladeAxis's own and those of the delegate post, so
    one argument line in the job configures both."""
    try:
        options, passed_on = parser.parse_known_args(shlex.split(argstring or ""))
    except (SystemExit, ValueError) as error:  # argparse exits on a bad value
        raise BladeAxisPostError(f"bad post arguments {argstring!r}: {error}", exit_code=2,
                                 code="InvalidArgument") from None
    if options.post == "bladeaxis":
        raise BladeAxisPostError("--post=bladeaxis would call itself; name the post that "
                                 "writes the program, such as --post=linuxcnc", exit_code=2,
                                 code="InvalidArgument")
    return options, passed_on


def post_and_reschedule(objectslist, filename, options, passed_on):
    """The delegate's program goes to NAME.original.EXT, the name the messages and the report
    use; the re-scheduled program and the report are written into a private folder beside it
    and moved into place only when BladeAxis succeeded, so FreeCAD's file is either the whole
    re-scheduled program or absent."""
    import bladeaxis  # here, so that FreeCAD can list this post where the module is missing

    target = None if filename == "-" else os.path.abspath(filename)
    work = tempfile.mkdtemp(prefix=".bladeaxis-", dir=os.path.dirname(target) if target else None)
    try:
        posted = os.path.join(work, os.path.basename(target) if target else "program.nc")
        write_with_delegate(objectslist, posted, options.post, passed_on)
        if target is not None:
            original, report = companions(target)
            os.replace(posted, original)
            posted = original
        job = job_for(posted, options, ball_radius_of(objectslist, options.tool_radius))
        try:
            outcome = bladeaxis.run_job(job, base_dir=work,
                                        warning=lambda message: FreeCAD.Console.PrintWarning(
                                            f"BladeAxis: {message}\n"))
            if target is None:
                return outcome.program_text
            rescheduled = os.path.join(work, "rescheduled")
            outcome.write_program(rescheduled)
            outcome.write_outputs()
        except bladeaxis.BladeAxisError as error:
            remove_stale(target)
            raise BladeAxisPostError(describe(error, target), error.exit_code, error.code,
                                     error.file, error.line) from None
        with open(os.path.join(work, "report", "summary.txt"), "w", encoding="utf-8") as out:
            out.write(outcome.summary)
        if os.path.isdir(report):
            shutil.rmtree(report)
        os.replace(os.path.join(work, "report"), report)
        os.replace(rescheduled, target)
        remember(target, original, report)
        FreeCAD.Console.PrintMessage(f"BladeAxis: re-scheduled {target}\n{outcome.summary}\n")
        with open(target, encoding="utf-8", errors="surrogateescape") as program:
            return program.read()
    finally:
        shutil.rmtree(work, ignore_errors=True)


def write_with_delegate(objectslist, path, post, passed_on):
    """Lets FreeCAD's own post write the program, loaded the way FreeCAD loads posts (fresh,
    from the post search path), so it behaves exactly as when the job names it directly."""
    from PathScripts.PathPostProcessor import PostProcessor

    if not PostProcessor.exists(post):
        raise BladeAxisPostError(f"no FreeCAD post named {post!r} (--post); FreeCAD has "
                                 f"{', '.join(available_posts())}", exit_code=2,
                                 code="InvalidArgument")
    gcode = PostProcessor.load(post).export(objectslist, path, shlex.join(passed_on))
    if gcode is None or not os.path.isfile(path):
        raise BladeAxisPostError(f"the FreeCAD post {post!r} wrote no program (its arguments "
                                 f"{shlex.join(passed_on)!r}, or the objects, were refused; "
                                 f"see its message above)", exit_code=2, code="InvalidArgument")


def available_posts():
    """The post names FreeCAD offers, for the message about a misspelt --post."""
    from PathScripts import PathPreferences

    return [name for name in PathPreferences.allAvailablePostProcessors() if name != "bladeaxis"]


def ball_radius_of(objectslist, radius_option):
    """The ball radius: --tool-radius if given, else half the diameter of the ball end mill the
    posted operations use. None when neither says (BladeAxis then reads it from the program or
    refuses with its own message); several different ball end mills are refused, since one
    program is re-scheduled for one ball."""
    if radius_option is not None:
        return radius_option
    radii = {radius for radius in map(ball_radius_of_controller, tool_controllers(objectslist))
             if radius is not None}
    if len(radii) > 1:
        raise BladeAxisPostError(
            f"the posted operations use ball end mills of radii {sorted(radii)} mm; BladeAxis "
            f"re-schedules one ball per program: post them separately or give --tool-radius",
            exit_code=2, code="InvalidArgument")
    return radii.pop() if radii else None


def tool_controllers(objectslist):
    """The tool controllers of the posted objects: FreeCAD's post list holds them, and each
    operation names its own."""
    found = []
    for obj in objectslist:
        for candidate in (obj, getattr(obj, "ToolController", None)):
            if candidate is not None and hasattr(candidate, "Tool") and candidate not in found:
                found.append(candidate)
    return found


def ball_radius_of_controller(controller):
    """Half the diameter of a ball end tool (a tool bit with the ballend shape, or a legacy
    tool of type BallEndMill), in mm; None for any other tool."""
    tool = controller.Tool
    shape = os.path.basename(str(getattr(tool, "BitShape", ""))).lower()
    is_ball = (getattr(tool, "ShapeName", "") == "ballend" or shape.startswith("ballend")
               or getattr(tool, "ToolType", "") == "BallEndMill")
    if not is_ball:
        return None
    diameter = tool.Diameter
    return float(getattr(diameter, "Value", diameter)) / 2.0


def job_for(program, options, radius):
    """The BladeAxis job (docs/job-file.md) for the posted program; outputs relative to the
    private folder it runs in."""
    job = {"program": program, "output_dir": "report"}
    if radius is not None:
        job["tool_radius_mm"] = radius
    if options.machine:
        job["machine"] = os.path.abspath(os.path.expanduser(options.machine))
    if options.preset:
        job["preset"] = options.preset
    if options.compare:
        job["compare"] = True
    return job


def describe(error, target):
    """The message for the report view: BladeAxis's own (with file:line), its code and exit
    code, and what was left on disk."""
    where = f"{error.file}:{error.line}" if error.file and error.line else error.file or "-"
    left = ""
    if target:
        left = (f"; nothing written to {target}, the program as the post wrote it is "
                f"{companions(target)[0]}")
    return (f"BladeAxis refused the program (exit code {error.exit_code}, {error.code}, at "
            f"{where}): {error}{left}")


def remove_stale(target):
    """Removes the program and report an earlier run left for this target, so a refused job
    never leaves an older program to be sent to the machine, nor a report that is not its own."""
    if target is None:
        return
    if os.path.isfile(target):
        os.remove(target)
    report = companions(target)[1]
    if os.path.isdir(report):
        shutil.rmtree(report)


def companions(target):
    """The original program and the report folder that go with a re-scheduled program."""
    stem, extension = os.path.splitext(target)
    return f"{stem}.original{extension}", f"{stem}.bladeaxis"


def remember(target, original, report):
    """Records the last job for the summary command, in FreeCAD's user parameters."""
    parameters = FreeCAD.ParamGet(PARAMETERS)
    parameters.SetString("LastProgram", target)
    parameters.SetString("LastOriginal", original)
    parameters.SetString("LastReportDir", report)
