#!/usr/bin/env bash
# One MeshLab GUI session for the GUI tests (tests/meshlab/test_meshlab.py: Debian 12's
# MeshLab 2020.09; tests/meshlab-roots/: MeshLab 2022.02 and 2025.07 inside Debian roots),
# run inside xvfb-run (screen 1280x960x24, no window manager: MeshLab's window sits at the
# top left). Usage: gui_session.sh SAMPLES SHOTS OUTDIR XDOTOOL(0|1) [LAYOUT]
#   SAMPLES  the samples folder as MeshLab sees it
#   LAYOUT   where that MeshLab version draws what is clicked (gui_layout_<version>.sh beside
#            this script; default 2020.09)
# Environment: MESHLAB (the command that starts MeshLab; default meshlab), GRID and STEPS
# (the filter's grid_resolution and steps; default 24 and 8), EXPORT (a .ply path as MeshLab
# sees it: the cut layer is saved there from File > Export Mesh As, with its TargetPosition).
# Opens torus.ply and sphere.ply (sphere is the current layer, so the source; the torus the
# default target); prints PLUGIN_LOADED when a libfilter_eulermap*.so is mapped into the
# meshlab process. With XDOTOOL=1 it opens Filters > Remeshing, Simplification and
# Reconstruction > Eulerian Surface Map, sets the grid and the steps, applies, closes the
# dialog, hides every layer but sphere_cut (eye icons of the layer dialog) for the screenshot
# meshlab_6_cut_only.png (the cut sphere with the torus's checker, if the GUI loaded the new
# layer's texture), with EXPORT saves the cut layer, and prints ALIVE_AFTER_FILTER if meshlab
# still runs. Screenshots: SHOTS/meshlab_*.png. MeshLab's output (its log included):
# OUTDIR/meshlab.out.
set -u
samples=$1 shots=$2 outdir=$3 drive=$4
layout=${5:-2020.09}
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=gui_layout_2020.09.sh
. "$here/gui_layout_$layout.sh"
shot() { import -window root "$shots/meshlab_$1.png"; }

${MESHLAB:-meshlab} "$samples/torus.ply" "$samples/sphere.ply" > "$outdir/meshlab.out" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null' EXIT
for _ in $(seq 90); do
  grep -q libfilter_eulermap "/proc/$pid/maps" 2>/dev/null && { echo PLUGIN_LOADED; break; }
  kill -0 $pid 2>/dev/null || { echo "meshlab exited early"; exit 1; }
  sleep 1
done
sleep 6   # let the window show its layers
shot 1_started
[ "$drive" = 1 ] || exit 0

click() { xdotool mousemove $1; sleep 0.3; xdotool click 1; sleep "${2:-1}"; }
field() { xdotool mousemove $1 click --repeat 3 1; sleep 0.3; xdotool key ctrl+a; xdotool type --delay 50 "$2"; }
click "$FILTERS_MENU"                   # Filters
xdotool mousemove $SUBMENU_APPROACH; sleep 0.3
click "$SUBMENU" 1.5                    # Remeshing, Simplification and Reconstruction
xdotool mousemove $ENTRY_APPROACH; sleep 0.3
xdotool mousemove $ENTRY; sleep 0.7
shot 2_filters_menu                     # the entry, highlighted
click "$ENTRY" 2                        # Eulerian Surface Map: its dialog
field "$GRID_FIELD" "${GRID:-24}"
field "$STEPS_FIELD" "${STEPS:-8}"
sleep 0.5
shot 3_parameters
click "$APPLY" 0
for _ in $(seq 120); do
  grep -q "Applied filter:\? Eulerian Surface Map\|Filter failed\|Eulerian Surface Map failed" "$outdir/meshlab.out" && break
  kill -0 $pid 2>/dev/null || break
  sleep 1
done
sleep 3
shot 4_applied
click "$CLOSE" 3                        # Close the dialog: the view shows the new layers
shot 5_result
for eye in "${HIDE_EYES[@]}"; do click "$eye" 0.7; done   # hide torus, sphere, sphere_mapped
shot 6_cut_only
if [ -n "${EXPORT:-}" ]; then           # File > Export Mesh As, the cut layer current
  click "$CUT_LAYER_NAME" 1
  xdotool key ctrl+shift+e; sleep 2
  xdotool type --delay 20 "$EXPORT"; xdotool key Return; sleep 2
  click "$EXPORT_TARGET_POSITION" 0.5   # the custom attribute TargetPosition: the images
  shot 7_export_options
  xdotool key Return; sleep 3
fi
kill -0 $pid 2>/dev/null && echo ALIVE_AFTER_FILTER
exit 0
