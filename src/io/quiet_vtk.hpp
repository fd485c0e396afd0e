#pragma once
/// @file quiet_vtk.hpp
/// @brief Silences VTK's own messages (the output window and the logger) while lucent reads a file:
/// VTK's readers report problems there, some a line per bad element, with colour codes and
/// timestamps. lucent reports the problem itself, in one line naming the file and the fix.
#include <vtkLogger.h>
#include <vtkOutputWindow.h>

namespace lucent::io {

/// For the scope of one read.
class QuietVtk {
 public:
  QuietVtk()
      : mMode(vtkOutputWindow::GetInstance()->GetDisplayMode()),
        mVerbosity(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~QuietVtk() {
    vtkOutputWindow::GetInstance()->SetDisplayMode(mMode);
    vtkLogger::SetStderrVerbosity(mVerbosity);
  }
  QuietVtk(const QuietVtk&) = delete;
  QuietVtk& operator=(const QuietVtk&) = delete;

 private:
  int mMode;
  vtkLogger::Verbosity mVerbosity;
};

}  // namespace lucent::io
