#!/usr/bin/env bash
# The sanitizer build: the whole suite built with clang under AddressSanitizer
# and UndefinedBehaviorSanitizer (undefined behaviour aborts) into build-san/,
# then run through ctest. The same build holds the libFuzzer targets that
# scripts/fuzz.sh runs. Runtime options and suppressions: CMakeLists.txt
# (MORPHOGEN_SANITIZER_ENV) and tests/sanitizers/.
#
#   scripts/sanitize.sh               build, then run the tests (those labelled
#                                     long excepted: tests/CMakeLists.txt says why)
#   scripts/sanitize.sh --build-only [TARGET...]
#                                     build only (everything, or the targets
#                                     named: scripts/fuzz.sh builds its fuzzers)
#   scripts/sanitize.sh -R session    extra arguments go to ctest
set -euo pipefail
cd "$(dirname "$0")/.."

build_only=0
if [ "${1:-}" = "--build-only" ]; then
  build_only=1
  shift
fi

bash scripts/setup.sh --packages-only # clang, libFuzzer and the libraries

build=build-san
echo "==> sanitize: configuring ($build/, clang, ASan + UBSan + libFuzzer)"
# -O2 keeps the simulation tests' time near the release build's; without
# NDEBUG, so asserts are checked too. Line tables are all a sanitizer report
# needs (file:line per frame); full debug information made each object 15%
# slower to compile.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only" \
  -DMORPHOGEN_FUZZ=ON >/dev/null
echo "==> sanitize: building"
if [ "$build_only" -eq 1 ]; then
  targets=()
  [ $# -gt 0 ] && targets=(--target "$@")
  cmake --build "$build" --parallel "$(nproc)" "${targets[@]}"
  exit 0
fi
cmake --build "$build" --parallel "$(nproc)"

echo "==> sanitize: ctest under ASan + UBSan (without the tests labelled long)"
cd "$build"
ctest --output-on-failure --parallel "$(nproc)" --label-exclude long "$@"
