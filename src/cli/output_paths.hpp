#pragma once
/// @file output_paths.hpp
/// @brief Every file a command will write, checked together before any work, so that nothing is
/// written unless everything can be: each output's folder exists and takes files, no output is a
/// folder, none is one of the command's inputs, and no two outputs are one file.
#include <string>
#include <vector>

#include "args.hpp"

namespace lucent::cli {

struct NamedOutput {
  std::string option;  ///< as the user wrote it: "--out", "--stats", "--knob vtu"
  std::string path;
};

/// Throws InputError for the first output that cannot be written. Inputs are the existing files
/// any other option of `args` names (whole, or as a part between ':', ',' and '=': env:FILE.exr,
/// FILE.vti:ARRAY), so a new option that reads a file is covered without a list to keep.
/// `hidden` adds inputs no option names directly (a scan header's data file, a DICOM folder's
/// slices: scene_setup's sceneInputFiles), each with the option that reads it.
void checkOutputs(const Args& args, const std::vector<NamedOutput>& outputs,
                  const std::vector<NamedOutput>& hidden = {});

}  // namespace lucent::cli
