#include "winding_remesh.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include <vtkPolyData.h>

#include <lucent/scene/shapes.hpp>
#include <lucent/scene/voxel_grid.hpp>
#include <lucent/scene/winding_number.hpp>

#include "../util/error.hpp"
#include "../util/tbb_parallel.hpp"
#include "lucentScanSurface.h"
#include "quiet_vtk.hpp"
#include "vtk_mesh.hpp"

namespace lucent::io {

namespace {
/// The grid around `b`: `resolution` voxels along its longest side, two more on every side.
scene::VoxelGrid gridAround(const scene::Bounds& b, int resolution) {
  const glm::dvec3 extent = b.hi - b.lo;
  const double h = std::max({extent.x, extent.y, extent.z}) / resolution;
  scene::VoxelGrid grid;
  grid.spacing = glm::dvec3(h);
  grid.dims = glm::ivec3(glm::ceil(extent / h)) + 5;
  grid.origin = b.center() - 0.5 * h * glm::dvec3(grid.dims - 1);
  return grid;
}

glm::dvec3 nodePosition(const scene::VoxelGrid& g, std::size_t n) {
  const std::size_t nx = std::size_t(g.dims.x), ny = std::size_t(g.dims.y);
  return g.origin +
         g.spacing * glm::dvec3(double(n % nx), double((n / nx) % ny), double(n / (nx * ny)));
}

/// Nodes of the grid in blocks of kBlock^3: a block farther from the soup than its own size holds
/// no triangle, and the winding number, harmonic there, crosses 1/2 inside it only across a hole.
constexpr int kBlock = 4;

/// +voxel at the nodes of block `b` (lo..hi inclusive) inside (|winding number| > 1/2), -voxel
/// outside. A block clear of the soup whose corners and centre lie all on one side, none within
/// 0.1 of 1/2, takes that side whole; any other block is evaluated node by node. |w| makes a soup
/// wound inside out as inside as an outward one.
void classifyBlock(const scene::TriangleSoupField& field, scene::VoxelGrid& g, const glm::ivec3& lo,
                   const glm::ivec3& hi) {
  const double h = g.spacing.x;
  const auto at = [&](int i, int j, int k) { return g.origin + h * glm::dvec3(i, j, k); };
  const glm::dvec3 centre = 0.5 * (at(lo.x, lo.y, lo.z) + at(hi.x, hi.y, hi.z));
  const double reach = 0.5 * glm::length(at(hi.x, hi.y, hi.z) - at(lo.x, lo.y, lo.z)) + h;
  if (field.distance(centre) > reach) {
    double least = std::fabs(field.windingNumber(centre)) - 0.5, most = least;
    for (int c = 0; c < 8; ++c) {
      const double w = std::fabs(field.windingNumber(
                           at(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z))) -
                       0.5;
      least = std::min(least, w), most = std::max(most, w);
    }
    if (least > 0.1 || most < -0.1) {
      for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
          for (int i = lo.x; i <= hi.x; ++i) g.values[g.index(i, j, k)] = float(least > 0 ? h : -h);
      return;
    }
  }
  for (int k = lo.z; k <= hi.z; ++k)
    for (int j = lo.y; j <= hi.y; ++j)
      for (int i = lo.x; i <= hi.x; ++i)
        g.values[g.index(i, j, k)] =
            std::fabs(field.windingNumber(at(i, j, k))) > 0.5 ? float(h) : float(-h);
}

/// Node values: the inside/outside of classifyBlock; then, on nodes beside a node of the other
/// side, the signed distance to the soup, so crossings land on the surface.
void signedField(const scene::TriangleSoupField& field, scene::VoxelGrid& g) {
  const double h = g.spacing.x;
  g.values.assign(std::size_t(g.dims.x) * g.dims.y * g.dims.z, 0.0f);
  const glm::ivec3 blocks = (g.dims + kBlock - 1) / kBlock;
  util::tbbFor(
      std::size_t(blocks.x) * blocks.y * blocks.z, [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b) {
          const glm::ivec3 lo = kBlock * glm::ivec3(int(b % blocks.x), int(b / blocks.x % blocks.y),
                                                    int(b / (std::size_t(blocks.x) * blocks.y)));
          classifyBlock(field, g, lo, glm::min(lo + kBlock, g.dims) - 1);
        }
      });
  const std::vector<std::size_t> band = scene::detail::crossingBand(g.values, g.dims);
  util::tbbFor(band.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t n = band[i];
      // At most a voxel and a half (past that the crossing closes a hole, away from the soup); at
      // least a trace, so a node on the soup keeps its side.
      const double d = std::clamp(field.distance(nodePosition(g, n)), 1e-6 * h, 1.5 * h);
      g.values[n] = float(g.values[n] > 0 ? d : -d);
    }
  });
}

/// Largest and mean distance from the vertices of `from` to the soup of `to`.
std::pair<double, double> vertexDistances(const scene::TriangleMesh& from,
                                          const scene::TriangleMesh& to) {
  const scene::TriangleSoupField field(to);
  std::vector<double> d(from.positions.size());
  util::tbbFor(d.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) d[i] = field.distance(glm::dvec3(from.positions[i]));
  });
  double sum = 0, most = 0;
  for (double v : d) sum += v, most = std::max(most, v);
  return {most, d.empty() ? 0.0 : sum / double(d.size())};
}
}  // namespace

RemeshResult remeshByWindingNumber(const scene::TriangleMesh& soup,
                                   const scene::TriangleMesh& input, int resolution,
                                   const std::string& what) {
  const scene::Bounds bounds = soup.bounds();
  const glm::dvec3 extent = bounds.hi - bounds.lo;
  if (soup.triangles.empty() || !(std::max({extent.x, extent.y, extent.z}) > 0) ||
      !std::isfinite(bounds.diagonal()))
    throw InputError(what +
                     " encloses nothing: its faces have no extent (every point at one "
                     "place); give a mesh of a solid object");
  const scene::TriangleSoupField field(soup);
  scene::VoxelGrid grid = gridAround(bounds, resolution);
  signedField(field, grid);
  if (std::none_of(grid.values.begin(), grid.values.end(), [](float v) { return v > 0; }))
    throw InputError(what +
                     " encloses nothing: its generalized winding number nowhere exceeds "
                     "1/2 (an open sheet or loose faces, not a surface around a volume); "
                     "give a mesh of a solid object");
  RemeshResult r;
  r.voxel = grid.spacing.x;
  {
    const QuietVtk quiet;
    r.mesh = fromPolyData(vtkadapter::closedIsosurface(grid, 0.0, what, "raise the resolution"));
  }
  scene::shapes::detail::orientOutward(r.mesh);
  std::tie(r.resultToInputMax, r.resultToInputMean) = vertexDistances(r.mesh, input);
  std::tie(r.inputToResultMax, r.inputToResultMean) = vertexDistances(input, r.mesh);
  return r;
}

}  // namespace lucent::io
