#!/usr/bin/env bash
# Quick start, second command: install what is missing, build everything (release preset) and run
# the whole test suite; ctest prints its summary last. Exit status is ctest's.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
