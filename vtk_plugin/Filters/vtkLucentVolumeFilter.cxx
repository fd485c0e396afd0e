#include "vtkLucentVolumeFilter.h"

#include <memory>
#include <optional>

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <lucent/technique/transfer_function.hpp>

#include "lucentScanSurface.h"

vtkStandardNewMacro(vtkLucentVolumeFilter);

namespace {
namespace lt = lucent::technique;
constexpr const char* kWhat = "vtkLucentVolumeFilter's input";
}  // namespace

vtkLucentVolumeFilter::vtkLucentVolumeFilter() {
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                               vtkDataSetAttributes::SCALARS);
}
vtkLucentVolumeFilter::~vtkLucentVolumeFilter() = default;

void vtkLucentVolumeFilter::SetTransfer(const char* spec) {
  const std::string value = spec ? spec : "";
  if (value == this->Transfer) return;
  this->Transfer = value;
  this->Modified();
}

void vtkLucentVolumeFilter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n"
     << indent << "Transfer: " << this->Transfer << "\n";
}

int vtkLucentVolumeFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  vtkImageData* image = vtkImageData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!image || !output) return 0;
  vtkSmartPointer<vtkPolyData> surface;
  std::shared_ptr<const lucent::scene::VoxelGrid> scan;
  std::optional<lt::ScanMedium> transfer;
  try {
    if (this->Controller && this->Controller->GetNumberOfProcesses() > 1)
      throw lt::RequestError(
          "vtkLucentVolumeFilter needs the whole scan on one process (a distributed image's "
          "medium is not gathered); run it without MPI, or contour the scan and use "
          "vtkLucentFilter");
    vtkDataArray* array = this->GetInputArrayToProcess(0, inputVector);
    if (!array && image->GetPointData()->GetNumberOfArrays() > 0)
      array = image->GetPointData()->GetArray(0);
    if (!array) {
      std::string names;
      for (int i = 0; i < image->GetPointData()->GetNumberOfArrays(); ++i)
        names += (i ? ", " : "") + std::string(image->GetPointData()->GetArrayName(i)
                                                   ? image->GetPointData()->GetArrayName(i)
                                                   : "(unnamed)");
      throw lt::RequestError(std::string(kWhat) + " has no point-data array to use; it has: " +
                             (names.empty() ? "none (convert cell data with Cell Data to Point "
                                              "Data)"
                                            : names));
    }
    scan = std::make_shared<lucent::scene::VoxelGrid>(
        lucent::vtkadapter::voxelGridOf(image, array, kWhat));
    if (!this->Transfer.empty()) transfer = lt::parseTransfer("Transfer", this->Transfer, scan);
    surface =
        transfer && transfer->mask
            ? lucent::vtkadapter::closedIsosurface(
                  *transfer->mask, 0.5, "the labels with a material", "give a label a material")
            : lucent::vtkadapter::closedIsosurface(*scan, this->IsoValue, kWhat,
                                                   "set IsoValue inside that range");
  } catch (const std::exception& e) {
    output->Initialize();
    vtkErrorMacro(<< e.what());
    return 0;
  }
  // The shading runs in millimetres, the scan in the data's units: a scene point p is p / scale
  // in the scan.
  const std::string name =
      std::string("the scan '") +
      (this->GetInputArrayInformation(0)->Get(vtkDataObject::FIELD_NAME())
           ? this->GetInputArrayInformation(0)->Get(vtkDataObject::FIELD_NAME())
           : "scalars") +
      "'";
  return this->ShadeSurface(surface, output, [&](lt::Medium& medium, double mmPerUnit) {
    const auto scanAt = [mmPerUnit](const glm::dvec3& p) { return p / mmPerUnit; };
    if (transfer)
      lt::transferMedium(*transfer, scanAt, name, medium);
    else
      lt::normalisedDensity(scan, scanAt, name, medium);
  });
}

int vtkLucentVolumeFilter::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}
