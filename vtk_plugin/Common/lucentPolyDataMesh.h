/// @file lucentPolyDataMesh.h
/// @brief The one conversion of VTK data into lucent's TriangleMesh, shared by the CLI's mesh
/// readers, vtkLucentFilter and vtkLucentPass (header-only: it builds against Debian's VTK and
/// ParaView's alike). Every polydata leaf (of a composite too) is triangulated (polygons and
/// strips; lines and vertices dropped), moved by an optional matrix, welded (points that coincide
/// exactly become one: an STL stores each triangle's corners apart, and unwelded it shades
/// faceted), and turned outward when it is wound inside out (the irradiance needs outward normals).
#ifndef lucentPolyDataMesh_h
#define lucentPolyDataMesh_h

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkFieldData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>

#include <lucent/scene/mesh.hpp>

namespace lucent::vtkadapter {

struct PolyDataMesh {
  scene::TriangleMesh mesh;  ///< the data's units, welded, outward
  vtkSmartPointer<vtkPolyData>
      triangles;         ///< the same triangles and points as VTK data (for output arrays)
  bool flipped = false;  ///< the input was wound inside out and was turned around
  /// Triangles missing from non-convex polygons VTK's triangulation left out (non-planar,
  /// self-overlapping or degenerate): their edges show as holes, so front ends say so before the
  /// mesh check. (Strips are not counted.)
  std::size_t missingTriangles = 0;
};

namespace detail {
/// A fan over a convex polygon from the corner whose thinnest fan triangle is widest, or false
/// for a non-convex one (left to VTK's ear cut). Collinear corners (T-junctions) are fine.
inline bool convexFan(vtkPolyData* poly, vtkIdType n, const vtkIdType* ids, vtkCellArray* out) {
  std::vector<std::array<double, 3>> p(static_cast<std::size_t>(n));
  for (vtkIdType k = 0; k < n; ++k) poly->GetPoint(ids[k], p[std::size_t(k)].data());
  auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    const double u[3] = {p[b][0] - p[a][0], p[b][1] - p[a][1], p[b][2] - p[a][2]};
    const double v[3] = {p[c][0] - p[a][0], p[c][1] - p[a][1], p[c][2] - p[a][2]};
    return std::array<double, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                 u[0] * v[1] - u[1] * v[0]};
  };
  const std::size_t m = p.size();
  std::array<double, 3> normal{0, 0, 0};  // Newell's normal: the polygon's area vector
  for (std::size_t k = 0; k < m; ++k) {
    const auto& a = p[k];
    const auto& b = p[(k + 1) % m];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  auto along = [&](const std::array<double, 3>& c) {
    return c[0] * normal[0] + c[1] * normal[1] + c[2] * normal[2];
  };
  for (std::size_t k = 0; k < m; ++k)  // every turn the same way (or straight): convex
    if (along(cross(k, (k + 1) % m, (k + 2) % m)) < 0) return false;
  std::size_t apex = 0;
  double best = -1;
  for (std::size_t k = 0; k < m; ++k) {
    double thinnest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j + 1 < m; ++j)
      thinnest = std::min(thinnest, along(cross(k, (k + j) % m, (k + j + 1) % m)));
    if (thinnest > best) best = thinnest, apex = k;
  }
  for (std::size_t j = 1; j + 1 < m; ++j) {
    const vtkIdType t[3] = {ids[apex], ids[(apex + j) % m], ids[(apex + j + 1) % m]};
    out->InsertNextCell(3, t);
  }
  return true;
}

/// The most corners a polygon is fanned with (the apex search is quadratic in them); larger ones go
/// to VTK's ear cut.
constexpr vtkIdType kMaxFannedCorners = 1024;

/// The polygons with every convex one fanned (convexFan): VTK's ear cut drops thin quads and
/// polygons with nearly coincident corners (a sliver of 1e-7 of the object made a closed box
/// report holes); a fan cannot fail. `expected` counts the triangles the polygons should give.
inline vtkSmartPointer<vtkPolyData> convexPolygonsFanned(vtkPolyData* poly, std::size_t& expected) {
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(poly);
  // Its cell data describes the unsplit cells: the triangulation would read tuples past its end.
  // Nothing downstream reads cell data.
  out->GetCellData()->Initialize();
  vtkNew<vtkCellArray> polys;
  vtkCellArray* cells = poly->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);) {
    if (n >= 3) expected += std::size_t(n - 2);
    if (n < 4 || n > kMaxFannedCorners || !convexFan(poly, n, ids, polys))
      polys->InsertNextCell(n, ids);
  }
  out->SetPolys(polys);
  return out;
}

