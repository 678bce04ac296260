#!/usr/bin/env bash
# test-setup/under-load.sh [RUNS] - runs ./antw test RUNS times (default 3) while two CPU-bound processes per core
# run beside it, as on a busy lab machine. The suite must pass every time: its waits are generous and it makes
# no timing claims (those live in ./antw bench-*). Needs stress-ng (Debian package stress-ng), else busy loops.
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
mkdir -p build
hogs=$(( $(nproc) * 2 ))
if command -v stress-ng >/dev/null 2>&1; then
  stress-ng --cpu "$hogs" --quiet &
else
  for _ in $(seq "$hogs"); do (while :; do :; done) & done
fi
trap 'kill $(jobs -p) 2>/dev/null' EXIT
failed=0
for run in $(seq "$runs"); do
  start=$(date +%s)
  if ./antw test > "build/under-load-$run.log" 2>&1; then result=passed; else result=FAILED; failed=$((failed + 1)); fi
  echo "run $run/$runs with $hogs CPU hogs: $result in $(( $(date +%s) - start )) s;" \
       "$(grep -h 'tests:' "build/under-load-$run.log" | tail -1 | sed 's/.*tests:/tests:/')" \
       "(log: build/under-load-$run.log)"
done
exit $(( failed > 0 ))
