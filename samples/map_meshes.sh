#!/usr/bin/env bash
# Maps one mesh file onto another with the Eulerian Surface Map filter, through
# meshlabserver (MeshLab 2020.09) under xvfb-run.
#
# Usage: samples/map_meshes.sh SOURCE TARGET OUTDIR [--grid N] [--steps N]
#   SOURCE, TARGET  mesh files MeshLab reads (.ply, .obj, .off, ...); layer 0 is the
#                   source, layer 1 the target. A .pp picked-points file beside each,
#                   with the same base name (spot.ply + spot.pp), gives named anchors.
#                   .obj files are converted to PLY first (OUTDIR/inputs/): Debian's
#                   MeshLab 2020.09 aborts on .obj files.
#   OUTDIR          gets cut.ply (the cut source: original positions, vertex quality =
#                   distortion, texture coordinates pulled from the target when it has
#                   them), mapped.ply (the same vertices in the same order, at their images
#                   on the target, with the source's own texture coordinates), the texture
#                   images they name (copied from beside the inputs), report.txt (the
#                   filter's log) and, for reruns and debugging, map.mlx,
#                   meshlabserver.log and meshlabserver.out.
#   --grid N        cells on the longest axis of the grid (default 64)
#   --steps N       time steps (default 40)
# Needs the project built (setup/build.sh) and the plugin installed (cmake --install build).
# Exits non-zero, with the filter's message, when the map fails.
set -euo pipefail

usage() { sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; }

if [ $# -lt 3 ]; then usage >&2; exit 2; fi
source_mesh=$1 target_mesh=$2 out=$3
shift 3
grid=64 steps=40
while [ $# -gt 0 ]; do
  case "$1" in
    --grid) grid=${2:-}; shift 2 || { usage >&2; exit 2; } ;;
    --steps) steps=${2:-}; shift 2 || { usage >&2; exit 2; } ;;
    -h|--help) usage; exit 0 ;;
    *) echo "map_meshes.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
for n in "$grid" "$steps"; do
  [[ "$n" =~ ^[0-9]+$ ]] || { echo "map_meshes.sh: --grid and --steps take whole numbers, got '$n'" >&2; exit 2; }
done
for f in "$source_mesh" "$target_mesh"; do
  [ -f "$f" ] || { echo "map_meshes.sh: no such mesh file: $f" >&2; exit 2; }
done
command -v meshlabserver >/dev/null || { echo "map_meshes.sh: meshlabserver not found (apt-get install meshlab)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "map_meshes.sh: xvfb-run not found (apt-get install xvfb xauth)" >&2; exit 2; }
plugin=/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_eulermap.so
[ -f "$plugin" ] || { echo "map_meshes.sh: $plugin missing: build and install the plugin (cmake --install build)" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
bench="$here/../build/tests/bench/eulermap_bench"  # writes the .mlx script
[ -x "$bench" ] || { echo "map_meshes.sh: $bench missing: build the project (bash setup/build.sh)" >&2; exit 2; }

mkdir -p "$out"
out=$(cd "$out" && pwd)

# Debian's MeshLab 2020.09 aborts on every .obj (vcglib import_obj.h assertion): hand it a
# PLY copy, with the .pp files beside it, so that default anchors still apply.
as_ply() {
  local f=$1 stem
  case "${f,,}" in
    *.obj)
      stem=$(basename "${f%.*}")
      mkdir -p "$out/inputs"
      python3 "$here/obj_to_ply.py" "$f" "$out/inputs/$stem.ply" >&2
      for pp in "${f%.*}.pp" "${f%.*}_picked_points.pp"; do
        if [ -f "$pp" ]; then cp "$pp" "$out/inputs/"; fi
      done
      echo "$out/inputs/$stem.ply" ;;
    *) echo "$f" ;;
  esac
}
source_mesh=$(as_ply "$source_mesh")
target_mesh=$(as_ply "$target_mesh")
script="$out/map.mlx" log="$out/meshlabserver.log"
rm -f "$out/cut.ply" "$out/mapped.ply" "$out/report.txt" "$log"

# Every parameter of the filter, in its order (meshlabserver 2020.09 asserts otherwise), from
# the core's table (core/parameters.h).
"$bench" mlx grid_resolution="$grid" steps="$steps" > "$script"

# -l LOG must come before the -o options (after -o, -l names the layer to save).
status=0
xvfb-run -a meshlabserver -l "$log" -i "$source_mesh" "$target_mesh" -s "$script" \
  -o "$out/cut.ply" -l 2 -m vq wt -o "$out/mapped.ply" -l 3 -m vq wt > "$out/meshlabserver.out" 2>&1 || status=$?

# The filter's log: the lines after "filter: Eulerian Surface Map" up to meshlabserver's own.
awk '/filter: Eulerian Surface Map/ { on = 1; next }
     on && /^(Mesh .* saved as|Output mesh|Problem with filter|Failed to apply|Invalid layer)/ { exit }
     on { print }' "$log" > "$out/report.txt" 2>/dev/null || true
cat "$out/report.txt"

if [ "$status" -ne 0 ] || [ ! -s "$out/cut.ply" ] || [ ! -s "$out/mapped.ply" ]; then
  echo "map_meshes.sh: the map failed (meshlabserver exit status $status); see $log and $out/meshlabserver.out" >&2
  exit 1
fi
# The texture images the outputs name (MeshLab 2020.09 writes the names, not the images):
# copied beside them from the inputs' folders, so they open textured.
for name in $(for f in cut mapped; do sed -n '/^end_header/q; s/^comment TextureFile //p' "$out/$f.ply"; done | sort -u); do
  [ -e "$out/$name" ] && continue
  for dir in "$(dirname "$source_mesh")" "$(dirname "$target_mesh")"; do
    if [ -f "$dir/$name" ]; then mkdir -p "$(dirname "$out/$name")"; cp "$dir/$name" "$out/$name"; break; fi
  done
done
echo "wrote $out/cut.ply, $out/mapped.ply, $out/report.txt"
