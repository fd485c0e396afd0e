/// @file vtkLucentProfile.h
/// @brief The diffusion profile that tsis's GPU twin sums (private to Lucent::Rendering): the
/// technique's `profile` and `rd` knobs, of the pass's material, as the uniforms of
/// shaders/tsis_shade.frag. A pole pair (the classic or the better dipole) with rd=exact goes in
/// closed form; every other case is the profile's radial table (optics::RadialTable, built as the
/// CPU tsis builds it, rMax the object's diagonal in mm), uploaded as rows of a 2-D texture.
/// Rebuilt only when the material, a knob or the diagonal changes. The hybrid's twin gives its
/// own table instead (UpdateTable).
#ifndef vtkLucentProfile_h
#define vtkLucentProfile_h

#include <cstddef>
#include <string>

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <lucent/optics/dipole_lut.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/optics/profile.hpp>

#include "lucentPassDrawing.h"

namespace lucent::technique {
class KnobValues;
}  // namespace lucent::technique

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkLucentProfile : public vtkObject {
 public:
  static vtkLucentProfile* New();
  vtkTypeMacro(vtkLucentProfile, vtkObject);

  /// Brings the profile up to date with tsis's knobs `profile` and `rd`. Sets @p warning when
  /// rd=exact asks for a closed form the profile lacks (its table is summed, as on the CPU); false
  /// with @p error when the table cannot be uploaded.
  bool Update(vtkOpenGLRenderWindow* window, const lucent::optics::Material& material,
              const lucent::technique::KnobValues& knobs, double diagonalMm, std::string& warning,
              std::string& error);

  /// A given table (the hybrid's Rd Wg) with its exit scale, uploaded when `key` changes.
  bool UpdateTable(vtkOpenGLRenderWindow* window, const std::string& key,
                   const lucent::optics::RadialTable<float>& table, double exitScale,
                   std::string& error);

  /// Sets the stage's uniforms and binds the table; Deactivate after drawing.
  void Activate(vtkShaderProgram* program);
  void Deactivate();
  void ReleaseGraphicsResources(vtkWindow* window);

  bool IsClosedForm() const { return this->ClosedForm; }
  /// Nodes of the radial table (0 in closed form).
  std::size_t GetTableNodes() const { return std::size_t(this->Rows.nodes); }

 protected:
  vtkLucentProfile() = default;
  ~vtkLucentProfile() override = default;

 private:
  vtkLucentProfile(const vtkLucentProfile&) = delete;
  void operator=(const vtkLucentProfile&) = delete;

  bool UploadTable(vtkOpenGLRenderWindow* window, const lucent::optics::RadialTable<float>& table,
                   const std::string& name, std::string& error);

  std::string BuiltKey;
  bool ClosedForm = false;
  /// sigma_tr, z_r, z_v, alpha', C_E, C_phi / D per channel (LucentDipole in optics.glsl).
  float Dipole[6][3] = {};
  float ExitScale = 1;
  lucent::vtkpass::RowTable Rows;  ///< the table's layout (nodes 0 in closed form)
  vtkSmartPointer<vtkTextureObject> Table;
};

#endif
