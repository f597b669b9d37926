# Where Debian 12's MeshLab 2020.09 draws what gui_session.sh clicks (x y on the 1280x960
# Xvfb screen, its window at the top left). CUT_LAYER_NAME: the sphere_cut row of the layer
# dialog; EXPORT_TARGET_POSITION: the TargetPosition box of the PLY save options. VIEW_BOX:
# the 3D view (x0 y0 x1 y1) the tests measure the cut layer's drawing in.
FILTERS_MENU="120 10"
SUBMENU_APPROACH="270 160"
SUBMENU="274 162"
ENTRY_APPROACH="420 238"
ENTRY="420 238"
GRID_FIELD="350 435"
STEPS_FIELD="350 466"
# The clicks below the dialog's rows (APPLY, CLOSE) were measured with this many filter
# parameters (rows); meshlab_host.check_dialog_rows fails the session when the table has another.
DIALOG_ROWS=13
APPLY="423 788"
CLOSE="145 788"
HIDE_EYES=("471 114" "471 145" "471 207")
CUT_LAYER_NAME="549 176"
EXPORT_TARGET_POSITION="38 308"
VIEW_BOX="0 70 430 585"
