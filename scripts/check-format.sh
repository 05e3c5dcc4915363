#!/usr/bin/env bash
# Fails (listing the files) when C++ code, the shared GLSL/C++ headers included, differs
# from what clang-format makes of it with the checked-in .clang-format. GLSL-only files
# (*.comp, *.glsl) are not checked: clang-format has no GLSL mode.
set -euo pipefail
cd "$(dirname "$0")/.."
bad=()
while IFS= read -r f; do
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done < <(git ls-files '*.cpp' '*.h')
if [ ${#bad[@]} -gt 0 ]; then
  echo "check-format: not clang-formatted (run: clang-format -i FILE): ${bad[*]}" >&2
  exit 1
fi
echo "check-format: $(git ls-files '*.cpp' '*.h' | wc -l) files formatted"
