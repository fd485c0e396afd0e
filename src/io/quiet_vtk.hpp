#pragma once
/// @file quiet_vtk.hpp
/// @brief Silences VTK's own messages (the output window and the logger) while lucent reads a file:
/// VTK's readers report problems there, some a line per bad element, with colour codes and
/// timestamps; MetaIO and VTK's DICOM parser print to std::cerr and std::cout directly. lucent
/// reports the problem itself, in one line naming the file and the fix.
#include <iostream>
#include <sstream>

#include <vtkLogger.h>
#include <vtkOutputWindow.h>

namespace lucent::io {

/// For the scope of one read.
class QuietVtk {
 public:
  QuietVtk()
      : mMode(vtkOutputWindow::GetInstance()->GetDisplayMode()),
        mVerbosity(vtkLogger::GetCurrentVerbosityCutoff()),
        mCerr(std::cerr.rdbuf(mSwallowed.rdbuf())),
        mCout(std::cout.rdbuf(mSwallowed.rdbuf())) {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~QuietVtk() {
    std::cerr.rdbuf(mCerr);
    std::cout.rdbuf(mCout);
    vtkOutputWindow::GetInstance()->SetDisplayMode(mMode);
    vtkLogger::SetStderrVerbosity(mVerbosity);
  }
  QuietVtk(const QuietVtk&) = delete;
  QuietVtk& operator=(const QuietVtk&) = delete;

 private:
  std::ostringstream mSwallowed;  // declared first: the streams point at it until the end
  int mMode;
  vtkLogger::Verbosity mVerbosity;
  std::streambuf* mCerr;
  std::streambuf* mCout;
};

}  // namespace lucent::io
