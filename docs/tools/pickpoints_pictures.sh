#!/usr/bin/env bash
# The README's pictures of picking named anchors in MeshLab 2020.09 (Debian 12's meshlab)
# under Xvfb, driven by xdotool:
#   docs/pictures/pickpoints_spot.png          Edit > PickPoints on spot.ply, whose 6 named
#                                              anchors (spot.pp, as spot_picked_points.pp
#                                              beside it) the editor loads by itself
#   docs/pictures/pickpoints_cow_template.png  the same editor on cow.off with no points yet:
#                                              the default template (samples/animal.pptpl as
#                                              ~/.pickPointsTemplate.pptpl) lists the same names
# Usage: docs/tools/pickpoints_pictures.sh [OUTDIR]   (default docs/pictures)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/docs/pictures}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home" "$work/spot" "$work/cow" "$out"
cp "$root/samples/animal.pptpl" "$work/home/.pickPointsTemplate.pptpl"
cp "$root/samples/spot.ply" "$root/samples/spot_checker.png" "$work/spot/"
cp "$root/samples/spot.pp" "$work/spot/spot_picked_points.pp"
cp "$root/samples/cow.off" "$work/cow/"

session() {  # session DIR MESH PICTURE: MeshLab on MESH, turned 90 degrees, then Edit > PickPoints
  xvfb-run -a -s "-screen 0 1280x960x24" bash -c '
    cd "$1"
    HOME="$4" meshlab "$2" > meshlab.out 2>&1 &
    pid=$!
    sleep 12
    xdotool mousemove 150 380 mousedown 1; sleep 0.2
    for x in 190 230 270 310 350; do xdotool mousemove $x 380; sleep 0.1; done
    xdotool mouseup 1; sleep 1            # turned about the vertical axis: the side view
    xdotool mousemove 74 10 click 1; sleep 1.5          # Edit
    xdotool mousemove 119 185; sleep 0.5; xdotool click 1; sleep 3   # PickPoints
    import -window root -crop 852x722+0+0 "$3"
    kill $pid' session "$1" "$2" "$3" "$work/home"
}
session "$work/spot" spot.ply "$out/pickpoints_spot.png"
session "$work/cow" cow.off "$out/pickpoints_cow_template.png"
echo "wrote $out/pickpoints_spot.png and $out/pickpoints_cow_template.png"
