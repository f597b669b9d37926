#!/usr/bin/env bash
# Fetches Debian's `meshlab` source package (MeshLab's src/common and vcglib headers)
# with apt's own client and a private deb-src list, leaving the machine's apt set-up as
# it is. Usage: setup/fetch-meshlab-source.sh VERSION_PREFIX DEST_DIR
#   VERSION_PREFIX  e.g. 2020.09+dfsg1 (bookworm) or 2025.07~dfsg (sid)
#   DEST_DIR        where the unpacked tree ends up (DEST_DIR/meshlab-<upstream version>)
# When the pool lacks the .dsc or Debian's patches but has the upstream tarball, that
# tarball (checked against the Sources index) is unpacked alone.
# Prints the unpacked tree's path on its last line. Safe to run twice.
set -euo pipefail
want="$1"; dest="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
state="$dest/apt-state"
mkdir -p "$state/lists/partial" "$state/cache/archives/partial"
# -H: DEST_DIR may be a symbolic link (a git worktree sharing another checkout's .deps).
find_tree() { find -H "$dest" -maxdepth 1 -type d -name "meshlab-${want%%-*}*" | head -n 1; }
unpacked="$(find_tree)"
if [ -n "$unpacked" ] && [ -f "$unpacked/.eulermap-complete" ]; then
  echo "$unpacked"; exit 0
fi
apt_opts=(-o "Dir::Etc::sourcelist=$root/setup/debian-sources.list" -o Dir::Etc::sourceparts=-
          -o "Dir::State::Lists=$state/lists" -o "Dir::Cache=$state/cache")
apt-get "${apt_opts[@]}" -q update >&2
found="$(apt-cache "${apt_opts[@]}" showsrc meshlab | sed -n 's/^Version: //p' | sort -u)"
version="$(printf '%s\n' "$found" | grep -F -- "$want" | sort -V | tail -n 1 || true)"
if [ -z "$version" ]; then
  echo "error: Debian source package meshlab $want* not found; versions offered: $(echo $found)" >&2
  exit 1
fi
cd "$dest"
if ! apt-get "${apt_opts[@]}" -q source "meshlab=$version" >&2; then
  # Debian's pool sometimes lacks a listed .dsc/.debian.tar.xz (sid's 2025.07~dfsg-4 gives
  # 404 for both) while the upstream tarball is there; apt has then fetched that tarball.
  # Its headers are all the build needs: check it against the hash in the signed Sources
  # index and unpack it as meshlab-<upstream version> (its own top folder is meshlab-<git sha>).
  upstream="${version%-*}"
  orig="$(ls "meshlab_${upstream}".orig.tar.* 2>/dev/null | head -n 1 || true)"
  sha="$(apt-cache "${apt_opts[@]}" showsrc meshlab | awk -v v="$version" -v f="$orig" '
    /^Version:/ { mine = ($2 == v) }
    /^[^ ]/ { sums = mine && /^Checksums-Sha256:/; next }
    sums && $3 == f { print $1 }')"
  if [ -z "$orig" ] || [ -z "$sha" ] || ! echo "$sha  $orig" | sha256sum -c --status; then
    echo "error: apt-get source meshlab=$version failed, and $dest holds no upstream tarball meshlab_${upstream}.orig.tar.* matching Debian's Sources index" >&2
    exit 1
  fi
  echo "note: Debian's pool lacks part of meshlab $version (see apt's errors above); using its verified upstream tarball $orig alone (Debian's patches are not applied: only the headers are used)" >&2
  rm -rf "meshlab-$upstream"
  mkdir "meshlab-$upstream"
  tar -xf "$orig" -C "meshlab-$upstream" --strip-components=1
fi
unpacked="$(find_tree)"
[ -n "$unpacked" ] || { echo "error: apt-get source left no meshlab-$want* tree in $dest" >&2; exit 1; }
touch "$unpacked/.eulermap-complete"
echo "$unpacked"
