#include "render/shader_program.hpp"

#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "base/input_file.hpp"
#include "render/resource_dir.hpp"

namespace tumble::render {
namespace {

constexpr const char* kShaderSource = " (tumble's own shaders/ folder, found beside the binary or in its source tree)";

std::string read_text(const std::filesystem::path& path) {
  try {
    return read_input_file(path, std::size_t(1) << 20, "shader");
  } catch (const std::exception& e) {
    throw ResourceError(e.what() + std::string(kShaderSource));
  }
}

GlObject compile(const GlFunctions& gl, GLenum type, const std::filesystem::path& path) {
  const std::string src = read_text(path);
  GlObject shader = make_shader(gl, type);
  const char* text = src.c_str();
  gl.ShaderSource(shader.id(), 1, &text, nullptr);
  gl.CompileShader(shader.id());
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetShaderInfoLog(shader.id(), sizeof log, nullptr, log);
    throw ResourceError("compiling " + path.string() + kShaderSource + ":\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const GlFunctions& gl, const std::filesystem::path& shader_dir,
                             const std::string& name)
    : gl_(&gl), program_(make_program(gl)) {
  const GlObject vs = compile(gl, GL_VERTEX_SHADER, shader_dir / (name + ".vert"));
  const GlObject fs = compile(gl, GL_FRAGMENT_SHADER, shader_dir / (name + ".frag"));
  gl.AttachShader(program_.id(), vs.id());
  gl.AttachShader(program_.id(), fs.id());
  gl.LinkProgram(program_.id());
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    gl.GetProgramInfoLog(program_.id(), sizeof log, nullptr, log);
    throw std::runtime_error("linking shader program " + name + ":\n" + log);
  }
}

GLint ShaderProgram::location(const char* name) const {
  return gl_->GetUniformLocation(program_.id(), name);
}

void ShaderProgram::set(const char* name, int v) const { gl_->Uniform1i(location(name), v); }
void ShaderProgram::set(const char* name, float v) const { gl_->Uniform1f(location(name), v); }
void ShaderProgram::set(const char* name, const glm::vec2& v) const {
  gl_->Uniform2f(location(name), v.x, v.y);
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
  gl_->Uniform3f(location(name), v.x, v.y, v.z);
}
void ShaderProgram::set(const char* name, const glm::vec4& v) const {
  gl_->Uniform4f(location(name), v.x, v.y, v.z, v.w);
}
void ShaderProgram::set(const char* name, const glm::mat4& v) const {
  gl_->UniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace tumble::render
