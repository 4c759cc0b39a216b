#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`, clang) and runs each for at most SECONDS (default 20).
# Corpora start from fuzz/corpus/<target>/ when present and grow in build/fuzz/corpus/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
bash scripts/setup-deps.sh --fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
status=0
for exe in build/fuzz/fuzz/fuzz_*; do
  [ -x "$exe" ] || continue
  name=$(basename "$exe")
  corpus=build/fuzz/corpus/$name
  mkdir -p "$corpus"
  seeds=()
  [ -d "fuzz/corpus/$name" ] && seeds=("fuzz/corpus/$name")
  echo "== $name: ${seconds}s"
  if ! "$exe" -max_total_time="$seconds" -print_final_stats=0 "$corpus" "${seeds[@]}" \
       >"build/fuzz/$name.log" 2>&1; then
    echo "FAILED: $name (log: build/fuzz/$name.log)"; tail -n 40 "build/fuzz/$name.log"; status=1
  else
    grep -E '^(#[0-9]+|Done)' "build/fuzz/$name.log" | tail -n 1
  fi
done
exit $status
