#include "vtkLucentFilter.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <thread>
#include <vector>

#include <vtkCommunicator.h>
#include <vtkCompositeDataSet.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <lucent/image/display_encode.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/plan/explain.hpp>
#include <lucent/plan/scene_features.hpp>
#include <lucent/scene/environment_image.hpp>
#include <lucent/technique/prepared_cache.hpp>
#include <lucent/util/fingerprint.hpp>

#include "io/exr_io.hpp"
#include "lucentFilterTechniques.h"
#include "lucentPolyDataMesh.h"
#include "lucentSmpFor.h"
#include "lucentSurfaceGather.h"
#include "vtkLucentRayCaster.h"

vtkStandardNewMacro(vtkLucentFilter);

namespace {
namespace lt = lucent::technique;

std::vector<const lt::Technique*> offered() {
  return lt::vertexTechniques(vtkLucentFilter::Techniques());
}

/// (property name, qualified name) of every knob property of the offered techniques.
std::vector<std::pair<std::string, std::string>> knobProperties() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [t, k] : lt::knobProperties(vtkLucentFilter::Techniques()))
    out.emplace_back(lt::propertyName(*t, *k), lt::qualifiedName(*t, *k));
  return out;
}

unsigned char displayByte(double x) {
  return static_cast<unsigned char>(std::lround(255 * lucent::image::displayEncode(x)));
}

