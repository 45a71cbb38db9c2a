#!/bin/sh
# Installs the Debian packages semsplat builds and runs with (run as root, or with sudo).
# This list is the one place dependencies are named; README.md points here.
set -e
PKGS="build-essential cmake pkg-config libpng-dev libjpeg-dev libcjson-dev libassimp-dev \
libopenblas-dev libxml2-dev zlib1g-dev python3 python3-numpy"
SUDO=""
if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "installing:$missing"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing
fi
