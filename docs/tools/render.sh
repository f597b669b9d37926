#!/usr/bin/env bash
# Renders meshes side by side into one PNG with MeshLab 2020.09 itself (Debian's meshlab
# GUI under xvfb-run), e.g. the Eulerian Surface Map's inputs and outputs.
#
# Usage: docs/tools/render.sh OUT.png [options] MESH [[options] MESH ...]
#        docs/tools/render.sh --readme
#   MESH            .ply, .off or .obj (.obj is converted to PLY first: MeshLab 2020.09
#                   aborts on .obj). Drawn left to right in the given order, each turned
#                   as the options before it say, scaled to the same height, with even
#                   gaps, in an orthographic view from +z (y up), on white, with
#                   MeshLab's default look: texture when the mesh has wedge texture
#                   coordinates and names a texture (PLY "comment TextureFile x.png"),
#                   else its per-vertex colours when it has them, else grey.
#   --rotate-y DEG  turn the meshes that follow about the vertical axis (y; their front,
#                   +z, towards the right for DEG > 0), then
#   --rotate-x DEG  about the horizontal axis (x; their top towards the viewer for
#                   DEG > 0); both stay in force until given again (default 0)
#   --textures DIR  also look for the meshes' texture images in DIR (by the name the mesh
#                   gives, then by its last part); first comes the mesh's own folder.
#                   A texture found nowhere is an error, before MeshLab starts.
#   --size WxH      the picture's size in pixels (default 1600x400); the meshes fill it
#                   but for a 5% border
#   --supersample K render at K times the picture's scale, then shrink (default 2)
#   --timeout S     give up after S seconds (default 180)
#   --keep          keep the work folder (the MeshLab project, its log, the screenshot)
#   --readme        make the README's pictures from real runs of the current plugin:
#                   samples/map_meshes.sh sphere -> torus, spot -> cow and cow -> spot
#                   (6 anchors) into out/pictures/, then docs/pictures/<pair>.png:
#                   source | target | cut source (with the texture pulled from the
#                   target, if any) | mapped source (with the source's own, if any)
# Needs meshlab, xvfb-run, xdotool, ImageMagick (import, convert) and python3. Settings
# go to a private HOME in the work folder: the user's MeshLab settings are not touched.
# Exits non-zero with a message when a mesh or texture cannot be loaded or MeshLab does
# not show the scene as laid out.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
usage() { awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; }
die() { echo "render.sh: $*" >&2; exit 1; }

