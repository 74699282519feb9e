#pragma once
// OpenGL 3.3 core contexts the renderer draws in: a headless one (EGL, no window system, no
// DISPLAY needed — Mesa's surfaceless platform, falling back to the device platform) and a
// windowed one (GLFW). The renderer does not know which it runs in; both make their context
// current on construction and keep it current on the creating thread.
#include <memory>
#include <string>

struct GLFWwindow;

namespace gestura {

class HeadlessGlContext {
 public:
  HeadlessGlContext();  // throws gestura::Error when no EGL display / GL 3.3 core context exists
  ~HeadlessGlContext();
  HeadlessGlContext(const HeadlessGlContext&) = delete;
  HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

  void make_current();
  const std::string& description() const { return description_; }  // platform + GL renderer

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

class WindowGlContext {
 public:
  WindowGlContext(int width, int height, const std::string& title);  // throws gestura::Error
  ~WindowGlContext();
  WindowGlContext(const WindowGlContext&) = delete;
  WindowGlContext& operator=(const WindowGlContext&) = delete;

  GLFWwindow* window() const { return window_; }
  void framebuffer_size(int& width, int& height) const;
  bool should_close() const;
  void swap_buffers();

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace gestura
