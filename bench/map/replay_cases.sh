#!/usr/bin/env bash
# The shelling replay of issue 21 point 4 (paper Sec. 4.3, Alg. 2) on the project's shellable
# inputs with a NOBUENOSS, one Markdown row per run:
# - the collared dunce-hat balls (`cmx generate-mesh --shape dunce-hat-ball:C`) with the hat
#   deferred (`--order priority,defer:A-B`, the last 8 ids): the greedy loop meets the hat as a
#   NOBUENOSS and the run replays a shelling after it;
# - the compact Bing's house in a box with the house deferred and the replay forced from the start
#   (`--init shrink --replay-shelling until-greedy`): the greedy loop alone passes the house, so
#   this asks whether the replay scales to a house-sized NOBUENOSS deep inside a mesh.
# Columns: exit, wall seconds, the report's replay figures (plans tried, the last replay's
# --shelled mode, times planned again part-way, planned expansions, splits made, refinement
# vertices drained, drains that gave up), output vertices, the doubles' verdict, and the
# independent checker's verdict. The dunce-hat balls are combinatorial (no source geometry), so
# they are checked with the shared tools' functions (every target tet positive by balltopo's exact
# orient, the output a ball); the house box with verify_tmap.py's command line against the same
# boundary.
# - with SUBDIVIDED="C:SEED:EDGES:TETS ...", the same balls after random stellar subdivisions
#   (bench/map/subdivide_facets.py: EDGES edge splits, never of a hat edge, then TETS tet splits,
#   with Python's random.Random(SEED)), the hat deferred as before: inputs the replay was not tuned on.
# Usage: bench/map/replay_cases.sh CMX OUT_DIR [LIMIT_SECONDS=300]
# COLLARS="1 2 ..." and SHAPES="sphere tet ..." replace the default lists (empty: none); HOUSE=0
# skips the box.
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=$1 out=$2 limit=${3:-300}
tools=$here/../shared/tools
collars=(${COLLARS-1 2 3 4 5 6 7 8 10 12 16 20 32})
shapes=(${SHAPES-sphere tet stiff-tet star star:2 star:3})
mkdir -p "$out"
if [ ! -f "$tools/verify_tmap.py" ]; then
  echo "skipped: $tools/verify_tmap.py is absent (the checkers live in ../shared/tools)" >&2
  exit 2
fi

check_combinatorial() {  # TMAP -> "positive, ball" or what failed
  python3 - "$tools" "$1" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from verify_tmap import read_tmap
from balltopo import check, orient
S, Tg, T = read_tmap(sys.argv[2])
# Exactly, on the rationals: verify_tmap.positive_count's float filter misjudged 762 of the 18,137
# tets of one output here (coordinates of hundreds of bits), all positive exactly.
bad = sum(1 for t in T if not orient(*(Tg[k] for k in t)) > 0)
ball = check([tuple(map(str, s)) for s in S], T, do_collapse=False)[0]['is_ball']
print(("positive" if bad == 0 else f"{bad} non-positive") + (", ball" if ball else ", NOT a ball"))
PY
}

report_fields() {  # REPORT.json -> "plans_tried | shelled | replans | expansions | splits | drained | drains_left | out_V | doubles"
  python3 - "$1" <<'PY'
import json, sys
try:
    r = json.load(open(sys.argv[1]))
except Exception:
    print("- | - | - | - | - | - | - | - | -"); sys.exit()
p = r.get("expansion", {}).get("replay", {})
g = lambda k: str(p.get(k, "-"))
out_v = r.get("output", {}).get("vertices", "-")
dv = r.get("verdict", {}).get("double_valid", "-")
print(" | ".join([g("plans_tried"), g("shelled"), g("replans"), g("expansions"), g("splits"), g("drained"), g("drains_left"),
                  str(out_v), {True: "yes", False: "no"}.get(dv, str(dv))]))
PY
}

run_case() {  # NAME MESH SHAPE CHECK_KIND [cmx map options...]
  local name=$1 mesh=$2 shape=$3 kind=$4 run rc t0 t1 sec check
  shift 4
  run=$out/${name}_$(echo "$shape" | tr ':' '_')
  rm -f "$run.tmap" "$run.json"
  t0=$(date +%s.%N)
  timeout $((limit + 120)) "$cmx" map "$mesh" --shape "$shape" -o "$run.tmap" --report "$run.json" \
    --report-on-failure --time-limit "$limit" --threads 1 --quiet "$@" 2>"$run.err"
  rc=$?; t1=$(date +%s.%N)
  sec=$(python3 -c "import sys;print(round(float(sys.argv[2]) - float(sys.argv[1]), 2))" "$t0" "$t1")
  check=-
  if [ "$rc" -eq 0 ]; then
    if [ "$kind" = combinatorial ]; then
      check=$(check_combinatorial "$run.tmap")
    else
      "$cmx" boundary "$mesh" --shape "$shape" -o "$run.bnd.txt" --quiet
      check=$(python3 "$tools/verify_tmap.py" "$mesh" "$run.bnd.txt" "$run.tmap" |
        python3 -c "import json,sys; print('valid' if json.load(sys.stdin)['valid'] else 'INVALID')")
    fi
  else
    check="exit $rc: $(head -c 160 "$run.err" | tr '\n|' ' /')"
  fi
  printf '| %s | %s | %s | %s | %s | %s |\n' "$name" "$shape" "$rc" "$sec" "$(report_fields "$run.json")" "$check"
}

echo "| case | shape | exit | seconds | plans tried | last mode | planned again | planned expansions | splits | drained | drains given up | output vertices | doubles valid | check |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for c in "${collars[@]}"; do
  mesh=$out/dunce_$c.facets
  "$cmx" generate-mesh --shape "dunce-hat-ball:$c" -o "$mesh" --quiet
  n=$((21 + 6 * c))  # vertices: the hat's 8 are the last ids
  for s in "${shapes[@]}"; do
    run_case "dunce-hat-ball:$c" "$mesh" "$s" combinatorial --order "priority,defer:$((n - 8))-$n"
  done
done
for spec in ${SUBDIVIDED:-}; do
  IFS=: read -r c seed edges tets <<<"$spec"
  "$cmx" generate-mesh --shape "dunce-hat-ball:$c" -o "$out/dunce_$c.facets" --quiet
  n=$((21 + 6 * c))
  mesh=$out/dunce_${c}_s${seed}_${edges}_${tets}.facets
  python3 "$here/bench/map/subdivide_facets.py" "$out/dunce_$c.facets" "$mesh" $((n - 8)) "$n" "$seed" "$edges" "$tets"
  for s in "${shapes[@]}"; do
    run_case "dunce-hat-ball:$c+s$seed:$edges:$tets" "$mesh" "$s" combinatorial --order "priority,defer:$((n - 8))-$n"
  done
done
if [ "${HOUSE:-1}" != 0 ]; then
  mesh=$out/compact_house_box.ovm
  "$cmx" generate-mesh --shape compact-bings-house-box -o "$mesh" --quiet
  for s in "${shapes[@]}"; do
    run_case compact-bings-house-box "$mesh" "$s" geometric --init shrink \
      --order priority,defer:1176-1485 --replay-shelling until-greedy
  done
fi
