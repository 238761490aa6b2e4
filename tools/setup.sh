#!/usr/bin/env bash
# ergo set-up: installs what is missing (Debian 12, apt-get), builds, and runs.
#
#   tools/setup.sh run            install + build + run the main job
#   tools/setup.sh test           install + build + run the whole test suite (ctest)
#   tools/setup.sh test --sanitize  the same with AddressSanitizer + UBSan (build-sanitize/)
#
# Idempotent: when every package is present it installs nothing and says nothing about it.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-}"
sanitize=0
[ "${2:-}" = "--sanitize" ] && sanitize=1
case "$mode" in run | test) ;; *)
  echo "usage: tools/setup.sh run|test [--sanitize]" >&2
  exit 2
  ;;
esac

packages=(build-essential cmake pkg-config libeigen3-dev libceres-dev libsuitesparse-dev
  libopenblas-dev libnlopt-cxx-dev libcgal-dev libgflags-dev libgoogle-glog-dev libtbb-dev
  nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev python3 python3-matplotlib
  python3-dev pybind11-dev python3-numpy)
# The fuzzers (tools/fuzz.sh, run by CI after the tests) need clang's libFuzzer and OpenMP.
[ "$mode" = test ] && packages+=(clang libclang-rt-14-dev libomp-14-dev)
# The Python bindings' tests (pytest, SciPy's optimisers in the example).
[ "$mode" = test ] && packages+=(python3-pytest python3-scipy)
# The VTU test reads the binary files back with meshio (skipped without it).
[ "$mode" = test ] && packages+=(python3-meshio)
# ergo_population --mpi and its tests (mpirun -np 3): Open MPI.
[ "$mode" = test ] && packages+=(openmpi-bin libopenmpi-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

jobs=$(nproc 2>/dev/null || echo 2)
if [ "$sanitize" = 1 ]; then
  build=build-sanitize
  # -O1 -g1: the CGAL-heavy units compile in half the time of -O2 -g (measured 77 s vs 164 s
  # for ergo/body/hole_filling.cc) and the reports still carry file:line.
  # The libraries and their stage tests only: the programs' tests are end-to-end runs,
  # minutes each under the sanitizers, and the Release run covers them (measured: this build
  # took 33 min with them and without unity builds, its tests 32 min).
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DERGO_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DERGO_BUILD_BENCHMARKS=OFF \
    -DERGO_BUILD_TOOLS=OFF -DCMAKE_UNITY_BUILD=ON >/dev/null
else
  build=build
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
fi
cmake --build "$build" -j "$jobs"

if [ "$mode" = test ]; then
  # Sanitizer runs: fail on the first report, and detect leaks (LeakSanitizer).
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  ctest --test-dir "$build" --output-on-failure -j "$jobs"
else
  # The main job: optimise the quick shoe sole; results, STL and pictures in ergo_out/.
  "$build/bin/ergo_optimize" --flagfile=data/shoe.flags --out=ergo_out
fi
