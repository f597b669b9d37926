#!/usr/bin/env bash
# Installs what the build needs (Debian packages), fetches Debian's meshlab source
# packages for the MeshLab/vcglib headers (2020.09 from bookworm, 2025.07 from sid),
# creates .venv with pymeshlab 2025.7.post1 and pytest, configures and builds both
# plugin flavours into build/, and builds the Python package's wheel (pymeshlab flavour,
# into build-wheel/dist/) and installs it into .venv (setup/python-package.sh). Safe to run
# twice: installed packages, the fetched trees, the venv and the builds are reused.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

packages=(build-essential cmake ninja-build pkg-config libeigen3-dev qtbase5-dev libqt5opengl5-dev
          libqt5xmlpatterns5-dev libglew-dev libgtest-dev googletest meshlab xvfb xauth dpkg-dev
          python3 python3-venv imagemagick xdotool mmdebstrap)
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

# The pymeshlab flavour: headers from Debian sid's meshlab 2025.07~dfsg, binaries from the
# pymeshlab 2025.7.post1 wheel in .venv. Without them the 2020.09 flavour is still built.
pymeshlab_flavour=()
echo "== fetching Debian source package meshlab 2025.07~dfsg (headers only; not committed)"
if src2025="$(bash setup/fetch-meshlab-source.sh 2025.07~dfsg "$root/.deps" | tail -n 1)" &&
   echo "== creating .venv with pymeshlab 2025.7.post1 and pytest" &&
   pymeshlab_dir="$(bash setup/pymeshlab-venv.sh | tail -n 1)"; then
  pymeshlab_flavour=(-DEULERMAP_MESHLAB_2025_SOURCE="$src2025" -DEULERMAP_PYMESHLAB_LIB="$pymeshlab_dir/lib")
else
  echo "warning: no meshlab 2025.07 source or no pymeshlab venv (see above): building without the" \
       "pymeshlab flavour (libfilter_eulermap_2025.so); its tests will fail" >&2
fi

echo "== configuring and building in build/"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DEULERMAP_MESHLAB_2020_SOURCE="$src2020" -DEULERMAP_BUILD_PLUGIN_2020=ON "${pymeshlab_flavour[@]}" >/dev/null
cmake --build build
if [ ${#pymeshlab_flavour[@]} -gt 0 ]; then
  echo "== building the Python package's wheel (pip wheel .) into build-wheel/dist/ and installing it into .venv"
  bash setup/python-package.sh "$src2025"
fi
