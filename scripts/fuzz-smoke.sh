#!/usr/bin/env bash
# Builds the libFuzzer targets (preset `fuzz`, clang) and runs each for at most SECONDS (default 20).
# Corpora start from fuzz/corpus/<target>/ when present and grow in build/fuzz/corpus/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
bash scripts/setup-deps.sh --fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
# Targets run side by side, one per core (CMX_FUZZ_JOBS to change): a smoke run is time-boxed, so
# N cores finish the set N times sooner. Each target's verdict is printed in a fixed order.
jobs=${CMX_FUZZ_JOBS:-$(nproc)}
run_one() {
  local exe=$1 name corpus seeds=()
  name=$(basename "$exe")
  corpus=build/fuzz/corpus/$name
  mkdir -p "$corpus"
  [ -d "fuzz/corpus/$name" ] && seeds=("fuzz/corpus/$name")
  if "$exe" -max_total_time="$seconds" -print_final_stats=0 "$corpus" "${seeds[@]}" \
       >"build/fuzz/$name.log" 2>&1; then
    echo ok >"build/fuzz/$name.verdict"
  else
    echo failed >"build/fuzz/$name.verdict"
  fi
}
targets=()
for exe in build/fuzz/fuzz/fuzz_*; do [ -x "$exe" ] && targets+=("$exe"); done
for exe in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  rm -f "build/fuzz/$(basename "$exe").verdict"
  run_one "$exe" &
done
wait
status=0
for exe in "${targets[@]}"; do
  name=$(basename "$exe")
  echo "== $name: ${seconds}s"
  if [ "$(cat "build/fuzz/$name.verdict" 2>/dev/null)" != ok ]; then
    echo "FAILED: $name (log: build/fuzz/$name.log)"; tail -n 40 "build/fuzz/$name.log"; status=1
  else
    grep -E '^(#[0-9]+|Done)' "build/fuzz/$name.log" | tail -n 1
  fi
done
exit $status
