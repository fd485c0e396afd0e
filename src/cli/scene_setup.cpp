#include "scene_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>

#include <lucent/scene/environment_image.hpp>
#include <lucent/scene/mesh_check.hpp>
#include <lucent/scene/shapes.hpp>
#include <lucent/technique/transfer_function.hpp>
#include <lucent/technique/validity.hpp>
#include "../io/exr_io.hpp"
#include "../io/mesh_io.hpp"
#include "../io/mesh_repair.hpp"
#include "../io/vtk_isosurface.hpp"
#include "../io/vtk_volume.hpp"
#include "../io/winding_remesh.hpp"
#include "../raycast/embree_ray_caster.hpp"
#include "../render/density_field.hpp"
#include "../scene/builtin_shapes.hpp"
#include "../util/error.hpp"
#include "../util/tbb_parallel.hpp"
#include "material_options.hpp"

namespace lucent::cli {

namespace {
constexpr const char* kDefaultShape = "genus7";
constexpr double kDefaultSizeMm = 30.0;
constexpr const char* kDefaultMaterial = "skin1";

/// "point:X,Y,Z[:R,G,B]" (mm; R,G,B = irradiance at the object's centre), "dir:X,Y,Z[:R,G,B]"
/// (towards the light; irradiance), "env:FILE.exr[:SCALE]" (lat-long radiance).
std::string shortNumber(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

/// An irradiance R,G,B (or a scale) each in [0, scene::kMaxLightValue].
void checkLightValues(const Args& args, const std::string& text, const glm::dvec3& e) {
  for (int c = 0; c < 3; ++c)
    if (!(e[c] >= 0 && e[c] <= scene::kMaxLightValue))
      args.fail("--light " + text + ": intensities must lie in [0, 1e12], not " +
                shortNumber(e[c]));
}

scene::Light parseLight(const Args& args, const std::string& text, double diag,
                        std::string& description) {
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  const auto colon2 = rest.find(':');
  const std::string first = rest.substr(0, colon2);
  const std::string second = colon2 == std::string::npos ? "" : rest.substr(colon2 + 1);
  const std::string what = "lucent " + args.command() + ": --light " + text;
  if (kind == "point" || kind == "dir") {
    if (first.empty())
      args.fail("--light " + text + ": give a position or direction, e.g. " + kind + ":0,50,-80");
    const glm::dvec3 v = parseTriple(first, what);
    const glm::dvec3 e = second.empty() ? glm::dvec3(1) : parseTriple(second, what);
    if (glm::length(v) <= 0) args.fail("--light " + text + ": the vector must not be zero");
    if (!std::isfinite(glm::dot(v, v)))
      args.fail("--light " + text + ": the vector's length must be finite; give a shorter one");
    checkLightValues(args, text, e);
    std::ostringstream d;
    d << kind << " (" << v.x << "," << v.y << "," << v.z << ") E=(" << e.x << "," << e.y << ","
      << e.z << ")";
    description = d.str();
    if (kind == "point") {
      if (glm::length(v) < 0.5 * diag)
        args.fail("--light " + text +
                  ": the point light is inside the object's bounding sphere; move it further out");
      const glm::dvec3 intensity = e * glm::dot(v, v);  // irradiance e at the centre, distance |v|
      if (!std::isfinite(intensity.x + intensity.y + intensity.z))
        args.fail("--light " + text +
                  ": the light is too far away (its intensity overflows); bring it closer");
      return scene::PointLight{v, intensity};
    }
    return scene::DirectionalLight{glm::normalize(v), e};
  }
  if (kind == "env") {
    if (first.empty())
      args.fail("--light env: give an EXR file, e.g. env:studio.exr, or env:uniform");
    scene::EnvironmentLight env;
    if (first ==
        "uniform") {  // radiance 1 (times SCALE) from every direction: the white-furnace light
      env.width = env.height = 1;
      env.radiance = {glm::vec3(1.0f)};
      env.scale = second.empty() ? 1.0 : parseNumber(second, what);
      checkLightValues(args, text, glm::dvec3(env.scale));
      env.source = "uniform";
      description = "uniform environment";
      return env;
    }
    const image::Image img = io::readExr(first);
    const scene::ScreenedTexels texels = scene::screenEnvironmentTexels(
        img.width, img.height, [&](int x, int y) { return glm::vec3(img.at(x, y)); });
    if (!texels.problem.empty())
      args.fail("--light " + text + ": " + texels.problem + " (fix the EXR)");
    if (!texels.note.empty())
      std::fprintf(stderr, "lucent %s: --light %s: %s\n", args.command().c_str(), text.c_str(),
                   texels.note.c_str());
    env = scene::environmentFromTexels(img.width, img.height, texels);
    env.source = first;
    env.scale = second.empty() ? 1.0 : parseNumber(second, what);
    checkLightValues(args, text, glm::dvec3(env.scale));
    description = "environment " + first +
                  (env.layout == scene::EnvironmentLayout::Cube ? " (cube map)" : "");
    return env;
  }
  args.fail("--light '" + text + "': unknown kind '" + kind +
            "'; use point:X,Y,Z[:R,G,B], dir:X,Y,Z[:R,G,B] or env:FILE.exr[:SCALE]");
}
bool inside(const scene::RayCaster& caster, const glm::dvec3& p, double epsilon) {
  return scene::insideByParity(caster, p, epsilon);
}

/// "--inclusion MATERIAL[:FRACTION]": a sphere of another material at the bounding-box centre, its
/// radius FRACTION (default 0.3) of half the smallest box extent; it must lie inside the object.
technique::Inclusion parseInclusion(const Args& args, const std::string& text, const Scene& s) {
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  const auto found = optics::findMaterial(name);
  if (!found)
    args.fail("--inclusion " + text + ": '" + name +
              "' is not a material; `lucent materials` lists them");
  const double fraction =
      colon == std::string::npos
          ? 0.3
          : parseNumber(text.substr(colon + 1), "lucent " + args.command() + ": --inclusion");
  if (!(fraction >= 1e-3 && fraction <= 1))
    args.fail("--inclusion " + text + ": the radius fraction must lie in [0.001, 1]");
  const scene::Bounds bounds = s.mesh.bounds();
  const glm::dvec3 extent = bounds.hi - bounds.lo, centre = bounds.center();
  const double radius = fraction * 0.5 * std::min(extent.x, std::min(extent.y, extent.z));
  technique::Inclusion inc;
  inc.surface = scene::shapes::sphere(radius, 4, centre);
  for (const auto& p : inc.surface.positions)
    if (!inside(*s.caster, glm::dvec3(p), 1e-5 * bounds.diagonal()))
      args.fail("--inclusion " + text + ": the sphere (radius " + technique::valueText(radius) +
                " mm at the bounding-box centre) is not inside the object; lower the fraction or "
                "use a shape that is "
                "solid at its centre (e.g. --shape sphere)");
  inc.medium.material = *found;
  inc.contains = [centre, radius](const glm::dvec3& p) { return glm::length(p - centre) < radius; };
  inc.description = found->name + " sphere of radius " + technique::lengthText(radius);
  return inc;
}
/// The built-in shapes' names, for the help text.
std::string shapeList() {
  std::string list;
  for (const auto& n : scene::builtinShapeNames()) list += (list.empty() ? "" : " ") + n;
  return list;
}

/// An inclusion bounded by a closed mesh, with a ray-parity inside test of its own.
technique::Inclusion meshInclusion(scene::TriangleMesh surface, const optics::Material& material,
                                   const std::string& description) {
  technique::Inclusion inc;
  inc.surface = std::move(surface);
  inc.medium.material = material;
  inc.description = description;
  const auto caster = std::make_shared<raycast::EmbreeRayCaster>(inc.surface);
  const double epsilon = 1e-5 * inc.surface.bounds().diagonal();  // Embree is float
  inc.contains = [caster, epsilon](const glm::dvec3& p) { return inside(*caster, p, epsilon); };
  return inc;
}

/// Moves a body with the object: the object's mesh was centred on `centre` and scaled by `scale`.
scene::TriangleMesh placedLikeObject(scene::TriangleMesh body, const glm::dvec3& centre,
                                     double scale) {
  for (auto& p : body.positions) p = glm::vec3((glm::dvec3(p) - centre) * scale);
  return body;
}

/// Every vertex of the body inside the object, and no vertex of the object (its cavities' walls
/// included) or of an earlier body inside it: nested media must not overlap or enclose a cavity.
void requireInside(const Args& args, const Scene& s, std::size_t which, const std::string& option) {
  const technique::Inclusion& inc = s.inclusions[which];
  const double epsilon = 1e-5 * s.mesh.bounds().diagonal();
  for (const auto& p : inc.surface.positions)
    if (!inside(*s.caster, glm::dvec3(p), epsilon))
      args.fail(option + ": " + inc.description +
                " is not inside the object; give a mesh in the object's own coordinates that "
                "lies within it");
  auto enclosesAny = [&](const scene::TriangleMesh& m) {
    return std::any_of(m.positions.begin(), m.positions.end(),
                       [&](const glm::vec3& p) { return inc.contains(glm::dvec3(p)); });
  };
  if (enclosesAny(s.mesh))
    args.fail(option + ": " + inc.description +
              " encloses part of the object's surface (a cavity or a wall); an inner body must lie "
              "in the material, apart from cavities");
  for (std::size_t k = 0; k < which; ++k)
    if (enclosesAny(s.inclusions[k].surface))
      args.fail(option + ": " + inc.description + " overlaps " + s.inclusions[k].description +
                "; inner bodies must not overlap");
}

/// "--inclusion-mesh FILE:MATERIAL": a closed mesh in the object mesh's coordinates.
technique::Inclusion parseInclusionMesh(const Args& args, const std::string& text,
                                        const glm::dvec3& centre, double scale) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos)
    args.fail("--inclusion-mesh " + text + ": give FILE:MATERIAL (`lucent materials` lists them)");
  const std::string file = text.substr(0, colon), name = text.substr(colon + 1);
  const auto material = optics::findMaterial(name);
  if (!material)
    args.fail("--inclusion-mesh " + text + ": '" + name +
              "' is not a material; `lucent materials` lists them");
  scene::TriangleMesh mesh;
  try {
    mesh = io::readMesh(file);
  } catch (const InputError& e) {
    args.fail("--inclusion-mesh: " + std::string(e.what()));
  }
  const scene::MeshReport report = scene::checkMesh(mesh);
  if (!report.ok())
    args.fail("--inclusion-mesh " + file + ": the mesh does not bound a volume (" +
              report.problems().front() + "); repair it first (lucent render --mesh " + file +
              " --repair reports what is wrong)");
  return meshInclusion(placedLikeObject(std::move(mesh), centre, scale), *material,
                       material->name + " body from " + file);
}

/// The built-in shape's own inner bodies (the bottle's liquid), of --fill's material when given.
void addInnerBodies(const Args& args, Scene& s, const std::string& shape, const glm::dvec3& centre,
                    double scale) {
  const auto bodies = scene::builtinInnerBodies(shape);
  if (bodies.empty() && args.has("fill"))
    args.fail("--fill: shape '" + shape + "' has no inner body to fill (the bottle has)");
  if (args.get("fill", "") == "none") return;  // the inside is the object's own material
  for (const auto& body : bodies) {
    const std::string name = args.get("fill", body.defaultMaterial);
    const auto material = optics::findMaterial(name);
    if (!material) args.fail("--fill " + name + ": not a material; `lucent materials` lists them");
    s.inclusions.push_back(meshInclusion(placedLikeObject(body.surface, centre, scale), *material,
                                         material->name + " as " + body.description));
  }
}
/// "--volume FILE[:ARRAY] [--transfer SPEC] --iso X": the scan, its medium, and its isosurface at X
/// (or, for a label map, where the labels with a material end) as the object's surface.
std::shared_ptr<const scene::VoxelGrid> readScan(const Args& args, Scene& s,
                                                 std::optional<technique::ScanMedium>& medium) {
  std::string path = args.get("volume"), array;
  const auto colon = path.rfind(':');
  if (!std::filesystem::exists(path) && colon != std::string::npos)
    array = path.substr(colon + 1), path = path.substr(0, colon);
  auto scan = std::make_shared<scene::VoxelGrid>(io::readImageVolume(path, array));
  s.meshName = path;
  if (args.has("transfer")) try {
      medium = technique::parseTransfer("--transfer", args.get("transfer"), scan);
    } catch (const technique::RequestError& e) {
      throw InputError(e.what());
    }
  if (medium && medium->mask) {
    if (args.has("iso"))
      args.fail("--iso " + args.get("iso") +
                ": a label map's surface is where its labels with a "
                "material end, not an isosurface; drop --iso (or give a points: transfer)");
    s.mesh = io::scanIsosurface(*medium->mask, 0.5,
                                "--volume " + path + " (its labels with a material)");
    return scan;
  }
  if (!args.has("iso")) {
    const auto [lo, hi] = std::minmax_element(scan->values.begin(), scan->values.end());
    args.fail("--volume " + path +
              ": give --iso X, the value whose isosurface is the object's "
              "surface (the values span [" +
              technique::valueText(*lo) + ", " + technique::valueText(*hi) + "])");
  }
  s.mesh = io::scanIsosurface(*scan, args.number("iso", 0, -1e30, 1e30), "--volume " + path);
  return scan;
}

/// The scan's medium: the transfer function's coefficients, or (none given) its values normalised
/// to [0, 1] over their range scaling the material. The object was centred on `centre` and scaled
/// by `scale`.
void scanMedium(std::shared_ptr<const scene::VoxelGrid> scan,
                const std::optional<technique::ScanMedium>& tf, const glm::dvec3& centre,
                double scale, Scene& s) {
  const auto scanAt = [centre, scale](const glm::dvec3& p) { return p / scale + centre; };
  if (tf)
    technique::transferMedium(*tf, scanAt, s.meshName, s.medium);
  else
    technique::normalisedDensity(scan, scanAt, s.meshName, s.medium);
}
}  // namespace

