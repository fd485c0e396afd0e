/// @file lucentPolyDataMesh.h
/// @brief The one conversion of VTK data into lucent's TriangleMesh, shared by the CLI's mesh
/// readers, vtkLucentFilter and vtkLucentPass (header-only: it builds against Debian's VTK and
/// ParaView's alike). Every polydata leaf (of a composite too) is triangulated (polygons and
/// strips; lines and vertices dropped), moved by an optional matrix, welded (points that coincide
/// exactly become one: an STL stores each triangle's corners apart, and unwelded it shades
/// faceted), and turned outward when it is wound inside out (the irradiance needs outward normals).
#ifndef lucentPolyDataMesh_h
#define lucentPolyDataMesh_h

#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <lucent/scene/mesh.hpp>

namespace lucent::vtkadapter {

struct PolyDataMesh {
  scene::TriangleMesh mesh;  ///< the data's units, welded, outward
  vtkSmartPointer<vtkPolyData>
      triangles;         ///< the same triangles and points as VTK data (for output arrays)
  bool flipped = false;  ///< the input was wound inside out and was turned around
};

namespace detail {
/// Triangulated and welded polydata of one leaf.
inline vtkSmartPointer<vtkPolyData> weldedTriangles(vtkPolyData* poly) {
  vtkNew<vtkTriangleFilter> triangulate;
  if (poly->GetCellGhostArray()) {  // a distributed piece's ghost cells belong to another rank
    vtkNew<vtkPolyData> owned;
    owned->ShallowCopy(poly);
    owned->RemoveGhostCells();
    triangulate->SetInputData(owned);
  } else {
    triangulate->SetInputData(poly);
  }
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  vtkNew<vtkCleanPolyData> weld;
  weld->SetInputConnection(triangulate->GetOutputPort());
  weld->PointMergingOn();
  weld->SetTolerance(0.0);
  weld->ConvertLinesToPointsOff();
  weld->ConvertPolysToLinesOff();
  weld->ConvertStripsToPolysOff();
  weld->Update();
  vtkSmartPointer<vtkPolyData> out = weld->GetOutput();
  return out;
}

inline vtkSmartPointer<vtkCellArray> polysOf(const scene::TriangleMesh& mesh) {
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {vtkIdType(t.x), vtkIdType(t.y), vtkIdType(t.z)};
    polys->InsertNextCell(3, ids);
  }
  return polys;
}

inline void collectLeaves(vtkDataObject* data, std::vector<vtkPolyData*>& leaves) {
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data)) {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      collectLeaves(it->GetCurrentDataObject(), leaves);
    return;
  }
  auto* poly = vtkPolyData::SafeDownCast(data);
  if (poly && poly->GetNumberOfPolys() + poly->GetNumberOfStrips() > 0) leaves.push_back(poly);
}
}  // namespace detail

/// @param matrix moves the points (an actor's matrix); null keeps them.
/// @param orient turn an inside-out surface outward (not for one piece of a distributed surface,
/// whose
///        volume means nothing: the whole surface decides).
inline PolyDataMesh meshFromData(vtkDataObject* data, vtkMatrix4x4* matrix = nullptr,
                                 bool orient = true) {
  std::vector<vtkPolyData*> leaves;
  detail::collectLeaves(data, leaves);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  PolyDataMesh out;
  std::vector<vtkSmartPointer<vtkPolyData>> welded;
  for (vtkPolyData* leaf : leaves) welded.push_back(detail::weldedTriangles(leaf));
  for (const auto& tri : welded) {
    const auto base = vtkIdType(out.mesh.positions.size());
    for (vtkIdType i = 0; i < tri->GetNumberOfPoints(); ++i) {
      double p[4] = {0, 0, 0, 1};
      tri->GetPoint(i, p);
      if (matrix) {
        double w[4];
        matrix->MultiplyPoint(p, w);
        for (int k = 0; k < 3; ++k) p[k] = w[k] / w[3];
      }
      points->InsertNextPoint(p);
      out.mesh.positions.emplace_back(float(p[0]), float(p[1]), float(p[2]));
    }
    vtkCellArray* cells = tri->GetPolys();
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
      if (n == 3)
        out.mesh.triangles.push_back(
            {unsigned(base + ids[0]), unsigned(base + ids[1]), unsigned(base + ids[2])});
  }
  if (orient && out.mesh.signedVolume() < 0) {
    out.flipped = true;
    for (auto& t : out.mesh.triangles) std::swap(t.y, t.z);
  }
  out.triangles = vtkSmartPointer<vtkPolyData>::New();
  if (welded.size() == 1 && !matrix) {
    // One leaf, unmoved: keep its (welded) point data for the output.
    out.triangles->ShallowCopy(welded.front());
    out.triangles->SetVerts(nullptr), out.triangles->SetLines(nullptr),
        out.triangles->SetStrips(nullptr);
  } else {
    out.triangles->SetPoints(points);
  }
  out.triangles->SetPolys(detail::polysOf(out.mesh));
  return out;
}

/// Reverses the winding of every triangle, in the mesh and in its VTK data.
inline void flip(PolyDataMesh& surface) {
  for (auto& t : surface.mesh.triangles) std::swap(t.y, t.z);
  surface.triangles->SetPolys(detail::polysOf(surface.mesh));
  surface.flipped = !surface.flipped;
}

}  // namespace lucent::vtkadapter

#endif
