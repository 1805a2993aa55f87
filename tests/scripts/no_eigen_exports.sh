#!/usr/bin/env bash
# No binary bipot links exports Eigen code (cmake/local_eigen.map): libgmsh exports the Eigen
# instantiations of its own build, and an exported copy on either side lets the other bind to
# it, mixing two Eigen builds' allocators (a heap-buffer-overflow under AddressSanitizer).
# Arguments: the binaries to check.
set -euo pipefail
status=0
for binary in "$@"; do
  found="$(nm -D --defined-only "$binary" | awk '{print $NF}' \
    | grep -E '^_Z(N|NK|ZN|ZNK|GVZN|GVZNK|TIN|TSN|TVN)5Eigen' || true)"
  if [ -n "$found" ]; then
    echo "$binary exports $(echo "$found" | wc -l) Eigen symbols, e.g.:" >&2
    echo "$found" | head -3 | c++filt >&2
    status=1
  fi
done
[ $status -eq 0 ] && echo "ok: no Eigen symbol exported by the $# binaries"
exit $status
