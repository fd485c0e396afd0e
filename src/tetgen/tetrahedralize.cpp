#define TETLIBRARY
#include "tetrahedralize.hpp"

#include <tetgen.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
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
void run(const std::string& switches, tetgenio& in, tetgenio& out, tetgenio* background = nullptr) {
  std::vector<char> buffer(switches.begin(), switches.end());
  buffer.push_back('\0');
  try {
    ::tetrahedralize(buffer.data(), &in, &out, nullptr, background);
  } catch (int code) {
    throw InputError("tetrahedralize: " + explain(code));
  }
}

scene::TetMesh convert(const tetgenio& out) {
  scene::TetMesh tets;
  tets.positions.resize(std::size_t(out.numberofpoints));
  for (int i = 0; i < out.numberofpoints; ++i)
    tets.positions[std::size_t(i)] = {out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]};
  tets.tets.reserve(std::size_t(out.numberoftetrahedra));
  double signedTotal = 0;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + std::size_t(t) * std::size_t(out.numberofcorners);
    tets.tets.push_back({unsigned(c[0]), unsigned(c[1]), unsigned(c[2]), unsigned(c[3])});
    signedTotal += tets.volume(tets.tets.size() - 1);
  }
  // TetGen orients every tet alike (by exact predicates); one flip for all keeps that orientation for
  // slivers whose volume rounds to zero or below in double (genus7 at 20 mm had one: a per-tet sign
  // test could turn such a sliver inside out).
  if (signedTotal < 0)
    for (glm::uvec4& t : tets.tets) std::swap(t.z, t.w);
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int marker = out.trifacemarkerlist ? out.trifacemarkerlist[f] : 0;
    if (marker <= 0) continue;  // an inner face TetGen listed (none without -f), or no source
    const int* v = out.trifacelist + 3 * f;
    tets.boundaryFaces.push_back({unsigned(v[0]), unsigned(v[1]), unsigned(v[2])});
    tets.boundarySource.push_back(std::uint32_t(marker - 1));
  }
  return tets;
}

/// The mean length of the boundary edges at each boundary vertex (0 elsewhere): the local surface size.
std::vector<double> localSurfaceSize(const scene::TetMesh& m) {
  std::vector<double> sum(m.positions.size(), 0.0), count(m.positions.size(), 0.0);
  for (const auto& f : m.boundaryFaces)
    for (int k = 0; k < 3; ++k) {
      const double len = glm::distance(m.positions[f[k]], m.positions[f[(k + 1) % 3]]);
      sum[f[k]] += len, count[f[k]] += 1;
      sum[f[(k + 1) % 3]] += len, count[f[(k + 1) % 3]] += 1;
    }
  for (std::size_t v = 0; v < sum.size(); ++v) sum[v] = count[v] > 0 ? sum[v] / count[v] : 0.0;
  return sum;
}

/// The target edge length h(x) = h_s + K d(x) at every vertex: d is the distance to the boundary along
/// tet edges (multi-source Dijkstra; an upper bound of the straight distance within a few tens of percent
/// on quality meshes, which is all a size field needs) and h_s the local surface size where that path starts.
std::vector<double> targetEdgeLength(const scene::TetMesh& m, double gradingK) {
  std::vector<std::vector<std::uint32_t>> adjacent(m.positions.size());
  for (const auto& t : m.tets)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) adjacent[t[a]].push_back(t[b]);
  const std::vector<double> surfaceSize = localSurfaceSize(m);
  std::vector<double> dist(m.positions.size(), std::numeric_limits<double>::infinity());
  std::vector<double> size(m.positions.size(), 0.0);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const auto& f : m.boundaryFaces)
    for (int k = 0; k < 3; ++k)
      if (dist[f[k]] != 0) dist[f[k]] = 0, size[f[k]] = surfaceSize[f[k]], queue.push({0.0, f[k]});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (std::uint32_t w : adjacent[v]) {
      const double nd = d + glm::distance(m.positions[v], m.positions[w]);
      if (nd < dist[w]) dist[w] = nd, size[w] = size[v], queue.push({nd, w});
    }
  }
  for (std::size_t v = 0; v < size.size(); ++v) size[v] += gradingK * dist[v];
  return size;
}

/// Copies the points into TetGen's input (which owns and frees the array).
template <class Point>
void setPoints(tetgenio& in, const std::vector<Point>& points) {
  in.numberofpoints = int(points.size());
  in.pointlist = new REAL[points.size() * 3];
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + std::size_t(k)] = points[i][k];
}

double shortestEdge(const scene::TriangleMesh& surface) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& t : surface.triangles)
    for (int k = 0; k < 3; ++k)
      if (const double e = glm::distance(glm::dvec3(surface.positions[t[k]]), glm::dvec3(surface.positions[t[(k + 1) % 3]]));
          e > 0)
        shortest = std::min(shortest, e);
  return shortest;
}

