#!/usr/bin/env bash
# The demo (the README's first command): builds and installs the plugin into Debian's
# MeshLab 2020.09 (setup/build.sh installs what is missing), then maps the bundled
# spot onto the bundled cow with their 6 named anchors through meshlabserver, and
# prints the filter's report. Outputs in out/demo/. Safe to run twice.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash setup/build.sh
cmake --install build
bash samples/map_meshes.sh samples/spot.ply samples/cow.off out/demo
echo "== report (out/demo/report.txt); layers in out/demo/cut.ply and out/demo/mapped.ply"
cat out/demo/report.txt
