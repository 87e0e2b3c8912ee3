#!/usr/bin/env bash
# Installs voltree's Debian 12 packages (only those missing), then configures and builds.
# Usage: scripts/setup.sh [extra cmake args]. Environment: BUILD_DIR (default: build), JOBS.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config git
  colmap libopencv-dev libceres-dev libeigen3-dev libopenimageio-dev openimageio-tools
  libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libsquish-dev libcli11-dev nlohmann-json3-dev libtbb-dev libzstd-dev
  libtinygltf-dev libtinyobjloader-dev gnuplot-nox ffmpeg
  libsqlite3-dev  # why a photo did not register: COLMAP's feature database
  snakemake  # voltree batch: many workspaces, locally or on a cluster
  libglfw3-dev libimgui-dev  # voltree view: a window and its panel
  chromium xvfb xauth  # the viewers' tests: WebGL2 in headless Chromium, a window under Xvfb
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

build_dir=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}
echo "setup: building in $build_dir with $jobs jobs (log: $build_dir/build.log)"
mkdir -p "$build_dir"
if ! { cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" &&
       cmake --build "$build_dir" -j "$jobs"; } >"$build_dir/build.log" 2>&1; then
  grep -E "error|Error" "$build_dir/build.log" | head -40 >&2
  echo "setup: build failed; full log: $build_dir/build.log" >&2
  exit 1
fi
grep -E "warning:" "$build_dir/build.log" | sort -u | head -20 >&2 || true
echo "setup: built $build_dir/voltree"
