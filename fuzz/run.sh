#!/usr/bin/env bash
# Builds the scene fuzzer in ./build-fuzz (clang++, ASan + UBSan + libFuzzer)
# and runs it on a scratch copy of the seed corpus. Extra arguments go to
# libFuzzer; crashers land in ./build-fuzz/crashers/. docs/fuzzing.md.
#
#   bash fuzz/run.sh                          # 1,000,000 inputs on 2 workers
#   bash fuzz/run.sh -max_total_time=900      # or a time box
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$here/build-fuzz}

cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  -DPARTICLES_FUZZ=ON -DPARTICLES_BUILD_TESTS=OFF -DPARTICLES_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target scene_fuzzer -j"$(nproc)"

# New inputs go to the scratch corpus; fuzz/corpus (committed) is only read.
mkdir -p "$build/corpus" "$build/crashers"
cd "$build"
jobs=${FUZZ_JOBS:-2}
exec ./scene_fuzzer -dict="$here/fuzz/scene.dict" -max_len=16384 -timeout=10 -rss_limit_mb=4096 \
  -artifact_prefix="$build/crashers/" -print_final_stats=1 \
  -jobs="$jobs" -workers="$jobs" -runs=$((1000000 / jobs)) "$@" \
  "$build/corpus" "$here/fuzz/corpus"
