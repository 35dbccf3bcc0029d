#!/usr/bin/env bash
# Installs the build tree into a temporary prefix, checks that every installed header compiles on
# its own against that prefix alone (no header may need one that is not installed), then builds and
# runs examples/plan_a_problem against the installed package, and imports the Python module from it. Usage: scripts/check-install.sh [BUILD]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" >/dev/null
headers=$(cd "$prefix/include" && find amp -name '*.hpp' | sort)
echo "check-install: $(echo "$headers" | wc -l) headers installed in $prefix"
# One source per header, compiled from inside the prefix with relative paths only, so that ccache
# (when installed) finds the same compilation in the next check, whatever the temporary prefix is
# called; without ccache, g++ alone. -c, not -fsyntax-only: ccache caches only compilations that
# write an object.
compiler=g++
if command -v ccache >/dev/null; then
  compiler="ccache g++"
  export CCACHE_SLOPPINESS=include_file_mtime,include_file_ctime
fi
mkdir -p "$prefix/header-check"
for h in $headers; do
  echo "#include <$h>" >"$prefix/header-check/$(echo "$h" | tr / _).cpp"
done
(cd "$prefix" && ls header-check/*.cpp | xargs -P "$(nproc)" -I{} sh -c \
  '$0 -std=c++20 -c -I include -I /usr/include/eigen3 {} -o {}.o \
     || { echo "check-install: {} does not compile alone against the install prefix"; exit 255; }' "$compiler")
cmake -S examples/plan_a_problem -B "$prefix/example" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$prefix/example" >/dev/null
"$prefix/example/plan_a_problem" problems/walls.yaml | grep -q 'status *solved'
echo "check-install: examples/plan_a_problem found amp::amp in the prefix and solved problems/walls.yaml"
if [ -d "$prefix/lib/python3/dist-packages" ]; then
  (cd "$prefix" && PYTHONPATH="$prefix/lib/python3/dist-packages" python3 -c "import amp; assert 'prm' in amp.planners()")
  echo "check-install: python3 -c 'import amp' works from the prefix"
fi
