#!/usr/bin/env bash
# `amp view` pages in headless Chromium (tests/viz/viewer_browser_check.py): one page per kind of
# world and robot, each playing a path `amp plan` found: an SE(3) rigid body among boxes and
# spheres, a 7-DOF arm (the Panda, every link posed), a SCARA arm, a planar linkage and a disc on
# an occupancy map; and OMPL.app's Twistycool when ../shared is there. Each page must load with no
# error, and the robot's pixels must move when the slider moves. Exit 77 (skipped) without Chromium.
# Usage: viewer_browser_test.sh AMP_BINARY SOURCE_DIR
set -euo pipefail
amp="$1"
src="$2"
command -v "${AMP_CHROMIUM:-chromium}" >/dev/null 2>&1 || { echo "chromium is not installed: skipped"; exit 77; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
pages=()
for problem in walls3d panda-box scara-wicket linkage office-map; do
  "$amp" plan "$src/problems/$problem.yaml" --seed 1 --out "$work/$problem.path" > "$work/$problem.log"
  "$amp" view "$src/problems/$problem.yaml" --path "$work/$problem.path" -o "$work/$problem.html" > /dev/null
  pages+=("$work/$problem.html")
done
# OMPL.app's Twistycool with its reference solution, where ../shared is (as in CI): a rigid body
# through a narrow passage inside a closed box, which the page's cutaway must open.
twisty="$src/../shared/omplapp/Twistycool"
if [ -f "$twisty.cfg" ]; then
  "$amp" view "$twisty.cfg" --path "$twisty.path" -o "$work/twistycool.html" > /dev/null
  pages+=("$work/twistycool.html")
fi
python3 "$src/tests/viz/viewer_browser_check.py" "${pages[@]}"
