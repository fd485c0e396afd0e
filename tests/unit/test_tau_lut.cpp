// The optical-thickness table between surface voxels (path_length_table.hpp, surface_paths.hpp)
// and the point-to-surface-voxel map (surface_voxel_lookup.hpp), against independent references:
// analytic chords of the shapes the grids discretise, and the exact walk for the stored forms.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <lucent/scene/shapes.hpp>
#include <lucent/util/rng.hpp>
#include <lucent/voxel/surface_paths.hpp>
#include <lucent/voxel/surface_voxel_lookup.hpp>
#include <lucent/voxel/voxelize.hpp>

using namespace lucent;

namespace {

/// Length of the chord of segment a -> b inside the sphere |x - c| < r.
double chordInSphere(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double r) {
  const glm::dvec3 d = b - a;
  const double len = glm::length(d);
  const glm::dvec3 u = d / len;
  const double p = glm::dot(a - c, u), q = glm::dot(a - c, a - c) - r * r;
  const double disc = p * p - q;
  if (disc <= 0) return 0;
  const double t0 = std::clamp(-p - std::sqrt(disc), 0.0, len);
  const double t1 = std::clamp(-p + std::sqrt(disc), 0.0, len);
  return t1 - t0;
}

/// Length of the chord of a -> b inside the cube |x|_inf < h.
double chordInCube(const glm::dvec3& a, const glm::dvec3& b, double h) {
  double t0 = 0, t1 = 1;
  const glm::dvec3 d = b - a;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (std::abs(a[k]) >= h) return 0;
      continue;
    }
    double e = (-h - a[k]) / d[k], l = (h - a[k]) / d[k];
    if (e > l) std::swap(e, l);
    t0 = std::max(t0, e), t1 = std::min(t1, l);
  }
  return t1 > t0 ? (t1 - t0) * glm::length(d) : 0;
}

struct Voxelised {
  voxel::MediaGrid grid;
  voxel::SurfaceVoxels surface;
};

Voxelised cubeWithCavity(int voxels) {
  const auto mesh = scene::shapes::cubeWithCavity(0.6);
  Voxelised v{voxel::gridAround(mesh, voxels), {}};
  voxel::fillInside(v.grid, mesh, 1);
  v.surface = voxel::surfaceVoxels(v.grid);
  return v;
}

/// A unit sphere of medium 1 holding a concentric sphere of radius 0.5 of medium 2.
Voxelised twoMediumSphere(int voxels) {
  const auto outer = scene::shapes::sphere(1.0, 5), inner = scene::shapes::sphere(0.5, 5);
  Voxelised v{voxel::gridAround(outer, voxels), {}};
  voxel::fillInside(v.grid, outer, 1);
  voxel::fillInside(v.grid, inner, 2);
  v.surface = voxel::surfaceVoxels(v.grid);
  return v;
}

}  // namespace

TEST_CASE("Path lengths between surface voxels converge to the analytic chords with resolution") {
  SUBCASE("a cube with a spherical cavity: the chord in the cube minus the cavity's chord") {
    double previous = 1e9;
    for (int voxels : {16, 32, 64}) {
      const Voxelised v = cubeWithCavity(voxels);
      voxel::SurfacePathOptions o;
      o.storage = voxel::Storage::March;
      const voxel::SurfacePaths paths(v.grid, v.surface, 1, o);
      util::Rng rng(7);
      double worst = 0;
      for (int i = 0; i < 400; ++i) {
        const auto a = std::int32_t(rng.uniform() * double(v.surface.count()));
        const auto b = std::int32_t(rng.uniform() * double(v.surface.count()));
        const glm::dvec3 pa = paths.centre(a), pb = paths.centre(b);
        float length = 0;
        paths.lengths(a, b, &length);
        const double truth = chordInCube(pa, pb, 1.0) - chordInSphere(pa, pb, glm::dvec3(0), 0.6);
        worst = std::max(worst, std::abs(double(length) - truth) / v.grid.spacing.x);
      }
      const double h = v.grid.spacing.x;
      INFO(voxels << " voxels: worst error " << worst << " voxel edges");
      // The staircase: about a voxel at each of the (at most 4) boundaries, and a chord grazing
      // the cavity runs along a step of up to sqrt(2 R h).
      CHECK(worst * h < 4 * h + 2 * std::sqrt(2 * 0.6 * h));
      CHECK(worst * h < previous);
      previous = worst * v.grid.spacing.x;
    }
  }
  SUBCASE("two concentric media: the inner chord through the centre is its diameter") {
    const Voxelised v = twoMediumSphere(48);
    voxel::SurfacePathOptions o;
    o.precision = voxel::Precision::Single;
    const voxel::SurfacePaths paths(v.grid, v.surface, 2, o);
    // Surface voxels nearest the poles on each axis: the chord passes the centre.
    const voxel::SurfaceVoxelLookup lookup(paths.grid(), v.surface);
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 pole(0);
      pole[axis] = 1;
      const std::int32_t a = lookup.numberOf(pole), b = lookup.numberOf(-pole);
      float length[2];
      paths.lengths(a, b, length);
      const glm::dvec3 pa = paths.centre(a), pb = paths.centre(b);
      const double inner = chordInSphere(pa, pb, glm::dvec3(0), 0.5);
      const double outer = chordInSphere(pa, pb, glm::dvec3(0), 1.0) - inner;
      CHECK(std::abs(length[1] - inner) < 2 * v.grid.spacing.x);
      CHECK(std::abs(length[0] - outer) < 3 * v.grid.spacing.x);
    }
  }
}

