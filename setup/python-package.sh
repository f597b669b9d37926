#!/usr/bin/env bash
# Builds the Python package's wheel (pip wheel . : scikit-build-core runs python/CMakeLists.txt,
# the pymeshlab flavour only, in build-wheel/<tag>/, kept between runs) into build-wheel/dist/
# and installs it into .venv with its dependencies (pymeshlab==2025.7.post1, distributed,
# tqdm), so that `.venv/bin/eulermap` and `import eulermap` work. setup/build.sh calls it.
# Usage: setup/python-package.sh MESHLAB_2025_SOURCE   (the unpacked meshlab 2025.07~dfsg)
# Safe to run twice: the CMake build is incremental and the wheel is installed again.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
src2025="$1"
python=.venv/bin/python
[ -x "$python" ] || { echo "error: $python missing: setup/pymeshlab-venv.sh creates it" >&2; exit 1; }

rm -f build-wheel/dist/eulermap-*.whl
[ -d build-wheel ] || echo "   (the first time it compiles the core and the plugin for MeshLab 2025.07: minutes)" >&2
EULERMAP_MESHLAB_2025_SOURCE="$src2025" "$python" -m pip wheel -q --disable-pip-version-check --no-deps \
  -w build-wheel/dist . >&2
wheel="$(ls build-wheel/dist/eulermap-*.whl)"
# The first install brings the dependencies; the second replaces eulermap even when its
# version has not changed (pip would otherwise keep the old plugin).
"$python" -m pip install -q --disable-pip-version-check "$wheel" >&2
"$python" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel" >&2
"$python" -c 'import eulermap; print(eulermap.PLUGIN)' >/dev/null
echo "$wheel"
