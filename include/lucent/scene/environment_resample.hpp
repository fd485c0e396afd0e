#pragma once
/// @file environment_resample.hpp
/// @brief Environments from one layout into another: a lat-long probe into a cube map that keeps
/// its integral, and a cube-map image (cube_layouts.hpp) into a cube-map environment.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "../optics/constants.hpp"
#include "cube_layouts.hpp"
#include "cube_map.hpp"
#include "light.hpp"

namespace lucent::scene {

/// The sub-cells per lat-long pixel side when splatting into cube texels `size` across: cells at
/// most half the smallest texel's side (a face corner's texel spans 1/3 of a centre one radially).
inline int splatSubdivision(const EnvironmentLight& latLong, int size) {
  const double pixelAngle = 2 * optics::kPi / std::max(1, latLong.width);
  const double smallestTexelAngle = 2.0 / (3.0 * size);
  return std::clamp(int(std::ceil(2 * pixelAngle / smallestTexelAngle)), 1, 1024);
}

namespace detail {
/// The share of [c - h, c + h] in texel cell `i` of `size` cells across [-1, 1], the interval first
/// clipped to [-1, 1] (a footprint past the face's side stays on the face).
inline double boxShare(double c, double h, int i, int size) {
  const double lo = std::max(-1.0, c - h), hi = std::min(1.0, c + h);
  const double a = std::max(lo, cube::edgeCoordinate(i, size));
  const double b = std::min(hi, cube::edgeCoordinate(i + 1, size));
  return b > a ? (b - a) / (hi - lo) : 0.0;
}

/// Adds `flux` over the texels a square footprint of face-plane area `area` centred at `p` covers,
/// in proportion to the overlap: the flux is kept exactly and the texel edges alias far less than
/// when a cell lands whole on one texel.
inline void splatBox(std::vector<glm::dvec3>& flux, int size, const cube::FacePoint& p, double area,
                     const glm::dvec3& cellFlux) {
  const double h = std::min(1.0, 0.5 * std::sqrt(area));
  auto cell = [size](double c) { return std::clamp(int((c + 1) * 0.5 * size), 0, size - 1); };
  const int s0 = cell(p.s - h), s1 = cell(p.s + h), t0 = cell(p.t - h), t1 = cell(p.t + h);
  const std::size_t base = std::size_t(p.face) * size * size;
  for (int row = t0; row <= t1; ++row) {
    const double wt = boxShare(p.t, h, row, size);
    if (!(wt > 0)) continue;
    for (int col = s0; col <= s1; ++col) {
      const double w = wt * boxShare(p.s, h, col, size);
      if (w > 0) flux[base + std::size_t(row) * size + col] += cellFlux * w;
    }
  }
}
}  // namespace detail

/// A direction turned by `angle` radians about +y (the up axis of the lat-long layout).
inline glm::dvec3 turnAboutY(const glm::dvec3& d, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

namespace detail {
/// Splats every source cell: (centre direction, solid angle, radiance) of the lat-long pixels cut
/// into equal-solid-angle cells (uniform in phi and cos theta).
template <class Splat>
void forEachLatLongCell(const EnvironmentLight& env, int split, Splat&& splat) {
  const double w = env.width, h = env.height;
  for (int row = 0; row < env.height; ++row) {
    const double cos0 = std::cos(optics::kPi * row / h),
                 cos1 = std::cos(optics::kPi * (row + 1) / h);
    for (int col = 0; col < env.width; ++col) {
      const std::size_t pixel = std::size_t(row) * env.width + col;
      const double cellSolidAngle = env.texelSolidAngle(pixel) / (split * split);
      for (int a = 0; a < split; ++a) {
        const double cosTheta = cos0 + (a + 0.5) / split * (cos1 - cos0);
        const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
        for (int b = 0; b < split; ++b) {
          const double phi = 2 * optics::kPi * (col + (b + 0.5) / split) / w;
          splat(glm::dvec3(sinTheta * std::sin(phi), cosTheta, -sinTheta * std::cos(phi)),
                cellSolidAngle, env.radiance[pixel]);
        }
      }
    }
  }
}

/// The same for a cube map's texels cut into split x split face rectangles.
template <class Splat>
void forEachCubeCell(const EnvironmentLight& env, int split, Splat&& splat) {
  const int n = env.width;
  const double cell = 2.0 / (double(n) * split);
  for (int face = 0; face < cube::kFaces; ++face)
    for (int row = 0; row < n * split; ++row)
      for (int col = 0; col < n * split; ++col) {
        const double s0 = -1 + col * cell, t0 = -1 + row * cell;
        splat(glm::normalize(cube::faceDirection(face, s0 + 0.5 * cell, t0 + 0.5 * cell)),
              cube::rectangleSolidAngle(s0, s0 + cell, t0, t0 + cell),
              env.radiance[(std::size_t(face) * n + row / split) * n + col / split]);
      }
}
}  // namespace detail

/// The cube map, `size` texels across a face, of an environment in either layout, turned by
/// `angle` radians about +y. Each source texel is cut into cells whose flux L dOmega is spread over
/// the texels under a square of the cell's area on the face plane; a texel's radiance is its flux
/// over its exact solid angle. The integral of the radiance over the sphere is kept to rounding (a
/// single bright texel included); the scale is carried over.
inline EnvironmentLight resampleToCube(const EnvironmentLight& env, int size, double angle = 0) {
  EnvironmentLight out;
  out.layout = EnvironmentLayout::Cube;
  out.width = size, out.height = cube::kFaces * size;
  out.scale = env.scale, out.source = env.source;
  std::vector<glm::dvec3> flux(out.texelCount(), glm::dvec3(0));
  auto splat = [&](const glm::dvec3& d, double solidAngle, const glm::vec3& radiance) {
    const cube::FacePoint p = cube::facePoint(angle == 0 ? d : turnAboutY(d, angle));
    const double r2 = 1 + p.s * p.s + p.t * p.t;
    detail::splatBox(flux, size, p, solidAngle * r2 * std::sqrt(r2),
                     glm::dvec3(radiance) * solidAngle);
  };
  if (env.layout == EnvironmentLayout::Cube) {
    // Source texels at most half the smallest target texel (2 / (3 size) on the face plane).
    detail::forEachCubeCell(env, std::clamp(int(std::ceil(3.0 * size / env.width)), 1, 64), splat);
  } else {
    detail::forEachLatLongCell(env, splatSubdivision(env, size), splat);
  }
  out.radiance.resize(flux.size());
  for (std::size_t i = 0; i < flux.size(); ++i)
    out.radiance[i] = glm::vec3(flux[i] / out.texelSolidAngle(i));
  return out;
}

/// The radiance of several environments (each times its scale) summed on one cube `size` across,
/// turned by `angle` radians about +y: what a PRT frame lights with.
inline std::vector<glm::vec3> sumOnCube(const std::vector<const EnvironmentLight*>& envs, int size,
                                        double angle) {
  std::vector<glm::vec3> cube(std::size_t(cube::kFaces) * size * size, glm::vec3(0));
  for (const EnvironmentLight* env : envs) {
    const EnvironmentLight c = resampleToCube(*env, size, angle);
    for (std::size_t i = 0; i < cube.size(); ++i) cube[i] += c.radiance[i] * float(c.scale);
  }
  return cube;
}

/// The cube map of a lat-long environment (resampleToCube, unturned).
inline EnvironmentLight latLongToCube(const EnvironmentLight& latLong, int size) {
  return resampleToCube(latLong, size);
}

/// The cube-map environment held by an image in `layout`, faces `size` across; `pixel(x, y)` reads
/// the image's radiance.
template <class PixelAt>
EnvironmentLight cubeFromImage(cube::ImageLayout layout, int size, PixelAt&& pixel) {
  EnvironmentLight out;
  out.layout = EnvironmentLayout::Cube;
  out.width = size, out.height = cube::kFaces * size;
  out.radiance.resize(out.texelCount());
  for (int face = 0; face < cube::kFaces; ++face)
    for (int row = 0; row < size; ++row)
      for (int column = 0; column < size; ++column) {
        const auto xy = cube::imagePixel(layout, size, face, row, column);
        out.radiance[(std::size_t(face) * size + row) * size + column] = pixel(xy[0], xy[1]);
      }
  return out;
}

}  // namespace lucent::scene
