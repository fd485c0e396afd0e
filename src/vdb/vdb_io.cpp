#include "vdb_io.hpp"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <filesystem>
#include <mutex>

#include "../io/atomic_file.hpp"
#include "../io/voxel_bound.hpp"
#include "../util/error.hpp"
#include "vdb_file_check.hpp"

namespace lucent::vdb {

namespace {
void initialize() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

openvdb::io::File openFile(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw InputError("cannot read '" + path + "': no such file; check the path");
  checkVdbLayout(path);  // OpenVDB trusts the lengths the file declares
  initialize();
  openvdb::io::File file(path);
  try {
    file.open(/*delayLoad=*/false);  // read in readGrid, inside the try: a delayed load throws
                                     // where nothing can catch it (a finding of fuzz_volume_vdb)
  } catch (const std::exception& e) {
    throw InputError("cannot read '" + path + "' as OpenVDB: " + e.what() + "; is it a .vdb file?");
  }
  return file;
}

openvdb::GridBase::Ptr readGrid(openvdb::io::File& file, const std::string& name,
                                const std::string& path) {
  try {
    return file.readGrid(name);
  } catch (const std::exception& e) {
    throw InputError("cannot read grid '" + name + "' of '" + path + "': " + e.what() +
                     "; is the file complete?");
  }
}

}  // namespace

std::vector<std::string> gridNames(const std::string& path) {
  openvdb::io::File file = openFile(path);
  std::vector<std::string> names;
  for (auto it = file.beginName(); it != file.endName(); ++it) names.push_back(it.gridName());
  file.close();
  return names;
}

scene::VoxelGrid readFloatGrid(const std::string& path, const std::string& gridName) {
  openvdb::io::File file = openFile(path);
  openvdb::GridBase::Ptr base;
  std::string available;
  for (auto it = file.beginName(); it != file.endName(); ++it) {
    available += (available.empty() ? "" : ", ") + it.gridName();
    if (base) continue;
    if (!gridName.empty() && it.gridName() != gridName) continue;
    openvdb::GridBase::Ptr g = readGrid(file, it.gridName(), path);
    if (gridName.empty() && !g->isType<openvdb::FloatGrid>()) continue;
    base = g;
  }
  file.close();
  if (!base)
    throw InputError("'" + path + "' has no " +
                     (gridName.empty() ? "float grid" : "grid named '" + gridName + "'") +
                     "; it holds: " + (available.empty() ? "nothing" : available));
  const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  if (!grid)
    throw InputError("grid '" + gridName + "' in '" + path +
                     "' is not a float grid; lucent reads scalar densities");
  const openvdb::Vec3d vs = grid->voxelSize();
  if (!(vs.x() > 0) || !std::isfinite(vs.x()))
    throw InputError("grid in '" + path + "' has a voxel size that is not a positive number");
  if (!grid->transform().isLinear() || std::abs(vs.x() - vs.y()) > 1e-9 * vs.x() ||
      std::abs(vs.x() - vs.z()) > 1e-9 * vs.x())
    throw InputError("grid in '" + path +
                     "' has non-uniform voxels; resample it to cubic voxels first");

  scene::VoxelGrid out;
  const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
  if (box.empty()) return out;
  // Densifying is an input-sized allocation: bounded before it is made (two far-apart active voxels
  // make a huge box from a tiny file).
  double span[3];
  for (int a = 0; a < 3; ++a) span[a] = double(box.max()[a]) - double(box.min()[a]) + 1;
  io::checkVoxelCount("grid in '" + path + "': its active voxels span ", span, "densifies",
                      "resample or crop the grid");
  const openvdb::Coord lo = box.min(), dim = box.dim();
  out.dims = {dim.x(), dim.y(), dim.z()};
  out.spacing = glm::dvec3(vs.x());
  const openvdb::Vec3d o = grid->indexToWorld(lo);
  out.origin = {o.x(), o.y(), o.z()};
  out.values.resize(std::size_t(dim.x()) * std::size_t(dim.y()) * std::size_t(dim.z()));
  const auto accessor = grid->getConstAccessor();
  for (int k = 0; k < dim.z(); ++k)
    for (int j = 0; j < dim.y(); ++j)
      for (int i = 0; i < dim.x(); ++i) {
        const float v = accessor.getValue(lo.offsetBy(i, j, k));
        if (!std::isfinite(v))
          throw InputError("grid in '" + path + "' has a non-finite value at voxel (" +
                           std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) +
                           "); replace NaN/inf before using it as a medium");
        out.values[out.index(i, j, k)] = v;
      }
  return out;
}

void writeFloatGrid(const std::string& path, const scene::VoxelGrid& grid,
                    const std::string& gridName, float background) {
  initialize();
  auto vdbGrid = openvdb::FloatGrid::create(background);
  vdbGrid->setName(gridName);
  auto transform = openvdb::math::Transform::createLinearTransform(grid.spacing.x);
  transform->postTranslate(openvdb::Vec3d(grid.origin.x, grid.origin.y, grid.origin.z));
  vdbGrid->setTransform(transform);
  auto accessor = vdbGrid->getAccessor();
  for (int k = 0; k < grid.dims.z; ++k)
    for (int j = 0; j < grid.dims.y; ++j)
      for (int i = 0; i < grid.dims.x; ++i)
        if (const float v = grid.at(i, j, k); v != background)
          accessor.setValue(openvdb::Coord(i, j, k), v);
  io::AtomicFile out(path);
  try {
    openvdb::io::File file(out.tempPath());
    file.write({vdbGrid});
    file.close();
  } catch (const std::exception& e) {
    throw InputError("cannot write '" + path + "': " + e.what());
  }
  out.commit();
}

}  // namespace lucent::vdb
