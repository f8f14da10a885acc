#!/usr/bin/env bash
# The main job: install, build, and render the default preset headlessly to
# out/morphogen.png (plus out/morphogen.json, the session that reproduces it).
set -euo pipefail
cd "$(dirname "$0")/.."
# The command, its completion and man page (cmake --install), not the test suite.
bash scripts/setup.sh --target morphogen morphogen_docs
mkdir -p out
echo "==> render: default preset -> out/morphogen.png"
./build/morphogen render --out out/morphogen.png "$@"
