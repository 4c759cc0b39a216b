#!/usr/bin/env bash
# cmx and a peer program side by side, one run each, on every case under ../shared/data. The peer
# is Galaxy Maps (galaxy-maps pairs as they are; the other cases through ../shared/tools/to_gm.py)
# or, when PEER's file name is ShrinkAndExpand, the Shrink-and-Expand program (domains as
# OpenVolumeMesh files, converted by `cmx convert` where they are not; boundary files as they
# are; the galaxy-maps pairs, which have no boundary file, left out; its exact map checked by
# bench/map/sae_map_to_vtk.py, its doubles being the nearest ones of that). One table row per case:
# for each program its exit, wall seconds, growth (output / input vertices) and whether its
# doubles are a valid map (../shared/tools/verify_doubles.py; cmx also verifies exactly, and
# its .tmap goes through verify_tmap.py, with bench/map/exact_orientation.py as a second opinion
# where that checker's float filter underflows), then the time ratio peer / cmx. A run
# under $REPEAT_BELOW seconds (default 2) is repeated to 5 runs and its median time reported:
# a single run of a 10 ms case is mostly process start-up noise.
# Both peers are built outside the repository by ../shared/tools/build-anchors.sh.
# Usage: bench/map/peers.sh CMX PEER OUT_DIR [LIMIT_SECONDS=600] [extra cmx map options...]
# CASES=REGEX runs only the cases whose name matches (grep -E), e.g. CASES='^(P07|bone_.*)$'.
# GM_LIMIT=S stops the peer after S seconds instead of LIMIT_SECONDS (Galaxy Maps fails on most
# star targets by running out of time, which otherwise dominates the run).
set -uo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=$1 gm=$2 out=$3
peer=gm
[ "$(basename "$gm")" = ShrinkAndExpand ] && peer=sae
limit=${4:-600}
gm_limit=${GM_LIMIT:-$limit}
shift 4 2>/dev/null || shift $#
extra=("$@")
data=$here/../shared/data
tools=$here/../shared/tools
[ -d "$data" ] || { echo "no shared data at $data"; exit 0; }
mkdir -p "$out"

seconds() { python3 -c "import sys;print(round(float(sys.argv[2]) - float(sys.argv[1]), 3))" "$1" "$2"; }
repeat_below=${REPEAT_BELOW:-2}
# timed CMD...: runs CMD, prints "rc seconds"; under $repeat_below seconds and successful, 4 more
# runs and the median of the 5 times.
timed() {
  local t0 t1 rc times
  t0=$(date +%s.%N); "$@"; rc=$?; t1=$(date +%s.%N)
  times=$(seconds "$t0" "$t1")
  if [ "$rc" -eq 0 ] && python3 -c "import sys;sys.exit(0 if float(sys.argv[1]) < float(sys.argv[2]) else 1)" "$times" "$repeat_below"; then
    for _ in 1 2 3 4; do t0=$(date +%s.%N); "$@"; t1=$(date +%s.%N); times="$times $(seconds "$t0" "$t1")"; done
    times=$(python3 -c "import sys,statistics;print(round(statistics.median(map(float,sys.argv[1:])),3))" $times)
  fi
  echo "$rc $times"
}
points() { awk '/^POINTS/ {print $2; exit}' "$1"; }

