#pragma once
/// @file report_page.hpp
/// @brief The accuracy-cost report as one offline HTML page: the Pareto plot, a table with a row
/// per setting (time per phase, memory, error against each truth, image and error maps), the
/// truths it was measured against, and what was not run and why.
#include <string>
#include <vector>

namespace lucent::report {

/// One truth the settings are measured against.
struct TruthEntry {
  std::string role;  ///< "physical" or "model: dipole"
  std::string technique, knobs;
  double seconds = 0;
  std::string image;  ///< relative path of its picture
};

/// One measured setting, as the page shows it.
struct PageRow {
  std::string technique, model, knobs;
  double seconds = 0, prepareSeconds = 0, frameSeconds = 0, samples = 0, megabytes = 0;
  std::string sampleUnit;
  double modelError = 0, physicalError = 0;  ///< relative RMS; NaN where there is no such truth
  bool onModelFront = false, onPhysicalFront = false;
  bool cached = false;                                 ///< measured by an earlier run
  std::string image, modelErrorMap, physicalErrorMap;  ///< relative paths ("" = none)
  std::vector<std::string> warnings;
};

struct PageNote {
  std::string technique, setting, reason;
};

struct ReportPage {
  std::string title, scene, command;
  double errorMapScale = 0;  ///< the relative error shown as the ramp's top
  std::string plot;          ///< relative path of the Pareto plot
  std::string csv;           ///< relative path of the table as CSV
  std::vector<TruthEntry> truths;
  std::vector<PageRow> rows;
  std::vector<PageNote> notRun;
};

/// The page's HTML (self-contained apart from the pictures it names).
std::string pageHtml(const ReportPage& page);
/// The table as CSV, a row per setting.
std::string pageCsv(const ReportPage& page);

}  // namespace lucent::report
