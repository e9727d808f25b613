// A linked GLSL program built from <resource_dir>/shaders/<name>.vert/.frag.
#pragma once

#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "render/gl_object.hpp"

namespace tumble::render {

class ShaderProgram {
 public:
  /// Compiles and links; throws std::runtime_error with the info log and
  /// the file name on failure.
  ShaderProgram(const GlFunctions& gl, const std::filesystem::path& shader_dir,
                const std::string& name);

  void use() const { gl_->UseProgram(program_.id()); }

  // Setters assume the program is in use. Unknown names are ignored, like GL.
  void set(const char* name, int v) const;
  void set(const char* name, float v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  GLint location(const char* name) const;

  const GlFunctions* gl_;
  GlObject program_;
};

}  // namespace tumble::render
