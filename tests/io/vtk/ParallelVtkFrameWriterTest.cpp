// Parallel VTK output emulated in one process: one ParallelVtkFrameWriter per rank, each shown
// only its owned part of a state, checked against the serial VtkFrameWriter's frames of the
// whole state by reading the .pvtp back with VTK's own parallel reader.

#include "VtkTestSupport.hpp"
#include "core/Error.hpp"
#include "io/vtk/ParallelVtkFrameWriter.hpp"
#include "io/vtk/PvtpWriter.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "io/vtk/VtpWriter.hpp"
#include "particles/Lattice.hpp"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPPolyDataReader.h>

#include <array>
#include <map>
#include <memory>

using namespace mfwave;
using namespace mfwave::vtktest;

namespace {

// A whole-domain state whose every value is known: u_dof = step * (dof + 1) + 0.25,
// v_dof = -dof * step / 2.
void globalState(Index n, int components, long step, Vector& u, Vector& v) {
  u.resize(n * components);
  v.resize(n * components);
  for (Index k = 0; k < u.size(); ++k) {
    u[k] = static_cast<Real>(step) * static_cast<Real>(k + 1) + 0.25;
    v[k] = -0.5 * static_cast<Real>(k) * static_cast<Real>(step);
  }
}

// The part of a whole-domain vector a rank holds: node k is particle owned[k].
Vector localPart(const Vector& global, const std::vector<Index>& owned, int components) {
  Vector local(static_cast<Index>(owned.size()) * components);
  for (std::size_t k = 0; k < owned.size(); ++k)
    for (int c = 0; c < components; ++c)
      local[static_cast<Index>(k) * components + c] = global[owned[k] * components + c];
  return local;
}

// A method field computed from the state it is given: the squared speed of each node.
void speedSquared(const StateView& state, Index count, std::vector<ParticleField>& fields) {
  const Index c = state.velocity.size() / std::max<Index>(count, 1);
  std::vector<Real> values(static_cast<std::size_t>(count), 0.0);
  for (Index p = 0; p < count; ++p)
    for (Index j = 0; j < c; ++j)
      values[static_cast<std::size_t>(p)] += state.velocity[p * c + j] * state.velocity[p * c + j];
  fields.push_back(ParticleField::scalar("speed2", std::move(values)));
}

vtkSmartPointer<vtkPolyData> readPvtp(const fs::path& path) {
  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
  return data;
}

using Point = std::array<double, 3>;

std::map<Point, vtkIdType> pointsByCoordinates(vtkPolyData& data) {
  std::map<Point, vtkIdType> points;
  for (vtkIdType p = 0; p < data.GetNumberOfPoints(); ++p) {
    Point x{};
    data.GetPoint(p, x.data());
    EXPECT_TRUE(points.emplace(x, p).second) << "point " << p << " appears twice";
  }
  return points;
}

std::vector<std::string> arrayNames(vtkPolyData& data) {
  std::vector<std::string> names;
  for (int a = 0; a < data.GetPointData()->GetNumberOfArrays(); ++a)
    names.emplace_back(data.GetPointData()->GetArrayName(a));
  return names;
}

// Writes frames at steps 0 and 3 (times 0 and 0.75) serially and split over the ranks of
// `split` (one owned list per rank), then checks the parallel output against the serial one.
template <int D>
void checkSplit(const ParticleSet<D>& particles, const std::vector<std::vector<Index>>& split, int components) {
  const fs::path root = scratchFolder();
  const Index n = particles.physicalCount();
  const int ranks = static_cast<int>(split.size());
  VtkFrameWriter<D> serial(particles, (root / "serial").string(), "wave", components, speedSquared);
  std::vector<std::unique_ptr<ParallelVtkFrameWriter<D>>> writers;
  for (int r = 0; r < ranks; ++r)
    writers.push_back(std::make_unique<ParallelVtkFrameWriter<D>>(
        particles, split[static_cast<std::size_t>(r)], (root / "parallel").string(), "wave", components, r, ranks,
        speedSquared));

  const long steps[] = {0, 3};
  for (const long step : steps) {
    Vector u, v;
    globalState(n, components, step, u, v);
    const Real time = 0.25 * static_cast<Real>(step);
    serial.observe(StateView{step, time, u, v});
    for (int r = 0; r < ranks; ++r) {
      const std::vector<Index>& owned = split[static_cast<std::size_t>(r)];
      const Vector ul = localPart(u, owned, components), vl = localPart(v, owned, components);
      writers[static_cast<std::size_t>(r)]->observe(StateView{step, time, ul, vl});
    }
  }

  std::vector<std::string> expectedFiles{"wave.pvd"};
  for (const char* frame : {"wave_000000", "wave_000001"}) {
    expectedFiles.push_back(std::string(frame) + ".pvtp");
    for (int r = 0; r < ranks; ++r) expectedFiles.push_back(std::string(frame) + "_" + std::to_string(r) + ".vtp");
  }
  std::sort(expectedFiles.begin(), expectedFiles.end());
  EXPECT_EQ(filesIn(root / "parallel"), expectedFiles);

  const std::string pvd = slurp(root / "parallel" / "wave.pvd");
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"wave_000000.pvtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.75\" group=\"\" part=\"0\" file=\"wave_000001.pvtp\""), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find(".vtp"), std::string::npos) << pvd;

  for (int f = 0; f < 2; ++f) {
    const std::string frame = "wave_00000" + std::to_string(f);
    const vtkSmartPointer<vtkPolyData> whole = readVtp(root / "serial" / (frame + ".vtp"));
    const vtkSmartPointer<vtkPolyData> merged = readPvtp(root / "parallel" / (frame + ".pvtp"));
    ASSERT_EQ(whole->GetNumberOfPoints(), n);
    ASSERT_EQ(merged->GetNumberOfPoints(), n) << frame;
    EXPECT_EQ(merged->GetNumberOfVerts(), n) << frame;
    const std::vector<std::string> names = arrayNames(*whole);
    EXPECT_EQ(names, (std::vector<std::string>{"displacement", "velocity", "speed2"}));
    EXPECT_EQ(arrayNames(*merged), names) << frame;

    const std::map<Point, vtkIdType> serialPoints = pointsByCoordinates(*whole);
    const std::map<Point, vtkIdType> parallelPoints = pointsByCoordinates(*merged);
    ASSERT_EQ(parallelPoints.size(), serialPoints.size());
    for (const auto& [x, p] : serialPoints) {
      const auto found = parallelPoints.find(x);
      ASSERT_NE(found, parallelPoints.end()) << "point (" << x[0] << ", " << x[1] << ", " << x[2] << ") missing";
      for (const std::string& name : names) {
        vtkDataArray* expected = whole->GetPointData()->GetArray(name.c_str());
        vtkDataArray* actual = merged->GetPointData()->GetArray(name.c_str());
        ASSERT_EQ(actual->GetNumberOfComponents(), expected->GetNumberOfComponents()) << name;
        for (int c = 0; c < expected->GetNumberOfComponents(); ++c)
          EXPECT_EQ(actual->GetComponent(found->second, c), expected->GetComponent(p, c))
              << frame << " " << name << "[" << c << "] at serial point " << p;
      }
    }
    // Not a tautology of the comparison above: the serial values themselves are the scripted ones.
    vtkDataArray* u = whole->GetPointData()->GetArray("displacement");
    const auto lastDof = static_cast<double>((n - 1) * components);
    EXPECT_EQ(u->GetComponent(n - 1, 0), static_cast<double>(3 * f) * (lastDof + 1) + 0.25);
  }
}

}  // namespace

