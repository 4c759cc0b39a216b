#!/usr/bin/env bash
# Generates the synthetic mapping dataset: the project's own meshes (jittered Freudenthal grids and
# voxel balls: thick; one- and two-layer slabs: thin, most or all tets touching the boundary), from
# about 1k to 50k tets, each with two jitter seeds, times the four boundary shapes of `cmx
# boundary` (star with a seed of its own). Reproducible: the same command writes the same files.
# Writes DIR/meshes/*.vtk, DIR/boundaries/*.txt and DIR/cases.txt (one line per case:
# "name mesh boundary tets").
# Usage: bench/dataset/generate.sh [CMX_BINARY] [DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cmx=${1:-$here/build/release/cli/cmx}
dir=${2:-/tmp/cmx-dataset}
mkdir -p "$dir/meshes" "$dir/boundaries"
meshes=(
  "grid:6,6,5" "grid:10,10,10" "grid:16,12,10" "grid:30,10,5" "grid:20,20,20"  # thick
  "ball:4" "ball:7" "ball:10"                                                  # thick, round
  "slab:20,15,2" "slab:40,30,2" "slab:60,50,2"                                 # thin, 2 layers
  "slab:25,20,1" "slab:50,40,1"                                                # thin, no interior vertex
)
shapes=("tet" "stiff-tet" "sphere" "star")
: > "$dir/cases.txt.tmp"
for m in "${meshes[@]}"; do
  for seed in 1 2; do
    name=$(echo "$m" | tr ':,' '__')_s$seed
    mesh=$dir/meshes/$name.vtk
    [ -f "$mesh" ] || "$cmx" generate-mesh --shape "$m" --perturb "$seed" -o "$mesh" >/dev/null 2>&1
    tets=$(awk '/^CELLS/ {print $2; exit}' "$mesh")
    for s in "${shapes[@]}"; do
      shape=$s
      [ "$s" = star ] && shape="star:$((seed * 7))"
      bnd=$dir/boundaries/${name}_$s.txt
      [ -f "$bnd" ] || "$cmx" boundary "$mesh" --shape "$shape" -o "$bnd" >/dev/null 2>&1
      echo "${name}_$s $mesh $bnd $tets" >> "$dir/cases.txt.tmp"
    done
  done
done
mv "$dir/cases.txt.tmp" "$dir/cases.txt"
echo "$(wc -l < "$dir/cases.txt") cases in $dir/cases.txt"
