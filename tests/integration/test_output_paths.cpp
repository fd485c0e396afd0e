// Every output is checked before any work (output_paths.cpp): an output that is one of the
// command's inputs, two outputs on one path, a folder as an output, a missing folder: exit 2
// naming the option, with nothing written and every input as it was.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "io/exr_io.hpp"
#include "temp_dir.hpp"

namespace {
using lucent::test::contains;
using lucent::test::lucentCli;
using lucent::test::Run;
using lucent::test::slurp;

/// A closed tetrahedron as OBJ text.
const char* kTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
}  // namespace

TEST_CASE(
    "An output onto an input, two outputs on one file, a folder or a missing folder as an "
    "output: exit 2 before any work, nothing written, inputs unchanged") {
  lucent::test::TempDir dir;
  const std::string mesh = dir / "tet.obj", env = dir / "probe.exr";
  std::ofstream(mesh) << kTetrahedron;
  lucent::image::Image sky(8, 4);
  for (auto& p : sky.pixels) p = glm::vec4(1);
  lucent::io::writeExr(env, sky);
  const std::string envBytes = slurp(env);
  std::filesystem::create_directories(dir / "folder");
  const std::string base = "render --mesh " + mesh + " --width 8 --height 8 --quiet ";
  std::vector<std::pair<std::string, std::string>> cases = {
      {base + "--out " + dir / "a.png --stats " + mesh, "--stats " + mesh + " is the input --mesh"},
      {"render --shape sphere --light env:" + env + " --width 8 --height 8 --out " + env,
       "is the input --light env:"},
      {base + "--out " + dir / "a.exr --stats " + dir / "a.exr", "is also another output"},
      {base + "--out " + dir / "a.png --out ./" + dir.path.filename().string() + "/../" +
           dir.path.filename().string() + "/a.png",
       ""},  // one file spelled two ways: refused as two outputs (checked below)
      {base + "--out " + dir / "a.png --stats " + dir / "folder", "is a folder"},
      {base + "--out " + dir / "a.png --out " + dir / "missing/b.png", "does not exist"},
      {"bench --mesh " + mesh + " --method tsis --csv " + mesh, "--csv " + mesh + " is the input"},
      {base + "--light env:" + env + " --out " +
           dir / "a.png --method pathtrace --knob stderr=" + env,
       "--knob stderr " + env + " is the input --light"}};
  // A scan's hidden inputs: the data file a detached NRRD header names, a DICOM folder's slice.
  std::ofstream(dir / "scan.nhdr") << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 16 16 16\n"
                                      "encoding: raw\ndata file: scan.raw\n";
  std::ofstream(dir / "scan.raw") << std::string(4096, '\x40');
  cases.push_back({"render --volume " + dir / "scan.nhdr" +
                       " --iso 50 --width 8 --height 8 --out " + dir / "a.png --stats " +
                       dir / "scan.raw",
                   "is read by --volume"});
  for (const auto& entry : cases) {
    const auto& args = std::get<0>(entry);  // no structured binding: clang 14 cannot capture one
    const auto& expected = std::get<1>(entry);
    const Run r = lucentCli(args, dir);
    INFO(args << "\n" << r.err);
    CHECK(r.code == 2);
    if (!expected.empty()) CHECK(contains(r.err, expected));
    CHECK_FALSE(std::filesystem::exists(dir / "a.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "a.exr"));
    CHECK(slurp(mesh) == kTetrahedron);
    CHECK(slurp(env) == envBytes);
    CHECK(slurp(dir / "scan.raw") == std::string(4096, '\x40'));
  }
}
