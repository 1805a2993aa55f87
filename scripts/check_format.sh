#!/usr/bin/env bash
# Fails, listing the files and the command that fixes them, when a C++ file of the project
# differs from what clang-format 14 makes of it with the repository's .clang-format.
# Usage: scripts/check_format.sh [SOURCE_ROOT]   (CI runs it: scripts/test.sh --ci)
# Only clang-format 14: other versions format some constructs differently.
set -euo pipefail
root="$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/..}" && pwd)"
cd "$root"
formatter="${CLANG_FORMAT:-$(command -v clang-format-14 || true)}"
if [ -z "$formatter" ]; then
  echo "check_format: clang-format-14 not found (apt-get install clang-format-14)" >&2
  exit 2
fi
# The project's own files: tracked ones in a git checkout, otherwise every C++ file outside
# build folders.
if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git -C "$root" ls-files -- '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find fem contact materials apps tests -name '*.cpp' -o -name '*.hpp' \
    -o -name '*.h' | sort)
fi
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue # deleted in the work tree, not yet in the index
  "$formatter" --dry-run --Werror "$f" > /dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} of ${#files[@]} files are not formatted:" >&2
  printf '  %s\n' "${bad[@]}" >&2
  echo "fix them with:" >&2
  echo "  (cd $root && $(basename "$formatter") -i ${bad[*]})" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
