#!/usr/bin/env bash
# Installs the Debian packages lucent builds against, only those that are missing.
# (libvtk9-dev brings python3-vtk9 back if scripts/paraview-plugin.sh swapped in python3-paraview.)
set -euo pipefail
exec "$(dirname "$0")/lib/apt-install-missing.sh" \
  build-essential cmake pkg-config \
  libglm-dev doctest-dev libtbb-dev libeigen3-dev \
  libembree-dev libopenexr-dev libvtk9-dev libtet1.5-dev libopenvdb-dev libboost-iostreams-dev \
  xvfb xauth
