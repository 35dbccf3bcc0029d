#!/usr/bin/env bash
# Draws every bundled problem with the path PRM finds for seed 1 into problems/img/<name>.svg,
# the pictures of problems/README.md. Run from anywhere after a build:
#   scripts/render_problem_pictures.sh            # uses build/bin/amp
#   AMP=/path/to/amp scripts/render_problem_pictures.sh
# <name> is the problem file's name without its extension (maze.yaml -> img/maze.svg,
# ompl/gap_planar.cfg -> img/gap_planar.svg). A problem that finds no path still gets its picture
# (without a path), and the script reports it and exits non-zero at the end.
set -uo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
amp="${AMP:-$root/build/bin/amp}"
if [[ ! -x "$amp" ]]; then
  echo "render_problem_pictures: no amp binary at '$amp' (build first, or set AMP=...)" >&2
  exit 2
fi

out_dir="$root/problems/img"
mkdir -p "$out_dir"

failed=0
shopt -s nullglob
for problem in "$root"/problems/*.yaml "$root"/problems/ompl/*.cfg; do
  file="$(basename "$problem")"
  name="${file%.*}"
  svg="$out_dir/$name.svg"
  if "$amp" plan "$problem" --seed 1 --svg "$svg" --force >/dev/null; then
    echo "ok      ${problem#"$root"/} -> ${svg#"$root"/}"
  else
    echo "FAILED  ${problem#"$root"/} (exit $?; picture without a path, if any, at ${svg#"$root"/})" >&2
    failed=1
  fi
done
exit "$failed"