vtkSmartPointer<vtkFloatArray> tupleArray(const char* name, const std::vector<glm::dvec3>& values) {
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(vtkIdType(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < 3; ++c) a->SetTypedComponent(vtkIdType(i), c, float(values[i][c]));
  return a;
}

vtkSmartPointer<vtkStringArray> textArray(const char* name, const std::vector<std::string>& lines) {
  auto a = vtkSmartPointer<vtkStringArray>::New();
  a->SetName(name);
  for (const auto& line : lines) a->InsertNextValue(line);
  return a;
}

vtkSmartPointer<vtkUnsignedCharArray> colourArray(const std::vector<glm::dvec3>& values,
                                                  double exposure) {
  auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
  a->SetName("TranslucentColor");
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(vtkIdType(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    for (int c = 0; c < 3; ++c)
      a->SetTypedComponent(vtkIdType(i), c, displayByte(exposure * values[i][c]));
  return a;
}
}  // namespace

lt::Registry& vtkLucentFilter::Techniques() {
  static lt::Registry registry = lucent::vtkadapter::filterTechniques();
  return registry;
}

/// The last run's scene and prepare (kept while the surface is unchanged), and the environment map
/// as last read.
struct vtkLucentFilter::KeptRun {
  std::string geometry;  ///< fingerprint of what `scene` was built from; empty: nothing kept
  lt::SceneDescription scene;
  vtkSmartPointer<vtkPolyData> millimetres;  ///< the surface in mm, which `caster` holds
  std::unique_ptr<vtkLucentRayCaster> caster;
  lt::PreparedCache prepared;
  std::string environmentPath;
  std::filesystem::file_time_type environmentTime;
  std::uintmax_t environmentSize = 0;
  lucent::scene::EnvironmentLight environment;  ///< radiance as read, scale 1
  ///@{ Progress of the run, reported from the calling thread only.
  std::thread::id caller;
  std::string stage;
  int stages = 0;
  ///@}
};

vtkLucentFilter::vtkLucentFilter()
    : Technique(Techniques().defaultReference().name), LastRun(std::make_unique<KeptRun>()) {
  this->SetController(vtkMultiProcessController::GetGlobalController());
}
vtkLucentFilter::~vtkLucentFilter() {
  this->LastRun->prepared.clear();  // before the scene it may point into
  this->SetController(nullptr);
}

void vtkLucentFilter::SetEnvironmentFileName(const char* path) {
  const std::string value = path ? path : "";
  if (value == this->EnvironmentFileName) return;
  this->EnvironmentFileName = value;
  this->Modified();
}

void vtkLucentFilter::SetMaterial(const char* name) {
  const std::string value = name ? name : "";
  if (value == this->Material) return;
  this->Material = value;
  this->Modified();
}

void vtkLucentFilter::SetCalibrationDirectory(const char* dir) {
  const std::string value = dir ? dir : "";
  if (value == this->CalibrationDirectory) return;
  this->CalibrationDirectory = value;
  this->Modified();
}

void vtkLucentFilter::SetTechnique(const char* name) {
  const std::string value = name ? name : "";
  if (value == this->Technique) return;
  this->Technique = value;
  this->Modified();
}

int vtkLucentFilter::GetNumberOfTechniques() { return int(offered().size()); }
std::string vtkLucentFilter::GetTechniqueName(int i) {
  const auto all = offered();
  return i >= 0 && i < int(all.size()) ? all[std::size_t(i)]->name : std::string();
}

void vtkLucentFilter::SetKnob(const char* qualifiedName, const char* value) {
  if (!qualifiedName) return;
  const std::string v = value ? value : "";
  auto [it, added] = this->Knobs.emplace(qualifiedName, v);
  if (!added && it->second == v) return;
  it->second = v;
  this->Modified();
}
void vtkLucentFilter::SetKnobInteger(const char* qualifiedName, int value) {
  this->SetKnob(qualifiedName, std::to_string(value).c_str());
}
void vtkLucentFilter::SetKnobReal(const char* qualifiedName, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  this->SetKnob(qualifiedName, text);
}

std::string vtkLucentFilter::GetKnob(const char* qualifiedName) const {
  if (!qualifiedName) return {};
  if (const auto it = this->Knobs.find(qualifiedName); it != this->Knobs.end()) return it->second;
  for (const lt::Technique* t : offered())
    for (const auto& k : t->knobs)
      if (lt::qualifiedName(*t, k) == qualifiedName) return k.defaultValue;
  return {};
}

int vtkLucentFilter::GetNumberOfKnobProperties() { return int(knobProperties().size()); }
std::string vtkLucentFilter::GetKnobPropertyName(int i) {
  const auto all = knobProperties();
  return i >= 0 && i < int(all.size()) ? all[std::size_t(i)].first : std::string();
}
std::string vtkLucentFilter::GetKnobQualifiedName(int i) {
  const auto all = knobProperties();
  return i >= 0 && i < int(all.size()) ? all[std::size_t(i)].second : std::string();
}

void vtkLucentFilter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Material: " << this->Material << "\n"
     << indent << "Technique: " << this->Technique << "\n"
     << indent << "SizeMm: " << this->SizeMm << "\n"
     << indent << "LightDirection: " << this->LightDirection[0] << " " << this->LightDirection[1]
     << " " << this->LightDirection[2] << "\n"
     << indent << "LightIrradiance: " << this->LightIrradiance << "\n"
     << indent << "EnvironmentFileName: " << this->EnvironmentFileName << "\n"
     << indent << "EnvironmentScale: " << this->EnvironmentScale << "\n"
     << indent << "Exposure: " << this->Exposure << "\n"
     << indent << "BudgetMs: " << this->BudgetMs << "\n"
     << indent << "MaxError: " << this->MaxError << "\n"
     << indent << "CalibrationDirectory: " << this->CalibrationDirectory << "\n"
     << indent << "PrepareReused: " << this->PrepareReused << "\n"
     << indent << "PrepareSeconds: " << this->PrepareSeconds << "\n"
     << indent << "FrameSeconds: " << this->FrameSeconds << "\n";
  for (const auto& [name, value] : this->Knobs) os << indent << name << ": " << value << "\n";
}

/// What a run is asked for, checked before any work (the same on every rank).
struct vtkLucentFilter::Request {
  lucent::optics::Material material;
  const lt::Technique* technique = nullptr;  ///< null with "auto" until the plan is made
  lt::KnobValues knobs;
  glm::dvec3 towardLight{0, 0, 1};
  lucent::plan::Calibration calibration;  ///< with "auto": read before any work
  lucent::plan::Budget budget;
};

namespace {
/// The surface this rank outputs, and the whole surface every rank shades from (the same one when
/// the filter runs in one process).
struct Surfaces {
  lucent::vtkadapter::PolyDataMesh local, whole;
  std::vector<vtkIdType> wholeIndex;  ///< for each local point, its point in `whole`
};

Surfaces surfacesOf(vtkDataObject* input, vtkMultiProcessController* controller) {
  namespace va = lucent::vtkadapter;
  Surfaces s;
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  s.local = va::meshFromData(input, nullptr, /*orient=*/!distributed);
  if (!distributed) {
    s.whole = s.local;
    s.wholeIndex.resize(s.local.mesh.positions.size());
    for (std::size_t i = 0; i < s.wholeIndex.size(); ++i) s.wholeIndex[i] = vtkIdType(i);
    return s;
  }
  // Every rank takes part in the all-gather, an empty piece too.
  s.whole = va::meshFromData(va::gatherTriangles(controller, s.local.triangles));
  if (s.whole.flipped) va::flip(s.local);  // the whole surface decides the orientation
  s.wholeIndex = va::matchPoints(s.local.triangles, s.whole.triangles);
  return s;
}

/// The whole surface in millimetres (scaled about the origin to SizeMm, or as given) and its ray
/// caster.
/// Millimetres per data unit: as given (0: the data's units are mm), or the diagonal made SizeMm.
double millimetresPerUnit(const lucent::scene::TriangleMesh& mesh, double sizeMm) {
  const double diagonal = mesh.bounds().diagonal();
  if (!(diagonal > 0) || !std::isfinite(diagonal))
    throw lt::RequestError("The input has zero or non-finite extent");
  return sizeMm > 0 ? sizeMm / diagonal : 1.0;
}

/// The surface scaled about the origin to millimetres, in the mesh and as VTK data (for its ray
/// caster).
vtkSmartPointer<vtkPolyData> scaleToMillimetres(lucent::scene::TriangleMesh& mesh,
                                                vtkCellArray* polys, double scale) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    mesh.positions[i] = glm::vec3(glm::dvec3(mesh.positions[i]) * scale);
    points->SetPoint(vtkIdType(i), mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  return out;
}

/// The input's inner bodies (kInnerMaterialArray) as inclusions in millimetres, each with its own
/// inside test; every vertex must lie inside the object.
std::vector<lt::Inclusion> inclusionsOf(vtkDataObject* input, double scale,
                                        const lucent::scene::RayCaster& object, double epsilon) {
  std::vector<lt::Inclusion> out;
  for (auto& body : lucent::vtkadapter::innerBodiesOf(input)) {
    const auto material = lucent::optics::findMaterial(body.material);
    if (!material)
      throw lt::RequestError(
          "an inner body's " + std::string(lucent::vtkadapter::kInnerMaterialArray) + " '" +
          body.material +
          "' is not a measured material; use one of: " + lucent::optics::measuredMaterialNames());
    lt::Inclusion inc;
    inc.surface = body.surface.mesh;
    const auto mm = scaleToMillimetres(inc.surface, body.surface.triangles->GetPolys(), scale);
    for (const auto& p : inc.surface.positions)
      if (!lucent::scene::insideByParity(object, glm::dvec3(p), epsilon))
        throw lt::RequestError("the inner body of " + material->name +
                               " is not inside the surface; an inner body must lie within it");
    const auto caster = std::make_shared<vtkLucentRayCaster>(mm);
    inc.contains = [caster, epsilon](const glm::dvec3& p) {
      return lucent::scene::insideByParity(*caster, p, epsilon);
    };
    inc.medium.material = *material;
    inc.description = material->name + " inner body";
    out.push_back(std::move(inc));
  }
  return out;
}

/// The unit direction towards the light.
glm::dvec3 unitTowardLight(const double direction[3]) {
  const glm::dvec3 toward(direction[0], direction[1], direction[2]);
  const double length = glm::length(toward);
  if (!(length > 0) || !std::isfinite(length))
    throw lt::RequestError(
        "LightDirection must be a finite, non-zero direction towards the light, e.g. 0 0 1");
  return toward / length;
}
/// What a kept scene was built from: the whole surface, the inner bodies and the scale.
std::string geometryFingerprint(const lucent::vtkadapter::PolyDataMesh& whole, vtkDataObject* input,
                                double mmPerUnit) {
  lucent::util::Fingerprint f;
  f.addArray(whole.mesh.positions).addArray(whole.mesh.triangles).addValue(mmPerUnit);
  for (const auto& body : lucent::vtkadapter::innerBodiesOf(input))
    f.add(body.material)
        .addArray(body.surface.mesh.positions)
        .addArray(body.surface.mesh.triangles);
  return f.hex();
}

/// The environment map in `path`, checked texel by texel.
lucent::scene::EnvironmentLight readEnvironment(const std::string& path) {
  const lucent::image::Image img = lucent::io::readExr(path);
  const auto texels = lucent::scene::screenEnvironmentTexels(
      img.width, img.height, [&](int x, int y) { return glm::vec3(img.at(x, y)); });
  if (!texels.problem.empty())
    throw lt::RequestError("EnvironmentFileName '" + path + "': " + texels.problem +
                           " (fix the EXR)");
  if (!texels.note.empty())
    vtkGenericWarningMacro("EnvironmentFileName '" << path << "': " << texels.note);
  auto env = lucent::scene::environmentFromTexels(img.width, img.height, texels);
  env.source = path;
  return env;
}

/// What the registry's default technique, when it is `chosen`, cannot take in `scene` shaded at
/// `whole` (the first unmet requirement); empty when `chosen` is another technique or takes it.
std::string defaultCannotTake(const lt::Technique* chosen, const lt::SceneDescription& scene,
                              const lt::ShadeRequest& whole) {
  if (chosen != &vtkLucentFilter::Techniques().defaultReference()) return "";
  const auto missing = lt::unmetBy(*chosen, scene, whole);
  return missing.empty() ? "" : missing.front();
}

/// The whole surface's vertex points that are this rank's own points, in its order.
lt::ShadeRequest localRequest(const lucent::scene::TriangleMesh& whole,
                              const std::vector<vtkIdType>& wholeIndex) {
  const lt::ShadeRequest all = lt::vertexRequest(whole);
  lt::ShadeRequest r;
  r.vertices = true;
  for (const vtkIdType i : wholeIndex) {
    if (i < 0) throw std::logic_error("a point of this piece is not on the gathered surface");
    r.points.push_back(all.points[std::size_t(i)]);
  }
  return r;
}
}  // namespace

vtkLucentFilter::Request vtkLucentFilter::CheckRequest() const {
  Request r;
  const auto material = lucent::optics::findMaterial(this->Material);
  if (!material)
    throw lt::RequestError(
        "Material '" + this->Material +
        "' is not a measured material; use one of: " + lucent::optics::measuredMaterialNames());
  r.material = *material;
  if (this->Technique == lucent::plan::kAutomatic) {
    this->ReadPlanInputs(r);
  } else {
    r.technique = &Techniques().get(this->Technique);
    r.knobs = this->KnobsOf(*r.technique);
  }
  r.towardLight = unitTowardLight(this->LightDirection);
  return r;
}

void vtkLucentFilter::ReadPlanInputs(Request& r) const {
  if (this->BudgetMs > 0) r.budget.seconds = this->BudgetMs / 1000;
  if (this->MaxError > 0) r.budget.error = this->MaxError;
  try {
    r.calibration = lucent::plan::readCalibration(
        lucent::plan::calibrationDirectory(this->CalibrationDirectory, LUCENT_SOURCE_DATA_DIR));
  } catch (const lucent::plan::CalibrationError& e) {
    throw lt::RequestError(std::string(e.what()) +
                           " (or set CalibrationDirectory to a folder "
                           "holding it)");
  }
}

lt::KnobValues vtkLucentFilter::KnobsOf(const lt::Technique& technique) const {
  if (!lt::shadesVertices(technique))
    throw lt::RequestError(
        "technique '" + technique.name + "' does not shade vertices; the filter offers: " +
        Techniques().names([](const lt::Technique& t) { return lt::shadesVertices(t); }) + ", or " +
        lucent::plan::kAutomatic);
  lt::KnobList given;
  const std::string prefix = technique.name + ".";
  for (const auto& [name, value] : this->Knobs)
    if (name.compare(0, prefix.size(), prefix) == 0)
      given.emplace_back(name.substr(prefix.size()), value);
  return technique.values(given);
}

std::vector<std::string> vtkLucentFilter::PlanTechnique(Request& request,
                                                        const lt::SceneDescription& scene,
                                                        const lt::ShadeRequest& shade) const {
  namespace lp = lucent::plan;
  const lp::SceneFeatures features = lp::sceneFeatures(scene, shade, /*camera=*/nullptr);
  const lp::Plan plan =
      lp::makePlan(Techniques(), scene, shade, features, request.calibration, request.budget);
  if (!plan.choice)
    throw lt::RequestError(
        "Technique auto: no calibrated technique that shades vertices can serve this surface" +
        lp::exclusionText(plan) + "; name a technique");
  request.technique = plan.choice->technique;
  request.knobs = request.technique->values(lp::knobPairs(plan.choice->knobs));
  return lp::explain(plan, request.budget);
}

std::vector<std::string> vtkLucentFilter::HandOverDefault(Request& request,
                                                          const lt::SceneDescription& scene,
                                                          const lt::ShadeRequest& whole,
                                                          const std::string& unmet) const {
  const std::string why = "the default technique cannot take " + unmet;
  request.technique = nullptr;
  try {
    this->ReadPlanInputs(request);  // no calibration: the fallback below
    std::vector<std::string> plan = this->PlanTechnique(request, scene, whole);
    plan.insert(plan.begin(), why + "; the planner chose one that can");
    return plan;
  } catch (const lt::RequestError&) {
    // No calibrated technique takes it: the first offered that does, at its defaults.
    for (const lt::Technique* t : offered()) {
      const lt::KnobValues defaults = t->values();
      if (!lt::unmetBy(*t, scene, whole).empty() ||
          (t->validity && !t->validity(scene, defaults).empty()))
        continue;
      request.technique = t, request.knobs = defaults;
      return {why +
              "; the planner has no calibrated technique that can, so the first offered "
              "that can: " +
              t->name + " at its defaults"};
    }
    throw;
  }
}

lt::SceneDescription& vtkLucentFilter::SceneFor(vtkDataObject* input,
                                                lucent::vtkadapter::PolyDataMesh& whole,
                                                const Request& request, const MediumSetup& medium) {
  KeptRun& run = *this->LastRun;
  const double mmPerUnit = millimetresPerUnit(whole.mesh, this->SizeMm);
  // A medium beyond the material (a scan) is not fingerprinted: such a scene is never kept.
  const std::string geometry = medium ? "" : geometryFingerprint(whole, input, mmPerUnit);
  lt::SceneDescription& scene = run.scene;
  if (geometry.empty() || geometry != run.geometry) {
    run.prepared.clear();  // before the scene it may point into
    run.geometry.clear();
    scene = lt::SceneDescription();
    scene.meshName = "the filter's input";
    scene.mesh = std::move(whole.mesh);
    run.millimetres = scaleToMillimetres(scene.mesh, whole.triangles->GetPolys(), mmPerUnit);
    run.caster = std::make_unique<vtkLucentRayCaster>(run.millimetres);
    scene.vertexNormals = scene.mesh.vertexNormals();
    scene.caster = run.caster.get();
    scene.parallelFor = lucent::vtkadapter::smpFor;
    scene.inclusions = inclusionsOf(input, mmPerUnit, *run.caster, scene.rayEpsilon());
    run.geometry = geometry;
  }
  scene.medium = lt::Medium();
  scene.medium.material = request.material;
  if (medium) medium(scene.medium, mmPerUnit);
  this->SetLights(scene, request);
  // Progress from the calling thread only (VTK's events are not thread-safe); each stage moves
  // the bar half of the way that is left, so it never goes back.
  run.caller = std::this_thread::get_id();
  run.stage.clear();
  run.stages = 0;
  scene.progress = [this, &run](const std::string& name, double f) {
    if (std::this_thread::get_id() != run.caller) return;
    if (name != run.stage) run.stage = name, ++run.stages;
    this->UpdateProgress(1 - std::pow(0.5, run.stages - 1) * (1 - 0.5 * std::clamp(f, 0.0, 1.0)));
  };
  return scene;
}

void vtkLucentFilter::ReadEnvironment() {
  const std::string& path = this->EnvironmentFileName;
  if (path.empty()) return;
  KeptRun& run = *this->LastRun;
  std::error_code timeError, sizeError;
  const auto time = std::filesystem::last_write_time(path, timeError);
  const auto size = std::filesystem::file_size(path, sizeError);
  if (timeError || sizeError)
    throw lt::RequestError("EnvironmentFileName '" + path + "' cannot be read (" +
                           (timeError ? timeError : sizeError).message() +
                           "); give an OpenEXR environment map, or leave it empty for the "
                           "directional light");
  if (path == run.environmentPath && time == run.environmentTime && size == run.environmentSize)
    return;
  run.environmentPath.clear();
  run.environment = readEnvironment(path);
  run.environmentPath = path, run.environmentTime = time, run.environmentSize = size;
}

void vtkLucentFilter::SetLights(lt::SceneDescription& scene, const Request& request) const {
  if (this->EnvironmentFileName.empty()) {
    scene.lights = {
        lucent::scene::DirectionalLight{request.towardLight, glm::dvec3(this->LightIrradiance)}};
    return;
  }
  lucent::scene::EnvironmentLight env = this->LastRun->environment;  // ReadEnvironment's
  env.scale = this->EnvironmentScale;
  scene.lights = {std::move(env)};
}

int vtkLucentFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                 vtkInformationVector* outputVector) {
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output) return 0;
  return this->ShadeSurface(input, output, {});
}

