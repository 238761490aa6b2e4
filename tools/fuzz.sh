#!/usr/bin/env bash
# Fuzzes the mesh readers: one libFuzzer harness per reader (tests/fuzz), built with Debian's
# clang under AddressSanitizer + UndefinedBehaviorSanitizer in build-fuzz/, seeded from
# tests/mesh/corpus and, when present, ../shared/peer-meshes.
#
#   tools/fuzz.sh [ci]            build, then each of the 6 harnesses for 18 s (108 s in all)
#   tools/fuzz.sh long [SECONDS]  build, then each harness for SECONDS (default 600)
#   tools/fuzz.sh build           build only
#
# What the long runs learn is kept in build-fuzz/corpus/<format>/ for the next long run; CI
# runs start from the seeds alone, so that a grown corpus cannot stretch their time
# (libFuzzer runs every corpus file before it looks at the clock).
#
# Exit 0: no finding. 1: a harness found a crash, an exception other than InputError, a
# sanitizer report, a leak, a hang or a message without its file, problem or fix; the input
# is in build-fuzz/findings/<format>/ and replays with build-fuzz/bin/fuzz_<format> FILE.
# Make it a corpus file (tests/mesh/corpus: make_corpus.py and EXPECTED.tsv) and fix the
# reader. 2: usage or build error.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-ci}"
case "$mode" in
  ci) seconds=18 ;;
  long) seconds="${2:-600}" ;;
  build) seconds=0 ;;
  *)
    echo "usage: tools/fuzz.sh [ci | long [SECONDS] | build]" >&2
    exit 2
    ;;
esac
if ! [[ "$seconds" =~ ^[0-9]+$ ]]; then
  echo "tools/fuzz.sh: SECONDS must be a whole number of seconds, not '$seconds'" >&2
  exit 2
fi
for tool in clang clang++; do
  if ! command -v "$tool" >/dev/null; then
    echo "tools/fuzz.sh: $tool not found (fix: apt-get install clang libclang-rt-14-dev)" >&2
    exit 2
  fi
done

build="build-fuzz"
formats=(obj off ply stl msh tetgen)
corpus="$build/corpus"
[ "$mode" = ci ] && corpus="$build/corpus-ci"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DERGO_BUILD_FUZZERS=ON -DERGO_BUILD_TESTS=OFF -DERGO_BUILD_BENCHMARKS=OFF \
  "${launcher[@]}" >/dev/null || exit 2
cmake --build "$build" -j "$(nproc 2>/dev/null || echo 2)" --target fuzzers >/dev/null || {
  echo "tools/fuzz.sh: the build failed; rerun: cmake --build $build --target fuzzers" >&2
  exit 2
}
[ "$seconds" = 0 ] && exit 0

# Seeds: the corpus files of each format (up to 1 MiB; libFuzzer cuts them to -max_len), and
# TetGen pairs joined by the harness's "#ele" line.
peers=../shared/peer-meshes
seed_dirs=(tests/mesh/corpus)
[ -d "$peers" ] && seed_dirs+=("$peers")
rm -rf "$build/seeds" "$build/corpus-ci"
for format in "${formats[@]}"; do
  mkdir -p "$build/seeds/$format" "$corpus/$format" "$build/findings/$format"
done
n=0
while IFS= read -r -d '' file; do
  name="${file##*/}"
  extension="$(echo "${name##*.}" | tr '[:upper:]' '[:lower:]')"
  n=$((n + 1))
  case "$extension" in
    obj | off | ply | stl | msh) cp "$file" "$build/seeds/$extension/$n.$extension" ;;
    node)
      ele="${file%.*}.ele"
      [ -f "$ele" ] && { cat "$file"; printf '\n#ele\n'; cat "$ele"; } >"$build/seeds/tetgen/$n"
      ;;
  esac
done < <(find "${seed_dirs[@]}" -type f -size -1025k -print0)

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
found=()
for format in "${formats[@]}"; do
  log="$build/findings/$format.log"
  # -timeout: a single input running 10 s is a hang (the harness's check budget is 1 s).
  if "$build/bin/fuzz_$format" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/findings/$format/" \
    "$corpus/$format" "$build/seeds/$format" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz_$format: ${runs:-?} inputs in ${seconds} s, no finding"
  else
    found+=("$format")
    echo "fuzz_$format: FINDING (log: $log)"
    grep -E "^==[0-9]+==ERROR|SUMMARY|runtime error|Test unit written" "$log" | head -5 || true
  fi
done
if [ ${#found[@]} -gt 0 ]; then
  echo "tools/fuzz.sh: findings in ${found[*]}: replay with $build/bin/fuzz_<format> FILE" >&2
  exit 1
fi
