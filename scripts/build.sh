#!/bin/sh
# Configures and builds semsplat into build/ (CLI at build/semsplat). Extra args go to cmake.
# SP_BUILD_DIR picks another folder (the sanitizer build: SP_BUILD_DIR=build-asan
# ./scripts/build.sh -DSP_SANITIZE=ON).
set -e
cd "$(dirname "$0")/.."
B=${SP_BUILD_DIR:-build}
cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$B" -j"$(nproc)"
