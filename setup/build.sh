#!/usr/bin/env bash
# Installs what the build needs (Debian packages), fetches Debian's meshlab source
# package for the MeshLab/vcglib headers, and configures and builds into build/.
# Safe to run twice: installed packages, the fetched tree and the build are reused.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

packages=(build-essential cmake ninja-build pkg-config libeigen3-dev qtbase5-dev libqt5opengl5-dev
          libqt5xmlpatterns5-dev libglew-dev libgtest-dev googletest meshlab xvfb xauth dpkg-dev
          python3 python3-venv imagemagick xdotool)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing Debian packages: ${missing[*]}"
  apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
fi

meshlab_version="$(dpkg-query -W -f='${Version}' meshlab)"
case "$meshlab_version" in
  2020.09*) ;;
  *) echo "error: expected Debian's meshlab 2020.09 (bookworm), found $meshlab_version" >&2; exit 1 ;;
esac

echo "== fetching Debian source package meshlab 2020.09+dfsg1 (headers only; not committed)"
src2020="$(bash setup/fetch-meshlab-source.sh 2020.09+dfsg1 "$root/.deps" | tail -n 1)"

echo "== configuring and building in build/"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DEULERMAP_MESHLAB_2020_SOURCE="$src2020" -DEULERMAP_BUILD_PLUGIN_2020=ON >/dev/null
cmake --build build
