#!/usr/bin/env bash
# Runs a command inside a Debian root of setup/debian-root.sh, in a mount namespace of its
# own (the mounts vanish with it): the clone at /src, BUILD_DIR (if given) at /build, the
# ccache folder at /ccache, and the host's /proc, /dev, /sys and /tmp (the X server's socket
# and xvfb-run's Xauthority file are there: a GUI inside draws on the host's Xvfb).
# The process keeps its pid (unshare and chroot exec), so /proc/PID/maps of the program
# can be read from outside.
# Usage: in_root.sh ROOT [--build BUILD_DIR] COMMAND [ARG...]
set -euo pipefail
root_dir=$1; shift
build=""
if [ "${1:-}" = --build ]; then build=$2; shift 2; mkdir -p "$build"; fi
src="$(cd "$(dirname "$0")/../.." && pwd)"
ccache_dir="${EULERMAP_CCACHE:-/var/cache/eulermap/ccache}"
mkdir -p "$ccache_dir"
export EULERMAP_IN_ROOT_SRC="$src" EULERMAP_IN_ROOT_BUILD="$build" EULERMAP_IN_ROOT_CCACHE="$ccache_dir"
exec unshare --mount --propagation private bash -c '
  set -e
  r=$1; shift
  mkdir -p "$r/src" "$r/build" "$r/ccache"
  mount --bind "$EULERMAP_IN_ROOT_SRC" "$r/src"
  [ -z "$EULERMAP_IN_ROOT_BUILD" ] || mount --bind "$EULERMAP_IN_ROOT_BUILD" "$r/build"
  mount --bind "$EULERMAP_IN_ROOT_CCACHE" "$r/ccache"
  mount -t proc proc "$r/proc"
  mount --rbind /dev "$r/dev"
  mount --rbind /sys "$r/sys"
  mount --bind /tmp "$r/tmp"
  exec chroot "$r" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/root LANG=C.UTF-8 \
    DISPLAY="${DISPLAY:-}" XAUTHORITY="${XAUTHORITY:-}" OMP_WAIT_POLICY=passive CCACHE_DIR=/ccache \
    QT_X11_NO_MITSHM=1 "$@"
' in_root "$root_dir" "$@"
