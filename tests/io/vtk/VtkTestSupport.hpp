#pragma once
// Shared by the lib/io/vtk tests: scratch folders, reading files back, a scripted integrator and
// a scoped change of an environment variable.

#include "support/ScriptedIntegrator.hpp"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace mfwave::vtktest {

namespace fs = std::filesystem;

// The folder of this test process under the system temporary folder; removed when the process
// ends unless MFWAVE_KEEP_TEST_OUTPUT is set (to look at the pictures).
inline const fs::path& scratchRoot() {
  struct Root {
    fs::path path = fs::temp_directory_path() / ("mfwave-vtk-" + std::to_string(::getpid()));
    ~Root() {
      std::error_code ignored;
      if (std::getenv("MFWAVE_KEEP_TEST_OUTPUT") == nullptr) fs::remove_all(path, ignored);
    }
  };
  static const Root root;
  return root.path;
}

// An empty folder for the current test, named after it.
inline fs::path scratchFolder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = scratchRoot() / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Names of the files in `dir` (not recursive), sorted.
inline std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A .vtp file read back with VTK's own reader.
inline vtkSmartPointer<vtkPolyData> readVtp(const fs::path& path) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
  return data;
}

using ScriptIntegrator = mfwave::testing::ScriptedIntegrator;

// Sets (or, with nullopt, unsets) an environment variable for the life of the object.
class ScopedEnvironment {
 public:
  ScopedEnvironment(std::string name, const std::optional<std::string>& value) : name_(std::move(name)) {
    if (const char* old = std::getenv(name_.c_str())) old_ = old;
    if (value)
      ::setenv(name_.c_str(), value->c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }
  ~ScopedEnvironment() {
    if (old_)
      ::setenv(name_.c_str(), old_->c_str(), 1);
    else
      ::unsetenv(name_.c_str());
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace mfwave::vtktest