int vtkLucentFilter::ShadeSurface(vtkDataObject* input, vtkPolyData* output,
                                  const MediumSetup& medium) {
  // Checked before any work; across processes every rank must agree before the collective gather.
  Request request;
  std::string problem;
  const bool distributed = this->Controller && this->Controller->GetNumberOfProcesses() > 1;
  try {
    request = this->CheckRequest();
    this->ReadEnvironment();  // before the ranks agree: a file one rank cannot read stops all
    if (distributed && !lucent::vtkadapter::innerBodiesOf(input).empty())
      throw lt::RequestError("inner bodies (" +
                             std::string(lucent::vtkadapter::kInnerMaterialArray) +
                             ") need the whole object on one process; run the filter without MPI");
  } catch (const std::exception& e) {
    problem = e.what();
  }
  if (distributed) {
    int ok = problem.empty() ? 1 : 0, allOk = 0;
    this->Controller->AllReduce(&ok, &allOk, 1, vtkCommunicator::MIN_OP);
    if (!allOk && problem.empty())
      problem = "another rank refused the request (its error says why)";
  }
  if (!problem.empty()) {
    output->Initialize();
    vtkErrorMacro(<< problem);
    return 0;
  }
  try {
    Surfaces surfaces = surfacesOf(input, this->Controller);
    if (surfaces.whole.mesh.triangles.empty())
      throw lt::RequestError(
          "The input has no polygons; apply the filter to a closed surface (for an image or "
          "volume, extract one first, e.g. Contour or Extract Surface)");
    // The output keeps the input's coordinates (it must line up with the user's other data); only
    // the computation is in millimetres.
    output->ShallowCopy(surfaces.local.triangles);
    lt::SceneDescription& scene = this->SceneFor(input, surfaces.whole, request, medium);
    // Every rank plans from the whole surface, so all choose the same. The default technique hands
    // a scene it cannot take (a scan's heterogeneous medium) to the planner, as the CLI does.
    const lt::ShadeRequest whole = lt::vertexRequest(scene.mesh);
    const std::string unmet = defaultCannotTake(request.technique, scene, whole);
    std::vector<std::string> plan;
    if (!unmet.empty()) {
      plan = this->HandOverDefault(request, scene, whole, unmet);
    } else if (!request.technique) {
      plan = this->PlanTechnique(request, scene, whole);
    }
    const lt::ShadeRequest shade = localRequest(scene.mesh, surfaces.wholeIndex);
    const lt::Rendered result = this->LastRun->prepared.render(
        Techniques(), *request.technique, scene, request.knobs, shade, this->LastRun->geometry);
    this->PrepareReused = this->LastRun->prepared.reused();
    this->PrepareSeconds = result.stats.totalPrepareSeconds();
    this->FrameSeconds = result.stats.totalFrameSeconds();
    for (const auto& w : result.stats.warnings)
      vtkWarningMacro(<< request.technique->name << ": " << w);
    this->SampleCount = vtkIdType(result.stats.samples);
    this->ChosenTechnique = lucent::plan::settingText(*request.technique, request.knobs);
    this->WriteArrays(output, result);
    output->GetFieldData()->AddArray(textArray("LucentTechnique", {this->ChosenTechnique}));
    if (!plan.empty()) output->GetFieldData()->AddArray(textArray("LucentPlan", plan));
    this->UpdateProgress(1.0);
    return 1;
  } catch (const std::exception& e) {
    output->Initialize();
    vtkErrorMacro(<< e.what());
    return 0;
  }
}

void vtkLucentFilter::WriteArrays(vtkPolyData* output, const lt::Rendered& result) const {
  const auto& frame = result.frame;
  const auto& shown = frame.radiosity.empty() ? frame.radiance : frame.radiosity;
  if (!frame.radiosity.empty())
    output->GetPointData()->AddArray(tupleArray("Radiosity", frame.radiosity));
  output->GetPointData()->AddArray(tupleArray("Radiance", frame.radiance));
  output->GetPointData()->SetScalars(colourArray(shown, this->Exposure));
}

int vtkLucentFilter::FillInputPortInformation(int port, vtkInformation* info) {
  // A composite of surfaces is one surface, shaded in one RequestData (never block by block: under
  // MPI the ranks would make different numbers of collective calls).
  if (!this->Superclass::FillInputPortInformation(port, info)) return 0;
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

void vtkLucentFilter::SetController(vtkMultiProcessController* controller) {
  if (this->Controller == controller) return;
  if (controller) controller->Register(this);
  if (this->Controller) this->Controller->UnRegister(this);
  this->Controller = controller;
  this->Modified();
}
