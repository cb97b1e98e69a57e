#include "io/vtk/VtpWriter.hpp"

#include "core/Error.hpp"
#include "io/vtk/FramePolyData.hpp"

#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkXMLPolyDataWriter.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace mfwave {

template <int D>
void VtpWriter::write(const ParticleFrame<D>& frame, const std::string& path) {
  const vtkSmartPointer<vtkPolyData> polyData = makePolyData(frame);

  // Checked here because VTK would only print an error and return 0 for a missing folder.
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw Error("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");

  // The temporary keeps the .vtp extension so it is never mistaken for anything but a frame.
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid()) + ".vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(polyData);
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // blocks over 4 GiB for large clouds
  // VTK prints a failure as a page of its pipeline's state; it is reported below, with the path.
  const int shown = vtkObject::GetGlobalWarningDisplay();
  vtkObject::SetGlobalWarningDisplay(0);
  const int ok = writer->Write();
  vtkObject::SetGlobalWarningDisplay(shown);
  if (ok != 1 || writer->GetErrorCode() != 0) {
    std::remove(temporary.c_str());
    throw Error("writing VTK frame '" + path + "' failed: " +
                vtkErrorCode::GetStringFromErrorCode(static_cast<int>(writer->GetErrorCode())) +
                " (VTK error code " + std::to_string(writer->GetErrorCode()) + ")");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    throw Error("cannot rename '" + temporary + "' to '" + path + "': " + std::strerror(error));
  }
}

template void VtpWriter::write(const ParticleFrame<1>&, const std::string&);
template void VtpWriter::write(const ParticleFrame<2>&, const std::string&);
template void VtpWriter::write(const ParticleFrame<3>&, const std::string&);

}  // namespace mfwave