cmx_case() {  # name domain option input -> "rc seconds growth doubles checker"
  local name=$1 domain=$2 opt=$3 input=$4 report=$out/$name.json
  rm -f "$out/$name.tmap" "$out/$name.vtk" "$report"
  local rc sec
  run() {
    timeout $((limit + 60)) "$cmx" map "$domain" "$opt" "$input" -o "$out/$name" --format tmap,vtk \
      --report "$report" --time-limit "$limit" --quiet "${extra[@]}" >/dev/null 2>"$out/$name.err"
  }
  read -r rc sec < <(timed run)
  if [ "$rc" -ne 0 ]; then echo "$rc $sec - - -"; return; fi
  local growth dv check
  growth=$(python3 -c "import json,sys;print(round(json.load(open(sys.argv[1]))['output']['growth_ratio'],4))" "$report")
  dv=$(python3 "$tools/verify_doubles.py" "$out/$name.vtk" 2>/dev/null |
       python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('valid' if r['valid'] else '%d-bad' % (r['inverted']+r['degenerate']))" 2>/dev/null)
  check=$(python3 "$tools/verify_tmap.py" "$domain" "$input" "$out/$name.tmap" 2>/dev/null |
          python3 -c "import json,sys;print('valid' if json.loads(sys.stdin.read())['valid'] else 'INVALID')" 2>/dev/null)
  if [ "$check" != valid ] && python3 "$here/bench/map/exact_orientation.py" "$out/$name.tmap" >/dev/null 2>&1; then
    check="exact-valid"  # positive in exact rationals: the checker's float filter underflowed
  fi
  echo "$rc $sec $growth ${dv:-error} ${check:-error}"
}

gm_case() {  # name object parameter input-vertices -> "rc seconds growth doubles"
  local name=$1 object=$2 parameter=$3 n=$4 prefix=$out/gm_$name
  rm -f "${prefix}_object.vtk" "${prefix}_parameter.vtk"
  local rc sec
  run() { timeout "$gm_limit" "$gm" "$object" "$parameter" -t -o "$prefix" >"$out/gm_$name.log" 2>&1; }
  read -r rc sec < <(timed run)
  if [ "$rc" -ne 0 ] || [ ! -s "${prefix}_parameter.vtk" ]; then echo "$rc $sec - -"; return; fi
  local growth dv
  growth=$(python3 -c "print(round($(points "${prefix}_parameter.vtk") / $n, 4))")
  dv=$(python3 "$tools/verify_doubles.py" "${prefix}_parameter.vtk" --negative 2>/dev/null |
       python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('valid' if r['valid'] else '%d-bad' % (r['inverted']+r['degenerate']))" 2>/dev/null)
  echo "$rc $sec $growth ${dv:-error}"
}

# The Shrink-and-Expand program writes its map (the refined codomain, doubles plus exact strings)
# only on success, and a debug file into its working directory: it runs in a scratch folder.
sae_case() {  # name domain boundary input-vertices -> "rc seconds growth doubles"
  local name=$1 domain=$2 boundary=$3 n=$4 dir=$out/sae_$name
  rm -rf "$dir"; mkdir -p "$dir"
  local ovm=$domain
  if [ "${domain##*.}" != ovm ]; then
    ovm=$dir/domain.ovm
    "$cmx" convert "$domain" "$ovm" >/dev/null 2>&1 || { echo "convert - - -"; return; }
  fi
  local rc sec
  run() { (cd "$dir" && timeout "$gm_limit" "$gm" "$ovm" "$dir/map.ovm" 0 "$boundary" 0 >"$dir/log" 2>&1); }
  read -r rc sec < <(timed run)
  if [ ! -s "$dir/map.ovm" ]; then echo "$rc $sec - -"; return; fi
  # Its exact map, checked exactly, and the nearest doubles of it (its own vertex lines have 6 digits).
  local exact
  exact=$(python3 "$here/bench/map/sae_map_to_vtk.py" "$dir/map.ovm" "$dir/map.vtk" 2>/dev/null |
          python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('' if r['valid'] else ',exact-%d-bad' % (r['inverted']+r['degenerate']))" 2>/dev/null) ||
    { echo "$rc $sec - unreadable"; return; }
  local growth dv
  growth=$(python3 -c "print(round($(points "$dir/map.vtk") / $n, 4))")
  dv=$(python3 "$tools/verify_doubles.py" "$dir/map.vtk" 2>/dev/null |
       python3 -c "import json,sys;r=json.loads(sys.stdin.read());print('valid' if r['valid'] else '%d-bad' % (r['inverted']+r['degenerate']))" 2>/dev/null)
  echo "$rc $sec $growth ${dv:-error}$exact"
}

row() {  # name domain option input object parameter
  local name=$1 domain=$2 opt=$3 input=$4 object=$5 parameter=$6
  [ -z "${CASES:-}" ] || grep -qE "$CASES" <<<"$name" || return 0
  [ $peer = sae ] && [ "$opt" != --boundary ] && return 0
  local n; n=$(python3 -c "
import sys; sys.path.insert(0, '$tools')
from balltopo import read_any
print(len(read_any('$domain')[0]))")
  read -r crc csec cgrow cdbl cchk < <(cmx_case "$name" "$domain" "$opt" "$input")
  if [ $peer = sae ]; then
    read -r grc gsec ggrow gdbl < <(sae_case "$name" "$domain" "$input" "$n")
  else
    read -r grc gsec ggrow gdbl < <(gm_case "$name" "$object" "$parameter" "$n")
  fi
  local ratio=-
  [ "$crc" = 0 ] && [ "$grc" = 0 ] && ratio=$(python3 -c "print(round($gsec / max($csec, 0.001), 2))")
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' \
    "$name" "$crc" "$csec" "$cgrow" "$cdbl" "$cchk" "$grc" "$gsec" "$ggrow" "$gdbl" "$ratio" "$n"
}

P=GM; [ $peer = sae ] && P=SaE
printf '| case | cmx exit | cmx s | cmx growth | cmx doubles | cmx exact map | %s exit | %s s | %s growth | %s doubles | %s s / cmx s | input vertices |\n' $P $P $P $P $P
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for g in example cub_rockerarm291 tlc_polycube_bird tgs_100349; do
  o=$data/galaxy-maps/${g}_object.vtk p=$data/galaxy-maps/${g}_parameter.vtk
  row "gm_$g" "$o" --codomain "$p" "$o" "$p"
done
convert_and_row() {  # name domain boundary
  local name=$1 domain=$2 boundary=$3
  [ -z "${CASES:-}" ] || grep -qE "$CASES" <<<"$name" || return 0
  [ $peer = sae ] && { row "$name" "$domain" --boundary "$boundary" - -; return; }
  python3 "$tools/to_gm.py" "$domain" "$boundary" "$out/in_$name" >/dev/null 2>&1 ||
    { printf '| %s | to_gm.py failed |\n' "$name"; return; }
  row "$name" "$domain" --boundary "$boundary" "$out/in_${name}_object.vtk" "$out/in_${name}_parameter.vtk"
}
s=$data/shrink-and-expand
convert_and_row prism "$s/prism_domain.ovm" "$s/prism_ball_boundary.txt"
convert_and_row notch "$s/notch_domain.ovm" "$s/notch_stiff_tet_boundary.txt"
convert_and_row thingi10k_83715 "$s/thingi10k_83715_domain.ovm" "$s/thingi10k_83715_tet_boundary.txt"
convert_and_row thingi10k_81152 "$s/thingi10k_81152_domain.ovm" "$s/thingi10k_81152_random_star_boundary.txt"
for p in "$data"/public/P*; do
  [ "$(basename "$p")" = P10 ] && continue  # not star-shaped: both refuse it
  convert_and_row "$(basename "$p")" "$(ls "$p"/domain.* | head -1)" "$p/boundary.txt"
done
for m in bone foot octa_flower gargoyle moai; do
  for t in cube tet pyr octa star; do
    convert_and_row "${m}_$t" "$data/volmap/$m.mesh" "$data/volmap/${m}_$t.txt"
  done
done
