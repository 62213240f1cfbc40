"""The BladeAxis summary of the last re-scheduled program, for FreeCAD.

The post (bladeaxis_post.py) records where its last report went; this module reads that report
and builds the text the command BladeAxis_Summary shows. The text is built without the GUI
(summary_text), so it is the same in a headless FreeCAD, where the test checks it, and in the
window, where show_last_summary adds the dialog and opens the report.
"""
import json
import os

import FreeCAD

PARAMETERS = "User parameter:BaseApp/Preferences/Mod/BladeAxis"


class NoReport(LookupError):
    """There is no report to show: nothing was re-scheduled yet, or its folder was removed."""


def last_report_dir():
    """The report folder of the last program the BladeAxis post re-scheduled."""
    folder = FreeCAD.ParamGet(PARAMETERS).GetString("LastReportDir", "")
    if not folder:
        raise NoReport("No program has been re-scheduled with the BladeAxis post yet: choose "
                       "the post 'bladeaxis' in the Path job's Output settings and post the job.")
    if not os.path.isfile(os.path.join(folder, "report.json")):
        raise NoReport(f"The report of the last re-scheduled program is gone: {folder}")
    return folder


def report_file(folder):
    """The file to open for a person: report.html when the job wrote one (with --compare),
    else report.json."""
    html = os.path.join(folder, "report.html")
    return html if os.path.isfile(html) else os.path.join(folder, "report.json")


def summary_text(folder):
    """A short before/after summary from report.json, the figures a CAM engineer checks first:
    A reversals, peak A velocity, layers that kept their orientation, and every warning."""
    with open(os.path.join(folder, "report.json"), encoding="utf-8") as stream:
        report = json.load(stream)
    before = report["original"]
    lines = [f"Program: {report['input'].get('file', '?')}",
             f"Machine: {report['machine'].get('name', '?')}"]
    if "tool_radius_mm" in report:
        lines.append(f"Ball radius: {report['tool_radius_mm']:g} mm")
    rescheduled = report.get("rescheduled")
    if rescheduled is None:
        lines.append(f"Analysed only: A reversals {before['a_reversals']}")
    else:
        after = rescheduled["analysis"]
        lines += [
            f"A reversals: {before['a_reversals']} -> {after['a_reversals']}",
            "Peak A velocity: "
            f"{peak(before, 'peak_velocity_deg_s')} -> {peak(after, 'peak_velocity_deg_s')} deg/s",
            "Peak A acceleration: "
            f"{peak(before, 'peak_acceleration_deg_s2')} -> "
            f"{peak(after, 'peak_acceleration_deg_s2')} deg/s²",
            f"Layers that kept their original orientation: "
            f"{rescheduled['checks']['layers_kept_original']} of {len(rescheduled['layers'])}",
        ]
    lines += [f"Warning: {warning}" for warning in report["warnings"]]
    summary = os.path.join(folder, "summary.txt")
    if os.path.isfile(summary):
        lines.append(f"Full summary: {summary}")
    lines.append(f"Report: {report_file(folder)}")
    return "\n".join(lines)


def peak(analysis, key):
    """A peak figure of the A axis (report.json's key), rounded for reading."""
    return f"{analysis['axes']['A'][key]:.4g}"


def show_last_summary():
    """The GUI command: the summary in a dialog whose Open report button opens the report with
    the desktop's viewer; a missing report is said in the dialog, not raised."""
    from PySide import QtCore, QtGui

    window = FreeCADGui_main_window()
    try:
        folder = last_report_dir()
    except NoReport as missing:
        QtGui.QMessageBox.information(window, "BladeAxis", str(missing))
        return
    box = QtGui.QMessageBox(window)
    box.setWindowTitle("BladeAxis: last re-scheduled program")
    box.setText(summary_text(folder))
    open_button = box.addButton("Open report", QtGui.QMessageBox.ActionRole)
    box.addButton(QtGui.QMessageBox.Close)
    box.exec_()
    if box.clickedButton() is open_button:
        url = QtCore.QUrl.fromLocalFile(report_file(folder))
        if not QtGui.QDesktopServices.openUrl(url):
            FreeCAD.Console.PrintError(f"BladeAxis: no program opens {url.toLocalFile()}\n")


def FreeCADGui_main_window():
    """FreeCAD's main window as the dialogs' parent (None when there is none)."""
    import FreeCADGui

    return FreeCADGui.getMainWindow()
