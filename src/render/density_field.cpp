#include "density_field.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <lucent/optics/constants.hpp>

#include "../io/vtk_volume.hpp"
#include "../util/error.hpp"
#include "../vdb/vdb_io.hpp"

namespace lucent::render {

namespace {
/// Splits "FILE.ext:NAME" into the file and the name after the extension ("" when none).
bool splitFileSpec(const std::string& spec, const std::string& ext, std::string& path,
                   std::string& name) {
  const auto at = spec.find(ext + ":");
  if (at != std::string::npos) {
    path = spec.substr(0, at + ext.size());
    name = spec.substr(at + ext.size() + 1);
    return true;
  }
  if (spec.size() >= ext.size() && spec.compare(spec.size() - ext.size(), ext.size(), ext) == 0) {
    path = spec;
    name.clear();
    return true;
  }
  return false;
}
}  // namespace

DensityField parseDensityField(const std::string& option, const std::string& spec,
                               const scene::Bounds& bounds) {
  DensityField field;
  if (spec.empty()) return field;
  const std::string what = option + " " + spec;
  if (spec.rfind("noise:", 0) == 0) {
    double periods = 0;
    try {
      periods = std::stod(spec.substr(6));
    } catch (const std::exception&) {
    }
    constexpr double kMaxPeriods = 1000;  // finer than any technique's grid resolves
    if (!(periods > 0 && periods <= kMaxPeriods))
      throw InputError(what + ": noise:F needs 0 < F <= 1000 periods across the object, e.g. "
                       "noise:3");
    const double k = 2 * optics::kPi * periods / bounds.diagonal();
    const glm::dvec3 lo = bounds.lo;
    field.at = [k, lo](const glm::dvec3& p) {
      const glm::dvec3 q = k * (p - lo);
      return 0.55 + 0.45 * std::sin(q.x) * std::sin(q.y + 1.0) * std::sin(q.z + 2.0);
    };
    field.description = "procedural, " + spec.substr(6) + " periods across the object, in [0.1, 1]";
    return field;
  }
  std::string path, name;
  std::shared_ptr<scene::VoxelGrid> voxels;
  if (splitFileSpec(spec, ".vdb", path, name))
    voxels = std::make_shared<scene::VoxelGrid>(vdb::readFloatGrid(path, name));
  else if (splitFileSpec(spec, ".vti", path, name))
    voxels = std::make_shared<scene::VoxelGrid>(io::readImageVolume(path, name));
  else
    throw InputError(
        what + ": give noise:F, an OpenVDB file FILE.vdb[:GRID] or a VTK volume FILE.vti[:ARRAY]");
  double maxValue = 0;
  for (float v : voxels->values) maxValue = std::max(maxValue, double(v));
  if (!(maxValue > 0))
    throw InputError(path +
                     ": the density has no positive value; a medium needs density > 0 somewhere");
  const glm::dvec3 lo = bounds.lo, extent = bounds.hi - bounds.lo;
  field.at = [voxels, maxValue, lo, extent](const glm::dvec3& p) {
    const glm::dvec3 u = (p - lo) / extent;
    const glm::dvec3 local = voxels->origin + u * glm::dvec3(voxels->dims - 1) * voxels->spacing;
    return std::max(0.0, voxels->sample(local) / maxValue);
  };
  field.description = path + " (" + std::to_string(voxels->dims.x) + "x" +
                      std::to_string(voxels->dims.y) + "x" + std::to_string(voxels->dims.z) +
                      " voxels fitted to the mesh's bounding box, divided by its maximum)";
  return field;
}

}  // namespace lucent::render
