#!/usr/bin/env bash
# Runs every case of a dataset (bench/dataset/generate.sh) through GNU parallel: one `cmx map`
# process per case, each with its own --time-limit just under parallel's --timeout, a joblog, and
# --resume so that an interrupted run continues with the unfinished cases. One JSON report per
# case in RESULTS_DIR/reports/ (the exact maps are written to RESULTS_DIR/maps/ and checked by the
# program itself; delete them if space matters).
# Usage: bench/dataset/run.sh DATASET_DIR RESULTS_DIR [CMX_BINARY] [-- extra parallel options]
#   CMX_TIME_LIMIT  per-case limit in seconds (default 300); parallel kills at limit + 30
#   CMX_JOBS        parallel jobs (default: one per core)
#   CMX_MAP_OPTIONS extra `cmx map` options, e.g. "--smooth 10" or "--snap nearest"
# Many machines: pass parallel's own options after --, e.g. `-- --sshloginfile hosts.txt`
# (DATASET_DIR, RESULTS_DIR and the binary must be at the same paths on every host, e.g. a
# shared filesystem); README "Dataset benchmark" has a Slurm job-array recipe too.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,14p' "$0"; exit 2; }
here=$(cd "$(dirname "$0")/../.." && pwd)
dataset=$(cd "$1" && pwd)
results=$2
shift 2
cmx=$here/build/release/cli/cmx
if [ $# -gt 0 ] && [ "$1" != "--" ]; then cmx=$(realpath "$1"); shift; fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
command -v parallel >/dev/null || { echo "run.sh: GNU parallel is missing (apt-get install parallel)" >&2; exit 2; }
limit=${CMX_TIME_LIMIT:-300}
mkdir -p "$results/reports" "$results/maps" "$results/logs"
results=$(cd "$results" && pwd)
# One job: the case's name, mesh, boundary (columns of cases.txt). The report exists for every
# outcome cmx itself can report (success, time limit, stuck, bad input); a case killed by
# parallel's timeout has none, which the summary counts as a timeout.
parallel --colsep ' ' --joblog "$results/joblog.txt" --resume --timeout $((limit + 30)) \
  ${CMX_JOBS:+-j "$CMX_JOBS"} --halt never "$@" \
  "$cmx" map {2} --boundary {3} -o "$results/maps/{1}" --report "$results/reports/{1}.json" \
  --time-limit "$limit" --quiet ${CMX_MAP_OPTIONS:-} '>' "$results/logs/{1}.out" '2>' "$results/logs/{1}.err" \
  :::: "$dataset/cases.txt" || true
echo "finished: $(ls "$results/reports" | wc -l) reports of $(wc -l < "$dataset/cases.txt") cases in $results"
