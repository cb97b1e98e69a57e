#include "io/vtk/PngRenderer.hpp"

#include "core/Error.hpp"
#include "io/vtk/DisplayCheck.hpp"
#include "io/vtk/FramePolyData.hpp"

// This translation unit creates the render window: the target's vtk_module_autoinit definitions
// apply here and register the OpenGL2 (and FreeType, interaction) factory overrides in its static
// initialisers, which every executable calling render() links in.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace mfwave {

namespace {

// The values that colour the particles: one component, or the Euclidean norm over all of them.
std::vector<Real> colourValues(const ParticleField& field, int component, Index count) {
  const auto n = static_cast<std::size_t>(count);
  const auto c = static_cast<std::size_t>(field.components);
  std::vector<Real> values(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (component == PngOptions::magnitude) {
      Real sum = 0;
      for (std::size_t k = 0; k < c; ++k) sum += field.values[p * c + k] * field.values[p * c + k];
      values[p] = std::sqrt(sum);
    } else {
      values[p] = field.values[p * c + static_cast<std::size_t>(component)];
    }
  }
  return values;
}

std::array<Real, 2> autoRange(const std::vector<Real>& values) {
  Real lo = 0, hi = 0;
  bool any = false;
  for (const Real v : values) {
    if (!std::isfinite(v)) continue;
    lo = any ? std::min(lo, v) : v;
    hi = any ? std::max(hi, v) : v;
    any = true;
  }
  // A constant field (the zero velocity of the initial state) still needs a range to map.
  if (!(hi > lo)) {
    const Real pad = lo != 0 ? 0.01 * std::abs(lo) : 1.0;
    lo -= pad;
    hi += pad;
  }
  return {lo, hi};
}

// "t = 1.250", "t = 2.500e-06": four significant digits, trailing zeros kept so a series of
// titles does not jitter.
std::string timeText(Real t) {
  char text[64];
  std::snprintf(text, sizeof text, "t = %#.4g", t);
  return text;
}

// Sphere diameter in pixels when none is given: a fraction of the mean particle spacing as it
// appears at the focal point (0.6 in 3-D, so the inside of the cloud shows between the spheres
// in front; 0.8 for a flat cloud, which then reads as a field). The spacing is estimated from the
// extent of the cloud along its occupied axes and the particle count.
double automaticPointSize(const double bounds[6], Index count, int dimension, vtkCamera& camera, int height) {
  double largest = 0;
  for (int a = 0; a < 3; ++a) largest = std::max(largest, bounds[2 * a + 1] - bounds[2 * a]);
  int axes = 0;
  double measure = 1;
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds[2 * a + 1] - bounds[2 * a];
    if (extent > 1e-9 * largest) {
      ++axes;
      measure *= extent;
    }
  }
  if (axes == 0 || count < 2) return 10.0;
  const double spacing = std::pow(measure / static_cast<double>(count), 1.0 / axes);
  const double halfHeight = camera.GetParallelProjection() != 0
                                ? camera.GetParallelScale()
                                : camera.GetDistance() * std::tan(0.5 * camera.GetViewAngle() * kPi / 180);
  const double pixelsPerUnit = 0.5 * height / halfHeight;
  const double fraction = dimension == 3 ? 0.6 : 0.8;
  return std::clamp(fraction * spacing * pixelsPerUnit, 3.0, 40.0);
}

