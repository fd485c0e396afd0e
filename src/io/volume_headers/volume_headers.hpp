#pragma once
/// @file volume_headers.hpp
/// @brief lucent's own reading of each volume format's header, before VTK's reader sees the file:
/// what it declares (DeclaredVolume), with the parts VTK's readers would misread or crash on
/// refused by name. Each throws InputError "<file>: <problem>; <fix>".
#include <string>

#include "declared_volume.hpp"

namespace lucent::io {

/// .nrrd / .nhdr: the text header up to its blank line (nrrd_header.cpp).
DeclaredVolume declaredNrrd(const std::string& path);

/// The detached data file a .nhdr/.nrrd header names ("" when the values are in the header's file).
std::string nrrdDataFile(const std::string& path);

/// The detached data file a .mhd/.mha header names ("" for LOCAL data).
std::string metaImageDataFile(const std::string& path);

/// .mha / .mhd: MetaImage's "Key = Value" lines up to ElementDataFile (metaimage_header.cpp).
DeclaredVolume declaredMetaImage(const std::string& path);

/// .nii / .nii.gz: the NIfTI-1 (348 bytes) or NIfTI-2 (540 bytes) binary header (nifti_header.cpp).
DeclaredVolume declaredNifti(const std::string& path);

/// A folder of DICOM slices: every file's tags up to its pixel data, which must agree across
/// the series (dicom_series.cpp).
DeclaredVolume declaredDicomSeries(const std::string& folder);

/// .vtk: the legacy format's STRUCTURED_POINTS header and its first point-data array
/// (legacy_vtk_header.cpp).
DeclaredVolume declaredLegacyVtk(const std::string& path);

}  // namespace lucent::io
