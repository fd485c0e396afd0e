// Closed meshes into media grids (voxelize.hpp) and the surface voxels (surface_voxels.hpp),
// against independent inside tests: the analytic sphere and cube the meshes approximate.
#include <doctest/doctest.h>

#include <cmath>

#include <lucent/scene/shapes.hpp>
#include <lucent/voxel/surface_voxels.hpp>
#include <lucent/voxel/voxelize.hpp>

using namespace lucent;

TEST_CASE("Voxelising: a voxel is inside exactly when its centre is inside the mesh") {
  SUBCASE("a sphere (an icosphere within 0.002 of radius 1)") {
    const auto mesh = scene::shapes::sphere(1.0, 4);
    voxel::MediaGrid g = voxel::gridAround(mesh, 40);
    voxel::fillInside(g, mesh, 1);
    int checked = 0;
    for (int z = 0; z < g.dims.z; ++z)
      for (int y = 0; y < g.dims.y; ++y)
        for (int x = 0; x < g.dims.x; ++x) {
          const double r = glm::length(g.centre({x, y, z}));
          if (std::abs(r - 1) < 0.002) continue;  // between the facets and the sphere
          CHECK(g.at({x, y, z}) == (r < 1 ? 1 : 0));
          ++checked;
        }
    CHECK(checked > 60000);
  }
  SUBCASE("a cube with a spherical cavity (the cavity's faces point in): winding, not parity") {
    const auto mesh = scene::shapes::cubeWithCavity(0.6);
    voxel::MediaGrid g = voxel::gridAround(mesh, 40);
    voxel::fillInside(g, mesh, 1);
    for (int z = 0; z < g.dims.z; ++z)
      for (int y = 0; y < g.dims.y; ++y)
        for (int x = 0; x < g.dims.x; ++x) {
          const glm::dvec3 c = g.centre({x, y, z});
          const double r = glm::length(c);
          if (std::abs(r - 0.6) < 0.002) continue;
          const bool inCube = std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}) < 1;
          CHECK(g.at({x, y, z}) == (inCube && r > 0.6 ? 1 : 0));
        }
  }
  SUBCASE("rows through the mesh's vertices and edges: counted once, nothing leaks") {
    // Box vertices at multiples of 0.5; voxel centres at multiples of 0.5 too.
    const auto mesh = scene::shapes::box(glm::dvec3(1.0), 0.5);
    voxel::MediaGrid g(glm::ivec3(7), glm::dvec3(-1.75), glm::dvec3(0.5));
    voxel::fillInside(g, mesh, 1);
    for (int z = 0; z < 7; ++z)
      for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 7; ++x) {
          const glm::dvec3 c = g.centre({x, y, z});
          const double m = std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)});
          if (m < 1) CHECK(g.at({x, y, z}) == 1);
          if (m > 1) CHECK(g.at({x, y, z}) == 0);
        }
  }
  SUBCASE("nested meshes fill in order: object, cavity, inclusion") {
    voxel::MediaGrid g = voxel::gridAround(scene::shapes::box(glm::dvec3(1.0), 0.25), 32);
    voxel::fillInside(g, scene::shapes::box(glm::dvec3(1.0), 0.25), 1);
    voxel::fillInside(g, scene::shapes::sphere(0.7, 3), voxel::kNoMedium);
    voxel::fillInside(g, scene::shapes::sphere(0.3, 3), 2);
    CHECK(g.at(g.voxelOf(glm::dvec3(0.9, 0, 0))) == 1);
    CHECK(g.at(g.voxelOf(glm::dvec3(0.5, 0, 0))) == 0);
    CHECK(g.at(g.voxelOf(glm::dvec3(0.05, 0.05, 0))) == 2);
  }
  SUBCASE("hard cases: an empty grid, a mesh outside the grid, a mesh far away") {
    voxel::MediaGrid empty;
    voxel::fillInside(empty, scene::shapes::sphere(1.0, 2), 1);
    CHECK(empty.voxelCount() == 0);
    voxel::MediaGrid g(glm::ivec3(8), glm::dvec3(0), glm::dvec3(1));
    voxel::fillInside(g, scene::shapes::sphere(1.0, 2, glm::dvec3(100, 0, 0)), 1);
    voxel::fillInside(g, scene::shapes::sphere(1.0, 2, glm::dvec3(1e25, -1e25, 3e24)), 1);
    for (auto m : g.medium) CHECK(m == 0);
  }
}

TEST_CASE(
    "Surface voxels: the medium's voxels that touch the outside, numbered, cavity walls excluded") {
  const auto mesh = scene::shapes::cubeWithCavity(0.6);
  voxel::MediaGrid g = voxel::gridAround(mesh, 30);
  voxel::fillInside(g, mesh, 1);
  const voxel::SurfaceVoxels s = voxel::surfaceVoxels(g);
  const std::vector<bool> outside = voxel::outsideVoxels(g);
  std::size_t cavity = 0;
  for (std::size_t i = 0; i < g.voxelCount(); ++i) cavity += g.medium[i] == 0 && !outside[i];
  CHECK(cavity > 100);  // the cavity is enclosed: not outside
  // A 30^3 cube's shell: 30^3 - 28^3 voxels.
  CHECK(s.count() == std::size_t(30 * 30 * 30 - 28 * 28 * 28));
  for (std::size_t i = 0; i < s.count(); ++i) {
    CHECK(s.number[g.index(s.voxels[i])] == std::int32_t(i));
    const glm::dvec3 c = g.centre(s.voxels[i]);
    CHECK(std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}) > 1 - 2.0 / 30);  // the shell
  }
  // A wall one voxel thick: every voxel of it is a surface voxel.
  voxel::MediaGrid wall(glm::ivec3(12, 12, 3), glm::dvec3(0), glm::dvec3(1));
  for (int y = 1; y < 11; ++y)
    for (int x = 1; x < 11; ++x) wall.set({x, y, 1}, 1);
  CHECK(voxel::surfaceVoxels(wall).count() == 100);
}
