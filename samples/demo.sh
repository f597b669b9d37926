#!/usr/bin/env bash
# The demo (the README's first command): builds and installs the plugin into Debian's
# MeshLab 2020.09 (setup/build.sh installs what is missing), then maps the bundled
# spot onto the bundled cow with their 6 named anchors through meshlabserver, prints the
# filter's report, then maps the sphere onto the torus through pymeshlab (the venv that
# setup/build.sh made). Outputs in out/demo/ and out/demo-python/. Safe to run twice.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash setup/build.sh
cmake --install build
bash samples/map_meshes.sh samples/spot.ply samples/cow.off out/demo
echo "== report (out/demo/report.txt); layers in out/demo/cut.ply and out/demo/mapped.ply"
cat out/demo/report.txt
if [ -x .venv/bin/python ] && [ -f build/filter_eulermap/libfilter_eulermap_2025.so ]; then
  echo "== pymeshlab: sphere -> torus (samples/map_meshes.py)"
  .venv/bin/python samples/map_meshes.py samples/sphere.ply samples/torus.ply out/demo-python
  grep -E "^(cut source|map quality)" out/demo-python/report.txt
fi
