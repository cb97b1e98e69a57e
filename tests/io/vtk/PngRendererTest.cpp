#include "VtkTestSupport.hpp"
#include "core/Error.hpp"
#include "io/vtk/PngFrameRenderer.hpp"
#include "io/vtk/PngRenderer.hpp"
#include "observers/TimeLoop.hpp"
#include "particles/Lattice.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <set>

using namespace mfwave;
using namespace mfwave::vtktest;

// Rendering needs an X display (Debian's VTK aborts without one). Where there is none these
// tests skip with the reason; the CTest entry that runs them under xvfb-run sets
// MFWAVE_REQUIRE_DISPLAY=1 so a missing display there fails instead of passing as skipped.
// Under AddressSanitizer they skip too unless asked for: Mesa's llvmpipe driver leaves ~240 bytes
// per render window that LeakSanitizer reports at exit (inside libLLVM and the unloaded driver,
// the same with or without our code sharing the display), which would fail an ASan run that
// merely happens to have a display.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool addressSanitizer = true;
#else
constexpr bool addressSanitizer = false;
#endif

#define MFWAVE_NEED_DISPLAY()                                                                     \
  do {                                                                                            \
    const bool required_ = std::getenv("MFWAVE_REQUIRE_DISPLAY") != nullptr;                      \
    if (addressSanitizer && !required_)                                                           \
      GTEST_SKIP() << "GL driver leaks under LeakSanitizer; the 'render' CTest entry runs this";  \
    std::string why_;                                                                             \
    if (!PngRenderer::displayAvailable(&why_)) {                                                  \
      if (required_) FAIL() << why_;                                                              \
      GTEST_SKIP() << why_;                                                                       \
    }                                                                                             \
  } while (false)

namespace {

struct Rgb {
  int r, g, b;
  bool operator<(const Rgb& o) const { return std::tie(r, g, b) < std::tie(o.r, o.g, o.b); }
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

// A PNG read back through VTK; pixel(x, y) with y counted from the top, as one looks at it.
struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> data;  // VTK order: rows from the bottom
  Rgb pixel(int x, int y) const {
    const std::size_t i =
        (static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
        static_cast<std::size_t>(channels);
    return {data[i], data[i + 1], data[i + 2]};
  }
  // Pixels in [x0, x1) x [y0, y1) (fractions of the size, y from the top) that differ from `bg`,
  // and the distinct colours among them.
  std::pair<long, std::size_t> foreground(double x0, double x1, double y0, double y1, Rgb bg) const {
    long count = 0;
    std::set<Rgb> colours;
    for (int y = static_cast<int>(y0 * height); y < static_cast<int>(y1 * height); ++y)
      for (int x = static_cast<int>(x0 * width); x < static_cast<int>(x1 * width); ++x) {
        const Rgb p = pixel(x, y);
        if (!(p == bg)) {
          ++count;
          colours.insert(p);
        }
      }
    return {count, colours.size()};
  }
};

Image readPng(const fs::path& path) {
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Image out;
  int dims[3];
  image->GetDimensions(dims);
  out.width = dims[0];
  out.height = dims[1];
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (scalars == nullptr) return out;
  out.channels = scalars->GetNumberOfComponents();
  out.data.assign(scalars->GetPointer(0),
                  scalars->GetPointer(0) + static_cast<std::size_t>(scalars->GetNumberOfValues()));
  return out;
}

const Rgb white{255, 255, 255};

// A 6 x 6 x 6 block with velocity_z = x + y + z - 1.5 (so both signs appear).
struct BlockFrame {
  ParticleSet<3> block = makeBlock(Vec3(0, 0, 0), Vec3(1, 1, 1), 0.2);
  ParticleFrame<3> frame() const {
    std::vector<Real> v;
    for (Index i = 0; i < block.size(); ++i) {
      const Vec3 x = block.position(i);
      v.insert(v.end(), {0.0, 0.1, x.sum() - 1.5});
    }
    return {&block.coordinates(), block.size(), 1.25, {ParticleField::vector("velocity", 3, v)}};
  }
};

}  // namespace

TEST(VtkPngRenderer, BlockShowsColouredSpheresColourBarAndTitle) {
  MFWAVE_NEED_DISPLAY();
  const fs::path dir = scratchFolder();
  const BlockFrame block;
  PngOptions options;
  options.field = "velocity";
  options.component = 2;
  options.width = 640;
  options.height = 480;
  PngRenderer(options).render(block.frame(), (dir / "block.png").string());
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"block.png"});  // no temporary left

  const Image image = readPng(dir / "block.png");
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 480);
  ASSERT_GE(image.channels, 3);
  // The cloud: a good share of the picture, many shades (lit spheres), both ends of the map.
  const auto [cloudPixels, cloudColours] = image.foreground(0.0, 0.82, 0.1, 0.9, white);
  EXPECT_GT(cloudPixels, static_cast<long>(0.1 * 640 * 480)) << cloudPixels;
  EXPECT_GT(cloudColours, 100u);
  long bluish = 0, reddish = 0;
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 520; ++x) {
      const Rgb p = image.pixel(x, y);
      bluish += p.b > p.r + 60;
      reddish += p.r > p.b + 60;
    }
  EXPECT_GT(bluish, 500);
  EXPECT_GT(reddish, 500);
  // The colour bar: a tall gradient in the right-hand strip.
  const auto [barPixels, barColours] = image.foreground(0.86, 0.92, 0.2, 0.8, white);
  EXPECT_GT(barPixels, static_cast<long>(0.5 * 0.06 * 640 * 0.6 * 480)) << barPixels;
  EXPECT_GT(barColours, 30u);
  // The title: text in the top strip.
  EXPECT_GT(image.foreground(0.2, 0.8, 0.0, 0.06, white).first, 200);

  // The same frame without bar and title leaves both strips empty.
  options.colourBar = false;
  options.title = false;
  PngRenderer(options).render(block.frame(), (dir / "plain.png").string());
  const Image plain = readPng(dir / "plain.png");
  EXPECT_EQ(plain.foreground(0.86, 0.92, 0.2, 0.8, white).first, 0);
  EXPECT_EQ(plain.foreground(0.2, 0.8, 0.0, 0.06, white).first, 0);
  EXPECT_GT(plain.foreground(0.0, 1.0, 0.0, 1.0, white).first, static_cast<long>(0.1 * 640 * 480));
}

