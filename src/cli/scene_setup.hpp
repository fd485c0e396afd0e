#pragma once
/// @file scene_setup.hpp
/// @brief The scene options render and bench share (mesh or shape, size, material, media, lights,
/// camera), and the built-in default scene: a back-lit skin1 genus-7 ring, whose thin parts glow.
#include <memory>
#include <string>
#include <vector>

#include <lucent/optics/materials.hpp>
#include <lucent/scene/camera.hpp>
#include <lucent/scene/light.hpp>
#include <lucent/scene/mesh.hpp>
#include <lucent/scene/ray_caster.hpp>
#include <lucent/technique/scene.hpp>

#include "args.hpp"
#include "output_paths.hpp"

namespace lucent::cli {

/// What every technique reads (technique::SceneDescription, with Embree ray casting and TBB loops),
/// plus what the CLI adds: the camera, the size asked for, and the lights as the user wrote them.
struct Scene : technique::SceneDescription {
  double sizeMm = 0;
  std::vector<std::string> lightDescriptions;
  scene::PinholeCamera camera;
  std::unique_ptr<scene::RayCaster> ownedCaster;  ///< `caster` points here
};

/// The options that describe a scene, for a subcommand's option list.
std::vector<OptionSpec> sceneOptionSpecs();
/// Builds the scene from parsed options; throws InputError on bad input (with the fix).
Scene buildScene(const Args& args);

/// The files a scan read by --volume touches beyond the path given (a header's detached data file,
/// a DICOM folder's slices), for checkOutputs.
std::vector<NamedOutput> sceneInputFiles(const Args& args);

}  // namespace lucent::cli
