#!/usr/bin/env bash
# The project's own mapping benchmark: 5 generated meshes (500 to 20,000 tets; thick and thin,
# with and without interior vertices) times the four generated boundary shapes = 20 cases. Each
# case is mapped twice (the two exact outputs must be bit-identical) and checked by the
# independent checker ../shared/tools/verify_tmap.py when it exists. Prints a Markdown table.
# Usage: bench/map/generated_cases.sh [CMX_BINARY] [OUT_DIR] [extra cmx map options...]
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=${1:-$here/build/release/cli/cmx}
out=${2:-/tmp/cmx-generated-cases}
shift 2 2>/dev/null || shift $#
extra=("$@")
checker=$here/../shared/tools/verify_tmap.py
mkdir -p "$out"
meshes=("grid:10,10,10" "grid:24,8,5" "ball:7" "slab:40,30,2" "slab:25,20,1")
shapes=("tet" "stiff-tet" "sphere" "star:7")
printf '| mesh | shape | tets in | status | seconds | s / input tet | growth | max bits | double valid | identical rerun | verify_tmap |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|\n'
for m in "${meshes[@]}"; do
  name=$(echo "$m" | tr ':,' '__')
  mesh=$out/$name.vtk
  "$cmx" generate-mesh --shape "$m" --perturb 1 -o "$mesh" >/dev/null 2>&1 || { echo "| $m | generate-mesh failed |"; continue; }
  for s in "${shapes[@]}"; do
    sname=$(echo "$s" | tr ':' '_')
    bnd=$out/${name}_$sname.txt
    "$cmx" boundary "$mesh" --shape "$s" -o "$bnd" >/dev/null 2>&1 || { printf '| %s | %s | | boundary failed |\n' "$m" "$s"; continue; }
    run=$out/${name}_$sname
    "$cmx" map "$mesh" --boundary "$bnd" -o "$run" --report "$run.json" --quiet "${extra[@]}" 2>"$run.err"
    rc=$?
    if [ $rc -ne 0 ]; then
      printf '| %s | %s | | exit %s: %s |\n' "$m" "$s" "$rc" "$(head -c 100 "$run.err" | tr '\n|' '  ')"
      continue
    fi
    "$cmx" map "$mesh" --boundary "$bnd" -o "$run.again" --quiet "${extra[@]}" 2>/dev/null
    same=$(cmp -s "$run.tmap" "$run.again.tmap" && echo yes || echo NO)
    check="(no checker)"
    if [ -f "$checker" ]; then
      check=$(python3 "$checker" "$mesh" "$bnd" "$run.tmap" 2>&1 |
              python3 -c "import json,sys;print('valid' if json.loads(sys.stdin.read())['valid'] else 'INVALID')" 2>/dev/null || echo error)
    fi
    python3 - "$run.json" "$m" "$s" "$same" "$check" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
t = r['input']['tets']; s = r['seconds']['total']
print('| %s | %s | %d | %s | %.3f | %.2e | %.4f | %d | %s | %s | %s |' % (
    sys.argv[2], sys.argv[3], t, r['status'], s, s / t, r['output']['growth_ratio'], r['bits']['max'],
    'yes' if r['verdict']['double_valid'] else 'no', sys.argv[4], sys.argv[5]))
PY
  done
done