// A small picture of the scalar field `name` with nothing but the particles: no colour bar, no
// title, so pixel counts see the particles alone.
namespace {
PngOptions bareScalarPicture(const std::string& name) {
  PngOptions options;
  options.field = name;
  options.component = 0;
  options.width = 320;
  options.height = 240;
  options.colourBar = false;
  options.title = false;
  return options;
}
}  // namespace

TEST(VtkPngRenderer, PlaneSeenFromAboveWithAFixedRange) {
  MFWAVE_NEED_DISPLAY();
  // p = -1 on the left half (x < 1), +1 on the right: blue left, red right when seen from +z.
  const ParticleSet<2> plane = makeRectangle(Vec2(0, 0), Vec2(2, 1), 0.1);
  std::vector<Real> p;
  for (Index i = 0; i < plane.size(); ++i) p.push_back(plane.position(i)[0] < 0.99 ? -1.0 : 1.0);
  const ParticleFrame<2> frame{&plane.coordinates(), plane.size(), 0.0, {ParticleField::scalar("p", p)}};
  PngOptions options = bareScalarPicture("p");
  options.range = std::array<Real, 2>{-1.0, 1.0};
  const fs::path path = scratchFolder() / "plane.png";
  PngRenderer(options).render(frame, path.string());
  const Image image = readPng(path);
  ASSERT_EQ(image.width, 320);
  long leftBlue = 0, leftRed = 0, rightBlue = 0, rightRed = 0;
  for (int y = 80; y < 160; ++y)
    for (int x = 0; x < 320; ++x) {
      const Rgb c = image.pixel(x, y);
      const bool blue = c.b > c.r + 60, red = c.r > c.b + 60;
      if (x < 140) {
        leftBlue += blue;
        leftRed += red;
      } else if (x > 180) {
        rightBlue += blue;
        rightRed += red;
      }
    }
  EXPECT_GT(leftBlue, 500) << leftBlue;
  EXPECT_GT(rightRed, 500) << rightRed;
  EXPECT_EQ(leftRed, 0);
  EXPECT_EQ(rightBlue, 0);
}

// A fixed window: the camera frames the box {0..4} x {0..4}, not the particles, so a unit square
// of particles at the origin sits in the lower-left of the picture (its centre at about 25 %
// across and 83 % down) and nothing is drawn in the rest.
TEST(VtkPngRenderer, AFixedWindowFramesTheBoxNotTheParticles) {
  MFWAVE_NEED_DISPLAY();
  const ParticleSet<2> square = makeRectangle(Vec2(0, 0), Vec2(1, 1), 0.1);
  const std::vector<Real> p(static_cast<std::size_t>(square.size()), 1.0);
  const ParticleFrame<2> frame{&square.coordinates(), square.size(), 0.0, {ParticleField::scalar("p", p)}};
  PngOptions options = bareScalarPicture("p");
  options.pointSize = 4;
  options.window = std::array<Real, 6>{0, 4, 0, 4, 0, 0};
  const fs::path path = scratchFolder() / "window.png";
  PngRenderer(options).render(frame, path.string());
  const Image image = readPng(path);
  ASSERT_EQ(image.width, 320);
  EXPECT_GT(image.foreground(0.1, 0.4, 0.65, 1.0, white).first, 200);  // the square, lower left
  EXPECT_EQ(image.foreground(0.45, 1.0, 0.0, 1.0, white).first, 0);   // nothing right of it
  EXPECT_EQ(image.foreground(0.0, 1.0, 0.0, 0.6, white).first, 0);    // nor above it
  options.window.reset();  // fitted to the particles: the square spans the middle instead
  const fs::path fitted = scratchFolder() / "fitted.png";
  PngRenderer(options).render(frame, fitted.string());
  EXPECT_GT(readPng(fitted).foreground(0.6, 0.9, 0.0, 0.6, white).first, 100);
}

