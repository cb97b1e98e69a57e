#include "VtkTestSupport.hpp"
#include "core/Error.hpp"
#include "io/vtk/VtpWriter.hpp"
#include "particles/Lattice.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

using namespace mfwave;
using namespace mfwave::vtktest;

namespace {

// Every point is a vertex cell of its own, in order, so ParaView shows each particle.
void expectOneVertexPerPoint(vtkPolyData& data) {
  const vtkIdType n = data.GetNumberOfPoints();
  ASSERT_EQ(data.GetNumberOfVerts(), n);
  EXPECT_EQ(data.GetNumberOfCells(), n);
  vtkNew<vtkIdList> ids;
  vtkCellArray* verts = data.GetVerts();
  for (vtkIdType c = 0; c < n; ++c) {
    verts->GetCellAtId(c, ids);
    ASSERT_EQ(ids->GetNumberOfIds(), 1);
    EXPECT_EQ(ids->GetId(0), c);
  }
}

}  // namespace

TEST(VtkVtpWriter, BlockFrameRoundTripsExactly) {
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(2, 1, 1), 0.5);  // 5 x 3 x 3
  const Index n = block.size();
  ASSERT_EQ(n, 45);
  std::vector<Real> displacement, velocity, pressure, stress;
  for (Index i = 0; i < n; ++i) {
    const Real r = static_cast<Real>(i);
    displacement.insert(displacement.end(), {0.1 * r, -0.25 * r, 1e-7 * r});
    velocity.insert(velocity.end(), {r, 2 * r, 3 * r});
    pressure.push_back(1.0 / (1.0 + r));  // not exactly representable in decimal: tests binary output
    for (int k = 0; k < 6; ++k) stress.push_back(10 * r + k);
  }
  ParticleFrame<3> frame;
  frame.positions = &block.coordinates();
  frame.count = n;
  frame.time = 1.25;
  frame.fields = {ParticleField::vector("displacement", 3, displacement), ParticleField::vector("velocity", 3, velocity),
                  ParticleField::scalar("pressure", pressure), ParticleField::tensor("stress", 6, stress)};

  const fs::path dir = scratchFolder();
  const fs::path path = dir / "block.vtp";
  VtpWriter::write(frame, path.string());
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"block.vtp"});  // no temporary left

  // Raw binary appended data, zlib-compressed, 64-bit headers.
  const std::string text = slurp(path);
  const std::string header = text.substr(0, text.find("<AppendedData"));
  EXPECT_NE(header.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(header.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(header.find("format=\"appended\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"binary\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);

  const vtkSmartPointer<vtkPolyData> data = readVtp(path);
  ASSERT_EQ(data->GetNumberOfPoints(), n);
  expectOneVertexPerPoint(*data);
  for (Index i = 0; i < n; ++i) {
    double x[3];
    data->GetPoint(i, x);
    EXPECT_EQ(x[0], block.position(i)[0]);
    EXPECT_EQ(x[1], block.position(i)[1]);
    EXPECT_EQ(x[2], block.position(i)[2]);
  }

  vtkPointData* pd = data->GetPointData();
  ASSERT_EQ(pd->GetNumberOfArrays(), 4);
  EXPECT_STREQ(pd->GetArrayName(0), "displacement");
  EXPECT_STREQ(pd->GetArrayName(1), "velocity");
  EXPECT_STREQ(pd->GetArrayName(2), "pressure");
  EXPECT_STREQ(pd->GetArrayName(3), "stress");
  vtkDataArray* u = pd->GetArray("displacement");
  vtkDataArray* v = pd->GetArray("velocity");
  vtkDataArray* p = pd->GetArray("pressure");
  vtkDataArray* s = pd->GetArray("stress");
  ASSERT_TRUE(u && v && p && s);
  EXPECT_EQ(u->GetNumberOfComponents(), 3);
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  EXPECT_EQ(p->GetNumberOfComponents(), 1);
  EXPECT_EQ(s->GetNumberOfComponents(), 6);
  EXPECT_EQ(v->GetNumberOfTuples(), n);
  for (Index i = 0; i < n; ++i) {
    const Real r = static_cast<Real>(i);
    EXPECT_EQ(v->GetComponent(i, 0), r);
    EXPECT_EQ(v->GetComponent(i, 1), 2 * r);
    EXPECT_EQ(v->GetComponent(i, 2), 3 * r);
    EXPECT_EQ(u->GetComponent(i, 0), 0.1 * r);
    EXPECT_EQ(u->GetComponent(i, 1), -0.25 * r);
    EXPECT_EQ(u->GetComponent(i, 2), 1e-7 * r);
    EXPECT_EQ(p->GetComponent(i, 0), 1.0 / (1.0 + r));
    for (int k = 0; k < 6; ++k) EXPECT_EQ(s->GetComponent(i, k), 10 * r + k);
  }

  vtkDataArray* time = data->GetFieldData()->GetArray("TimeValue");
  ASSERT_NE(time, nullptr);
  ASSERT_EQ(time->GetNumberOfTuples(), 1);
  EXPECT_EQ(time->GetComponent(0, 0), 1.25);
}

TEST(VtkVtpWriter, LineFramePadsPointsAndVectors) {
  const ParticleSet<1> line = makeLine(0.0, 1.0, 0.25);  // 5 particles
  ParticleFrame<1> frame;
  frame.positions = &line.coordinates();
  frame.count = 4;  // only the first four: a frame may leave out trailing particles (ghosts)
  frame.time = -0.5;
  frame.fields = {ParticleField::scalar("pressure", {1, 2, 3, 4}),
                  ParticleField::vector("displacement", 1, {0.5, 0.25, -0.5, -1})};
  const fs::path path = scratchFolder() / "line.vtp";
  VtpWriter::write(frame, path.string());

  const vtkSmartPointer<vtkPolyData> data = readVtp(path);
  ASSERT_EQ(data->GetNumberOfPoints(), 4);
  expectOneVertexPerPoint(*data);
  const double expectedX[] = {0.0, 0.25, 0.5, 0.75};
  for (vtkIdType i = 0; i < 4; ++i) {
    double x[3];
    data->GetPoint(i, x);
    EXPECT_EQ(x[0], expectedX[i]);
    EXPECT_EQ(x[1], 0.0);
    EXPECT_EQ(x[2], 0.0);
  }
  vtkDataArray* p = data->GetPointData()->GetArray("pressure");
  vtkDataArray* u = data->GetPointData()->GetArray("displacement");
  ASSERT_TRUE(p && u);
  ASSERT_EQ(p->GetNumberOfComponents(), 1);
  ASSERT_EQ(u->GetNumberOfComponents(), 3);  // a 1-D vector padded for ParaView's glyphs
  const double expectedU[] = {0.5, 0.25, -0.5, -1};
  for (vtkIdType i = 0; i < 4; ++i) {
    EXPECT_EQ(p->GetComponent(i, 0), static_cast<double>(i + 1));
    EXPECT_EQ(u->GetComponent(i, 0), expectedU[i]);
    EXPECT_EQ(u->GetComponent(i, 1), 0.0);
    EXPECT_EQ(u->GetComponent(i, 2), 0.0);
  }
  EXPECT_EQ(data->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), -0.5);
}

TEST(VtkVtpWriter, PlaneFramePadsTwoComponentVectors) {
  const ParticleSet<2> plane = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.5);  // 3 x 3
  std::vector<Real> velocity;
  for (Index i = 0; i < 9; ++i) velocity.insert(velocity.end(), {static_cast<Real>(i), -static_cast<Real>(i)});
  ParticleFrame<2> frame{&plane.coordinates(), 9, 0.0, {ParticleField::vector("velocity", 2, velocity)}};
  const fs::path path = scratchFolder() / "plane.vtp";
  VtpWriter::write(frame, path.string());
  const vtkSmartPointer<vtkPolyData> data = readVtp(path);
  ASSERT_EQ(data->GetNumberOfPoints(), 9);
  vtkDataArray* v = data->GetPointData()->GetArray("velocity");
  ASSERT_EQ(v->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < 9; ++i) {
    double x[3];
    data->GetPoint(i, x);
    EXPECT_EQ(x[0], plane.position(i)[0]);
    EXPECT_EQ(x[1], plane.position(i)[1]);
    EXPECT_EQ(x[2], 0.0);
    EXPECT_EQ(v->GetComponent(i, 0), static_cast<double>(i));
    EXPECT_EQ(v->GetComponent(i, 1), -static_cast<double>(i));
    EXPECT_EQ(v->GetComponent(i, 2), 0.0);
  }
}