/// Triangulated and welded polydata of one leaf; `missing` grows by the triangles VTK's
/// triangulation left out.
inline vtkSmartPointer<vtkPolyData> weldedTriangles(vtkPolyData* poly, std::size_t& missing) {
  vtkNew<vtkTriangleFilter> triangulate;
  std::size_t expected = 0;
  vtkSmartPointer<vtkPolyData> split;
  if (poly->GetCellGhostArray()) {  // a distributed piece's ghost cells belong to another rank
    vtkNew<vtkPolyData> owned;
    owned->ShallowCopy(poly);
    owned->RemoveGhostCells();
    split = convexPolygonsFanned(owned, expected);
  } else {
    split = convexPolygonsFanned(poly, expected);
  }
  triangulate->SetInputData(split);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  vtkNew<vtkCleanPolyData> weld;
  weld->SetInputConnection(triangulate->GetOutputPort());
  weld->PointMergingOn();
  weld->SetTolerance(0.0);
  weld->ConvertLinesToPointsOff();
  weld->ConvertPolysToLinesOff();
  weld->ConvertStripsToPolysOff();
  triangulate->Update();
  const std::size_t made = std::size_t(triangulate->GetOutput()->GetNumberOfPolys());
  if (poly->GetNumberOfStrips() == 0 && made < expected) missing += expected - made;
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

/// The surface leaves of `data`: the object's (inner = false) or the inner bodies' (true).
inline void collectLeaves(vtkDataObject* data, std::vector<vtkPolyData*>& leaves,
                          bool inner = false);
}  // namespace detail

/// The field-data string array that makes a data set an inner body of the object around it, filled
/// with the measured material it names (the wine in a bottle): vtkLucentFilter takes such blocks of
/// a composite input, vtkLucentPass such actors, as inclusions of the surrounding surface.
inline constexpr const char* kInnerMaterialArray = "LucentInnerMaterial";

/// The material `data` is an inner body of, or "" when it is none.
inline std::string innerMaterialOf(vtkDataObject* data) {
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  auto* names =
      field ? vtkStringArray::SafeDownCast(field->GetAbstractArray(kInnerMaterialArray)) : nullptr;
  return names && names->GetNumberOfValues() > 0 ? names->GetValue(0) : std::string();
}

/// Marks `data` as an inner body filled with `material`.
inline void markInnerBody(vtkDataObject* data, const std::string& material) {
  vtkNew<vtkStringArray> names;
  names->SetName(kInnerMaterialArray);
  names->InsertNextValue(material);
  data->GetFieldData()->AddArray(names);
}

inline void detail::collectLeaves(vtkDataObject* data, std::vector<vtkPolyData*>& leaves,
                                  bool inner) {
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data)) {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      collectLeaves(it->GetCurrentDataObject(), leaves, inner);
    return;
  }
  auto* poly = vtkPolyData::SafeDownCast(data);
  if (poly && poly->GetNumberOfPolys() + poly->GetNumberOfStrips() > 0 &&
      innerMaterialOf(poly).empty() != inner)
    leaves.push_back(poly);
}

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
  for (vtkPolyData* leaf : leaves)
    welded.push_back(detail::weldedTriangles(leaf, out.missingTriangles));
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

/// An inner body of the data: its material and its surface (welded, outward, moved by `matrix`).
struct InnerBodyData {
  std::string material;
  PolyDataMesh surface;
};

/// The leaves of `data` marked as inner bodies (kInnerMaterialArray), in traversal order.
inline std::vector<InnerBodyData> innerBodiesOf(vtkDataObject* data,
                                                vtkMatrix4x4* matrix = nullptr) {
  std::vector<vtkPolyData*> leaves;
  detail::collectLeaves(data, leaves, /*inner=*/true);
  std::vector<InnerBodyData> bodies;
  for (vtkPolyData* leaf : leaves) {
    vtkNew<vtkPolyData> unmarked;  // meshFromData takes the object's (unmarked) leaves
    unmarked->ShallowCopy(leaf);
    vtkNew<vtkFieldData> none;
    unmarked->SetFieldData(none);
    bodies.push_back({innerMaterialOf(leaf), meshFromData(unmarked, matrix)});
  }
  return bodies;
}

/// Reverses the winding of every triangle, in the mesh and in its VTK data.
inline void flip(PolyDataMesh& surface) {
  for (auto& t : surface.mesh.triangles) std::swap(t.y, t.z);
  surface.triangles->SetPolys(detail::polysOf(surface.mesh));
  surface.flipped = !surface.flipped;
}

/// A lucent mesh as vtkPolyData (points and triangles, nothing welded or turned).
inline vtkSmartPointer<vtkPolyData> polyDataOf(const scene::TriangleMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(vtkIdType(mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    points->SetPoint(vtkIdType(i), mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(detail::polysOf(mesh));
  return data;
}

}  // namespace lucent::vtkadapter

#endif
