#define TETLIBRARY
#include "tetrahedralize.hpp"

#include <tetgen.h>

#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "../util/error.hpp"

namespace lucent::tetgen {

namespace {
/// Connected components of the triangles (sharing a vertex), as lists of triangle indices.
std::vector<std::vector<std::size_t>> components(const scene::TriangleMesh& m) {
  std::vector<std::size_t> parent(m.positions.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : m.triangles) {
    parent[find(t.y)] = find(t.x);
    parent[find(t.z)] = find(t.x);
  }
  std::vector<std::vector<std::size_t>> groups(m.positions.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) groups[find(m.triangles[t].x)].push_back(t);
  std::vector<std::vector<std::size_t>> out;
  for (auto& g : groups)
    if (!g.empty()) out.push_back(std::move(g));
  return out;
}

/// A point just inside each inward-facing component: TetGen's hole markers, so cavities stay empty.
std::vector<glm::dvec3> cavityPoints(const scene::TriangleMesh& m) {
  std::vector<glm::dvec3> holes;
  for (const auto& comp : components(m)) {
    double volume = 0, largest = 0;
    std::size_t best = comp.front();
    for (std::size_t t : comp) {
      const auto& tri = m.triangles[t];
      volume += glm::dot(glm::dvec3(m.positions[tri.x]),
                         glm::cross(glm::dvec3(m.positions[tri.y]), glm::dvec3(m.positions[tri.z]))) / 6.0;
      if (m.triangleArea(t) > largest) largest = m.triangleArea(t), best = t;
    }
    if (volume >= 0) continue;  // outward: material inside
    // The cavity's faces point into the cavity: step from the largest face's centroid along its normal,
    // by a fraction of the face's size, which stays inside a closed component.
    const auto& tri = m.triangles[best];
    const glm::dvec3 c = (glm::dvec3(m.positions[tri.x]) + glm::dvec3(m.positions[tri.y]) + glm::dvec3(m.positions[tri.z])) / 3.0;
    const glm::dvec3 n = glm::normalize(m.areaVector(best));
    holes.push_back(c + n * (0.1 * std::sqrt(largest)));
  }
  return holes;
}

std::string explain(int code) {
  switch (code) {
    case 1: return "TetGen ran out of memory; lower the quality (radius-edge ratio) or raise the volume bound";
    case 3: return "the surface intersects itself; repair it (e.g. MeshLab's 'Select Self Intersecting Faces', or remesh)";
    case 4: return "the surface has a feature far smaller than the rest; remove tiny edges (vtkCleanPolyData with a tolerance)";
    case 5: return "two surface facets are nearly coincident; remove duplicated or overlapping sheets";
    case 10: return "TetGen rejected the input; check that the mesh is closed and manifold";
    default: return "TetGen failed with internal error " + std::to_string(code) + "; try without surface preservation";
  }
}
}  // namespace

scene::TetMesh tetrahedralize(const scene::TriangleMesh& surface, const TetOptions& options) {
  if (surface.triangles.empty()) throw InputError("tetrahedralize: the surface has no triangles");
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(surface.positions.size());
  in.pointlist = new REAL[surface.positions.size() * 3];
  for (std::size_t i = 0; i < surface.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = surface.positions[i][k];
  in.numberoffacets = int(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3]{int(surface.triangles[t].x), int(surface.triangles[t].y), int(surface.triangles[t].z)};
  }
  const std::vector<glm::dvec3> holes = cavityPoints(surface);
  in.numberofholes = int(holes.size());
  if (!holes.empty()) {
    in.holelist = new REAL[holes.size() * 3];
    for (std::size_t h = 0; h < holes.size(); ++h)
      for (int k = 0; k < 3; ++k) in.holelist[3 * h + k] = holes[h][k];
  }

  // TetGen can crash, not throw, on self-intersecting input when it meshes; its -d pass only detects the
  // intersecting faces, safely. Run it first so bad input gets an error instead of a segfault.
  {
    tetgenio intersections;
    char detect[] = "pdQ";
    try {
      ::tetrahedralize(detect, &in, &intersections);
    } catch (int code) {
      throw InputError("tetrahedralize: " + explain(code));
    }
    if (intersections.numberoftrifaces > 0)
      throw InputError("tetrahedralize: " + explain(3) + " (" + std::to_string(intersections.numberoftrifaces) +
                       " intersecting faces)");
  }

  char switches[128];
  std::string s = "pzQq" + std::to_string(options.radiusEdgeRatio);
  if (options.maxVolume > 0) s += "a" + std::to_string(options.maxVolume);
  if (options.preserveSurface) s += "Y";
  s += "S" + std::to_string(options.maxSteinerPoints);
  std::snprintf(switches, sizeof switches, "%s", s.c_str());
  try {
    ::tetrahedralize(switches, &in, &out);
  } catch (int code) {
    throw InputError("tetrahedralize: " + explain(code));
  }

  scene::TetMesh tets;
  tets.positions.resize(std::size_t(out.numberofpoints));
  for (int i = 0; i < out.numberofpoints; ++i)
    tets.positions[std::size_t(i)] = {out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]};
  tets.tets.reserve(std::size_t(out.numberoftetrahedra));
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + std::size_t(t) * std::size_t(out.numberofcorners);
    tets.tets.push_back({unsigned(c[0]), unsigned(c[1]), unsigned(c[2]), unsigned(c[3])});
    if (tets.volume(tets.tets.size() - 1) < 0) std::swap(tets.tets.back().z, tets.tets.back().w);
  }
  return tets;
}

}  // namespace lucent::tetgen
