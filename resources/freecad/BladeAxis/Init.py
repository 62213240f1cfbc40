# BladeAxis add-on for FreeCAD 0.20. Nothing to set up without the window: the post
# (bladeaxis_post.py) and the summary (bladeaxis_summary.py) import from this folder, which
# FreeCAD puts on sys.path.