void placeCamera(vtkRenderer& renderer, int dimension, const PngOptions& options) {
  vtkCamera* camera = renderer.GetActiveCamera();
  double bounds[6];
  if (options.window)
    std::copy(options.window->begin(), options.window->end(), bounds);
  else
    renderer.ComputeVisiblePropBounds(bounds);
  const double centre[3] = {0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                            0.5 * (bounds[4] + bounds[5])};
  camera->SetFocalPoint(centre);
  if (dimension == 3) {
    camera->SetPosition(centre[0] + 1, centre[1] + 1, centre[2] + 1);
    camera->SetViewUp(0, 0, 1);
  } else {
    camera->SetPosition(centre[0], centre[1], centre[2] + 1);
    camera->SetViewUp(0, 1, 0);
    camera->ParallelProjectionOn();  // a flat cloud seen flat: no perspective distortion
  }
  // ResetCamera keeps the direction and fits the bounding sphere of the box exactly.
  renderer.ResetCamera(bounds);
  // The colour bar takes the right-hand strip: the cloud gets the left 80 %, centred there.
  const double usableWidth = options.colourBar ? 0.8 : 1.0;
  if (options.colourBar) camera->SetWindowCenter(0.15, 0.0);
  if (dimension == 3) {
    camera->Zoom(0.85);  // room for the spheres' radius and the title
  } else {
    // A flat cloud fills the picture better than its bounding circle does: fit its rectangle,
    // with 12 % to spare for the spheres and the title.
    const double halfWidth = 0.5 * (bounds[1] - bounds[0]), halfHeight = 0.5 * (bounds[3] - bounds[2]);
    const double aspect = static_cast<double>(options.width) * usableWidth / options.height;
    const double scale = std::max(halfHeight, halfWidth / aspect);
    if (scale > 0) camera->SetParallelScale(scale / 0.88);
  }
  const PngCamera& requested = options.camera;
  if (requested.position) camera->SetPosition(requested.position->data());
  if (requested.focalPoint) camera->SetFocalPoint(requested.focalPoint->data());
  if (requested.viewUp) camera->SetViewUp(requested.viewUp->data());
  camera->OrthogonalizeViewUp();
  renderer.ResetCameraClippingRange();
}

}  // namespace

std::string fieldLabel(const ParticleField& field, int component) {
  if (component == PngOptions::magnitude) return field.components == 1 ? field.name : field.name + " magnitude";
  if (field.kind == FieldKind::ScalarField) return field.name;
  static const char* const axes[] = {"x", "y", "z"};
  static const char* const symmetric[] = {"xx", "yy", "zz", "xy", "yz", "xz"};  // VTK/ParaView order
  static const char* const full[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};
  const auto k = static_cast<std::size_t>(component);
  if (field.kind == FieldKind::VectorField && component < 3) return field.name + "_" + axes[k];
  if (field.kind == FieldKind::TensorField && field.components == 6) return field.name + "_" + symmetric[k];
  if (field.kind == FieldKind::TensorField && field.components == 9) return field.name + "_" + full[k];
  return field.name + "_" + std::to_string(component);
}

PngRenderer::PngRenderer(PngOptions options) : options_(std::move(options)) {
  if (options_.width < 16 || options_.height < 16)
    throw Error("PNG rendering: image size " + std::to_string(options_.width) + "x" + std::to_string(options_.height) +
                " is too small (at least 16x16)");
  if (options_.range && !((*options_.range)[1] > (*options_.range)[0]))
    throw Error("PNG rendering: colour range must have min < max");
  if (!(options_.pointSize >= 0)) throw Error("PNG rendering: point size must be >= 0");
}

bool PngRenderer::displayAvailable(std::string* why) { return renderDisplayAvailable(why); }

