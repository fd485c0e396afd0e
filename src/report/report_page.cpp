#include "report_page.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lucent::report {

namespace {
std::string escaped(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

std::string number(double v, const char* format = "%.3g") {
  if (!std::isfinite(v)) return "&ndash;";
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string picture(const std::string& path, const std::string& alt) {
  if (path.empty()) return "&ndash;";
  return "<a href=\"" + escaped(path) + "\"><img src=\"" + escaped(path) + "\" alt=\"" +
         escaped(alt) + "\" width=\"128\"></a>";
}

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; color: #222; }
table { border-collapse: collapse; font-size: 90%; }
th, td { border: 1px solid #ccc; padding: 4px 6px; text-align: right; vertical-align: middle; }
th { background: #eee; }
td.text { text-align: left; }
tr.front td.err { font-weight: bold; }
.on { color: #b00; }
</style>
)";

// Counts pictures that failed to load into body[data-broken-images] (read by the browser test).
constexpr const char* kImageCheck = R"(<script>
window.addEventListener('load', function () {
  var broken = 0;
  for (var img of document.images) if (!img.complete || img.naturalWidth === 0) broken++;
  document.body.dataset.brokenImages = String(broken);
  document.body.dataset.images = String(document.images.length);
});
</script>
)";

void truthsSection(std::ostringstream& o, const ReportPage& page) {
  o << "<h2>Truths</h2>\n<table>\n<tr><th>role</th><th>technique</th><th>knobs</th>"
       "<th>seconds</th><th>image</th></tr>\n";
  for (const auto& t : page.truths)
    o << "<tr class=\"truth\"><td class=\"text\">" << escaped(t.role) << "</td><td class=\"text\">"
      << escaped(t.technique) << "</td><td class=\"text\">" << escaped(t.knobs) << "</td><td>"
      << number(t.seconds) << "</td><td>" << picture(t.image, t.technique) << "</td></tr>\n";
  o << "</table>\n";
}

void settingRow(std::ostringstream& o, const PageRow& r) {
  const bool front = r.onModelFront || r.onPhysicalFront;
  o << "<tr class=\"setting" << (front ? " front" : "") << "\"><td class=\"text\">"
    << escaped(r.technique) << "</td><td class=\"text\">" << escaped(r.model)
    << "</td><td class=\"text\">" << escaped(r.knobs.empty() ? "(defaults)" : r.knobs)
    << "</td><td>" << number(r.prepareSeconds) << "</td><td>" << number(r.frameSeconds)
    << "</td><td>" << number(r.seconds) << (r.cached ? "*" : "") << "</td><td>"
    << number(r.samples, "%.0f") << " " << escaped(r.sampleUnit) << "</td><td>"
    << number(r.megabytes, "%.2f") << "</td><td class=\"err\">" << number(r.modelError)
    << (r.onModelFront ? " <span class=\"on\">&#9733;</span>" : "") << "</td><td class=\"err\">"
    << number(r.physicalError) << (r.onPhysicalFront ? " <span class=\"on\">&#9733;</span>" : "")
    << "</td><td>" << picture(r.image, r.technique) << "</td><td>"
    << picture(r.modelErrorMap, "error map") << "</td><td>"
    << picture(r.physicalErrorMap, "error map") << "</td><td class=\"text\">";
  for (const auto& w : r.warnings) o << escaped(w) << "<br>";
  o << "</td></tr>\n";
}
}  // namespace

std::string pageHtml(const ReportPage& page) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
    << escaped(page.title) << "</title>\n"
    << kStyle << "</head>\n<body>\n<h1>" << escaped(page.title) << "</h1>\n<p>"
    << escaped(page.scene) << "</p>\n<p>Reproduce: <code>" << escaped(page.command)
    << "</code></p>\n<h2>Error against time</h2>\n<p><img src=\"" << escaped(page.plot)
    << "\" alt=\"Pareto plot\" width=\"900\"></p>\n<p>Each point is one setting of one technique: "
       "its wall time (prepare and one frame) against its relative RMS error, measured against "
       "the physical truth (circles) and against the truth of its own model (crosses). The lines "
       "join each truth's Pareto front: the settings no other setting beats on time and error "
       "at once (&#9733; in the table).</p>\n";
  truthsSection(o, page);
  o << "<h2>Settings</h2>\n<p>Error maps: |L &minus; L<sub>truth</sub>| over the truth's mean "
       "luminance, black at 0, yellow at "
    << number(page.errorMapScale) << ". * measured by an earlier run (cached). Table as <a href=\""
    << escaped(page.csv)
    << "\">CSV</a>.</p>\n<table>\n<tr><th>technique</th><th>model</th>"
       "<th>knobs</th><th>prepare s</th><th>frame s</th><th>total s</th><th>samples</th>"
       "<th>data MiB</th><th>error vs model truth</th><th>error vs physical truth</th>"
       "<th>image</th><th>error map (model)</th><th>error map (physical)</th><th>warnings</th>"
       "</tr>\n";
  for (const auto& r : page.rows) settingRow(o, r);
  o << "</table>\n";
  if (!page.notRun.empty()) {
    o << "<h2>Not run</h2>\n<ul>\n";
    for (const auto& n : page.notRun)
      o << "<li class=\"not-run\"><b>" << escaped(n.technique) << "</b> " << escaped(n.setting)
        << ": " << escaped(n.reason) << "</li>\n";
    o << "</ul>\n";
  }
  o << kImageCheck << "</body>\n</html>\n";
  return o.str();
}

std::string pageCsv(const ReportPage& page) {
  std::ostringstream o;
  o.precision(9);
  o << "technique,model,knobs,seconds,prepare_seconds,frame_seconds,samples,sample_unit,data_mib,"
       "relative_rms_model,relative_rms_physical,on_model_front,on_physical_front,cached\n";
  for (const auto& r : page.rows)
    o << r.technique << "," << r.model << ",\"" << r.knobs << "\"," << r.seconds << ","
      << r.prepareSeconds << "," << r.frameSeconds << "," << r.samples << ",\"" << r.sampleUnit
      << "\"," << r.megabytes << "," << r.modelError << "," << r.physicalError << ","
      << r.onModelFront << "," << r.onPhysicalFront << "," << r.cached << "\n";
  return o.str();
}

}  // namespace lucent::report
