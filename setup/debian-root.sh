#!/usr/bin/env bash
# Builds (once per machine) a minimal Debian root with Debian's own mmdebstrap, in which
# Debian's `meshlab` of that suite is installed with the libraries it recommends, together
# with what building the plugin's flavour needs there (a compiler, cmake, ccache, Eigen, Qt 5's
# and GLEW's headers) and nothing else (--variant=minbase, no other Recommends, no
# documentation, no apt lists or .deb cache kept). A sid root holds sid as it was the day it
# was built, until its package list here changes.
# The GUI tests (tests/meshlab-roots/) run that MeshLab inside it.
# Usage: setup/debian-root.sh SUITE      SUITE: trixie (MeshLab 2022.02) or sid (MeshLab 2025.07)
# The root is /var/cache/eulermap/roots/SUITE (EULERMAP_ROOTS=DIR for another place: it lives
# outside the clone, so a fresh clone (CI) reuses it). A root is complete when its stamp
# file names the same package list; otherwise it is built again. Prints the root's path
# on its last line. Safe to run twice.
set -euo pipefail
suite=$1
base="${EULERMAP_ROOTS:-/var/cache/eulermap/roots}"
dir="$base/$suite"
packages="meshlab,g++,make,cmake,ccache,libeigen3-dev,qtbase5-dev,libqt5opengl5-dev,libglew-dev,libgl1-mesa-dri,fonts-dejavu-core"
# meshlab's Recommends, which a user's apt installs: without them MeshLab opens with a dialog
# listing the plugins it could not load (their libraries missing).
case "$suite" in
  trixie) packages+=",lib3ds-1-3,libmuparser2v5,libopenctm1,libqhull-r8.0,libxerces-c3.2t64,libgmp10,libmpfr6" ;;
  sid) packages+=",lib3ds-1-3,libmuparser2v5,libopenctm1,libqhull-r8.0" ;;
  *) echo "error: unknown suite '$suite' (trixie or sid)" >&2; exit 1 ;;
esac
stamp="$dir/.eulermap-root"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$suite $packages" ]; then
  echo "$dir"; exit 0
fi
mkdir -p "$base"
if ! command -v mmdebstrap >/dev/null; then  # setup/build.sh installs it; this is for a bare machine
  (
    flock 8
    if ! command -v mmdebstrap >/dev/null; then
      echo "== installing Debian's mmdebstrap" >&2
      apt-get update -q >&2
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q mmdebstrap >&2
    fi
  ) 8>"$base/.mmdebstrap.lock"
fi
# One build of a root at a time (tests/run and a developer's shell may both ask).
exec 9>"$base/.$suite.lock"
flock 9
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$suite $packages" ]; then
  echo "$dir"; exit 0
fi
# Never delete through a mount: an interrupted mmdebstrap can leave /proc, /sys or /dev
# mounted inside its unfinished root.
if grep -qF " $dir" /proc/mounts; then
  echo "error: something is mounted under $dir (an interrupted build?): $(grep -F " $dir" /proc/mounts | cut -d' ' -f2 | tr '\n' ' ')- unmount it (umount -R) and run again" >&2
  exit 1
fi
rm -rf --one-file-system "$dir" "$dir.partial"
echo "== building the $suite root in $dir with mmdebstrap (once per machine)" >&2
start=$SECONDS
# Debian's archive keys as the machine has them (bookworm's debian-archive-keyring verifies
# trixie's and sid's Release files). Check-Valid-Until off: the mirror this
# machine reaches may serve a sid Release older than its Valid-Until allows (apt then says
# "Release file ... is expired"); the signature is still checked.
mmdebstrap --mode=root --variant=minbase --include="$packages" \
  --dpkgopt='path-exclude=/usr/share/doc/*' --dpkgopt='path-exclude=/usr/share/man/*' \
  --dpkgopt='path-exclude=/usr/share/locale/*' --dpkgopt='path-include=/usr/share/locale/locale.alias' \
  --aptopt='APT::Install-Recommends "false"' --aptopt='Acquire::Check-Valid-Until "false"' \
  "$suite" "$dir.partial" \
  "deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" >&2
rm -rf "$dir.partial/var/lib/apt/lists/"* "$dir.partial/var/cache/apt/"*.bin
mv "$dir.partial" "$dir"
echo "$suite $packages" > "$stamp"
echo "== $suite root built in $((SECONDS - start)) s, $(du -sh "$dir" | cut -f1)" >&2
echo "$dir"