std::vector<OptionSpec> sceneOptionSpecs() {
  std::vector<OptionSpec> specs{
      {"mesh", "FILE", "mesh to render (.ply .obj .stl .off .vtp .vtk)"},
      {"shape", "NAME",
       std::string("built-in shape (default ") + kDefaultShape + "): " + shapeList()},
      {"size-mm", "X", "scale the object so its bounding-box diagonal is X mm (default 30)"},
      {"light", "SPEC",
       "point:X,Y,Z[:R,G,B] | dir:X,Y,Z[:R,G,B] | env:FILE.exr[:SCALE] | env:uniform[:SCALE] (mm; "
       "R,G,B = irradiance at the centre)",
       true},
      {"view", "X,Y,Z", "direction from the object towards the camera (default 0,0.6,1)"},
      {"width", "W", "image width in pixels (default 400)"},
      {"height", "H", "image height in pixels (default 400)"},
      {"repair", "",
       "weld, drop degenerate faces, close holes and orient the mesh before the check; when that "
       "is not enough, remesh it by its generalized winding number (reports what changed and how "
       "far the result lies from the input)"},
      {"repair-resolution", "N",
       "with --repair: voxels along the longest side when the mesh must be remeshed by its "
       "winding number (default " +
           std::to_string(io::kDefaultRemeshResolution) + ", " +
           std::to_string(io::kMinRemeshResolution) + " to " +
           std::to_string(io::kMaxRemeshResolution) + ")"},
      {"skip-mesh-check", "", "render even if the mesh is not closed and outward-oriented"},
      {"density", "SPEC",
       "heterogeneous medium: sigma_a and sigma_s' times a density, noise:F, FILE.vdb[:GRID] or "
       "FILE.vti[:ARRAY] (fitted to the bounding box)"},
      {"inclusion", "MATERIAL[:F]",
       "a sphere of another material at the bounding-box centre, radius F (default "
       "0.3) of half the smallest extent"},
      {"volume", "FILE[:ARRAY]",
       "a scan as the object (.vti .vtk .nrrd .nhdr .mha .mhd .nii .nii.gz, or a DICOM folder): "
       "its "
       "isosurface at --iso is the surface, its values normalised to [0, 1] scale --material"},
      {"iso", "X", "the scan value whose isosurface bounds the object (with --volume)"},
      {"transfer", "SPEC",
       "the scan's values as coefficients: labels:V=MATERIAL,...,V=none (a label map; no --iso) or "
       "points:V/SA_R,SA_G,SA_B/SS_R,SS_G,SS_B;... (piecewise linear, mm^-1)"},
      {"inclusion-mesh", "FILE:MATERIAL",
       "a closed body of another material, in the object mesh's coordinates", true},
      {"fill", "MATERIAL|none",
       "the material of a built-in shape's inner body (bottle: default Merlot; none: the "
       "object's own)"},
  };
  for (auto& m : materialOptionSpecs()) specs.push_back(m);
  return specs;
}

