#include "vtkLucentRayCaster.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <vtkPolyData.h>

vtkLucentRayCaster::vtkLucentRayCaster(vtkPolyData* triangles) {  // the locator holds a reference to it
  this->Locator->SetDataSet(triangles);
  this->Locator->BuildLocator();
  this->Reach = 2 * triangles->GetLength();
  double centre[3];
  triangles->GetCenter(centre);
  this->Centre = {centre[0], centre[1], centre[2]};
}

std::optional<lucent::scene::RayHit> vtkLucentRayCaster::intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                                                   double tMin, double tMax) const {
  // A segment long enough to leave the data from wherever the ray starts stands in for an infinite ray.
  const double farthest = this->Reach + glm::length(origin - this->Centre);
  const double tEnd = std::min(tMax, farthest);
  if (!(tEnd > tMin)) return std::nullopt;
  const glm::dvec3 a = origin + direction * tMin, b = origin + direction * tEnd;
  double p1[3] = {a.x, a.y, a.z}, p2[3] = {b.x, b.y, b.z}, x[3], pcoords[3], t = 0;
  int subId = 0;
  vtkIdType cellId = -1;
  int hit = 0;
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    hit = this->Locator->IntersectWithLine(p1, p2, 0.0, t, x, pcoords, subId, cellId);
  }
  if (!hit || cellId < 0) return std::nullopt;
  lucent::scene::RayHit out;
  out.t = tMin + t * (tEnd - tMin);
  out.triangle = std::uint32_t(cellId);
  out.u = pcoords[0];  // a triangle's parametric coordinates are the barycentrics of its vertices 1 and 2
  out.v = pcoords[1];
  return out;
}
