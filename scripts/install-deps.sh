#!/usr/bin/env bash
# Installs every Debian package the project builds, tests or benchmarks with.
# Idempotent: when everything is already installed it only checks (dpkg) and exits.
set -euo pipefail

PACKAGES=(
  build-essential cmake g++ make pkg-config
  libeigen3-dev            # linear algebra
  libqhull-dev             # convex hulls (reentrant C API, libqhull_r)
  libigraph-dev libarpack2-dev libglpk-dev libplfit-dev   # Leiden (igraph + its CMake deps)
  libnanoflann-dev         # kd-trees
  nlohmann-json3-dev       # JSON
  libyaml-cpp-dev          # YAML configs
  libcli11-dev             # CLI
  libspdlog-dev            # logging
  libcpp-httplib-dev       # OpenAI-compatible client + loopback fake server in tests
  wordnet-dev wordnet-base # offline word semantics
  libgtest-dev libgmock-dev libbenchmark-dev
  liboctomap-dev           # real Freiburg scans + benchmark reference
  libassimp-dev            # COLLADA wall meshes of the AWS Gazebo worlds
  libpng-dev zlib1g-dev    # pictures and 2D maps
  nodejs                   # tests run the web pages' own scripts (scene_graph.html, index.html)
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
