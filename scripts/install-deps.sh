#!/usr/bin/env bash
# Installs the Debian packages lucent builds against, only those that are missing.
set -euo pipefail
exec "$(dirname "$0")/lib/apt-install-missing.sh" \
  build-essential cmake pkg-config \
  libglm-dev doctest-dev libtbb-dev libeigen3-dev \
  libembree-dev libopenexr-dev libvtk9-dev libtet1.5-dev libopenvdb-dev libboost-iostreams-dev \
  xvfb xauth \
  python3-paraview-  # conflicts with python3-vtk9 (libvtk9-dev's); scripts/paraview-plugin.sh installs it
