#!/usr/bin/env bash
# Installs debrisflow's build and test dependencies from Debian 12 packages.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
    build-essential cmake libomp-dev \
    libtomlplusplus-dev libcli11-dev libfmt-dev libeigen3-dev \
    libgtest-dev libbenchmark-dev zlib1g-dev \
    python3-numpy python3-matplotlib
