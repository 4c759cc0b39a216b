#!/usr/bin/env bash
# Usage: bench/map/compare_map_times.sh OLD_CMX NEW_CMX [ROUNDS] [DATA_DIR]
# Wall time of `cmx map --threads 1` for two builds on six shared cases (three by the default
# local repair, three by the global method), the builds alternated in every round so that a
# loaded machine slows both alike. Prints one line per run, then median and minimum per case.
set -u
old=$1; new=$2; rounds=${3:-5}
D=${4:-$(cd "$(dirname "$0")/../../.." && pwd)/shared/data}
[ -d "$D/volmap" ] || { echo "compare_map_times.sh: no data folder $D" >&2; exit 77; }
V=$D/volmap; S=$D/shrink-and-expand; out=$(mktemp -d)
cases=("foot_cube|$V/foot.mesh --boundary $V/foot_cube.txt"
       "bone_tet|$V/bone.mesh --boundary $V/bone_tet.txt"
       "t83715|$S/thingi10k_83715_domain.ovm --boundary $S/thingi10k_83715_tet_boundary.txt"
       "bone_tet_shrink|$V/bone.mesh --boundary $V/bone_tet.txt --init shrink"
       "t81152_shrink|$S/thingi10k_81152_domain.ovm --boundary $S/thingi10k_81152_random_star_boundary.txt --init shrink"
       "foot_octa_shrink|$V/foot.mesh --boundary $V/foot_octa.txt --init shrink")
for ((r = 1; r <= rounds; ++r)); do
  for c in "${cases[@]}"; do
    name=${c%%|*}; args=${c#*|}
    for tag in old new; do
      bin=$old; [ $tag = new ] && bin=$new
      s=$(date +%s.%N)
      # shellcheck disable=SC2086  # args is a word list on purpose
      "$bin" map $args -o "$out/$tag.tmap" --threads 1 > /dev/null 2>&1; rc=$?
      e=$(date +%s.%N)
      echo "$name $tag $r rc=$rc $(echo "$e - $s" | bc)"
    done
  done
done | tee "$out/times.txt"
python3 - "$out/times.txt" <<'PY'
import collections, statistics, sys
d = collections.defaultdict(list)
for line in open(sys.argv[1]):
    f = line.split(); d[(f[0], f[1])].append(float(f[4]))
for (name, tag), v in sorted(d.items()):
    print(f"{name} {tag} median {statistics.median(v):.3f} s, min {min(v):.3f} s, runs {len(v)}")
PY
rm -rf "$out"
