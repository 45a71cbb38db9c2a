#!/bin/sh
# Installs the Debian packages semsplat builds and runs with (run as root, or with sudo).
# This list is the one place dependencies are named; README.md points here.
set -e
# Round 1: the core. Round 2: libcurl (LLM APIs), Cairo (maps, sheets, plots, captions), FFmpeg's
# libraries (the demo video; ffmpeg for ffprobe in tests), Cyclone DDS (ROS 2), WordNet (offline
# text); Fast DDS, COLMAP and clang (libFuzzer) are test references and tools; Node.js runs the
# independent ROS 2 serializer of the wire tests (npm packages installed by the tests themselves,
# skipped when npm or the registry is missing; npm ships with NodeSource's nodejs, Debian splits
# it into the npm package).
PKGS="build-essential cmake pkg-config libpng-dev libjpeg-dev libcjson-dev libassimp-dev \
libopenblas-dev libxml2-dev zlib1g-dev python3 python3-numpy \
libcurl4-openssl-dev libcairo2-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev \
cyclonedds-dev cyclonedds-tools wordnet-base \
libfastrtps-dev colmap ffmpeg clang libclang-rt-14-dev nodejs"
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
