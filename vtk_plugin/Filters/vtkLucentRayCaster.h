/// @file vtkLucentRayCaster.h
/// @brief lucent's RayCaster interface over VTK's static cell locator, so the filters cast shadow rays with
/// what every VTK build has (Embree is not part of ParaView). Queries are serialised: vtkStaticCellLocator's
/// IntersectWithLine shares scratch state.
#ifndef vtkLucentRayCaster_h
#define vtkLucentRayCaster_h

#include <mutex>

#include <vtkNew.h>
#include <vtkStaticCellLocator.h>

#include <lucent/scene/ray_caster.hpp>

class vtkPolyData;

class vtkLucentRayCaster final : public lucent::scene::RayCaster {
 public:
  /// @param triangles a triangle-only vtkPolyData in the same units (mm) as the queries
  explicit vtkLucentRayCaster(vtkPolyData* triangles);
  std::optional<lucent::scene::RayHit> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                                 double tMax) const override;
  bool occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax) const override {
    return intersect(origin, direction, tMin, tMax).has_value();
  }

 private:
  vtkNew<vtkStaticCellLocator> Locator;
  double Reach = 0;  ///< segment length standing in for an infinite ray: twice the data's diagonal
  glm::dvec3 Centre{0};
  mutable std::mutex Lock;
};

#endif
