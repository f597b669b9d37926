#!/usr/bin/env bash
# Run inside a Debian root (in_root.sh ROOT --build DIR): configures the clone at /src for the
# MeshLab installed in the root (EULERMAP_MESHLAB_SYSTEM_SOURCE: Debian's source package of
# its version, fetched by the host into .deps/), builds the plugin's target alone (its core,
# a unity build as core/CMakeLists.txt makes every core, and the shim; no tests, no benchmark)
# with ccache, and installs it into MeshLab's plugin folder with cmake --install.
# Usage: build_plugin.sh MESHLAB_SOURCE_DIR_NAME (in /src/.deps)
set -euo pipefail
tree=/src/.deps/$1
cmake -S /src -B /build -DCMAKE_BUILD_TYPE=Release -DEULERMAP_BUILD_TESTS=OFF \
  -DEULERMAP_MESHLAB_SYSTEM_SOURCE="$tree" \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/build/configure.log 2>&1 || { cat /build/configure.log; exit 1; }
grep -- '-- filter_eulermap_system:' /build/configure.log
ccache -z >/dev/null
cmake --build /build --target filter_eulermap_system -j 2
cmake --install /build
ccache -s | grep -iE '^ *(hits|misses|cache hit)' || true
