#include "gestura/render/gl_program.hpp"

#include <epoxy/gl.h>

#include "gestura/core/error.hpp"

namespace gestura::gl {
namespace {

GLuint compile(const char* who, GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw Error(std::string(who) + ": " + (type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                " shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

unsigned link_program(const char* who, const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vs = compile(who, GL_VERTEX_SHADER, vertex_source);
  GLuint fs = 0;
  try {
    fs = compile(who, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw Error(std::string(who) + ": shaders do not link: " + log);
  }
  return program;
}

void check(const char* who, const char* what) {
  const GLenum e = glGetError();
  if (e == GL_OUT_OF_MEMORY) throw Error(std::string(who) + ": out of GPU memory while " + what);
  if (e != GL_NO_ERROR)
    throw Error(std::string(who) + ": OpenGL error " + std::to_string(e) + " while " + what);
}

}  // namespace gestura::gl
