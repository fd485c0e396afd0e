#include "png_io.hpp"

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <filesystem>

#include "../util/error.hpp"
#include "atomic_file.hpp"

namespace lucent::io {

void writePng(const std::string& path, const image::Image& display) {
  AtomicFile out(path);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(display.width, display.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* px = static_cast<unsigned char*>(data->GetScalarPointer());
  for (int y = 0; y < display.height; ++y)
    for (int x = 0; x < display.width; ++x) {
      const glm::vec4& p = display.at(x, display.height - 1 - y);  // VTK's rows run bottom-up
      for (int c = 0; c < 3; ++c)
        px[(std::size_t(y) * display.width + x) * 3 + c] =
            static_cast<unsigned char>(std::clamp(p[c], 0.0f, 1.0f) * 255.0f + 0.5f);
    }
  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(out.tempPath().c_str());
  writer->SetInputData(data);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(out.tempPath()))
    throw InputError("cannot write '" + path + "': the PNG writer failed; check free space and permissions");
  out.commit();
}

image::Image readPng(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError("cannot read '" + path + "': no such file; check the path");
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  if (!reader->CanReadFile(path.c_str())) throw InputError("cannot read '" + path + "': not a PNG file");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  const int comps = data->GetNumberOfScalarComponents();
  image::Image img(dims[0], dims[1]);
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      glm::vec4 p(0, 0, 0, 1);
      for (int c = 0; c < 3; ++c)
        p[c] = float(data->GetScalarComponentAsDouble(x, y, 0, comps >= 3 ? c : 0)) / 255.0f;
      img.at(x, dims[1] - 1 - y) = p;
    }
  return img;
}

}  // namespace lucent::io
