#!/usr/bin/env bash
# Configures and builds the sanitizer build of the core and its unit tests into
# build-sanitize/ (EULERMAP_SANITIZE: ASan + LSan + UBSan, assertions on, -O1; no plugin
# flavour, no benchmark). tests/run's stage 2 calls it after setup/build.sh, which installs
# the Debian packages and fetches the meshlab 2020.09 source package this reuses.
# Safe to run twice: the configured build-sanitize/ is reused and only rebuilt as needed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

src2020="$(bash setup/fetch-meshlab-source.sh 2020.09+dfsg1 "$root/.deps" | tail -n 1)"
echo "== configuring and building the sanitizer build in build-sanitize/"
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DEULERMAP_SANITIZE=ON \
  -DEULERMAP_MESHLAB_2020_SOURCE="$src2020" >/dev/null
cmake --build build-sanitize
