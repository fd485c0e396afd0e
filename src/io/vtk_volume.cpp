#include "vtk_volume.hpp"

#include "quiet_vtk.hpp"
#include "voxel_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDICOMImageReader.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredPoints.h>
#include <vtkStructuredPointsReader.h>
#include <vtkXMLImageDataReader.h>

#include "../util/error.hpp"
#include "lucentScanSurface.h"
#include "volume_headers/volume_headers.hpp"

namespace lucent::io {

namespace {
bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

constexpr const char* kResampleFix =
    "resample the volume (vtkImageResample, or ParaView's Resample To Image)";

/// Voxels named by a reader's header, before the data is read: an input-sized allocation is bounded
/// (scene::kMaxVoxels) from the extent the file declares, not from what VTK has already allocated.
/// With `declared` (lucent's own reading of the header), VTK's reading must agree with it: where
/// they differ, VTK would misread the values.
void checkDeclaredExtent(vtkAlgorithm& reader, const std::string& path,
                         const DeclaredVolume* declared) {
  reader.UpdateInformation();
  int extent[6] = {0, -1, 0, -1, 0, -1};
  vtkInformation* info = reader.GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    throw InputError(path + ": the header declares no extent; check the file in ParaView");
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double dims[3];
  for (int a = 0; a < 3; ++a) dims[a] = double(extent[2 * a + 1]) - double(extent[2 * a]) + 1;
  if (!(dims[0] > 0 && dims[1] > 0 && dims[2] > 0))
    throw InputError(path + ": the header's extent is empty; check the file in ParaView");
  checkVoxelCount(path + ": the header declares ", dims, "reads", kResampleFix);
  if (declared && (dims[0] != declared->dims[0] || dims[1] != declared->dims[1] ||
                   dims[2] != declared->dims[2]))
    throw InputError(path + ": VTK's reader takes it for " + numberShown(dims[0]) + " x " +
                     numberShown(dims[1]) + " x " + numberShown(dims[2]) +
                     " voxels, its header declares " + numberShown(declared->dims[0]) + " x " +
                     numberShown(declared->dims[1]) + " x " + numberShown(declared->dims[2]) +
                     "; convert it to .vti (ParaView: File > Save Data)");
}

/// The first error a VTK algorithm reported while it ran (empty: none).
class ErrorCatcher {
 public:
  explicit ErrorCatcher(vtkAlgorithm& algorithm) {
    mCommand->SetClientData(&mMessage);
    mCommand->SetCallback([](vtkObject*, unsigned long, void* sink, void* text) {
      auto& message = *static_cast<std::string*>(sink);
      if (message.empty() && text) message = static_cast<const char*>(text);
    });
    algorithm.AddObserver(vtkCommand::ErrorEvent, mCommand);
  }
  const std::string& message() const { return mMessage; }