std::vector<NamedOutput> sceneInputFiles(const Args& args) {
  std::vector<NamedOutput> files;
  if (!args.has("volume")) return files;
  std::string path = args.get("volume");
  const auto colon = path.rfind(':');  // FILE[:ARRAY], as readScan splits it
  if (!std::filesystem::exists(path) && colon != std::string::npos) path = path.substr(0, colon);
  for (const std::string& file : io::volumeInputFiles(path))
    files.push_back({"--volume " + args.get("volume"), file});
  return files;
}

Scene buildScene(const Args& args) {
  Scene s;
  if (int(args.has("mesh")) + int(args.has("shape")) + int(args.has("volume")) > 1)
    args.fail("give one of --mesh, --shape and --volume");
  std::shared_ptr<const scene::VoxelGrid> scan;
  std::optional<technique::ScanMedium> transfer;
  if (args.has("transfer") && !args.has("volume"))
    args.fail("--transfer maps a scan's values: give it with --volume");
  if (args.has("volume")) {
    if (args.has("density"))
      args.fail("--volume brings its own density (the scan's values); drop --density");
    scan = readScan(args, s, transfer);
  } else if (args.has("mesh")) {
    s.meshName = args.get("mesh");
    s.mesh = io::readMesh(s.meshName);
  } else {
    s.meshName = args.get("shape", kDefaultShape);
    s.mesh = scene::makeBuiltinShape(s.meshName);
  }
  // A scan keeps its own millimetres unless --size-mm asks otherwise.
  s.sizeMm = args.number("size-mm", scan ? s.mesh.bounds().diagonal() : kDefaultSizeMm, 1e-6, 1e9);
  const std::vector<std::string> inclusionMeshes = args.all("inclusion-mesh");
  if (!inclusionMeshes.empty() && !args.has("mesh"))
    args.fail("--inclusion-mesh needs --mesh (its coordinates are the object mesh's)");
  if (args.has("repair-resolution") && !args.has("repair"))
    args.fail("--repair-resolution goes with --repair");
  if (args.has("repair")) {
    const int resolution = args.integer("repair-resolution", io::kDefaultRemeshResolution,
                                        io::kMinRemeshResolution, io::kMaxRemeshResolution);
    const io::RepairReport repaired = io::repairMesh(
        s.mesh, resolution, "lucent " + args.command() + ": mesh '" + s.meshName + "'");
    const auto changes = repaired.changes();
    std::fprintf(stderr, "lucent %s: --repair: %s\n", args.command().c_str(),
                 changes.empty() ? "nothing to repair" : changes.front().c_str());
    for (std::size_t i = 1; i < changes.size(); ++i)
      std::fprintf(stderr, "lucent %s: --repair: %s\n", args.command().c_str(), changes[i].c_str());
  }
  if (!args.has("skip-mesh-check")) {
    const scene::MeshReport report = scene::checkMesh(s.mesh);
    if (!report.ok()) {
      std::string msg = "mesh '" + s.meshName + "' does not bound a volume:";
      for (const auto& p : report.problems()) msg += "\n  - " + p;
      msg +=
          args.has("repair")
              ? "\n  (--repair could not fix this; repair the mesh in MeshLab or Blender, or pass "
                "--skip-mesh-check to render it anyway; subsurface results will not be physical)"
              : "\n  (pass --repair to weld, close holes and orient it, or --skip-mesh-check to "
                "render "
                "it anyway; subsurface results will not be physical)";
      throw InputError("lucent " + args.command() + ": " + msg);
    }
  }
  const glm::dvec3 unscaledCentre = s.mesh.bounds().center();
  const double scale = s.mesh.scaleToSize(s.sizeMm);
  s.vertexNormals = s.mesh.vertexNormals();
  s.medium.material = materialFromArgs(args, kDefaultMaterial);

  const double diag = s.mesh.bounds().diagonal();
  for (const std::string& spec : args.all("light")) {
    std::string d;
    s.lights.push_back(parseLight(args, spec, diag, d));
    s.lightDescriptions.push_back(d);
  }
  if (s.lights.empty()) {
    // Default: a back light above and behind the object (the translucent glow) and a weak frontal
    // fill.
    const glm::dvec3 back = glm::normalize(glm::dvec3(0.3, 0.9, -1.0)) * (2.0 * diag);
    s.lights.push_back(scene::PointLight{back, glm::dvec3(1.0) * glm::dot(back, back)});
    s.lights.push_back(
        scene::DirectionalLight{glm::normalize(glm::dvec3(-0.6, 0.5, 1.0)), glm::dvec3(0.12)});
    s.lightDescriptions = {"point back light (irradiance 1 at the centre)",
                           "directional front fill (0.12)"};
  }

  const int w = args.integer("width", 400, 1, 16384), h = args.integer("height", 400, 1, 16384);
  const glm::dvec3 view = args.triple("view", glm::dvec3(0, 0.6, 1));
  if (glm::length(view) <= 0) args.fail("--view must not be the zero vector");
  if (!std::isfinite(glm::dot(view, view)))
    args.fail("--view " + args.get("view") +
              ": the direction's length must be finite; give a "
              "shorter vector (only its direction counts)");
  s.camera = scene::PinholeCamera::frame(s.mesh.bounds(), view, w, h);
  s.ownedCaster = std::make_unique<raycast::EmbreeRayCaster>(s.mesh);
  s.caster = s.ownedCaster.get();
  s.makeRayCaster = [](const scene::TriangleMesh& m) {
    return std::make_unique<raycast::EmbreeRayCaster>(m);
  };
  s.parallelFor = util::tbbFor;

  if (args.has("density")) {
    const render::DensityField field = render::parseDensityField(
        "lucent " + args.command() + ": --density", args.get("density"), s.mesh.bounds());
    s.medium.density = field.at;
    s.medium.densityDescription = field.description;
  }
  if (scan) scanMedium(scan, transfer, unscaledCentre, scale, s);
  if (args.has("inclusion")) s.inclusions.push_back(parseInclusion(args, args.get("inclusion"), s));
  for (const auto& text : inclusionMeshes)
    s.inclusions.push_back(parseInclusionMesh(args, text, unscaledCentre, scale));
  if (args.has("mesh") && args.has("fill"))
    args.fail(
        "--fill fills a built-in shape's inner body (the bottle's); with --mesh give the "
        "body as --inclusion-mesh FILE:MATERIAL");
  if (!args.has("mesh")) addInnerBodies(args, s, s.meshName, unscaledCentre, scale);
  for (std::size_t i = 0; i < s.inclusions.size(); ++i) requireInside(args, s, i, "inclusion");
  return s;
}

}  // namespace lucent::cli
