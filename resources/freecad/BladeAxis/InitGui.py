# BladeAxis add-on for FreeCAD 0.20: the command BladeAxis_Summary, shown in the Path workbench.
# FreeCAD runs this file when its window starts; the folder is on sys.path, so the modules beside
# it import by name (FreeCAD 0.20 does not set __file__ here).


class BladeAxisSummaryCommand:
    """Shows the summary of the last program the BladeAxis post re-scheduled and opens its
    report: the figures are in a file beside the program, which a CAM engineer would otherwise
    have to find by hand."""

    def GetResources(self):
        return {
            "MenuText": "BladeAxis summary",
            "ToolTip": "Show the summary of the last program re-scheduled by the BladeAxis post "
                       "and open its report",
        }

    def IsActive(self):
        return True

    def Activated(self):
        import bladeaxis_summary

        bladeaxis_summary.show_last_summary()


def _bladeaxis_add_to_path_workbench(name):
    """Puts the command on a toolbar and in a menu of the Path workbench when it is activated:
    FreeCAD 0.20 has no other way for an add-on to extend another workbench."""
    if name != "PathWorkbench":
        return
    workbench = FreeCADGui.getWorkbench("PathWorkbench")
    if "BladeAxis" in workbench.listToolbars():
        return
    workbench.appendToolbar("BladeAxis", ["BladeAxis_Summary"])
    workbench.appendMenu("BladeAxis", ["BladeAxis_Summary"])
    workbench.reloadActive()


FreeCADGui.addCommand("BladeAxis_Summary", BladeAxisSummaryCommand())
FreeCADGui.getMainWindow().workbenchActivated.connect(_bladeaxis_add_to_path_workbench)
