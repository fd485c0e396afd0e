/// @file lucentSurfaceGather.h
/// @brief The filter across processes (pvbatch --mpi, pvserver): subsurface light at a vertex
/// depends on the whole surface (every lit point within a few diffusion lengths, and shadows cast
/// by other pieces), so every rank gathers all ranks' triangles, runs the technique on the whole
/// (welded, outward) surface, and shades only its own vertices. Communication: one all-gather of
/// the triangle corners, 72 bytes per triangle (9 doubles) received by each of P ranks: P x 72 x T
/// bytes in all for T triangles.
#ifndef lucentSurfaceGather_h
#define lucentSurfaceGather_h

#include <array>
#include <map>
#include <vector>

#include <vtkCellArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "lucentPolyDataMesh.h"

namespace lucent::vtkadapter {

/// The triangles of every rank as one polydata of corner positions (not yet welded).
inline vtkSmartPointer<vtkPolyData> gatherTriangles(vtkMultiProcessController* controller,
                                                    vtkPolyData* local) {
  std::vector<double> soup;
  vtkCellArray* cells = local->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
    for (vtkIdType k = 0; k < n; ++k) {
      double p[3];
      local->GetPoint(ids[k], p);
      soup.insert(soup.end(), p, p + 3);
    }
  const int ranks = controller->GetNumberOfProcesses();
  long long length = static_cast<long long>(soup.size());
  std::vector<long long> lengths(static_cast<std::size_t>(ranks));
  controller->AllGather(&length, lengths.data(), 1);
  std::vector<vtkIdType> counts(lengths.begin(), lengths.end()), offsets(std::size_t(ranks), 0);
  for (int r = 1; r < ranks; ++r)
    offsets[std::size_t(r)] = offsets[std::size_t(r - 1)] + counts[std::size_t(r - 1)];
  std::vector<double> all(std::size_t(offsets.back() + counts.back()));
  controller->AllGatherV(soup.data(), all.data(), vtkIdType(soup.size()), counts.data(),
                         offsets.data());

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> triangles;
  for (std::size_t i = 0; i + 8 < all.size(); i += 9) {
    vtkIdType corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = points->InsertNextPoint(&all[i + 3 * std::size_t(k)]);
    triangles->InsertNextCell(3, corner);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(triangles);
  return out;
}

/// For each point of `local`, the index of the point at exactly the same position in `global`.
inline std::vector<vtkIdType> matchPoints(vtkPolyData* local, vtkPolyData* global) {
  std::map<std::array<double, 3>, vtkIdType> index;
  for (vtkIdType i = 0; i < global->GetNumberOfPoints(); ++i) {
    std::array<double, 3> p;
    global->GetPoint(i, p.data());
    index.emplace(p, i);
  }
  std::vector<vtkIdType> out(std::size_t(local->GetNumberOfPoints()), -1);
  for (vtkIdType i = 0; i < local->GetNumberOfPoints(); ++i) {
    std::array<double, 3> p;
    local->GetPoint(i, p.data());
    if (const auto it = index.find(p); it != index.end()) out[std::size_t(i)] = it->second;
  }
  return out;
}

}  // namespace lucent::vtkadapter

#endif
