#pragma once
// The GL backend's frames on screen: the window's own GL context (GLFW's, Mesa llvmpipe
// through GLX on X11, Xvfb included) draws the image with glDrawPixels and reads it back
// from the back buffer before swapping. The backend's OSMesa context lives on the render
// thread; this one is current on the window's thread only.
#include <memory>

#include "viewer/Presenter.h"

struct GLFWwindow;

namespace shaderbed::viewer {

struct GlfwLibrary;

class GlPresenter final : public Presenter {
 public:
  // For a window created with a GL context: makes it current on this thread.
  static Result<std::unique_ptr<GlPresenter>> create(const GlfwLibrary& glfw, GLFWwindow* window);
  ~GlPresenter() override;

  Result<void> present(const DisplayImage& image, bool alert, DisplayImage* capture) override;
  std::string description() const override;

 private:
  struct Calls;
  GlPresenter(const GlfwLibrary& glfw, GLFWwindow* window);

  const GlfwLibrary& glfw_;
  GLFWwindow* window_;
  std::unique_ptr<Calls> gl_;
  std::string renderer_;
};

}  // namespace shaderbed::viewer
