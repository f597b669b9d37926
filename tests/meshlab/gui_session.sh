#!/usr/bin/env bash
# One MeshLab GUI session for tests/meshlab/test_meshlab.py, run inside xvfb-run (screen
# 1280x960x24, no window manager: MeshLab's window sits at the top left).
# Usage: gui_session.sh SAMPLES SHOTS OUTDIR XDOTOOL(0|1)
# Opens torus.ply and sphere.ply (sphere is the current layer, so the source; the torus the
# default target); prints PLUGIN_LOADED when libfilter_eulermap.so is mapped into the
# meshlab process. With XDOTOOL=1 it opens Filters > Remeshing, Simplification and
# Reconstruction > Eulerian Surface Map, sets the grid to 24 and the steps to 8, applies,
# closes the dialog, hides every layer but sphere_cut (eye icons of the layer dialog) for
# the screenshot meshlab_6_cut_only.png (the cut sphere with the torus's checker, if the
# GUI loaded the new layer's texture), and prints ALIVE_AFTER_FILTER if meshlab still runs. Screenshots: SHOTS/meshlab_*.png. MeshLab's
# output (its log included): OUTDIR/meshlab.out.
set -u
samples=$1 shots=$2 outdir=$3 drive=$4
shot() { import -window root "$shots/meshlab_$1.png"; }

meshlab "$samples/torus.ply" "$samples/sphere.ply" > "$outdir/meshlab.out" 2>&1 &
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

click() { xdotool mousemove "$1" "$2"; sleep 0.3; xdotool click 1; sleep "${3:-1}"; }
click 120 10                       # Filters
xdotool mousemove 270 160; sleep 0.3
click 274 162 1.5                  # Remeshing, Simplification and Reconstruction
xdotool mousemove 420 238; sleep 0.7
shot 2_filters_menu                # the entry, highlighted
click 420 238 2                    # Eulerian Surface Map: its dialog
xdotool mousemove 350 435 click --repeat 3 1; sleep 0.3; xdotool key ctrl+a; xdotool type --delay 50 24
xdotool mousemove 350 466 click --repeat 3 1; sleep 0.3; xdotool key ctrl+a; xdotool type --delay 50 8
sleep 0.5
shot 3_parameters
click 423 788 0                    # Apply
for _ in $(seq 300); do
  grep -q "Applied filter Eulerian Surface Map\|Filter failed" "$outdir/meshlab.out" && break
  kill -0 $pid 2>/dev/null || break
  sleep 1
done
sleep 3
shot 4_applied
click 145 788 3                    # Close the dialog: the view shows the new layers
shot 5_result
for y in 114 145 207; do click 471 $y 0.7; done   # hide torus, sphere, sphere_mapped
shot 6_cut_only
kill -0 $pid 2>/dev/null && echo ALIVE_AFTER_FILTER
exit 0
