#include "VtkTestSupport.hpp"
#include "io/vtk/PvdCollection.hpp"
#include "io/vtk/VtpWriter.hpp"
#include "particles/Lattice.hpp"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

using namespace mfwave;
using namespace mfwave::vtktest;

namespace {

struct PvdEntry {
  double time;
  std::string file;
};

// Parses the .pvd as XML (failing the test if it is not) and returns its DataSet entries.
std::vector<PvdEntry> readPvd(const fs::path& path) {
  vtkNew<vtkXMLDataParser> parser;
  const std::string name = path.string();
  parser->SetFileName(name.c_str());
  EXPECT_EQ(parser->Parse(), 1) << "not valid XML: " << name;
  vtkXMLDataElement* root = parser->GetRootElement();
  std::vector<PvdEntry> entries;
  if (root == nullptr) return entries;
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  EXPECT_NE(collection, nullptr);
  if (collection == nullptr) return entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* dataSet = collection->GetNestedElement(i);
    EXPECT_STREQ(dataSet->GetName(), "DataSet");
    double t = 0;
    EXPECT_EQ(dataSet->GetScalarAttribute("timestep", t), 1);
    const char* file = dataSet->GetAttribute("file");
    entries.push_back({t, file != nullptr ? file : ""});
  }
  return entries;
}

}  // namespace

TEST(VtkPvdCollection, ListsEveryFrameWithRelativeNamesAfterEachAdd) {
  const fs::path dir = scratchFolder();
  const ParticleSet<2> plane = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.5);
  PvdCollection collection((dir / "series.pvd").string());
  EXPECT_FALSE(fs::exists(dir / "series.pvd"));  // nothing written before the first frame

  const double times[] = {0.0, 0.1, 1.0 / 3.0};
  for (int f = 0; f < 3; ++f) {
    std::vector<Real> p(9, static_cast<Real>(f));
    ParticleFrame<2> frame{&plane.coordinates(), 9, times[f], {ParticleField::scalar("p", p)}};
    const fs::path file = dir / ("series_" + std::to_string(f) + ".vtp");
    VtpWriter::write(frame, file.string());
    collection.add(times[f], file.string());

    // After every frame the .pvd is complete and lists exactly the frames so far.
    const std::vector<PvdEntry> entries = readPvd(dir / "series.pvd");
    ASSERT_EQ(entries.size(), static_cast<std::size_t>(f + 1));
    EXPECT_EQ(entries.back().file, "series_" + std::to_string(f) + ".vtp");
  }

  const std::vector<PvdEntry> entries = readPvd(dir / "series.pvd");
  ASSERT_EQ(entries.size(), 3u);
  for (int f = 0; f < 3; ++f) {
    EXPECT_EQ(entries[static_cast<std::size_t>(f)].time, times[f]);  // written with 17 digits: exact
    // Each listed file opens, relative to the .pvd's folder, and holds the frame of that time.
    vtkNew<vtkXMLPolyDataReader> reader;
    const std::string file = (dir / entries[static_cast<std::size_t>(f)].file).string();
    reader->SetFileName(file.c_str());
    reader->Update();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 9);
  }
  EXPECT_EQ(collection.entries().size(), 3u);
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"series.pvd", "series_0.vtp", "series_1.vtp", "series_2.vtp"}));
}

TEST(VtkPvdCollection, NamesAreRelativeToThePvdFolderAndEscaped) {
  const fs::path dir = scratchFolder();
  PvdCollection collection((dir / "out" / "run.pvd").string());
  fs::create_directories(dir / "out" / "frames");
  collection.add(0.5, (dir / "out" / "frames" / "a&b.vtp").string());
  collection.add(1.5, (dir / "out" / "." / "c.vtp").string());
  const std::string text = slurp(dir / "out" / "run.pvd");
  EXPECT_NE(text.find("file=\"frames/a&amp;b.vtp\""), std::string::npos) << text;
  const std::vector<PvdEntry> entries = readPvd(dir / "out" / "run.pvd");
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].file, "frames/a&b.vtp");
  EXPECT_EQ(entries[1].file, "c.vtp");
  EXPECT_EQ(entries[1].time, 1.5);
  EXPECT_EQ(filesIn(dir / "out"), (std::vector<std::string>{"frames", "run.pvd"}));  // no temporary
}
