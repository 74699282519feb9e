#pragma once
// The two things every renderer does with OpenGL besides drawing: build a shader program, and
// turn the GL error flag into an exception. Both need a current OpenGL 3.3 core context. `who`
// names the renderer in the message ("renderer", "scene renderer") so a failure says where it
// happened; out-of-memory is told apart because it is the user's to fix (a smaller --size).
#include <string>

namespace gestura::gl {

// Compiles both stages and links them; the returned program name (a GLuint) owns no shaders.
// Throws gestura::Error with the driver's log when a stage does not compile or the pair does not link.
unsigned link_program(const char* who, const std::string& vertex_source, const std::string& fragment_source);

// Throws gestura::Error when glGetError() reports anything; `what` says what was being done.
void check(const char* who, const char* what);

}  // namespace gestura::gl
