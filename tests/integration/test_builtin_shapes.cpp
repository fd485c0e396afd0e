#include <doctest/doctest.h>

#include <set>
#include <utility>

#include <lucent/scene/mesh_check.hpp>

#include "scene/builtin_shapes.hpp"
#include "util/error.hpp"

using namespace lucent;

TEST_CASE("Every built-in shape bounds a volume and has the genus its name promises") {
  // Euler characteristic V - E + F = 2 (components) - 2 (genus).
  const std::pair<const char*, long> expected[] = {{"sphere", 2},       {"torus", 0},  {"double-torus", -2},
                                                   {"genus7", -12},     {"cube-cavity", 4}, {"twirl", 2},
                                                   {"slab", 2}};
  for (const auto& [name, euler] : expected) {
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

TEST_CASE("An unknown shape name gives an error that lists the valid names") {
  try {
    scene::makeBuiltinShape("dodecahedron");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("genus7") != std::string::npos);
  }
}
