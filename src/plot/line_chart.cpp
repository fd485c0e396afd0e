#include "line_chart.hpp"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <filesystem>

#include "../io/atomic_file.hpp"
#include "../util/error.hpp"

namespace lucent::plot {

bool chartsAvailable() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

void writeLineChart(const std::string& path, const ChartSpec& spec,
                    const std::vector<Series>& series) {
  if (!chartsAvailable())
    throw InputError("cannot draw '" + path +
                     "': VTK charts need an X display; run under 'xvfb-run -a'");
  io::AtomicFile out(path);
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(spec.width, spec.height);
  view->GetRenderer()->SetBackground(1, 1, 1);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(spec.title);
  chart->GetTitleProperties()->SetFontSize(16);
  chart->SetShowLegend(series.size() > 1);
  if (spec.legendOutside) {  // the chart shrinks its plot area to make room on the right
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  }
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(spec.xLabel);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(spec.yLabel);
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(spec.logX);
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(spec.logY);
  std::vector<vtkSmartPointer<vtkTable>> tables;
  for (const Series& s : series) {
    vtkNew<vtkDoubleArray> xs, ys;
    xs->SetName("x");
    ys->SetName(s.name.c_str());
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      // Log axes cannot show values <= 0; leave those points out rather than distort the chart.
      if ((spec.logX && !(s.x[i] > 0)) || (spec.logY && !(s.y[i] > 0))) continue;
      xs->InsertNextValue(s.x[i]);
      ys->InsertNextValue(s.y[i]);
    }
    auto table = vtkSmartPointer<vtkTable>::New();
    table->AddColumn(xs);
    table->AddColumn(ys);
    tables.push_back(table);
    vtkPlot* plot = chart->AddPlot(s.points ? vtkChart::POINTS : vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(s.rgb[0], s.rgb[1], s.rgb[2], 255);
    plot->SetWidth(2.0);
    if (auto* pts = vtkPlotPoints::SafeDownCast(plot)) {
      pts->SetMarkerSize(8);
      if (s.marker != Marker::Default) pts->SetMarkerStyle(int(s.marker));  // same order as VTK's
    }
  }
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(out.tempPath().c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(out.tempPath()))
    throw InputError("cannot write '" + path + "': the PNG writer failed");
  out.commit();
}

}  // namespace lucent::plot