TEST(VtkPngRenderer, BadFieldOrComponentThrows) {
  MFWAVE_NEED_DISPLAY();
  const BlockFrame block;
  const fs::path dir = scratchFolder();
  PngOptions options;
  options.field = "stress";
  try {
    PngRenderer(options).render(block.frame(), (dir / "x.png").string());
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no field 'stress' (fields: velocity)"), std::string::npos) << e.what();
  }
  options.field = "velocity";
  options.component = 3;
  EXPECT_THROW(PngRenderer(options).render(block.frame(), (dir / "x.png").string()), Error);
  EXPECT_TRUE(filesIn(dir).empty());
  options.component = PngOptions::magnitude;
  options.range = std::array<Real, 2>{1.0, 1.0};
  EXPECT_THROW(PngRenderer{options}, Error);
}

TEST(VtkPngRenderer, FrameRendererRendersEveryNthObservedState) {
  MFWAVE_NEED_DISPLAY();
  const ParticleSet<1> line = makeLine(0.0, 1.0, 0.05);
  const Index n = line.size();
  ScriptIntegrator integrator(Vector::Zero(n), Vector::Zero(n), 0.1, [](long step, Vector& u, Vector& v) {
    for (Index k = 0; k < u.size(); ++k) {
      u[k] = std::sin(0.3 * static_cast<Real>(k + step));
      v[k] = std::cos(0.3 * static_cast<Real>(k + step));
    }
  });
  PngOptions options;
  options.width = 200;
  options.height = 120;
  options.component = 0;
  const fs::path folder = scratchFolder() / "pictures";
  PngFrameRenderer<1> renderer(line, folder.string(), "line", 1, options, 2);
  TimeLoop loop;
  loop.add(renderer, 1);
  loop.run(integrator, 0.5);  // observed states 0..5: pictures of 0, 2, 4
  EXPECT_EQ(renderer.framesRendered(), 3);
  EXPECT_EQ(renderer.skippedReason(), "");
  EXPECT_EQ(filesIn(folder), (std::vector<std::string>{"line_000000.png", "line_000002.png", "line_000004.png"}));
  const Image image = readPng(folder / "line_000004.png");
  EXPECT_EQ(image.width, 200);
  EXPECT_EQ(image.height, 120);
  EXPECT_GT(image.foreground(0.0, 1.0, 0.0, 1.0, white).second, 10u);
}

// Runs everywhere (no display needed): the checks must not touch VTK rendering, which would
// abort the process here.
TEST(VtkDisplay, WithoutDisplayNothingRendersAndTheReasonIsKept) {
  const ScopedEnvironment noDisplay("DISPLAY", std::nullopt);
  std::string why;
  EXPECT_FALSE(PngRenderer::displayAvailable(&why));
  EXPECT_NE(why.find("no DISPLAY set"), std::string::npos) << why;
  EXPECT_NE(why.find("xvfb-run"), std::string::npos) << why;

  const fs::path dir = scratchFolder();
  const BlockFrame block;
  const std::string path = (dir / "never.png").string();
  try {
    PngRenderer().render(block.frame(), path);
    FAIL() << "expected Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("xvfb-run"), std::string::npos) << e.what();
  }

  PngFrameRenderer<3> renderer(block.block, dir.string(), "block", 3);
  const Vector u = Vector::Zero(3 * block.block.size()), v = Vector::Ones(3 * block.block.size());
  for (long step = 0; step < 3; ++step) renderer.observe(StateView{step, 0.1 * static_cast<Real>(step), u, v});
  EXPECT_EQ(renderer.framesRendered(), 0);
  EXPECT_NE(renderer.skippedReason().find("xvfb-run"), std::string::npos) << renderer.skippedReason();
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST(VtkDisplay, UnreachableDisplayIsNamed) {
  const ScopedEnvironment badDisplay("DISPLAY", std::string(":987654"));
  std::string why;
  EXPECT_FALSE(PngRenderer::displayAvailable(&why));
  EXPECT_NE(why.find("cannot open display :987654"), std::string::npos) << why;
}
