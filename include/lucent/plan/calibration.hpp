#pragma once
/// @file calibration.hpp
/// @brief What the planner knows from measurement: every technique setting timed and measured
/// against its model's truth on a suite of scenes (`bench/calibrate_planner.py` runs `lucent
/// report` on each and writes data/planner/settings.csv), and each model's own error against the
/// physical truth with the share of single scattering (data/planner/model-floors.csv, from the
/// dipole-against-path-tracer benchmark). The files are read at run time, so a recalibration
/// changes no code.
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_features.hpp"

namespace lucent::plan {

/// A calibration file that cannot be read as written; the message names the file, the line and
/// the fix.
class CalibrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One technique setting measured on one calibration scene.
struct SettingMeasurement {
  std::string scene;
  SceneFeatures features;
  std::string technique, model;
  std::string knobs;  ///< the knobs that differ from the defaults, "a=1;b=2" or "defaults"
  double seconds = 0, prepareSeconds = 0, frameSeconds = 0;
  double modelError = 0;  ///< relative RMS against the truth of its model
};

/// A model's error against the physical truth on one scene: what no technique of the model can go
/// below.
struct ModelFloor {
  std::string scene, model;
  SceneFeatures features;
  double error = 0;  ///< relative RMS of the model's truth against the physical truth
  double singleShare =
      0;  ///< the share of the light that single scattering carries, largest channel
};

struct Calibration {
  std::vector<SettingMeasurement> settings;
  std::vector<ModelFloor> floors;
  std::string source;  ///< where it was read from, for the explanation
};

/// "a=1;b=2" into pairs ("defaults": none).
inline std::vector<std::pair<std::string, std::string>> knobPairs(const std::string& knobs) {
  std::vector<std::pair<std::string, std::string>> out;
  if (knobs == "defaults" || knobs.empty()) return out;
  std::stringstream in(knobs);
  for (std::string item; std::getline(in, item, ';');) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("knob '" + item + "' has no '='");
    out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return out;
}

namespace detail {

/// One CSV line's fields; a field in double quotes may hold commas.
inline std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else if (c != '\r')
      out.back() += c;
  }
  return out;
}

/// A CSV file as named columns, each row checked to have every column.
class CsvTable {
 public:
  CsvTable(const std::string& path, const std::string& regenerate) : mPath(path), mFix(regenerate) {
    std::ifstream in(path);
    if (!in) fail(0, "cannot be read");
    std::string line;
    if (!std::getline(in, line)) fail(1, "is empty");
    mHeader = csvFields(line);
    for (std::size_t n = 2; std::getline(in, line); ++n) {
      if (line.empty()) continue;
      mRows.push_back(csvFields(line));
      mLines.push_back(n);
      if (mRows.back().size() != mHeader.size())
        fail(n, "has " + std::to_string(mRows.back().size()) + " fields, the header " +
                    std::to_string(mHeader.size()));
    }
  }
  std::size_t rows() const { return mRows.size(); }
  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < mHeader.size(); ++i)
      if (mHeader[i] == name) return i;
    fail(1, "has no column '" + name + "'");
    return 0;
  }
  const std::string& text(std::size_t row, std::size_t col) const { return mRows[row][col]; }
  std::size_t line(std::size_t row) const { return mLines[row]; }
  double number(std::size_t row, std::size_t col) const {
    const std::string& s = mRows[row][col];
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || std::isnan(v))
      fail(mLines[row], "column '" + mHeader[col] + "' is '" + s + "', not a number");
    return v;
  }
  SceneFeatures features(std::size_t row) const {
    std::array<double, kFeatureNames.size()> v{};
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = number(row, column(kFeatureNames[k]));
    return featuresFromValues(v);
  }
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw CalibrationError("planner calibration file '" + mPath + "'" +
                           (line ? " line " + std::to_string(line) : std::string()) + " " +
                           problem + "; " + mFix);
  }

 private:
  std::string mPath, mFix;
  std::vector<std::string> mHeader;
  std::vector<std::vector<std::string>> mRows;
  std::vector<std::size_t> mLines;
};

}  // namespace detail

/// How the calibration files are made again, for every error message about them.
inline const char* kRecalibrate = "regenerate it with bench/calibrate_planner.py";

/// The folder the calibration is read from: `given` when not empty, else $LUCENT_DATA_DIR/planner
/// (an installed copy), else `builtInDataDir`/planner (the source tree's data/, compiled in).
inline std::string calibrationDirectory(const std::string& given,
                                        const std::string& builtInDataDir) {
  if (!given.empty()) return given;
  const char* env = std::getenv("LUCENT_DATA_DIR");
  return (env && *env ? std::string(env) : builtInDataDir) + "/planner";
}

/// Reads DIR/settings.csv and DIR/model-floors.csv.
inline Calibration readCalibration(const std::string& dir) {
  Calibration c;
  c.source = dir;
  {
    const detail::CsvTable t(dir + "/settings.csv", kRecalibrate);
    const std::size_t scene = t.column("scene"), tech = t.column("technique"),
                      model = t.column("model"), knobs = t.column("knobs"),
                      seconds = t.column("seconds"), prep = t.column("prepare_seconds"),
                      frame = t.column("frame_seconds"), err = t.column("relative_rms_model");
    for (std::size_t r = 0; r < t.rows(); ++r) {
      SettingMeasurement m{t.text(r, scene),  t.features(r),      t.text(r, tech),
                           t.text(r, model),  t.text(r, knobs),   t.number(r, seconds),
                           t.number(r, prep), t.number(r, frame), t.number(r, err)};
      const bool finite = std::isfinite(m.seconds) && std::isfinite(m.prepareSeconds) &&
                          std::isfinite(m.frameSeconds) && std::isfinite(m.modelError);
      if (!finite || !(m.seconds > 0) || !(m.frameSeconds > 0) || !(m.prepareSeconds >= 0) ||
          !(m.modelError >= 0))
        t.fail(t.line(r), "has a time or error that is not a finite positive number");
      c.settings.push_back(std::move(m));
    }
  }
  const detail::CsvTable t(dir + "/model-floors.csv", kRecalibrate);
  const std::size_t scene = t.column("scene"), model = t.column("model"),
                    err = t.column("relative_rms_physical"), single = t.column("single_share");
  for (std::size_t r = 0; r < t.rows(); ++r) {
    c.floors.push_back(
        {t.text(r, scene), t.text(r, model), t.features(r), t.number(r, err), t.number(r, single)});
    const ModelFloor& f = c.floors.back();
    if (!(f.error >= 0) || !std::isfinite(f.error) || !(f.singleShare >= 0 && f.singleShare <= 1))
      t.fail(t.line(r), "has an error that is not finite and >= 0, or a share outside [0, 1]");
  }
  return c;
}

}  // namespace lucent::plan
