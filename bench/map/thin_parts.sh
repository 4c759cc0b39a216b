#!/usr/bin/env bash
# The thin-part family of issue 21 point 2: palms with thin bent fingers
# (`cmx generate-mesh --shape fingers:F,W,L --perturb 1`) times the four generated boundary
# shapes, each mapped once with a time limit. Real hands with thin fingers time out where thick
# ones of the same size map in seconds; this family reproduces that on meshes the project writes.
# One Markdown row per case: cmx's exit, wall seconds, growth, the doubles' verdict (report's
# double_valid), ../shared/tools/verify_tmap.py's verdict on the .tmap, and for a run without a
# map the first line of its message (stuck or time limit: how many cluster vertices were left).
# Usage: bench/map/thin_parts.sh CMX OUT_DIR [LIMIT_SECONDS=600] [extra cmx map options...]
# MESHES="F,W,L ..." replaces the default list; JOBS=N runs N cases at once (default 2, each
# with --threads 1, so that the cases do not share cores); SPREAD=N passes --spread N to
# `cmx boundary` (default 0: plain Tutte, which crowds each finger's tip to a point).
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=$1 out=$2 limit=${3:-600}
shift 3 2>/dev/null || shift $#
extra=("$@")
checker=$here/../shared/tools/verify_tmap.py
meshes=(${MESHES:-8,2,50 3,3,40 4,3,30 5,3,40 5,3,60 6,3,50 8,3,30})
spread=${SPREAD:-0}
shapes=(tet stiff-tet sphere star:7)
mkdir -p "$out"

one_case() {  # F,W,L shape -> writes $out/row_NAME_SHAPE.md
  local m=$1 s=$2 name sname mesh bnd run rc t0 t1 sec growth dv check msg tets
  name=fingers_$(echo "$m" | tr ',' '_'); sname=$(echo "$s" | tr ':' '_')
  mesh=$out/$name.vtk bnd=$out/${name}_$sname.txt run=$out/${name}_$sname
  tets=$(awk '/^CELLS/ {print $2; exit}' "$mesh")
  if ! "$cmx" boundary "$mesh" --shape "$s" --spread "$spread" -o "$bnd" --quiet 2>"$run.berr"; then
    printf '| %s | %s | %s | boundary failed: %s |\n' "$m" "$s" "$tets" "$(head -1 "$run.berr")" >"$out/row_${name}_$sname.md"
    return
  fi
  rm -f "$run.tmap" "$run.json"
  t0=$(date +%s.%N)
  timeout $((limit + 120)) "$cmx" map "$mesh" --boundary "$bnd" -o "$run" --format tmap,vtk \
    --report "$run.json" --time-limit "$limit" --threads 1 --quiet "${extra[@]}" 2>"$run.err"
  rc=$?; t1=$(date +%s.%N)
  sec=$(python3 -c "import sys;print(round(float(sys.argv[2]) - float(sys.argv[1]), 2))" "$t0" "$t1")
  growth=- dv=- check=- msg=
  if [ "$rc" -eq 0 ]; then
    read -r growth dv < <(python3 -c "
import json,sys; r=json.load(open(sys.argv[1])); v=r['verdict']
bad=v.get('double_inverted',0)+v.get('double_degenerate',0)
print(round(r['output']['growth_ratio'],4), 'valid' if v.get('double_valid') else '%d-bad' % bad)" "$run.json")
    check=skipped
    [ -f "$checker" ] && check=$(python3 "$checker" "$mesh" "$bnd" "$run.tmap" 2>/dev/null |
      python3 -c "import json,sys;print('valid' if json.loads(sys.stdin.read())['valid'] else 'INVALID')" 2>/dev/null)
  else
    msg=$(head -1 "$run.err" | cut -c1-160)
  fi
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' \
    "$m" "$s" "$tets" "$rc" "$sec" "$growth" "$dv" "${check:-error}" "$msg" >"$out/row_${name}_$sname.md"
}
export -f one_case
export cmx out limit checker spread
export EXTRA="${extra[*]:-}"

for m in "${meshes[@]}"; do
  name=fingers_$(echo "$m" | tr ',' '_')
  "$cmx" generate-mesh --shape "fingers:$m" --perturb 1 -o "$out/$name.vtk" --quiet ||
    { echo "| $m | generate-mesh failed |"; continue; }
done
rm -f "$out"/row_*.md
for m in "${meshes[@]}"; do for s in "${shapes[@]}"; do echo "$m $s"; done; done |
  xargs -P "${JOBS:-2}" -L 1 bash -c 'extra=($EXTRA); one_case "$0" "$1"'
printf '| fingers F,W,L | shape | tets | exit | seconds | growth | double valid | verify_tmap | message |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
for m in "${meshes[@]}"; do for s in "${shapes[@]}"; do
  f=$out/row_fingers_$(echo "$m" | tr ',' '_')_$(echo "$s" | tr ':' '_').md
  [ -f "$f" ] && cat "$f"
done; done