TEST_CASE("The stored table equals the walk either way: fp32 to rounding, fp16 to 2^-11") {
  const Voxelised v = twoMediumSphere(20);
  voxel::SurfacePathOptions lut32, lut16, march;
  lut32.precision = voxel::Precision::Single;
  march.storage = voxel::Storage::March;
  const voxel::SurfacePaths t32(v.grid, v.surface, 2, lut32), t16(v.grid, v.surface, 2, lut16),
      walk(v.grid, v.surface, 2, march);
  CHECK(t32.tableBytes() == voxel::packedPairs(v.surface.count()) * 2 * 4);
  CHECK(t16.tableBytes() == voxel::packedPairs(v.surface.count()) * 2 * 2);
  CHECK(walk.tableBytes() == 0);
  const auto n = std::int32_t(v.surface.count());
  for (std::int32_t a = 0; a < n; a += 7)
    for (std::int32_t b = 0; b < n; b += 5) {
      // The walk from b to a against the half the table stores (a <= b or not): symmetry is
      // a property of the walk the table relies on, checked here.
      float exact[2], single[2], half[2];
      walk.lengths(b, a, exact);
      t32.lengths(a, b, single);
      t16.lengths(a, b, half);
      for (int m = 0; m < 2; ++m) {
        CHECK(single[m] == doctest::Approx(exact[m]).epsilon(1e-5));
        CHECK(std::abs(half[m] - exact[m]) <= std::ldexp(exact[m], -11) + 1e-5);
      }
    }
}

TEST_CASE(
    "Hierarchical storage: neighbouring clusters exact, far pairs within a stated error, "
    "memory down") {
  const Voxelised v = twoMediumSphere(40);
  voxel::SurfacePathOptions lut, tree;
  lut.precision = tree.precision = voxel::Precision::Single;
  tree.storage = voxel::Storage::Hierarchical;
  tree.clusterEdge = 4;
  const voxel::SurfacePaths full(v.grid, v.surface, 2, lut), clustered(v.grid, v.surface, 2, tree);
  // Clusters cover the surface: up to edge^2 voxels each (fewer where the surface curves through a
  // cluster's corner), so the table shrinks by up to edge^4; 98 times on this sphere.
  CHECK(double(full.tableBytes()) / double(clustered.tableBytes()) > 50);
  util::Rng rng(11);
  std::vector<double> errors;
  int neighbours = 0;
  for (int i = 0; i < 4000; ++i) {
    const auto a = std::int32_t(rng.uniform() * double(v.surface.count()));
    const auto b = std::int32_t(rng.uniform() * double(v.surface.count()));
    float exact[2], approx[2];
    full.lengths(a, b, exact);
    clustered.lengths(a, b, approx);
    const glm::ivec3 gap = glm::abs(v.surface.voxels[std::size_t(a)] / tree.clusterEdge -
                                    v.surface.voxels[std::size_t(b)] / tree.clusterEdge);
    if (std::max({gap.x, gap.y, gap.z}) <= 1) {
      ++neighbours;
      for (int m = 0; m < 2; ++m) CHECK(approx[m] == doctest::Approx(exact[m]));
    }
    const double chord = glm::length(full.centre(a) - full.centre(b));
    if (chord > 0) errors.push_back(std::abs(approx[1] - exact[1]) / chord);  // the inner medium
  }
  CHECK(neighbours > 20);
  std::sort(errors.begin(), errors.end());
  INFO("median " << errors[errors.size() / 2] << ", 95th " << errors[errors.size() * 95 / 100]);
  CHECK(errors[errors.size() / 2] < 0.03);  // of the chord
  CHECK(errors[errors.size() * 95 / 100] < 0.15);
}

TEST_CASE("A table over the memory bound is refused before it is allocated") {
  const Voxelised v = cubeWithCavity(32);
  voxel::SurfacePathOptions o;
  o.maxTableBytes = 1 << 20;
  CHECK_THROWS_AS(voxel::SurfacePaths(v.grid, v.surface, 1, o), voxel::TableTooLarge);
  o.storage = voxel::Storage::March;
  CHECK_NOTHROW(voxel::SurfacePaths(v.grid, v.surface, 1, o));
}

TEST_CASE("Every point of the mesh maps to a surface voxel within a voxel of it") {
  for (int voxels : {6, 25}) {
    const auto mesh = scene::shapes::cubeWithCavity(0.6);
    const Voxelised v = cubeWithCavity(voxels);
    const voxel::SurfaceVoxelLookup lookup(v.grid, v.surface);
    const double diagonal = glm::length(v.grid.spacing);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p(mesh.positions[i]);
      if (glm::length(p) < 0.7) continue;  // the cavity's wall is not surface
      const std::int32_t n = lookup.numberOf(p);
      REQUIRE(n >= 0);
      CHECK(glm::length(v.grid.centre(v.surface.voxels[std::size_t(n)]) - p) <= diagonal);
    }
    CHECK(lookup.farPoints() == 0);
  }
}

TEST_CASE("An empty grid has no surface voxel and no number to give") {
  voxel::MediaGrid empty(glm::ivec3(4), glm::dvec3(0), glm::dvec3(1));
  const voxel::SurfaceVoxels none = voxel::surfaceVoxels(empty);
  CHECK(none.count() == 0);
  CHECK(voxel::SurfaceVoxelLookup(empty, none).numberOf(glm::dvec3(2)) == -1);
}
