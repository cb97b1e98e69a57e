#pragma once
// Whether off-screen rendering can work here. Debian's VTK renders only through X11 (no OSMesa,
// no EGL), and without a display vtkRenderWindow::Render() aborts the whole process; so this is
// asked before any VTK rendering object is created, and uses Xlib directly, never VTK.

#include <string>

namespace mfwave {

// A checked connection to the X server named by $DISPLAY. The renderer hands it to VTK
// (vtkRenderWindow::SetDisplayId) and keeps it open while rendering, so the display VTK draws
// on is the one that was checked: Xvfb resets itself whenever its last client disconnects, and a
// connection VTK opened on its own during such a reset would abort the process.
class DisplayConnection {
 public:
  // Connects (retrying briefly, to ride out an Xvfb reset) and checks for GLX.
  DisplayConnection();
  ~DisplayConnection();
  DisplayConnection(const DisplayConnection&) = delete;
  DisplayConnection& operator=(const DisplayConnection&) = delete;

  explicit operator bool() const { return display_ != nullptr; }
  // Why there is no usable connection: "no DISPLAY set: run under xvfb-run -a to render PNG
  // frames", "cannot open display :99: ...", "display :99 has no GLX extension ..."; empty if ok.
  const std::string& reason() const { return reason_; }
  // The Xlib Display*, as VTK takes it (nullptr when there is none).
  void* handle() const { return display_; }

 private:
  void* display_ = nullptr;
  std::string reason_;
};

// True when a DisplayConnection can be made; otherwise false with its reason in *why.
bool renderDisplayAvailable(std::string* why = nullptr);

}  // namespace mfwave
