#!/bin/sh
# Test set-up: installs the independent ROS 2 serializer (npm @foxglove/rosmsg2-serialization and
# the common message definitions, versions pinned by npm/package-lock.json) into BUILD/npm.
# Exits 77 (CTest: skipped) when Node.js/npm are missing or the registry cannot be reached; the
# wire test then skips too.
set -u
out="$1"
src="$(dirname "$0")/npm"
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "SKIP: node or npm not installed (Debian: nodejs npm)"; exit 77
fi
mkdir -p "$out"
if [ -f "$out/node_modules/.semsplat-lock" ] && cmp -s "$src/package-lock.json" "$out/node_modules/.semsplat-lock"; then
  echo "already installed in $out"; exit 0
fi
cp "$src/package.json" "$src/package-lock.json" "$out/"
cd "$out" || exit 1
if ! timeout 180 npm ci --no-audit --no-fund --loglevel=error; then
  echo "SKIP: npm ci failed (is the npm registry reachable?)"; rm -rf node_modules; exit 77
fi
cp package-lock.json node_modules/.semsplat-lock
echo "installed the reference serializer into $out"
