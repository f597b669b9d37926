#!/usr/bin/env bash
# One pytest stage of tests/run: pytest from .venv on the folder DIR, its JUnit report in
# out/NAME/, and last the line 'N passed, N failed' (tests/junit_summary.py; pytest's own
# summary line has another form). Exits 1 when any test failed or pytest could not run.
# Usage: tests/pytest_stage.sh DIR NAME [pytest arguments, e.g. -k spot]
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
dir=$1 name=$2
shift 2

python=.venv/bin/python
if [ ! -e "$python" ]; then
  echo "$dir: $python missing: run setup/build.sh (it creates .venv with pytest)"
  echo "0 passed, 1 failed"
  exit 1
fi
mkdir -p "out/$name"
junit="out/$name/junit.xml"
rm -f "$junit"
"$python" -m pytest "$dir" -v -s -p no:cacheprovider --junitxml="$junit" "$@"
status=$?
"$python" tests/junit_summary.py "$junit" "$status"
exit $status
