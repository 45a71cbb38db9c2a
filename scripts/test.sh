#!/bin/sh
# Installs dependencies, builds, and runs the whole test suite (what CI runs).
set -e
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
cd build && ctest --output-on-failure -j"$(nproc)" "$@"