 private:
  std::string mMessage;
  vtkNew<vtkCallbackCommand> mCommand;
};
}  // namespace

/// Reads through `reader` after bounding its header's extent; the reader must outlive the image.
/// A reader that reports an error has left its output unfilled: that is refused.
template <class Reader>
vtkImageData* readWith(Reader& reader, const std::string& path,
                       const DeclaredVolume* declared = nullptr) {
  const QuietVtk quiet;
  const ErrorCatcher errors(reader);
  checkDeclaredExtent(reader, path, declared);
  reader.Update();
  if (!errors.message().empty() || reader.GetErrorCode() != 0) {
    std::string why = errors.message().substr(0, 160);
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw InputError(path + ": VTK's reader failed" + (why.empty() ? "" : " (" + why + ")") +
                     "; the file is damaged or of a kind VTK misreads: re-export the scan");
  }
  return reader.GetOutput();
}

/// Reads a file after checking the reader takes it; else InputError with the path and `refusal`.
template <class Reader>
vtkImageData* readFile(Reader& reader, const std::string& path, const std::string& refusal,
                       const DeclaredVolume* declared = nullptr) {
  if (!reader.CanReadFile(path.c_str())) throw InputError(path + refusal);
  reader.SetFileName(path.c_str());
  return readWith(reader, path, declared);
}

std::string unreadable(const char* format) {
  return std::string(": not a readable ") + format +
         " file; check it in ParaView, or convert it to .vti there";
}

constexpr const char* kFormats =
    ".vti (VTK XML image data), .vtk (legacy structured points), .nrrd/.nhdr, .mha/.mhd "
    "(MetaImage), .nii/.nii.gz (NIfTI) or a folder of DICOM slices";

scene::VoxelGrid readImageVolume(const std::string& path, const std::string& arrayName) {
  const bool folder = std::filesystem::is_directory(path);
  if (!folder && !std::filesystem::is_regular_file(path))
    throw InputError(path + ": no such file; give an existing volume: " + kFormats);
  vtkImageData* image = nullptr;
  vtkNew<vtkXMLImageDataReader> xml;
  vtkNew<vtkStructuredPointsReader> legacy;
  vtkNew<vtkNrrdReader> nrrd;
  vtkNew<vtkMetaImageReader> meta;
  vtkNew<vtkNIFTIImageReader> nifti;
  vtkNew<vtkDICOMImageReader> dicom;
  double slope = 1, intercept = 0;  // NIfTI stores values to be rescaled
  // Every format but .vti (whose XML VTK parses and checkDeclaredExtent bounds) has its header
  // checked by lucent before VTK's reader allocates from it (volume_headers/).
  const auto noted = [](DeclaredVolume declared) {
    for (const std::string& note : declared.notes)
      std::fprintf(stderr, "lucent: note: %s\n", note.c_str());
    return declared;
  };
  if (folder) {
    const DeclaredVolume declared = noted(declaredDicomSeries(path));
    dicom->SetDirectoryName(path.c_str());
    image = readWith(*dicom, path, &declared);
  } else if (endsWith(path, ".vti")) {
    image = readFile(*xml, path,
                     ": not a VTK XML image-data file; save the volume from ParaView as .vti");
  } else if (endsWith(path, ".vtk")) {
    const DeclaredVolume declared = noted(declaredLegacyVtk(path));
    legacy->SetFileName(path.c_str());
    image = readWith(*legacy, path, &declared);
  } else if (endsWith(path, ".nrrd") || endsWith(path, ".nhdr")) {
    const DeclaredVolume declared = noted(declaredNrrd(path));
    image = readFile(*nrrd, path, unreadable("NRRD"), &declared);
  } else if (endsWith(path, ".mha") || endsWith(path, ".mhd")) {
    const DeclaredVolume declared = noted(declaredMetaImage(path));
    image = readFile(*meta, path, unreadable("MetaImage"), &declared);
  } else if (endsWith(path, ".nii") || endsWith(path, ".nii.gz")) {
    const DeclaredVolume declared = noted(declaredNifti(path));
    image = readFile(*nifti, path, unreadable("NIfTI"), &declared);
    double spacing[3];  // a negative pixdim is read as its magnitude, as the header check noted
    if (image) image->GetSpacing(spacing);
    if (image)
      image->SetSpacing(std::fabs(spacing[0]), std::fabs(spacing[1]), std::fabs(spacing[2]));
    if (nifti->GetRescaleSlope() != 0) {  // NIfTI-1: scl_slope 0 means no scaling at all
      slope = nifti->GetRescaleSlope();
      intercept = nifti->GetRescaleIntercept();
    }
  } else {
    throw InputError(path + ": unknown volume format; give " + kFormats);
  }
  int dims[3] = {0, 0, 0};
  if (image) image->GetDimensions(dims);
  if (!image || !(dims[0] > 0 && dims[1] > 0 && dims[2] > 0))
    throw InputError(path +
                     ": the volume is empty or could not be read; check the file in ParaView");
  const double read[3] = {double(dims[0]), double(dims[1]), double(dims[2])};
  checkVoxelCount(path + ": ", read, "reads", kResampleFix);  // as read, besides as declared
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* array = arrayName.empty() ? pd->GetScalars() : pd->GetArray(arrayName.c_str());
  if (!array && arrayName.empty() && pd->GetNumberOfArrays() > 0) array = pd->GetArray(0);
  if (!array) {
    std::string names;
    for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
      names +=
          (i ? ", " : "") + std::string(pd->GetArrayName(i) ? pd->GetArrayName(i) : "(unnamed)");
    throw InputError(path + ": no point-data array '" + arrayName + "'; the file has: " +
                     (names.empty()
                          ? "none (cell data is not read; convert with Cell Data to Point Data)"
                          : names));
  }
  try {
    return vtkadapter::voxelGridOf(image, array, path, slope, intercept);
  } catch (const technique::RequestError& e) {
    throw InputError(e.what());
  }
}

std::vector<std::string> volumeInputFiles(const std::string& path) {
  std::vector<std::string> files{path};
  std::error_code ec;
  try {
    if (std::filesystem::is_directory(path, ec)) {
      for (const auto& entry : std::filesystem::directory_iterator(path, ec))
        if (entry.is_regular_file() && files.size() <= 100000) files.push_back(entry.path());
    } else if (endsWith(path, ".nrrd") || endsWith(path, ".nhdr")) {
      files.push_back(nrrdDataFile(path));
    } else if (endsWith(path, ".mha") || endsWith(path, ".mhd")) {
      files.push_back(metaImageDataFile(path));
    }
  } catch (const InputError&) {
  }
  files.erase(std::remove(files.begin(), files.end(), std::string()), files.end());
  return files;
}

}  // namespace lucent::io
