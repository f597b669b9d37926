#!/usr/bin/env bash
# Creates <repo>/.venv with PyPI's pymeshlab (default 2025.7.post1, which bundles
# MeshLab 2025.07, its libmeshlab-common and its own Qt 5) and pytest. The 2025.07 flavour
# of the plugin links that libmeshlab-common and that Qt; samples/map_meshes.py and
# tests/pymeshlab load it with pymeshlab.load_plugin(). Safe to run twice: an existing
# venv with the wanted versions is left as it is.
# Usage: setup/pymeshlab-venv.sh   (env: PYTHON=python3, PYMESHLAB_VERSION, PYTEST_VERSION)
# Prints the venv's pymeshlab package folder (the wheel's lib/ is below it) last.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/.venv"
python="${PYTHON:-python3}"
want="${PYMESHLAB_VERSION:-2025.7.post1}"
pytest_want="${PYTEST_VERSION:-8.4.2}"

# The wheels are cp3X-only (2025.7.post1: cp39..cp313, manylinux_2_35 = glibc >= 2.35).
"$python" - <<'EOF'
import sys
if sys.version_info < (3, 9):
    sys.exit("error: pymeshlab 2025.7 wheels need CPython >= 3.9, found %s" % sys.version.split()[0])
EOF

have() {
  [ -x "$venv/bin/python" ] &&
    "$venv/bin/python" -c 'import importlib.metadata as m, sys
sys.exit(m.version("pymeshlab") != sys.argv[1] or m.version("pytest") != sys.argv[2])' "$want" "$pytest_want" 2>/dev/null
}

if ! have; then
  [ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "pymeshlab==$want" "pytest==$pytest_want" >&2
  have || { echo "error: pymeshlab==$want and pytest==$pytest_want not both installed in $venv" >&2; exit 1; }
fi
"$venv/bin/python" -c 'import os, pymeshlab; print(os.path.dirname(pymeshlab.__file__))'