TEST(ParallelVtkFrameWriter, ThreeRanksOf2DElasticityMatchTheSerialFrames) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 0.5), 0.25);  // 5 x 3
  ASSERT_EQ(particles.physicalCount(), 15);
  // Interleaved and out of order: rank r owns the particles i with i % 3 == r, rank 1 backwards.
  std::vector<std::vector<Index>> split(3);
  for (Index i = 0; i < 15; ++i) split[static_cast<std::size_t>(i % 3)].push_back(i);
  std::reverse(split[1].begin(), split[1].end());
  checkSplit(particles, split, 2);
}

TEST(ParallelVtkFrameWriter, ThreeUnequalRanksOf3DScalarAndElasticStatesMatchTheSerialFrames) {
  const ParticleSet<3> particles = makeBlock(Vec3(0, 0, 0), Vec3(1, 1, 1), 0.5);  // 3 x 3 x 3
  ASSERT_EQ(particles.physicalCount(), 27);
  const std::vector<std::vector<Index>> split{
      {26, 0, 13, 5, 7},
      {1, 2, 3, 4, 6, 8, 9, 10, 11, 12, 14, 15},
      {25, 24, 23, 22, 21, 20, 19, 18, 17, 16}};
  checkSplit(particles, split, 3);
  checkSplit(particles, split, 1);
}