template <int D>
void PngRenderer::render(const ParticleFrame<D>& frame, const std::string& path) const {
  // First, before any VTK rendering object exists: without a display VTK would abort. The
  // connection stays open until the window is gone (declared first, destroyed last) and VTK
  // renders through it.
  const DisplayConnection display;
  if (!display) throw Error("cannot render '" + path + "': " + display.reason());

  checkFrame(frame);
  const ParticleField* field = frame.find(options_.field);
  if (field == nullptr) {
    std::string names;
    for (const auto& f : frame.fields) names += (names.empty() ? "" : ", ") + f.name;
    throw Error("cannot render '" + path + "': no field '" + options_.field + "' (fields: " + names + ")");
  }
  if (options_.component != PngOptions::magnitude && (options_.component < 0 || options_.component >= field->components))
    throw Error("cannot render '" + path + "': field '" + field->name + "' has " + std::to_string(field->components) +
                " components, component " + std::to_string(options_.component) + " asked");

  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw Error("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");

  const std::vector<Real> values = colourValues(*field, options_.component, frame.count);
  const std::array<Real, 2> range = options_.range ? *options_.range : autoRange(values);
  const std::string label = fieldLabel(*field, options_.component);

  const vtkSmartPointer<vtkPolyData> polyData = makePolyData(frame);
  vtkNew<vtkDoubleArray> colour;
  colour->SetName("colour");
  colour->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), colour->GetPointer(0));
  polyData->GetPointData()->SetScalars(colour);

  // Moreland's cool-to-warm diverging map: readable for signed fields, fine for magnitudes.
  vtkNew<vtkColorTransferFunction> colours;
  colours->SetColorSpaceToDiverging();
  colours->AddRGBPoint(range[0], 0.230, 0.299, 0.754);
  colours->AddRGBPoint(range[1], 0.706, 0.016, 0.150);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  mapper->SetLookupTable(colours);
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToMapScalars();
  mapper->ScalarVisibilityOn();
  mapper->SetScalarRange(range[0], range[1]);

  double bounds[6];
  polyData->GetBounds(bounds);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  // Impostor spheres drawn by a shader: one vertex per particle, cheap even for large clouds,
  // and correct under Mesa's llvmpipe (xvfb-run).
  actor->GetProperty()->SetRepresentationToPoints();
  actor->GetProperty()->RenderPointsAsSpheresOn();

  const double brightness = (options_.background[0] + options_.background[1] + options_.background[2]) / 3;
  const double ink = brightness > 0.5 ? 0.0 : 1.0;  // black text on light backgrounds, white on dark

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(options_.background.data());
  renderer->AddActor(actor);

  vtkNew<vtkScalarBarActor> bar;
  if (options_.colourBar) {
    bar->SetLookupTable(colours);
    bar->SetTitle((options_.colourBarTitle.empty() ? label : options_.colourBarTitle).c_str());
    bar->SetNumberOfLabels(5);
    bar->SetLabelFormat("%-#6.3g");
    bar->SetOrientationToVertical();
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.86, 0.1);
    bar->SetWidth(0.12);
    bar->SetHeight(0.78);
    bar->UnconstrainedFontSizeOn();
    for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
      text->SetColor(ink, ink, ink);
      text->SetFontSize(std::max(10, options_.height / 48));
      text->BoldOff();
      text->ItalicOff();
      text->ShadowOff();
    }
    renderer->AddViewProp(bar);
  }

  vtkNew<vtkTextActor> title;
  if (options_.title) {
    title->SetInput((options_.titleText.empty() ? label + "  " + timeText(frame.time) : options_.titleText).c_str());
    vtkTextProperty* text = title->GetTextProperty();
    text->SetFontSize(std::max(12, options_.height / 32));
    text->SetColor(ink, ink, ink);
    text->SetJustificationToCentered();
    text->SetVerticalJustificationToTop();
    title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    title->GetPositionCoordinate()->SetValue(0.5, 0.97);
    renderer->AddViewProp(title);
  }

  placeCamera(*renderer, D, options_);
  actor->GetProperty()->SetPointSize(static_cast<float>(
      options_.pointSize > 0 ? options_.pointSize
                             : automaticPointSize(bounds, frame.count, D, *renderer->GetActiveCamera(), options_.height)));

  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(display.handle());
  window->SetOffScreenRendering(1);
  window->SetSize(options_.width, options_.height);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  image->SetInputBufferTypeToRGB();
  image->ReadFrontBufferOff();
  image->Update();

  const std::string temporary = path + ".tmp-" + std::to_string(::getpid()) + ".png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(temporary.c_str());
  writer->SetInputConnection(image->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary)) {
    std::remove(temporary.c_str());
    throw Error("writing PNG '" + path + "' failed (VTK error code " + std::to_string(writer->GetErrorCode()) + ")");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    throw Error("cannot rename '" + temporary + "' to '" + path + "': " + std::strerror(error));
  }
}

template void PngRenderer::render(const ParticleFrame<1>&, const std::string&) const;
template void PngRenderer::render(const ParticleFrame<2>&, const std::string&) const;
template void PngRenderer::render(const ParticleFrame<3>&, const std::string&) const;

}  // namespace mfwave
