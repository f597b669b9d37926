#!/usr/bin/env bash
# The README's parameter list is the one the core's table writes (`eulermap_bench parameters`),
# between the lines <!-- parameters: eulermap_bench parameters --> and <!-- /parameters -->.
set -euo pipefail
bench=$1 readme=$2
listed=$(sed -n '/^<!-- parameters: eulermap_bench parameters -->$/,/^<!-- \/parameters -->$/p' "$readme" | sed '1d;$d')
if [ "$listed" != "$("$bench" parameters)" ]; then
  echo "README.md's parameter list differs from the table's; write it again with: eulermap_bench parameters" >&2
  diff <(echo "$listed") <("$bench" parameters) >&2 || true
  exit 1
fi