TEST(ParallelVtkFrameWriter, MasterListsEveryPieceInRankOrderRelativeToItsFolder) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);  // 4 corners
  const fs::path folder = scratchFolder() / "out";
  ParallelVtkFrameWriter<2> writer(particles, {3, 1}, folder.string(), "w", 2, 0, 4);
  const Vector u = Vector::Zero(4), v = Vector::Zero(4);
  writer.observe(StateView{0, 0.0, u, v});
  EXPECT_EQ(writer.masterPath(0), (folder / "w_000000.pvtp").string());
  EXPECT_EQ(writer.piecePath(7, 3), (folder / "w_000007_3.vtp").string());
  const std::string master = slurp(folder / "w_000000.pvtp");
  const std::string header =
      "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">";
  EXPECT_NE(master.find(header), std::string::npos) << master;
  EXPECT_NE(master.find("<PDataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\"/>"),
            std::string::npos)
      << master;
  const std::size_t first = master.find("<Piece Source=\"w_000000_0.vtp\"/>");
  const std::size_t last = master.find("<Piece Source=\"w_000000_3.vtp\"/>");
  ASSERT_NE(first, std::string::npos) << master;
  ASSERT_NE(last, std::string::npos) << master;
  EXPECT_LT(first, master.find("w_000000_1.vtp"));
  EXPECT_LT(master.find("w_000000_2.vtp"), last);
  // The piece holds the owned particles in the owned order.
  const vtkSmartPointer<vtkPolyData> piece = readVtp(writer.piecePath(0, 0));
  ASSERT_EQ(piece->GetNumberOfPoints(), 2);
  double x[3];
  piece->GetPoint(0, x);
  EXPECT_EQ(x[0], particles.position(3)[0]);
  EXPECT_EQ(x[1], particles.position(3)[1]);
  piece->GetPoint(1, x);
  EXPECT_EQ(x[0], particles.position(1)[0]);
  EXPECT_EQ(x[1], particles.position(1)[1]);
}

TEST(ParallelVtkFrameWriter, OtherRanksWriteOnlyTheirPieces) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);
  const fs::path folder = scratchFolder();
  ParallelVtkFrameWriter<2> one(particles, {0, 1}, folder.string(), "w", 1, 1, 3);
  ParallelVtkFrameWriter<2> two(particles, {2, 3}, folder.string(), "w", 1, 2, 3);
  const Vector u = Vector::Ones(2), v = Vector::Zero(2);
  one.observe(StateView{0, 0.0, u, v});
  two.observe(StateView{0, 0.0, u, v});
  two.observe(StateView{1, 0.5, u, v});
  EXPECT_EQ(filesIn(folder), (std::vector<std::string>{"w_000000_1.vtp", "w_000000_2.vtp", "w_000001_2.vtp"}));
  EXPECT_EQ(two.framesWritten(), 2);
}

TEST(ParallelVtkFrameWriter, ARankOwningNothingWritesAnEmptyPiece) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);  // 4 particles
  const fs::path folder = scratchFolder();
  ParallelVtkFrameWriter<2> full(particles, {0, 1, 2, 3}, folder.string(), "w", 1, 0, 2);
  ParallelVtkFrameWriter<2> none(particles, {}, folder.string(), "w", 1, 1, 2);
  const Vector u = Vector::LinSpaced(4, 1.0, 4.0), v = Vector::Zero(4), empty;
  full.observe(StateView{0, 0.0, u, v});
  none.observe(StateView{0, 0.0, empty, empty});
  EXPECT_EQ(readVtp(none.piecePath(0, 1))->GetNumberOfPoints(), 0);
  const vtkSmartPointer<vtkPolyData> merged = readPvtp(folder / "w_000000.pvtp");
  ASSERT_EQ(merged->GetNumberOfPoints(), 4);
  vtkDataArray* displacement = merged->GetPointData()->GetArray("displacement");
  ASSERT_NE(displacement, nullptr);
  EXPECT_EQ(displacement->GetComponent(3, 0), 4.0);
}

TEST(ParallelVtkFrameWriter, RestoredWritersNumberOnAndKeepTheEarlierFramesInTheCollection) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);
  const fs::path folder = scratchFolder();
  const std::vector<std::vector<Index>> split{{0, 2}, {3, 1}};
  const Vector u = Vector::Ones(2), v = Vector::Zero(2);
  std::vector<StateArchive> archives(2);
  for (int r = 0; r < 2; ++r) {
    ParallelVtkFrameWriter<2> writer(particles, split[static_cast<std::size_t>(r)], folder.string(), "w", 1, r, 2);
    writer.observe(StateView{0, 0.0, u, v});
    writer.observe(StateView{4, 0.5, u, v});
    writer.saveState(archives[static_cast<std::size_t>(r)]);
  }
  fs::remove(folder / "w.pvd");  // a restarted run rewrites it whole
  for (int r = 0; r < 2; ++r) {
    ParallelVtkFrameWriter<2> writer(particles, split[static_cast<std::size_t>(r)], folder.string(), "w", 1, r, 2);
    writer.restoreState(archives[static_cast<std::size_t>(r)]);
    EXPECT_EQ(writer.framesWritten(), 2);
    writer.observe(StateView{8, 1.0, u, v});
    EXPECT_EQ(writer.framesWritten(), 3);
  }
  EXPECT_TRUE(fs::exists(folder / "w_000002_1.vtp"));
  const std::string pvd = slurp(folder / "w.pvd");
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"w_000000.pvtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.5\" group=\"\" part=\"0\" file=\"w_000001.pvtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"1\" group=\"\" part=\"0\" file=\"w_000002.pvtp\""), std::string::npos) << pvd;
  EXPECT_EQ(readPvtp(folder / "w_000002.pvtp")->GetNumberOfPoints(), 4);
}

