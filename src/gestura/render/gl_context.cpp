#include "gestura/render/gl_context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstring>

#include "gestura/core/error.hpp"

namespace gestura {
namespace {

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// Tries the surfaceless platform first (needs nothing but Mesa), then the first EGL device.
EGLDisplay open_display(std::string& platform) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
      platform = "EGL surfaceless";
      return d;
    }
  }
  if (has_extension(client, "EGL_EXT_platform_device") && has_extension(client, "EGL_EXT_device_enumeration")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
      EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
      if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
        platform = "EGL device";
        return d;
      }
    }
  }
  throw Error("headless rendering: no EGL display (needs EGL_MESA_platform_surfaceless or EGL_EXT_platform_device)");
}

}  // namespace

HeadlessGlContext::HeadlessGlContext() {
  std::string platform;
  EGLDisplay display = open_display(platform);
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) throw Error("headless rendering: EGL cannot bind the desktop OpenGL API");
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  // Surfaceless displays may expose no configs at all; a context without config is fine then.
  eglChooseConfig(display, config_attributes, &config, 1, &config_count);
  if (config_count == 0) config = EGL_NO_CONFIG_KHR;
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    eglTerminate(display);
    throw Error("headless rendering: EGL could not create an OpenGL 3.3 core context");
  }
  context_ = context;
  make_current();
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  description_ = platform + ", " + (renderer ? renderer : "unknown GL renderer");
}

HeadlessGlContext::~HeadlessGlContext() {
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
}

void HeadlessGlContext::make_current() {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_)))
    throw Error("headless rendering: eglMakeCurrent failed");
}

WindowGlContext::WindowGlContext(int width, int height, const std::string& title) {
  if (!glfwInit()) throw Error("viewer: cannot initialise GLFW (is DISPLAY set? try xvfb-run -a)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    glfwTerminate();
    throw Error("viewer: cannot open a window with an OpenGL 3.3 core context");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
}

WindowGlContext::~WindowGlContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void WindowGlContext::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
bool WindowGlContext::should_close() const { return glfwWindowShouldClose(window_); }
void WindowGlContext::swap_buffers() { glfwSwapBuffers(window_); }

}  // namespace gestura