# ---------------------------------------------------------------- inside xvfb-run
# render.sh --session WORK TIMEOUT: starts meshlab on WORK/scene.mlp, hides the panels,
# waits for a steady picture and saves the screen as WORK/shot.ppm.
if [ "${1:-}" = --session ]; then
  work=$2 timeout=$3
  # shellcheck disable=SC1091
  . "$work/scene.env"
  deadline=$((SECONDS + timeout))
  log=$work/meshlab.log
  (cd "$work" && exec env HOME="$work/home" XDG_CONFIG_HOME="$work/home/.config" \
     XDG_RUNTIME_DIR="$work/home" meshlab "$work/scene.mlp") > "$log" 2>&1 &
  pid=$!
  trap 'kill $pid 2>/dev/null || true; wait $pid 2>/dev/null || true' EXIT
  fail() { echo "render.sh: $*" >&2; exit 1; }
  alive() { kill -0 $pid 2>/dev/null || fail "meshlab exited early; its log: $(tail -5 "$log")"; }
  late() { [ $SECONDS -lt $deadline ] || fail "timed out ($timeout s) $1; see $log"; }
  dialog() {  # a message box (a failed load, a missing texture) blocks meshlab
    local w name
    for w in $(xdotool search --onlyvisible --name '.' 2>/dev/null); do
      name=$(xdotool getwindowname "$w" 2>/dev/null) || continue
      case "$name" in "MeshLab "*|MeshLab_64bit_fp|"") ;; *) fail "meshlab shows a dialog '$name'; see $log" ;; esac
    done
  }
  check_log() {
    if grep -q "Failure of loading texture\|Missing texture files\|Failure loading textures" "$log"; then
      fail "meshlab could not load a texture: $(grep -A3 'Missing texture files\|Failure of loading texture' "$log" | tr '\n' ' ')"
    fi
  }

  win=
  while [ -z "$win" ]; do
    alive; late "waiting for MeshLab's window"; sleep 0.2
    win=$(xdotool search --onlyvisible --name '^MeshLab ' 2>/dev/null | head -1) || true
  done
  # every layer loaded: meshlab logs "Opened mesh FILE in N msec" for each
  while IFS= read -r f; do
    until grep -qF "Opened mesh $f in" "$log"; do
      alive; check_log; dialog; late "loading $f"; sleep 0.2
    done
  done < "$work/files.txt"
  check_log
  xdotool windowmove --sync "$win" 0 0 windowsize --sync "$win" "$SCREEN_W" "$SCREEN_H"
  xdotool windowfocus --sync "$win" mousemove --sync 5 5
  sleep 0.5
  # View menu: Show Info Panel off (no shortcut of its own), trackball off (shift+H),
  # layer dialog off (ctrl+L), orthographic camera (keypad 5).
  xdotool key --delay 150 alt+v p shift+h ctrl+l KP_5
  # the picture is ready when two screenshots in a row are the same and the drawing
  # has the layout's size (render_scene.py check)
  previous= why="no steady picture"
  while :; do
    alive; check_log; dialog; late "waiting for the scene as laid out: $why (see $work/shot.ppm)"
    sleep 0.5
    import -window root -depth 8 "ppm:$work/shot.ppm"
    sum=$(md5sum < "$work/shot.ppm")
    if [ "$sum" = "$previous" ]; then
      why=$(python3 "$here/render_scene.py" check "$work" 2>&1) && exit 0
      why=${why#render.sh: }
    fi
    previous=$sum
  done
fi

# ---------------------------------------------------------------- README pictures
if [ "${1:-}" = --readme ]; then
  [ $# -eq 1 ] || { usage >&2; exit 2; }
  cd "$root"
  installed=/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_eulermap.so
  built=build/filter_eulermap/libfilter_eulermap.so
  build_id() { readelf -n "$1" 2>/dev/null | sed -n 's/.*Build ID: //p'; }
  if [ -f "$built" ] && [ -f "$installed" ] && [ "$(build_id "$built")" != "$(build_id "$installed")" ]; then
    echo "render.sh: warning: the installed plugin is not the one in build/ (cmake --install build); the pictures show the installed one" >&2
  fi
  out=out/pictures
  mkdir -p "$out" docs/pictures
  samples/map_meshes.sh samples/sphere.ply samples/torus.ply "$out/sphere_to_torus" > "$out/sphere_to_torus.txt"
  samples/map_meshes.sh samples/spot.ply samples/cow.off "$out/spot_to_cow" > "$out/spot_to_cow.txt"
  samples/map_meshes.sh samples/cow.off samples/spot.ply "$out/cow_to_spot" --grid 80 > "$out/cow_to_spot.txt"  # as cow_to_spot.mlx
  # sphere -> torus: seen from above the torus's axis, a little tilted
  "$0" docs/pictures/sphere_to_torus.png --textures samples --rotate-x -25 \
    samples/sphere.ply samples/torus.ply "$out/sphere_to_torus/cut.ply" "$out/sphere_to_torus/mapped.ply"
  # spot -> cow: both from their right side, a little from the front and above
  "$0" docs/pictures/spot_to_cow.png --textures samples \
    --rotate-x 15 --rotate-y -120 samples/spot.ply --rotate-y -30 samples/cow.off \
    --rotate-y -120 "$out/spot_to_cow/cut.ply" --rotate-y -30 "$out/spot_to_cow/mapped.ply"
  # cow -> spot: the cow takes spot's texture through the map
  "$0" docs/pictures/cow_to_spot.png --textures samples \
    --rotate-x 15 --rotate-y -30 samples/cow.off --rotate-y -120 samples/spot.ply \
    --rotate-y -30 "$out/cow_to_spot/cut.ply" --rotate-y -120 "$out/cow_to_spot/mapped.ply"
  for pair in sphere_to_torus spot_to_cow cow_to_spot; do
    grep -E "^(cut source|map quality)" "$out/$pair/report.txt" | sed "s/^/$pair: /"
  done
  echo "wrote docs/pictures/sphere_to_torus.png, docs/pictures/spot_to_cow.png, docs/pictures/cow_to_spot.png"
  exit 0
fi

# ---------------------------------------------------------------- one picture
case "${1:-}" in
  ""|-h|--help) usage; [ $# -gt 0 ] || exit 2; exit 0 ;;
  -*) echo "render.sh: the first argument is the picture to write, got '$1'" >&2; usage >&2; exit 2 ;;
esac
picture=$1; shift
timeout=180 keep=0 args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --timeout) [[ "${2:-}" =~ ^[0-9]+$ ]] || die "--timeout takes whole seconds"; timeout=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    *) args+=("$1"); shift ;;
  esac
done
for tool in meshlab xvfb-run xdotool import convert python3; do
  command -v "$tool" >/dev/null || die "$tool not found (apt-get install meshlab xvfb xauth xdotool imagemagick python3)"
done
case "$picture" in *.png|*.PNG) ;; *) die "the picture's name must end in .png: $picture" ;; esac
mkdir -p "$(dirname "$picture")"

work=$(mktemp -d "${TMPDIR:-/tmp}/render.XXXXXX")
cleanup() { if [ $keep = 1 ]; then echo "render.sh: work folder kept: $work" >&2; else rm -rf "$work"; fi; }
trap cleanup EXIT
python3 "$here/render_scene.py" prepare "$work" "${args[@]}" || exit $?
# shellcheck disable=SC1091
. "$work/scene.env"
status=0
xvfb-run -a -s "-screen 0 ${SCREEN_W}x${SCREEN_H}x24" "$0" --session "$work" "$timeout" || status=$?
if [ $status -ne 0 ]; then
  keep=1
  exit $status
fi
python3 "$here/render_scene.py" finish "$work" "$picture" || { keep=1; exit 1; }
echo "wrote $picture"
