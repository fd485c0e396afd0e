#!/usr/bin/env bash
# The real-data corpus (docs/real-data.md): real MRI scans and a label atlas, real HDR probes, real
# meshes with holes, flips and non-manifold parts, and a real DICOM series, all from Debian packages.
# The packages are downloaded and unpacked into .corpus/ (apt-get download + dpkg -x): nothing is
# installed, so the machine's packages stay as they were. Quick when .corpus/MANIFEST exists.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=.corpus
[ -f "$dest/MANIFEST" ] && exit 0
packages=(mricron-data blender-data assimp-testmodels libcgal-demo python3-pydicom)
work=$(mktemp -d)
trap 'rm -rf "$work" "$dest.partial"' EXIT
echo "lucent corpus: downloading ${packages[*]} (about 95 MB)" >&2
if ! (cd "$work" && apt-get download -qq "${packages[@]}" 2>/dev/null); then
  if [ "$(id -u)" -eq 0 ]; then apt-get update -qq; else sudo apt-get update -qq; fi
  (cd "$work" && apt-get download -qq "${packages[@]}")
fi
for deb in "$work"/*.deb; do dpkg-deb -x "$deb" "$work/root"; done
r=$work/root
rm -rf "$dest.partial"
mkdir -p "$dest.partial"/{scans,probes,meshes,dicom/ct5n}
# Scans: a T1 head (ch2), the same brain extracted (ch2bet), a 0.5 mm head (ch2better), a label atlas.
for f in ch2 ch2bet ch2better aal; do cp "$r/usr/share/mricron/templates/$f.nii.gz" "$dest.partial/scans/"; done
cp "$r"/usr/share/blender/datafiles/studiolights/world/{*.exr,license.txt} "$dest.partial/probes/"
# Meshes: open, non-manifold, flipped and unwelded models as users bring them.
a=$r/usr/share/assimp/models
cp "$a/STL/Wuson.stl" "$a/STL/sphereWithHole.stl" "$a/STL/Spider_binary.stl" \
  "$a/STL/3DSMaxExport.STL" "$a/OBJ/regr01.obj" "$dest.partial/meshes/"
tar -xzf "$r/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" data/meshes/elephant-with-holes.off \
  data/meshes/nefertiti.off data/meshes/blobby-shuffled.off data/meshes/pig.stl
cp "$work"/data/meshes/* "$dest.partial/meshes/"
# A CT series of five slices (pixels reduced to 16 x 16 by pydicom's authors; headers real).
cp "$r"/usr/lib/python3/dist-packages/pydicom/data/test_files/dicomdirtests/98892001/CT5N/* \
  "$dest.partial/dicom/ct5n/"
for deb in "$work"/*.deb; do
  printf '%s %s\n' "$(dpkg-deb -f "$deb" Package)" "$(dpkg-deb -f "$deb" Version)"
done > "$dest.partial/MANIFEST"
(cd "$dest.partial" && find . -type f ! -name MANIFEST | sort) >> "$dest.partial/MANIFEST"
mv "$dest.partial" "$dest"
echo "lucent corpus: $(($(wc -l < "$dest/MANIFEST") - ${#packages[@]})) files in $dest" >&2
