#!/usr/bin/env bash
# CTest (registered when MPI is found): `mpirun -n 2 amp bench` gives the runs of a one-process run.
set -euo pipefail
amp=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
exp="$src/problems/experiments/quick.yaml"
"$amp" bench "$exp" --runs 3 -j 2 --out "$work/single" >/dev/null
extra=()
[ "$(id -u)" -eq 0 ] && extra+=(--allow-run-as-root)
mpirun "${extra[@]}" --oversubscribe -n 2 "$amp" bench "$exp" --runs 3 -j 1 --out "$work/mpi" >/dev/null
# Every column but wall_time_s (the 8th) must be equal, row for row.
strip() { cut -d, -f1-7,9- "$1"; }
diff <(strip "$work/single/runs.csv") <(strip "$work/mpi/runs.csv")
for f in summary.json results.db report.html manifest.json; do test -s "$work/mpi/$f"; done
echo "mpirun -n 2: identical runs ($(($(wc -l < "$work/mpi/runs.csv") - 1)) rows)"