namespace {

// The message of the InputError `make` throws, with its key.
template <typename Make>
std::string inputErrorOf(Make make, std::string& key) {
  try {
    make();
  } catch (const InputError& e) {
    key = e.key();
    return e.what();
  }
  return "(nothing thrown)";
}

}  // namespace

TEST(ParallelVtkFrameWriter, BadSplitsThrowNamingTheProblem) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);  // 4 particles
  const std::string folder = scratchFolder().string();
  using Writer = ParallelVtkFrameWriter<2>;
  std::string key;

  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {0}, folder, "w", 2, 0, 0); }, key),
            "rankCount: must be at least 1, got 0");
  EXPECT_EQ(key, "rankCount");
  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {0}, folder, "w", 2, 3, 3); }, key), "rank: 3 is outside [0, 3)");
  EXPECT_EQ(key, "rank");
  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {0}, folder, "w", 2, -1, 3); }, key), "rank: -1 is outside [0, 3)");
  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {0, 4}, folder, "w", 2, 0, 1); }, key),
            "owned: entry 1 is particle 4, outside the 4 particles");
  EXPECT_EQ(key, "owned");
  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {-2}, folder, "w", 2, 0, 1); }, key),
            "owned: entry 0 is particle -2, outside the 4 particles");
  EXPECT_EQ(inputErrorOf([&] { Writer(particles, {2, 0, 2}, folder, "w", 2, 0, 1); }, key),
            "owned: particle 2 is listed twice (entries 0 and 2)");
  EXPECT_THROW(Writer(particles, {0}, folder, "", 2, 0, 1), Error);
  EXPECT_THROW(Writer(particles, {0}, folder, "w", 0, 0, 1), Error);

  // A state that is not the owned particles' throws and writes nothing.
  Writer writer(particles, {0, 1}, folder, "w", 2, 0, 1);
  const Vector u = Vector::Zero(8), v = Vector::Zero(8);
  try {
    writer.observe(StateView{0, 0.0, u, v});
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("state of size 8 does not fit 2 owned particles x 2 components"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(writer.framesWritten(), 0);
  EXPECT_TRUE(filesIn(folder).empty());
}

TEST(VtkPvtpWriter, RefusesNoPiecesAndBadFields) {
  const fs::path path = scratchFolder() / "m.pvtp";
  const std::vector<ParticleField> fields{ParticleField::vector("u", 2, {})};
  EXPECT_THROW(PvtpWriter::write(fields, {}, path.string()), Error);
  EXPECT_THROW(PvtpWriter::write({ParticleField::scalar("a", {}), ParticleField::scalar("a", {})}, {"p.vtp"},
                                 path.string()),
               Error);
  EXPECT_FALSE(fs::exists(path));
  // Tensors keep their components; the field's values do not matter to the master.
  PvtpWriter::write({ParticleField::tensor("stress", 6, {1, 2, 3, 4, 5, 6})}, {"p.vtp"}, path.string());
  EXPECT_NE(slurp(path).find("Name=\"stress\" NumberOfComponents=\"6\""), std::string::npos);
}

TEST(VtkParticleFrame, IndexListsAreChecked) {
  const ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 1), 1.0);  // 4 particles
  ParticleFrame<2> frame;
  frame.positions = &particles.coordinates();
  const std::vector<Index> outside{1, 4};
  frame.indices = &outside;
  frame.count = 2;
  EXPECT_THROW(checkFrame(frame), Error);
  const std::vector<Index> negative{-1};
  frame.indices = &negative;
  frame.count = 1;
  EXPECT_THROW(checkFrame(frame), Error);
  const std::vector<Index> fine{3, 0};
  frame.indices = &fine;
  EXPECT_THROW(checkFrame(frame), Error);  // count 1 for 2 indices
  frame.count = 2;
  EXPECT_NO_THROW(checkFrame(frame));
}
