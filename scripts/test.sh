#!/usr/bin/env bash
# Install, build, and run the whole suite through ctest (GL tests under both
# EGL and OSMesa on Mesa's llvmpipe; no GPU needed).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "==> test: ctest"
cd build
ctest --output-on-failure --parallel "$(nproc)"
