#!/usr/bin/env bash
# Installs the Debian packages bipot needs (only those missing), then configures and builds
# Release into build/. Idempotent: a second run only rebuilds what changed.
# Usage: scripts/setup.sh [--packages-only]
#   (BUILD_DIR, BUILD_TYPE, JOBS, BIPOT_SANITIZE and BIPOT_WERROR=ON|OFF may be set in the
#   environment; BIPOT_WERROR=ON, as CI sets it, makes warnings in bipot's code errors;
#   BUILD_TARGETS="a b" builds only those targets; EXTRA_PACKAGES="p q" installs more packages)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${BUILD_DIR:-$root/build}"
build_type="${BUILD_TYPE:-Release}"
source "$root/scripts/env.sh"
jobs="${JOBS:-$BIPOT_JOBS}"

# trilinos-all-dev rather than the split packages: find_package(Trilinos) needs every package's
# config file. Its exported targets reference scotch/ptscotch, VTK's reference libXi/libXxf86vm.
# libopenblas0-serial becomes the system BLAS/LAPACK (Debian alternatives): MUMPS analyses and
# factorises 2.8 times faster with it than with the reference BLAS at 306k DOFs
# (docs/performance.md); serial, so that MPI ranks do not also start BLAS threads.
packages=(
  build-essential cmake pkg-config
  trilinos-all-dev libptscotch-dev libscotch-dev libmumps-dev libopenblas0-serial
  libeigen3-dev libyaml-cpp-dev libvtk9-dev libxi-dev libxxf86vm-dev
  libgmsh-dev gmsh
  openmpi-bin libopenmpi-dev
  libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy
)
read -r -a extra <<< "${EXTRA_PACKAGES:-}"
packages+=("${extra[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" > "${TMPDIR:-/tmp}/bipot-apt.log" \
    || { echo "setup: apt-get failed, see ${TMPDIR:-/tmp}/bipot-apt.log" >&2; exit 1; }
fi

if [ "${1:-}" = "--packages-only" ]; then exit 0; fi

mkdir -p "$build_dir"
cmake_args=(-DCMAKE_BUILD_TYPE="$build_type" -DBIPOT_WERROR="${BIPOT_WERROR:-OFF}")
[ -z "${BIPOT_SANITIZE:-}" ] || cmake_args+=(-DBIPOT_SANITIZE="$BIPOT_SANITIZE")
cmake -S "$root" -B "$build_dir" "${cmake_args[@]}" > "$build_dir/configure.log" 2>&1 \
  || { cat "$build_dir/configure.log" >&2; exit 1; }
echo "setup: building in $build_dir with $jobs jobs"
# Every line of BUILD_TARGETS (test.sh lists them over several): `read` alone takes the first.
read -r -d '' -a targets <<< "${BUILD_TARGETS:-}" || true
cmake --build "$build_dir" -j "$jobs" ${targets[@]:+--target "${targets[@]}"}
