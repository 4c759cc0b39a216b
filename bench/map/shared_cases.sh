#!/usr/bin/env bash
# Runs `cmx map` on every case under ../shared/data (when present) and prints one table row per
# case: status, wall time, time per input tet, growth, largest coordinate bits, double validity,
# whether a second run writes a bit-identical .tmap (RERUN=0 skips it), and the independent
# checkers' verdicts on the exact map (../shared/tools/verify_tmap.py) and on the written doubles
# (../shared/tools/verify_doubles.py on the .vtk).
# Usage: bench/map/shared_cases.sh [CMX_BINARY] [OUT_DIR] [extra cmx map options...]
# CASES=REGEX runs only the cases whose name matches (grep -E), e.g. CASES='_star$'.
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=${1:-$here/build/release/cli/cmx}
out=${2:-/tmp/cmx-shared-cases}
shift 2 2>/dev/null || shift $#
extra=("$@")
data=$here/../shared/data
tools=$here/../shared/tools
[ -d "$data" ] || { echo "no shared data at $data"; exit 0; }
mkdir -p "$out"
printf '| case | status | tets in | seconds | s / input tet | growth | max bits | double valid | identical rerun | verify_tmap | verify_doubles |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|\n'
run_case() {  # name domain boundary-option boundary-path
  local name=$1 domain=$2 opt=$3 bnd=$4
  [ -z "${CASES:-}" ] || echo "$name" | grep -Eq "$CASES" || return 0
  local report=$out/$name.json
  rm -f "$out/$name.tmap" "$out/$name.vtk" "$report"
  "$cmx" map "$domain" "$opt" "$bnd" -o "$out/$name" --format vtk --report "$report" --quiet "${extra[@]}" >/dev/null 2>"$out/$name.err"
  local rc=$?
  local status tets secs growth bits dv check
  status=$(python3 -c "import json;print(json.load(open('$report'))['status'])" 2>/dev/null || echo "rc=$rc")
  if [ "$status" = success ]; then
    read -r tets secs growth bits dv < <(python3 - "$report" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(r['input']['tets'], round(r['seconds']['total'], 3), round(r['output']['growth_ratio'], 4), r['bits']['max'],
      'yes' if r['verdict']['double_valid'] else 'no')
PY
)
    local same=skipped
    if [ "${RERUN:-1}" != 0 ]; then
      "$cmx" map "$domain" "$opt" "$bnd" -o "$out/$name.again" --quiet "${extra[@]}" >/dev/null 2>&1
      same=$(cmp -s "$out/$name.tmap" "$out/$name.again.tmap" && echo yes || echo NO)
    fi
    local per; per=$(python3 -c "print('%.2e' % ($secs / $tets))")
    # (verify_tmap exits 1 on an invalid map: the verdict is read from its JSON, not its status)
    check=$(python3 "$tools/verify_tmap.py" "$domain" "$bnd" "$out/$name.tmap" 2>&1 |
            python3 -c "import json,sys;print('valid' if json.loads(sys.stdin.read())['valid'] else 'INVALID')" 2>/dev/null)
    [ -n "$check" ] || check=error
    # verify_tmap's float filter underflows on coordinates below about 1e-103 (bench/map/
    # exact_orientation.py says why); its INVALID then gets an exact second opinion on orientations.
    if [ "$check" != valid ]; then
      check="$check (exact orientations: $(python3 "$here/bench/map/exact_orientation.py" "$out/$name.tmap" 2>&1 |
              python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('%d target, %d source not positive' % (r['target_nonpositive'], r['source_nonpositive']))" 2>/dev/null || echo error))"
    fi
    local doubles
    doubles=$(python3 "$tools/verify_doubles.py" "$out/$name.vtk" 2>&1 | tail -1 |
              python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('valid' if r['valid'] else '%d inverted, %d flat' % (r['inverted'], r['degenerate']))" 2>/dev/null)
    [ -n "$doubles" ] || doubles=error
    printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" "$status" "$tets" "$secs" "$per" "$growth" "$bits" "$dv" "$same" "$check" "$doubles"
  else
    printf '| %s | %s | | | | | | | | %s | |\n' "$name" "$status" "$(head -c 120 "$out/$name.err" | tr '\n|' '  ')"
  fi
}
s=$data/shrink-and-expand
run_case prism "$s/prism_domain.ovm" --boundary "$s/prism_ball_boundary.txt"
run_case notch "$s/notch_domain.ovm" --boundary "$s/notch_stiff_tet_boundary.txt"
run_case thingi10k_83715 "$s/thingi10k_83715_domain.ovm" --boundary "$s/thingi10k_83715_tet_boundary.txt"
run_case thingi10k_81152 "$s/thingi10k_81152_domain.ovm" --boundary "$s/thingi10k_81152_random_star_boundary.txt"
for g in example cub_rockerarm291 tlc_polycube_bird tgs_100349; do
  run_case "gm_$g" "$data/galaxy-maps/${g}_object.vtk" --codomain "$data/galaxy-maps/${g}_parameter.vtk"
done
for p in "$data"/public/P*; do
  d=$(ls "$p"/domain.* | head -1)
  run_case "$(basename "$p")" "$d" --boundary "$p/boundary.txt"
done
v=$data/volmap
for m in bone foot octa_flower moai gargoyle; do
  for t in cube tet pyr octa star; do
    [ -f "$v/$m.mesh" ] && run_case "${m}_$t" "$v/$m.mesh" --boundary "$v/${m}_$t.txt"
  done
done
