#pragma once
/// @file line_chart.hpp
/// @brief Line and scatter charts written to PNG with VTK's charts (vtkChartXY, offscreen).
/// VTK on Debian renders through X: without a DISPLAY the CLI re-runs itself under xvfb-run.
#include <string>
#include <vector>

namespace lucent::plot {

/// Marker shapes of point series (vtkPlotPoints' own).
enum class Marker { Default, Cross, Plus, Square, Circle, Diamond };

struct Series {
  std::string name;
  std::vector<double> x, y;
  unsigned char rgb[3] = {31, 119, 180};
  bool points = false;  ///< markers instead of a line
  Marker marker = Marker::Default;
};

struct ChartSpec {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  int width = 800, height = 500;
  bool legendOutside = false;  ///< beside the plot area, not over it (charts whose data fill it)
};

/// Throws InputError if the PNG cannot be written.
void writeLineChart(const std::string& path, const ChartSpec& spec,
                    const std::vector<Series>& series);

/// Whether charts can be drawn in this process (an X display is reachable).
bool chartsAvailable();

}  // namespace lucent::plot