/// A tet whose every edge is below this fraction of the surface's shortest edge is a speck: no size
/// K's grading asks for (it never asks below the surface's own edges) comes near it; the clusters
/// TetGen left had edges of 1e-16 mm against surface edges of 1e-1 mm.
constexpr double kSpeckFraction = 1e-3;

/// Whether some tet has every edge below `length`.
bool hasSpecks(const scene::TetMesh& m, double length) {
  return std::any_of(m.tets.begin(), m.tets.end(), [&](const glm::uvec4& t) {
    return scene::TetMesh::longestEdge(m.positions, t) < length;
  });
}

/// TetGen's refine mode (-r) with a volume target per tet from targetEdgeLength (a regular tet of edge h
/// has volume h^3 / (6 sqrt 2)). The Steiner budget is twice the point count the targets ask for, so a
/// surface TetGen cannot satisfy stops early instead of hanging. `keepSurface` (-Y): no surface face is
/// split; without it, pieces keep their source triangle.
scene::TetMesh refineToSize(const scene::TetMesh& mesh, const TetOptions& options, bool keepSurface,
                            std::size_t* budget) {
  const std::vector<double> target = targetEdgeLength(mesh, options.gradingK);
  tetgenio in, out;
  in.firstnumber = 0;
  setPoints(in, mesh.positions);
  in.numberoftetrahedra = int(mesh.tets.size());
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[mesh.tets.size() * 4];
  in.tetrahedronvolumelist = new REAL[mesh.tets.size()];
  double wantedTets = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    double h = 0;
    for (int k = 0; k < 4; ++k) in.tetrahedronlist[4 * t + std::size_t(k)] = int(mesh.tets[t][k]), h += target[mesh.tets[t][k]] / 4;
    in.tetrahedronvolumelist[t] = h * h * h / (6 * std::sqrt(2.0));
    wantedTets += std::max(1.0, mesh.volume(t) / in.tetrahedronvolumelist[t]);
  }
  in.numberoftrifaces = int(mesh.boundaryFaces.size());
  in.trifacelist = new int[mesh.boundaryFaces.size() * 3];
  in.trifacemarkerlist = new int[mesh.boundaryFaces.size()];
  for (std::size_t f = 0; f < mesh.boundaryFaces.size(); ++f) {
    for (int k = 0; k < 3; ++k) in.trifacelist[3 * f + std::size_t(k)] = int(mesh.boundaryFaces[f][k]);
    in.trifacemarkerlist[f] = int(mesh.boundarySource[f] + 1);
  }
  // A tet mesh has about 6 tets per point.
  const std::size_t steiner = std::min<std::size_t>(std::size_t(options.maxSteinerPoints),
                                                    std::size_t(2 * wantedTets / 6) + 1000);
  if (budget) *budget = steiner;
  std::string s = "rzQq" + std::to_string(options.radiusEdgeRatio) + "a";
  if (keepSurface) s += "Y";
  s += "S" + std::to_string(steiner);
  run(s, in, out);
  return convert(out);
}
}  // namespace

scene::TetMesh tetrahedralize(const scene::TriangleMesh& surface, const TetOptions& options, TetReport* report) {
  if (surface.triangles.empty()) throw InputError("tetrahedralize: the surface has no triangles");
  tetgenio in, out;
  in.firstnumber = 0;
  setPoints(in, surface.positions);
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
  // Marker t + 1 (0 means "none" to TetGen): every output boundary face names its input triangle.
  in.facetmarkerlist = new int[surface.triangles.size()];
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) in.facetmarkerlist[t] = int(t + 1);
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

  std::string s = "pzQq" + std::to_string(options.radiusEdgeRatio);
  if (options.maxVolume > 0) s += "a" + std::to_string(options.maxVolume);
  if (options.preserveSurface) s += "Y";
  s += "S" + std::to_string(options.maxSteinerPoints);
  run(s, in, out);
  scene::TetMesh tets = convert(out);
  if (options.gradingK >= 0) {
    std::size_t budget = 0;
    const std::size_t before = tets.positions.size();
    const auto added = [before](const scene::TetMesh& m) {  // Steiner points of the grading pass
      return m.positions.size() > before ? m.positions.size() - before : std::size_t(0);
    };
    scene::TetMesh graded = refineToSize(tets, options, options.preserveSurface, &budget);
    // With -Y, TetGen cannot split a surface face a new point encroaches; near small surface angles it
    // then clusters points within 1e-10 mm of each other until the budget is spent (genus7 at 20 mm:
    // 60 % of the tets without volume), sometimes within the budget. Such a surface is refined again
    // with its faces split.
    const bool clustered =
        options.preserveSurface &&
        (added(graded) >= budget || hasSpecks(graded, kSpeckFraction * shortestEdge(surface)));
    if (clustered) graded = refineToSize(tets, options, false, &budget);
    if (report)
      report->steinerBudget = budget, report->steinerUsed = added(graded),
      report->surfaceSplit = clustered;
    tets = std::move(graded);
  }
  return tets;
}

}  // namespace lucent::tetgen
