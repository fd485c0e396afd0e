/// @file vtkLucentVolumeFilter.h
/// @brief A scan (vtkImageData: CT, MRI, a label map) as a translucent object: its closed
/// isosurface at IsoValue (padded by one voxel, so a structure touching the scan's border is
/// capped), shaded by any technique of vtkLucentFilter with the scan as the medium
/// (lucent/technique/ transfer_function.hpp):
///  - Transfer "points:V/SA/SS;..." maps the value to sigma_a, sigma_s' per channel (piecewise
///    linear), "labels:V=MATERIAL,...,V=none" gives each label a material (the surface is then
///    where the labelled material ends; IsoValue is not used);
///  - no Transfer: the value normalised to [0, 1] over its range scales Material (a density).
/// The array is the one SetInputArrayToProcess(0, ...) names (default: the active scalars). Output,
/// units, knobs and progress as vtkLucentFilter's. The whole scan must be on one process: under MPI
/// the filter refuses (a medium field of a distributed image is not gathered).
#ifndef vtkLucentVolumeFilter_h
#define vtkLucentVolumeFilter_h

#include <string>

#include "LucentFiltersModule.h"
#include "vtkLucentFilter.h"

class LUCENTFILTERS_EXPORT vtkLucentVolumeFilter : public vtkLucentFilter {
 public:
  static vtkLucentVolumeFilter* New();
  vtkTypeMacro(vtkLucentVolumeFilter, vtkLucentFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scan value whose isosurface bounds the object (not used with a label map).
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /// The transfer function (see above); empty: the normalised value scales Material.
  void SetTransfer(const char* spec);
  const char* GetTransfer() const { return this->Transfer.c_str(); }
  ///@}

 protected:
  vtkLucentVolumeFilter();
  ~vtkLucentVolumeFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  double IsoValue = 0.0;
  std::string Transfer;

 private:
  vtkLucentVolumeFilter(const vtkLucentVolumeFilter&) = delete;
  void operator=(const vtkLucentVolumeFilter&) = delete;
};

#endif
