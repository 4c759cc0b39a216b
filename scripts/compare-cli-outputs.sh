#!/usr/bin/env bash
# Usage: scripts/compare-cli-outputs.sh CMX_BINARY OUTDIR [DATA_DIR] — runs cmx map on the shared cases with several option
# sets; writes every output file, stdout/stderr (timings masked) and exit code into OUTDIR.
# Run it with two builds of cmx and `diff -r` the folders: what differs is what the change changed
# Timings and the report's cmx_version are masked in stdout, reports and traces. Besides the shared
# cases (needs DATA_DIR), it maps generated meshes with the generated boundary shapes of
# bench/map/generated_cases.sh (smaller sizes), the meshes and boundaries written by the binary itself.
set -u
bin=$(realpath "$1"); out=$2; rm -rf "$out"; mkdir -p "$out"; out=$(realpath "$out")
S=${3:-$(cd "$(dirname "$0")/../.." && pwd)/shared/data}
[ -d "$S" ] || { echo "compare-cli-outputs.sh: no data folder $S" >&2; exit 77; }
run() { # name, args...
  local name=$1; shift
  ( cd "$out" && "$bin" map "$@" -o "$name.vtu" --format ovm --report "$name.json" --trace "$name.csv" \
      > "$name.stdout" 2> "$name.stderr"; echo $? > "$name.rc" )
  # mask timings in text outputs
  sed -i -E 's/[0-9]+\.[0-9]+ s$/T s/' "$out/$name.stdout"
  [ -f "$out/$name.json" ] && sed -i -E 's/"cmx_version": "[^"]*"/"cmx_version": "V"/' "$out/$name.json"
  [ -f "$out/$name.json" ] && sed -i -E '/"(peak_rss_kb|validate|preprocess|expand|subcluster_search|shelling_search|collapse|double|verify|total|initial_map|classify_and_grow|map_stars|stitch)": [0-9.e+-]+/s/: [0-9.e+-]+/: T/' "$out/$name.json"
  [ -f "$out/$name.csv" ] && awk -F, 'BEGIN{OFS=","} NR>1{$12="T"} {print}' "$out/$name.csv" > "$out/$name.csv.m" && mv "$out/$name.csv.m" "$out/$name.csv"
}
run prism $S/shrink-and-expand/prism_domain.ovm --boundary $S/shrink-and-expand/prism_ball_boundary.txt
run prism_shrink $S/shrink-and-expand/prism_domain.ovm --boundary $S/shrink-and-expand/prism_ball_boundary.txt --init shrink --no-merge
run prism_double $S/shrink-and-expand/prism_domain.ovm --boundary $S/shrink-and-expand/prism_ball_boundary.txt --init shrink --arith double
run notch $S/shrink-and-expand/notch_domain.ovm --boundary $S/shrink-and-expand/notch_stiff_tet_boundary.txt
run notch_nearest $S/shrink-and-expand/notch_domain.ovm --boundary $S/shrink-and-expand/notch_stiff_tet_boundary.txt --snap nearest --no-flip-collapse --no-collapse-refinement
run t83715 $S/shrink-and-expand/thingi10k_83715_domain.ovm --boundary $S/shrink-and-expand/thingi10k_83715_tet_boundary.txt
run t81152 $S/shrink-and-expand/thingi10k_81152_domain.ovm --boundary $S/shrink-and-expand/thingi10k_81152_random_star_boundary.txt --threads 1
run gm_example $S/galaxy-maps/example_object.vtk --codomain $S/galaxy-maps/example_parameter.vtk
run gm_example_codomain $S/galaxy-maps/example_object.vtk --codomain $S/galaxy-maps/example_parameter.vtk --init codomain
run tgs $S/galaxy-maps/tgs_100349_object.vtk --codomain $S/galaxy-maps/tgs_100349_parameter.vtk
run rocker $S/galaxy-maps/cub_rockerarm291_object.vtk --codomain $S/galaxy-maps/cub_rockerarm291_parameter.vtk
for p in P01:vtk P02:ovm P03:ovm P04:ovm P05:ovm P06:ovm P07:ovm P09:mesh P10:ovm; do
  c=${p%%:*}; e=${p##*:}
  run $c $S/public/$c/domain.$e --boundary $S/public/$c/boundary.txt --time-limit 120
done
run foot_cube $S/volmap/foot.mesh --boundary $S/volmap/foot_cube.txt
run prism_sphere $S/shrink-and-expand/prism_domain.ovm --shape sphere
# failures
run fail_time $S/shrink-and-expand/notch_domain.ovm --boundary $S/shrink-and-expand/notch_stiff_tet_boundary.txt --init shrink --time-limit 0.01
run fail_mismatch $S/shrink-and-expand/notch_domain.ovm --boundary $S/shrink-and-expand/prism_ball_boundary.txt
run fail_notstar $S/shrink-and-expand/prism_domain.ovm --shape star:0
run fail_option $S/shrink-and-expand/prism_domain.ovm --shape sphere --filter bogus
# generated cases: the binary writes the mesh and the boundary, then maps them
mkdir -p "$out/gen"
for m in grid:8,8,8 ball:6 slab:20,16,1; do
  g=$(echo "$m" | tr ':,' '__')
  "$bin" generate-mesh --shape "$m" --perturb 1 -o "$out/gen/$g.vtk" > /dev/null 2>&1
  for s in tet stiff-tet sphere star:7; do
    b=$(echo "$s" | tr ':' '_')
    "$bin" boundary "$out/gen/$g.vtk" --shape "$s" -o "$out/gen/${g}_$b.txt" > /dev/null 2>&1
    run "gen_${g}_$b" "gen/$g.vtk" --boundary "gen/${g}_$b.txt"  # relative: the report names it
  done
done
true
