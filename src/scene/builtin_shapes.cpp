#include "builtin_shapes.hpp"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <functional>

#include <glm/geometric.hpp>
#include <lucent/scene/shapes.hpp>

#include "../io/vtk_isosurface.hpp"
#include "../util/error.hpp"

namespace lucent::scene {

namespace {
/// Signed distance to a torus in the x-z plane centred at c (ring radius R, tube radius r).
double torusDistance(const glm::dvec3& p, const glm::dvec3& c, double R, double r) {
  const glm::dvec3 q = p - c;
  const double ring = std::sqrt(q.x * q.x + q.z * q.z) - R;
  return std::sqrt(ring * ring + q.y * q.y) - r;
}

/// Contours f = 0 (f < 0 inside) on a res^3 grid over [-extent, extent]^3.
TriangleMesh contour(const std::function<double(const glm::dvec3&)>& f, glm::dvec3 extent,
                     int res) {
  auto grid = vtkSmartPointer<vtkImageData>::New();
  const glm::ivec3 dims =
      glm::max(glm::ivec3(8),
               glm::ivec3(glm::dvec3(res) * extent / std::max({extent.x, extent.y, extent.z})));
  grid->SetDimensions(dims.x, dims.y, dims.z);
  const glm::dvec3 spacing = 2.0 * extent / glm::dvec3(dims - 1);
  grid->SetOrigin(-extent.x, -extent.y, -extent.z);
  grid->SetSpacing(spacing.x, spacing.y, spacing.z);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetNumberOfTuples(vtkIdType(dims.x) * dims.y * dims.z);
  vtkIdType id = 0;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i) {
        const glm::dvec3 p = -extent + glm::dvec3(i, j, k) * spacing;
        // A tiny offset keeps grid values off exactly 0, where contouring can emit zero-area
        // triangles.
        values->SetValue(id++, float(f(p) + 1e-7));
      }
  grid->GetPointData()->SetScalars(values);
  return io::isosurfaceOf(grid, 0.0);
}

TriangleMesh tangentTori(int count, bool ring) {
  const double R = 1.0, r = 0.35;
  std::vector<glm::dvec3> centers;
  if (ring) {
    // Neighbouring centres 2R apart, so their core circles touch: a ring of n tori has genus n + 1.
    const double ringRadius = R / std::sin(optics::kPi / count);
    for (int i = 0; i < count; ++i) {
      const double a = 2 * optics::kPi * i / count;
      centers.push_back({ringRadius * std::cos(a), 0, ringRadius * std::sin(a)});
    }
  } else {
    for (int i = 0; i < count; ++i) centers.push_back({(2 * i - (count - 1)) * R, 0, 0});
  }
  glm::dvec3 extent(0);
  for (const auto& c : centers) extent = glm::max(extent, glm::abs(c));
  extent += glm::dvec3(R + r + 0.2, r + 0.2, R + r + 0.2);
  auto f = [&](const glm::dvec3& p) {
    double d = 1e30;
    for (const auto& c : centers) d = std::min(d, torusDistance(p, c, R, r));
    return d;
  };
  return contour(f, extent, ring ? 150 : 110);
}
}  // namespace

namespace {
/// A bottle standing along y (the paper's Fig. 2 scene): body radius 1 up to y = 2, a cosine
/// shoulder to the neck (radius 0.36) at y = 2.7, closed at y = 3.5; walls kBottleWall thick. The
/// liquid fills the inside up to kBottleFill; the headspace above it is air, a wall's thickness
/// above the liquid (every interface then has the bottle's material on one side, as nested media
/// need).
constexpr double kBottleWall = 0.1, kBottleFill = 1.6, kBottleTop = 3.5;

double bottleRadius(double y) {
  if (y <= 2.0) return 1.0;
  if (y >= 2.7) return 0.36;
  const double s = (y - 2.0) / 0.7;
  return 0.36 + (1.0 - 0.36) * 0.5 * (1 + std::cos(optics::kPi * s));
}

/// Contours a solid of revolution about y: radius(y) - inset, for y in [y0, y1] (bottle
/// coordinates, centred on the bottle's middle).
TriangleMesh revolved(double inset, double y0, double y1) {
  const double mid = 0.5 * kBottleTop;
  auto f = [=](const glm::dvec3& p) {
    const double y = p.y + mid;
    return std::max({std::hypot(p.x, p.z) - (bottleRadius(y) - inset), y0 - y, y - y1});
  };
  return contour(f, glm::dvec3(1.1, mid + 0.1, 1.1), 170);
}

TriangleMesh bottle() {
  TriangleMesh m = revolved(0, 0, kBottleTop);
  const TriangleMesh headspace =
      revolved(kBottleWall, kBottleFill + kBottleWall, kBottleTop - kBottleWall);
  const auto offset = std::uint32_t(m.positions.size());
  m.positions.insert(m.positions.end(), headspace.positions.begin(), headspace.positions.end());
  for (const auto& t : headspace.triangles)
    m.triangles.push_back({t.x + offset, t.z + offset, t.y + offset});  // a cavity faces inward
  return m;
}
}  // namespace

const std::vector<std::string>& builtinShapeNames() {
  static const std::vector<std::string> names{"sphere",      "torus", "double-torus", "genus7",
                                              "cube-cavity", "twirl", "slab",         "bottle"};
  return names;
}

std::vector<InnerBody> builtinInnerBodies(const std::string& name) {
  if (name != "bottle") return {};
  return {{revolved(kBottleWall, kBottleWall, kBottleFill), "Merlot", "the liquid"}};
}

namespace {
/// Turns a shape lying in the x-z plane to face +z (the default camera), by 90 degrees about x.
TriangleMesh faceCamera(TriangleMesh m) {
  for (auto& p : m.positions) p = glm::vec3(p.x, -p.z, p.y);
  return m;
}
}  // namespace

TriangleMesh makeBuiltinShape(const std::string& name) {
  if (name == "sphere") return shapes::sphere(1.0, 5);
  if (name == "torus") return faceCamera(shapes::torus());
  if (name == "double-torus") return faceCamera(tangentTori(2, false));
  if (name == "genus7")
    return faceCamera(tangentTori(6, true));  // six holes around a central one: genus 7
  if (name == "cube-cavity") return shapes::cubeWithCavity();
  if (name == "twirl") return shapes::twirl();
  if (name == "slab") return shapes::slab();
  if (name == "bottle") return bottle();
  std::string list;
  for (const auto& n : builtinShapeNames()) list += (list.empty() ? "" : ", ") + n;
  throw InputError("unknown shape '" + name + "'; built-in shapes are: " + list);
}

}  // namespace lucent::scene