TEST(VtkVtpWriter, DataAreCompressed) {
  // 20000 particles on a line with a zero field: 1.3 MB of raw arrays that zlib squeezes hard.
  const Index n = 20000;
  Coordinates<1> x{std::vector<Real>(static_cast<std::size_t>(n))};
  for (Index i = 0; i < n; ++i) x[0][static_cast<std::size_t>(i)] = 1e-3 * static_cast<Real>(i);
  ParticleFrame<1> frame{&x, n, 0.0, {ParticleField::vector("velocity", 1, std::vector<Real>(20000, 0.0))}};
  const fs::path path = scratchFolder() / "big.vtp";
  VtpWriter::write(frame, path.string());
  // Raw: points 3 doubles, velocity 3 doubles, vertex offsets and connectivity 1 id each.
  const auto raw = static_cast<std::uintmax_t>(n) * (3 * 8 + 3 * 8 + 2 * 8);
  EXPECT_LT(fs::file_size(path), raw / 4);
  EXPECT_EQ(readVtp(path)->GetNumberOfPoints(), n);
}

TEST(VtkVtpWriter, FailuresThrowNamingThePathAndLeaveNoTemporary) {
  const fs::path dir = scratchFolder();
  const ParticleSet<1> line = makeLine(0.0, 1.0, 0.5);
  ParticleFrame<1> frame{&line.coordinates(), 3, 0.0, {ParticleField::scalar("p", {1, 2, 3})}};

  const std::string missing = (dir / "no-such-folder" / "f.vtp").string();
  try {
    VtpWriter::write(frame, missing);
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }

  frame.fields[0].values.pop_back();  // 2 values for 3 particles
  try {
    VtpWriter::write(frame, (dir / "bad.vtp").string());
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'p' holds 2 values, expected 3"), std::string::npos) << e.what();
  }
  frame.fields[0] = ParticleField::vector("v", 4, std::vector<Real>(12, 0.0));
  EXPECT_THROW(VtpWriter::write(frame, (dir / "bad.vtp").string()), Error);
  frame.count = 4;  // more than the 3 particles there are
  frame.fields.clear();
  EXPECT_THROW(VtpWriter::write(frame, (dir / "bad.vtp").string()), Error);
  EXPECT_TRUE(filesIn(dir).empty());
}
