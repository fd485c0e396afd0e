#include <doctest/doctest.h>

#include <set>
#include <utility>

#include <lucent/scene/mesh_check.hpp>
#include <lucent/scene/shapes.hpp>

using namespace lucent::scene;

namespace {
// Euler characteristic V - E + F; for a closed orientable surface of c components, 2c - 2 * genus.
long eulerCharacteristic(const TriangleMesh& m) {
  std::set<std::pair<unsigned, unsigned>> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  return long(m.positions.size()) - long(edges.size()) + long(m.triangles.size());
}
}  // namespace

TEST_CASE("The parametric shapes are closed, manifold, outward and of the expected genus") {
  struct Case {
    const char* name;
    TriangleMesh mesh;
    long euler;
  };
  const Case cases[] = {{"sphere", shapes::sphere(1.0, 3), 2},
                        {"torus", shapes::torus(), 0},
                        {"slab", shapes::slab(), 2},
                        {"twirl", shapes::twirl(), 2},
                        {"cube-cavity", shapes::cubeWithCavity(), 4}};
  for (const auto& c : cases) {
    INFO(c.name);
    const MeshReport r = checkMesh(c.mesh);
    CHECK(r.ok());
    CHECK(r.problems().empty());
    CHECK(eulerCharacteristic(c.mesh) == c.euler);
  }
  // The cavity is a hole in the volume: 8 - (4/3) pi 0.6^3.
  CHECK(shapes::cubeWithCavity().signedVolume() == doctest::Approx(8.0 - 4.0 / 3.0 * lucent::optics::kPi * 0.216).epsilon(0.01));
}

TEST_CASE("Mesh checks name holes, non-manifold edges, flipped faces, inward meshes, degenerate faces") {
  const TriangleMesh good = shapes::sphere(1.0, 2);

  TriangleMesh holed = good;
  holed.triangles.pop_back();
  CHECK(checkMesh(holed).boundaryEdges == 3);
  CHECK(checkMesh(holed).problems().front().find("vtkFillHolesFilter") != std::string::npos);

  TriangleMesh flippedOne = good;
  std::swap(flippedOne.triangles[0].y, flippedOne.triangles[0].z);
  CHECK(checkMesh(flippedOne).inconsistentEdges == 3);
  CHECK_FALSE(checkMesh(flippedOne).ok());

  TriangleMesh inward = good;
  for (auto& t : inward.triangles) std::swap(t.y, t.z);
  CHECK(checkMesh(inward).consistentlyOriented());
  CHECK_FALSE(checkMesh(inward).outward());
  CHECK(checkMesh(inward).problems().front().find("inward") != std::string::npos);

  TriangleMesh fin = good;  // a third face on an existing edge
  const auto t0 = good.triangles[0];
  fin.positions.push_back(glm::vec3(5, 5, 5));
  fin.triangles.push_back({t0.x, t0.y, unsigned(fin.positions.size() - 1)});
  CHECK(checkMesh(fin).nonManifoldEdges >= 1);

  TriangleMesh degenerate = good;
  degenerate.triangles.push_back({t0.x, t0.x, t0.y});
  CHECK(checkMesh(degenerate).degenerateFaces == 1);

  CHECK_FALSE(checkMesh(TriangleMesh{}).ok());
}

TEST_CASE("scaleToSize centres the mesh and sets its diagonal, for tiny and huge sizes") {
  for (double size : {0.01, 30.0, 1e4}) {
    TriangleMesh m = shapes::torus();
    m.scaleToSize(size);
    CHECK(m.bounds().diagonal() == doctest::Approx(size).epsilon(1e-5));
    CHECK(glm::length(m.bounds().center()) < 1e-5 * size);
  }
}
