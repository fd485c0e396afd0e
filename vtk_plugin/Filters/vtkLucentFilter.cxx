#include "vtkLucentFilter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>

#include <lucent/atlas/importance_samples.hpp>
#include <lucent/atlas/irradiance_atlas.hpp>
#include <lucent/atlas/texture_atlas.hpp>
#include <lucent/atlas/tsis_evaluator.hpp>
#include <lucent/image/display_encode.hpp>
#include <lucent/optics/dipole.hpp>
#include <lucent/optics/materials.hpp>
#include <lucent/reference/dipole_truth.hpp>

#include "vtkLucentRayCaster.h"

vtkStandardNewMacro(vtkLucentFilter);

namespace {
unsigned char displayByte(double x) {
  return static_cast<unsigned char>(std::lround(255 * lucent::image::displayEncode(x)));
}
}  // namespace

vtkLucentFilter::vtkLucentFilter() = default;

void vtkLucentFilter::SetMaterial(const char* name) {
  const std::string value = name ? name : "";
  if (value == this->Material) return;
  this->Material = value;
  this->Modified();
}

void vtkLucentFilter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Material: " << this->Material << "\n"
     << indent << "Technique: " << (this->Technique == TSIS ? "TSIS" : "Reference") << "\n"
     << indent << "TsisSamples: " << this->TsisSamples << "\n"
     << indent << "AtlasResolution: " << this->AtlasResolution << "\n"
     << indent << "SizeMm: " << this->SizeMm << "\n"
     << indent << "LightDirection: " << this->LightDirection[0] << " " << this->LightDirection[1] << " "
     << this->LightDirection[2] << "\n"
     << indent << "LightIrradiance: " << this->LightIrradiance << "\n"
     << indent << "SampleFraction: " << this->SampleFraction << "\n"
     << indent << "MaxSamples: " << this->MaxSamples << "\n"
     << indent << "Exposure: " << this->Exposure << "\n";
}

int vtkLucentFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output) return 0;

  const auto material = lucent::optics::findMaterial(this->Material);
  if (!material) {
    vtkErrorMacro("Material '" << this->Material << "' is not a measured material; use one of: "
                  << lucent::optics::measuredMaterialNames());
    return 0;
  }
  const double lightLength = std::sqrt(this->LightDirection[0] * this->LightDirection[0] +
                                       this->LightDirection[1] * this->LightDirection[1] +
                                       this->LightDirection[2] * this->LightDirection[2]);
  if (!(lightLength > 0)) {
    vtkErrorMacro("LightDirection is the zero vector; give the direction towards the light, e.g. 0 0 1");
    return 0;
  }

  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(input);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();
  if (triangles->GetNumberOfPolys() == 0) {
    vtkErrorMacro("The input has no polygons; apply the filter to a closed surface (for an image or volume, "
                  "extract one first, e.g. Contour or Extract Surface)");
    return 0;
  }

  // The mesh in millimetres: as given, or scaled about the origin to SizeMm.
  const double scale = this->SizeMm > 0 ? this->SizeMm / std::max(triangles->GetLength(), 1e-300) : 1.0;
  lucent::scene::TriangleMesh mesh;
  const vtkIdType pointCount = triangles->GetNumberOfPoints();
  vtkNew<vtkPoints> scaledPoints;
  scaledPoints->SetDataTypeToDouble();
  scaledPoints->SetNumberOfPoints(pointCount);
  mesh.positions.resize(std::size_t(pointCount));
  for (vtkIdType i = 0; i < pointCount; ++i) {
    double p[3];
    triangles->GetPoint(i, p);
    for (double& c : p) c *= scale;
    scaledPoints->SetPoint(i, p);
    mesh.positions[std::size_t(i)] = glm::vec3(float(p[0]), float(p[1]), float(p[2]));
  }
  vtkCellArray* polys = triangles->GetPolys();
  polys->InitTraversal();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  while (polys->GetNextCell(n, ids))
    if (n == 3) mesh.triangles.push_back({unsigned(ids[0]), unsigned(ids[1]), unsigned(ids[2])});
  vtkNew<vtkPolyData> scaled;
  scaled->SetPoints(scaledPoints);
  scaled->SetPolys(polys);
  const vtkLucentRayCaster caster(scaled);

  // Stage 1 (first half of the progress): samples and their shadowed, Fresnel-transmitted irradiance.
  const auto dipole = lucent::optics::Dipole<float>::make(lucent::optics::Rgb<float>(material->sigmaA),
                                                          lucent::optics::Rgb<float>(material->sigmaSPrime),
                                                          float(material->eta));
  const glm::dvec3 towardLight =
      glm::dvec3(this->LightDirection[0], this->LightDirection[1], this->LightDirection[2]) / lightLength;
  const std::vector<lucent::scene::Light> lights = {
      lucent::scene::DirectionalLight{towardLight, glm::dvec3(this->LightIrradiance)}};
  lucent::scene::IrradianceSettings irradiance;
  irradiance.eta = material->eta;
  irradiance.rayEpsilon = 1e-5 * mesh.bounds().diagonal();
  auto stageOne = [this](double f) { this->UpdateProgress(0.5 * f); };
  std::function<glm::dvec3(const glm::dvec3&)> radiosityAt;
  std::unique_ptr<lucent::reference::DipoleTruth<float>> truth;
  std::unique_ptr<lucent::atlas::TsisEvaluator> tsis;
  if (this->Technique == TSIS) {
    lucent::atlas::AtlasOptions atlasOptions;
    atlasOptions.resolution = this->AtlasResolution;
    lucent::atlas::TextureAtlas atlas;
    try {
      atlas = lucent::atlas::buildTextureAtlas(mesh, atlasOptions);
    } catch (const std::exception& e) {
      vtkErrorMacro("The texture atlas could not be built (" << e.what() << "); raise AtlasResolution or use the "
                    "Reference technique");
      return 0;
    }
    const auto irradianceAtlas = lucent::atlas::renderIrradianceAtlas(atlas, mesh, mesh.vertexNormals(), lights, caster,
                                                                      irradiance, lucent::util::serialFor, stageOne);
    lucent::atlas::SamplingOptions sampling;
    sampling.samples = this->TsisSamples;
    tsis = std::make_unique<lucent::atlas::TsisEvaluator>(lucent::atlas::drawImportanceSamples(irradianceAtlas, sampling),
                                                          dipole);
    this->SampleCount = vtkIdType(tsis->samples().size());
    radiosityAt = [&tsis](const glm::dvec3& p) { return tsis->radiosity(p); };
  } else {
    const auto spacing = lucent::reference::chooseSpacing(mesh, double(dipole.minMeanFreePath()), this->SampleFraction,
                                                          std::size_t(this->MaxSamples));
    if (spacing.budgetLimited)
      vtkWarningMacro("MaxSamples limits the sample spacing to " << spacing.spacing << " mm (" << this->SampleFraction
                      << " of the mean free path asked); raise MaxSamples for a converged result");
    const auto samples = lucent::reference::buildSurfaceSamples(mesh, spacing.spacing);
    this->SampleCount = vtkIdType(samples.size());
    truth = std::make_unique<lucent::reference::DipoleTruth<float>>(samples, dipole, lights, caster, irradiance,
                                                                    lucent::util::serialFor, stageOne);
    radiosityAt = [&truth](const glm::dvec3& p) { return truth->radiosity(p); };
  }

  // Stage 2: B at every vertex (Eq. 3), in parallel chunks with progress between them.
  vtkNew<vtkFloatArray> radiosity;
  radiosity->SetName("Radiosity");
  radiosity->SetNumberOfComponents(3);
  radiosity->SetNumberOfTuples(pointCount);
  vtkNew<vtkUnsignedCharArray> colour;
  colour->SetName("TranslucentColor");
  colour->SetNumberOfComponents(3);
  colour->SetNumberOfTuples(pointCount);
  const vtkIdType chunk = std::max<vtkIdType>(1, pointCount / 20);
  for (vtkIdType begin = 0; begin < pointCount; begin += chunk) {
    const vtkIdType end = std::min(pointCount, begin + chunk);
    vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType i = first; i < last; ++i) {
        const glm::dvec3 b = radiosityAt(glm::dvec3(mesh.positions[std::size_t(i)]));
        for (int c = 0; c < 3; ++c) {
          radiosity->SetTypedComponent(i, c, float(b[c]));
          colour->SetTypedComponent(i, c, displayByte(this->Exposure * b[c]));
        }
      }
    });
    this->UpdateProgress(0.5 + 0.5 * double(end) / double(pointCount));
  }

  output->ShallowCopy(triangles);
  output->GetPointData()->AddArray(radiosity);
  output->GetPointData()->SetScalars(colour);
  return 1;
}
