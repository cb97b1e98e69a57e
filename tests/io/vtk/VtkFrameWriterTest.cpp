#include "VtkTestSupport.hpp"
#include "core/Error.hpp"
#include "io/vtk/VtkFrameWriter.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/Lattice.hpp"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

using namespace mfwave;
using namespace mfwave::vtktest;

namespace {

// u_dof = step * (dof + 1), v_dof = -dof * step / 2: every frame's values are known exactly.
void script(long step, Vector& u, Vector& v) {
  for (Index k = 0; k < u.size(); ++k) {
    u[k] = static_cast<Real>(step) * static_cast<Real>(k + 1);
    v[k] = -0.5 * static_cast<Real>(k) * static_cast<Real>(step);
  }
}

}  // namespace

TEST(VtkFrameWriter, TimeLoopWritesEveryFrameAndTheCollection) {
  // 3 x 2 physical particles in 2-D, then two ghosts that carry no unknowns and are not written.
  ParticleSet<2> particles = makeRectangle(Vec2(0, 0), Vec2(1, 0.5), 0.5);
  ASSERT_EQ(particles.size(), 6);
  particles.add(Vec2(-0.5, 0), 0.25, ParticleKind::Ghost);
  particles.add(Vec2(1.5, 0), 0.25, ParticleKind::Ghost);
  const Index n = particles.physicalCount();
  const int components = 2;

  const fs::path folder = scratchFolder() / "nested" / "out";  // created by the writer
  ScriptIntegrator integrator(Vector::Zero(n * components), Vector::Zero(n * components), 0.25, script);
  VtkFrameWriter<2> writer(particles, folder.string(), "wave", components,
                           [](const StateView& state, Index count, std::vector<ParticleField>& fields) {
                             std::vector<Real> step(static_cast<std::size_t>(count), static_cast<Real>(state.step));
                             fields.push_back(ParticleField::scalar("step", std::move(step)));
                           });
  EXPECT_TRUE(fs::is_directory(folder));
  TimeLoop loop;
  loop.add(writer, 2);
  loop.run(integrator, 1.25);  // 5 steps: frames at steps 0, 2, 4 and the last, 5

  ASSERT_EQ(writer.framesWritten(), 4);
  EXPECT_EQ(filesIn(folder), (std::vector<std::string>{"wave.pvd", "wave_000000.vtp", "wave_000001.vtp",
                                                       "wave_000002.vtp", "wave_000003.vtp"}));
  EXPECT_EQ(writer.pvdPath(), (folder / "wave.pvd").string());
  EXPECT_EQ(writer.lastFramePath(), (folder / "wave_000003.vtp").string());

  const std::string pvd = slurp(folder / "wave.pvd");
  const long steps[] = {0, 2, 4, 5};
  for (int f = 0; f < 4; ++f) {
    EXPECT_NE(pvd.find("file=\"wave_00000" + std::to_string(f) + ".vtp\""), std::string::npos) << pvd;
  }
  EXPECT_NE(pvd.find("timestep=\"1.25\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos) << pvd;

  for (int f = 0; f < 4; ++f) {
    const vtkSmartPointer<vtkPolyData> data = readVtp(folder / ("wave_00000" + std::to_string(f) + ".vtp"));
    ASSERT_EQ(data->GetNumberOfPoints(), n);
    EXPECT_EQ(data->GetNumberOfVerts(), n);
    EXPECT_EQ(data->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), 0.25 * static_cast<double>(steps[f]));
    vtkDataArray* u = data->GetPointData()->GetArray("displacement");
    vtkDataArray* v = data->GetPointData()->GetArray("velocity");
    vtkDataArray* s = data->GetPointData()->GetArray("step");
    ASSERT_TRUE(u && v && s);
    ASSERT_EQ(u->GetNumberOfComponents(), 3);
    ASSERT_EQ(s->GetNumberOfComponents(), 1);
    const auto step = static_cast<Real>(steps[f]);
    for (Index p = 0; p < n; ++p) {
      for (int c = 0; c < components; ++c) {
        const auto dof = static_cast<Real>(p * components + c);
        EXPECT_EQ(u->GetComponent(p, c), step * (dof + 1));
        EXPECT_EQ(v->GetComponent(p, c), -0.5 * dof * step);
      }
      EXPECT_EQ(u->GetComponent(p, 2), 0.0);
      EXPECT_EQ(s->GetComponent(p, 0), step);
      double x[3];
      data->GetPoint(p, x);
      EXPECT_EQ(x[0], particles.position(p)[0]);
      EXPECT_EQ(x[1], particles.position(p)[1]);
    }
  }
}

TEST(VtkFrameWriter, ScalarStateOnABlockIsAScalarField) {
  const ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(1, 1, 1), 1.0);  // 8 corners
  VtkFrameWriter<3> writer(block, scratchFolder().string(), "p", 1);
  Vector u = Vector::LinSpaced(8, 0.0, 7.0), v = Vector::Constant(8, 2.0);
  writer.observe(StateView{3, 0.75, u, v});
  const vtkSmartPointer<vtkPolyData> data = readVtp(writer.lastFramePath());
  vtkDataArray* displacement = data->GetPointData()->GetArray("displacement");
  ASSERT_NE(displacement, nullptr);
  ASSERT_EQ(displacement->GetNumberOfComponents(), 1);
  for (vtkIdType p = 0; p < 8; ++p) EXPECT_EQ(displacement->GetComponent(p, 0), static_cast<double>(p));
  EXPECT_EQ(data->GetPointData()->GetArray("velocity")->GetComponent(5, 0), 2.0);
}

TEST(VtkFrameWriter, StateOfTheWrongSizeThrows) {
  const ParticleSet<1> line = makeLine(0.0, 1.0, 0.5);  // 3 particles
  VtkFrameWriter<1> writer(line, scratchFolder().string(), "line", 1);
  const Vector u = Vector::Zero(4), v = Vector::Zero(4);
  try {
    writer.observe(StateView{0, 0.0, u, v});
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("state of size 4"), std::string::npos) << e.what();
  }
  EXPECT_EQ(writer.framesWritten(), 0);
  EXPECT_THROW(VtkFrameWriter<1>(line, scratchFolder().string(), "", 1), Error);
  EXPECT_THROW(VtkFrameWriter<1>(line, scratchFolder().string(), "x", 0), Error);
}
