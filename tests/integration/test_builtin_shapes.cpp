#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include <set>
#include <utility>

#include <lucent/scene/mesh_check.hpp>

#include "raycast/embree_ray_caster.hpp"
#include "scene/builtin_shapes.hpp"
#include "util/error.hpp"

using namespace lucent;

TEST_CASE("Every built-in shape bounds a volume and has the genus its name promises") {
  // Euler characteristic V - E + F = 2 (components) - 2 (genus).
  const std::pair<const char*, long> expected[] = {
      {"sphere", 2},      {"torus", 0}, {"double-torus", -2}, {"genus7", -12},
      {"cube-cavity", 4}, {"twirl", 2}, {"slab", 2},          {"bottle", 4}};
  for (const auto& entry : expected) {
    const auto& name = std::get<0>(entry);  // no structured binding: clang 14 cannot capture one
    const auto& euler = std::get<1>(entry);
    const scene::TriangleMesh m = scene::makeBuiltinShape(name);
    const scene::MeshReport r = scene::checkMesh(m);
    INFO(name);
    for (const auto& p : r.problems()) INFO(p);
    CHECK(r.ok());
    std::set<std::pair<unsigned, unsigned>> edges;
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    CHECK(long(m.positions.size()) - long(edges.size()) + long(m.triangles.size()) == euler);
  }
  CHECK(scene::builtinShapeNames().size() == std::size(expected));
}

TEST_CASE("The bottle's liquid is a closed body inside the bottle's material, apart from the air") {
  const scene::TriangleMesh bottle = scene::makeBuiltinShape("bottle");
  const auto bodies = scene::builtinInnerBodies("bottle");
  REQUIRE(bodies.size() == 1);
  CHECK(scene::checkMesh(bodies[0].surface).ok());
  CHECK(scene::builtinInnerBodies("sphere").empty());
  // Ray parity against the bottle (outer wall + headspace): odd = in the material. The bodies
  // are contoured on one grid, so a ray may pass exactly through an edge: three directions vote;
  // each step starts 1e-4 past the last hit (Embree intersects in float).
  const raycast::EmbreeRayCaster caster(bottle);
  auto parity = [&](glm::dvec3 p, const glm::dvec3& dir) {
    int crossings = 0;
    for (auto hit = caster.intersect(p, dir, 1e-4, 1e9); hit;
         hit = caster.intersect(p, dir, 1e-4, 1e9)) {
      ++crossings;
      p += hit->t * dir;
    }
    return crossings % 2;
  };
  auto inMaterial = [&](const glm::dvec3& p) {
    return parity(p, glm::normalize(glm::dvec3(0.31, 0.17, 1))) +
               parity(p, glm::normalize(glm::dvec3(-0.7, 0.23, 0.41))) +
               parity(p, glm::normalize(glm::dvec3(0.13, -0.91, -0.29))) >=
           2;
  };
  for (std::size_t i = 0; i < bodies[0].surface.positions.size(); i += 7) {
    const glm::dvec3 p(bodies[0].surface.positions[i]);
    INFO(p.x << " " << p.y << " " << p.z);
    CHECK(inMaterial(p));
  }
}

TEST_CASE("An unknown shape name gives an error that lists the valid names") {
  try {
    scene::makeBuiltinShape("dodecahedron");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("genus7") != std::string::npos);
  }
}
