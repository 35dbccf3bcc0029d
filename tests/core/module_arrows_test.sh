#!/usr/bin/env bash
# Layout check: no module includes a module above it (ARCHITECTURE.md, "Module graph"), and in
# roadmap only uas/ uses learn. Prints each offending include; exits 1 if there is one.
set -euo pipefail
root=${1:?usage: module_arrows_test.sh SOURCE_DIR}
declare -A allowed=(
  [core]="core" [stats]="core stats" [world]="core world" [learn]="core learn"
  [roadmap]="core world learn roadmap" [nav]="core stats world learn nav" [viz]="core world roadmap stats viz"
  [study]="core world learn nav stats viz study" [bench]="core world learn nav roadmap stats viz study bench")
bad=0
for module in "${!allowed[@]}"; do
  for dir in "$root/src/$module" "$root/include/amp/$module"; do
    [[ -d $dir ]] || continue
    while IFS=: read -r file line target; do
      used=${target%%/*}
      if [[ " ${allowed[$module]} " != *" $used "* ]]; then
        echo "${file#$root/}:$line: $module includes amp/$target"
        bad=1
      fi
    done < <(grep -rnoE '#include "amp/[a-z_]+/[^"]*"' "$dir" | sed -E 's|#include "amp/||; s|"$||')
  done
done
while IFS= read -r hit; do
  echo "${hit#$root/}: learn used outside roadmap/uas"
  bad=1
done < <(grep -rlE '#include "amp/learn/' "$root/src/roadmap" "$root/include/amp/roadmap" 2>/dev/null | grep -v '/uas/' || true)
exit $bad
