#!/usr/bin/env bash
# Fuzzes one of bipot's input readers with libFuzzer under ASan + UBSan (docs/testing.md).
# Usage: scripts/fuzz.sh [yaml|msh] [seconds]     (defaults: yaml, 60)
#   yaml  the YAML input reader (read_problem_text), from tests/fuzz/corpus_yaml
#   msh   the .msh reader (read_gmsh, bipot's own MSH 4.1 parser), from tests/fuzz/corpus_msh
# Installs clang if missing, builds only the harness (clang, -DBIPOT_FUZZ=ON) into
# build-fuzz/ (FUZZ_BUILD_DIR), and fuzzes for the given time. New inputs go to
# build-fuzz/fuzz-work/<reader>/corpus; a crash is saved in build-fuzz/fuzz-work/<reader>/ and
# ends the run with a non-zero exit code. Extra arguments after the seconds go to libFuzzer
# (e.g. `-fork=1 -ignore_crashes=1` to go on after a crash; crashes are still saved).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
reader="${1:-yaml}"
seconds="${2:-60}"
shift $(( $# < 2 ? $# : 2 ))
case "$reader" in
  yaml) flags=(-max_len=4096 -timeout=10) ;;
  # An input is read in well under a millisecond; a hang is a finding.
  msh) flags=(-max_len=4096 -timeout=20) ;;
  *) echo "usage: scripts/fuzz.sh [yaml|msh] [seconds]" >&2; exit 1 ;;
esac
build_dir="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${JOBS:-$BIPOT_JOBS}"

# libFuzzer is in libclang-rt-14-dev (Debian 12's clang 14 recommends it; installed explicitly
# because the scripts install with --no-install-recommends).
missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "fuzz: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" > "${TMPDIR:-/tmp}/bipot-apt.log"
fi
# The rest of bipot's dependencies: the normal set-up's packages.
"$root/scripts/setup.sh" --packages-only

mkdir -p "$build_dir"
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  CXX=clang++ cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Debug -DBIPOT_FUZZ=ON \
    > "$build_dir/configure.log" 2>&1 || { cat "$build_dir/configure.log" >&2; exit 1; }
fi
cmake --build "$build_dir" -j "$jobs" --target "fuzz_$reader"

source "$root/scripts/sanitize_env.sh"
work="$build_dir/fuzz-work/$reader"
mkdir -p "$work/corpus"
echo "fuzz: $reader for $seconds s; new inputs in $work/corpus"
cd "$work"
exec "$build_dir/tests/fuzz/fuzz_$reader" -max_total_time="$seconds" -print_final_stats=1 \
  -dict="$root/tests/fuzz/$reader.dict" -artifact_prefix="$work/" "${flags[@]}" "$@" \
  "$work/corpus" "$root/tests/fuzz/corpus_$reader"
