#include "io/vtk/DisplayCheck.hpp"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace mfwave {

DisplayConnection::DisplayConnection() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    reason_ = "no DISPLAY set: run under xvfb-run -a to render PNG frames";
    return;
  }
  Display* display = nullptr;
  // A few tries 50 ms apart: an Xvfb that just lost its last client refuses connections while it
  // resets. A display that is really absent costs 0.1 s, once.
  for (int attempt = 0; attempt < 3 && display == nullptr; ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    display = XOpenDisplay(name);
  }
  if (display == nullptr) {
    reason_ = std::string("cannot open display ") + name + ": run under xvfb-run -a to render PNG frames";
    return;
  }
  // VTK's X11 render window needs GLX; without it VTK would fail later, and not gracefully.
  int opcode = 0, event = 0, error = 0;
  if (XQueryExtension(display, "GLX", &opcode, &event, &error) == 0) {
    XCloseDisplay(display);
    reason_ = std::string("display ") + name + " has no GLX extension, which VTK needs to render";
    return;
  }
  display_ = display;
}

DisplayConnection::~DisplayConnection() {
  if (display_ != nullptr) XCloseDisplay(static_cast<Display*>(display_));
}

bool renderDisplayAvailable(std::string* why) {
  const DisplayConnection connection;
  if (why != nullptr) *why = connection.reason();
  return static_cast<bool>(connection);
}

}  // namespace mfwave
