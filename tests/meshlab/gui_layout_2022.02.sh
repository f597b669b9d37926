# Where MeshLab 2022.02 (Debian 13's meshlab 2022.02+dfsg1-1 in the trixie root, with the
# plugins of its Recommends) draws what gui_session.sh clicks: x y on the 1280x960 Xvfb
# screen, its window at the top left. CUT_LAYER_NAME: the sphere_cut row of the layer
# dialog; EXPORT_TARGET_POSITION: the TargetPosition box of the PLY save options. VIEW_BOX:
# the 3D view (x0 y0 x1 y1) the tests measure the cut layer's drawing in.
FILTERS_MENU="116 10"
SUBMENU_APPROACH="200 148"
SUBMENU="262 148"
ENTRY_APPROACH="420 148"
ENTRY="483 172"
GRID_FIELD="509 363"
STEPS_FIELD="509 392"
# The clicks below the dialog's rows (APPLY, CLOSE) were measured with this many filter
# parameters (rows); meshlab_host.check_dialog_rows fails the session when the table has another.
DIALOG_ROWS=13
APPLY="551 724"
CLOSE="300 724"
HIDE_EYES=("490 111" "490 142" "490 205")
CUT_LAYER_NAME="565 173"
EXPORT_TARGET_POSITION="426 404"
VIEW_BOX="10 75 440 575"
