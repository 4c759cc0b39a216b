#!/usr/bin/env bash
# Quick start, first command: install what is missing, build the cmx program and run it on an
# embedded example. Until `cmx map` exists this is an orientation test that plain doubles get
# wrong: it prints the naive double answer next to the exact one.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target cmx >/dev/null
exec build/release/cli/cmx orient3d --demo
