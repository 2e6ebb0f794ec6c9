// RAII shaders and programs built from flattened GLSL (include_flattener.hpp).
// Compile and link failures throw Error with the stage, the root file and the
// driver's log rewritten to file:line, so a typo in an included file is
// reported at that file, not at "0:213".
//
//   auto cs = snell::gpu::flattenGlslFile("blur.comp", {"glsl"});
//   snell::gpu::Program p = snell::gpu::Program::compute(ctx.gl(), cs);
//   p.set("radius", 3); p.dispatch(groupsX);
#pragma once

#include "error.hpp"
#include "gl_api.hpp"
#include "include_flattener.hpp"

#include <glm/glm.hpp>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace snell::gpu {

enum class Stage { Vertex, Fragment, Compute };

inline const char* stageName(Stage s) {
  switch (s) {
    case Stage::Vertex: return "vertex";
    case Stage::Fragment: return "fragment";
    case Stage::Compute:
    default: return "compute";
  }
}

inline GLenum glShaderType(Stage s) {
  switch (s) {
    case Stage::Vertex: return GL_VERTEX_SHADER;
    case Stage::Fragment: return GL_FRAGMENT_SHADER;
    case Stage::Compute:
    default: return GL_COMPUTE_SHADER;
  }
}

class Shader {
 public:
  Shader(const GlApi& gl, Stage stage, const FlatSource& source)
      : gl_(&gl), stage_(stage), name_(source.files.empty() ? "<source>" : source.files[0]) {
    id_ = gl.CreateShader(glShaderType(stage));
    if (id_ == 0) throw Error(std::string("glCreateShader(") + stageName(stage) + ") failed; is a context current?");
    const GLchar* text = source.text.c_str();
    const GLint length = static_cast<GLint>(source.text.size());
    gl.ShaderSource(id_, 1, &text, &length);
    gl.CompileShader(id_);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(id_, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      const std::string log = mapInfoLog(infoLog(), source);
      gl.DeleteShader(id_);
      id_ = 0;
      throw Error(std::string(stageName(stage)) + " shader " + name_ + " failed to compile:\n" + log);
    }
  }
  ~Shader() {
    if (id_) gl_->DeleteShader(id_);
  }
  Shader(const Shader&) = delete;
  Shader& operator=(const Shader&) = delete;
  Shader(Shader&& o) noexcept : gl_(o.gl_), stage_(o.stage_), name_(std::move(o.name_)), id_(std::exchange(o.id_, 0u)) {}
  Shader& operator=(Shader&& o) noexcept {
    if (this != &o) {
      if (id_) gl_->DeleteShader(id_);
      gl_ = o.gl_;
      stage_ = o.stage_;
      name_ = std::move(o.name_);
      id_ = std::exchange(o.id_, 0u);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  Stage stage() const { return stage_; }
  const std::string& name() const { return name_; }  // files[0] of its source

 private:
  const GlApi* gl_;
  Stage stage_;
  std::string name_;
  GLuint id_ = 0;

  std::string infoLog() const {
    GLint length = 0;
    gl_->GetShaderiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    GLsizei written = 0;
    gl_->GetShaderInfoLog(id_, static_cast<GLsizei>(log.size()), &written, log.data());
    log.resize(static_cast<std::size_t>(written > 0 ? written : 0));
    return log;
  }
};

class Program {
 public:
  // Links already compiled shaders; they may be destroyed afterwards.
  Program(const GlApi& gl, std::initializer_list<const Shader*> shaders) : gl_(&gl) {
    id_ = gl.CreateProgram();
    if (id_ == 0) throw Error("glCreateProgram failed; is a context current?");
    std::string names;
    for (const Shader* s : shaders) {
      gl.AttachShader(id_, s->id());
      names += std::string(names.empty() ? "" : ", ") + stageName(s->stage()) + " " + s->name();
    }
    gl.LinkProgram(id_);
    for (const Shader* s : shaders) gl.DetachShader(id_, s->id());
    GLint ok = GL_FALSE;
    gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
      GLint length = 0;
      gl.GetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
      std::string log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
      GLsizei written = 0;
      gl.GetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), &written, log.data());
      log.resize(static_cast<std::size_t>(written > 0 ? written : 0));
      gl.DeleteProgram(id_);
      id_ = 0;
      throw Error("program (" + names + ") failed to link:\n" + log);
    }
  }

  static Program compute(const GlApi& gl, const FlatSource& cs) {
    Shader s(gl, Stage::Compute, cs);
    return Program(gl, {&s});
  }
  static Program graphics(const GlApi& gl, const FlatSource& vs, const FlatSource& fs) {
    Shader v(gl, Stage::Vertex, vs);
    Shader f(gl, Stage::Fragment, fs);
    return Program(gl, {&v, &f});
  }

  ~Program() {
    if (id_) gl_->DeleteProgram(id_);
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  Program(Program&& o) noexcept : gl_(o.gl_), id_(std::exchange(o.id_, 0u)) {}
  Program& operator=(Program&& o) noexcept {
    if (this != &o) {
      if (id_) gl_->DeleteProgram(id_);
      gl_ = o.gl_;
      id_ = std::exchange(o.id_, 0u);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  void use() const { gl_->UseProgram(id_); }

  // use() + glDispatchCompute + an error check.
  void dispatch(GLuint groupsX, GLuint groupsY = 1, GLuint groupsZ = 1) const {
    use();
    gl_->DispatchCompute(groupsX, groupsY, groupsZ);
    checkGl(*gl_, "glDispatchCompute");
  }

  // Uniforms by name. Setting one the program does not have is an Error:
  // GL would silently ignore it, hiding a misspelled name. An unused uniform
  // is removed by the compiler, so test hasUniform() first when it may be.
  bool hasUniform(const std::string& name) const { return gl_->GetUniformLocation(id_, name.c_str()) >= 0; }

  // Checks that the program has the uniform block `name` at `binding` (its
  // layout(binding = N)) and that the block holds `bytes` bytes rounded up to
  // 16 (as std140 rounds a block). A block the program lacks, at another
  // binding or of another size is an Error naming both. It checks sizes, not
  // member offsets: the host keeps its struct std140 (static_assert its
  // offsets, as examples/lab/app/gpu_lab.cpp does).
  void requireUniformBlock(const std::string& name, GLuint binding, std::size_t bytes) const {
    const GLuint index = gl_->GetUniformBlockIndex(id_, name.c_str());
    if (index == GL_INVALID_INDEX) throw Error("program has no uniform block " + name);
    GLint size = 0, bound = -1;
    gl_->GetActiveUniformBlockiv(id_, index, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    gl_->GetActiveUniformBlockiv(id_, index, GL_UNIFORM_BLOCK_BINDING, &bound);
    checkGl(*gl_, "glGetActiveUniformBlockiv(" + name + ")");
    const std::size_t rounded = (bytes + 15u) / 16u * 16u;
    if (static_cast<std::size_t>(size) != rounded)
      throw Error("uniform block " + name + " holds " + std::to_string(size) + " bytes, the host struct " +
                  std::to_string(bytes) + " (" + std::to_string(rounded) + " as std140 rounds it)");
    if (bound != static_cast<GLint>(binding))
      throw Error("uniform block " + name + " is at binding " + std::to_string(bound) + ", expected " +
                  std::to_string(binding));
  }

  // A value of the wrong type for the uniform (a float for an int) is
  // GL_INVALID_OPERATION: checked here, so it is not blamed on a later call.
  void set(const std::string& name, int v) const {
    gl_->ProgramUniform1i(id_, location(name), v);
    checkUniform("glProgramUniform1i", name);
  }
  void set(const std::string& name, float v) const {
    gl_->ProgramUniform1f(id_, location(name), v);
    checkUniform("glProgramUniform1f", name);
  }
  void set(const std::string& name, const glm::vec2& v) const {
    gl_->ProgramUniform2fv(id_, location(name), 1, &v[0]);
    checkUniform("glProgramUniform2fv", name);
  }
  void set(const std::string& name, const glm::vec3& v) const {
    gl_->ProgramUniform3fv(id_, location(name), 1, &v[0]);
    checkUniform("glProgramUniform3fv", name);
  }
  void set(const std::string& name, const glm::vec4& v) const {
    gl_->ProgramUniform4fv(id_, location(name), 1, &v[0]);
    checkUniform("glProgramUniform4fv", name);
  }
  void set(const std::string& name, const glm::ivec2& v) const {
    gl_->ProgramUniform2iv(id_, location(name), 1, &v[0]);
    checkUniform("glProgramUniform2iv", name);
  }
  // GLM is column-major like GL, so no transpose.
  void set(const std::string& name, const glm::mat4& m) const {
    gl_->ProgramUniformMatrix4fv(id_, location(name), 1, GL_FALSE, &m[0][0]);
    checkUniform("glProgramUniformMatrix4fv", name);
  }
  // A sampler2D reads the texture bound to texture unit `unit` (Texture::bind).
  void setSampler(const std::string& name, int unit) const { set(name, unit); }

 private:
  const GlApi* gl_;
  GLuint id_ = 0;

  void checkUniform(const char* call, const std::string& name) const {
    checkGl(*gl_, std::string(call) + " for uniform '" + name + "'");
  }

  GLint location(const std::string& name) const {
    const GLint loc = gl_->GetUniformLocation(id_, name.c_str());
    if (loc < 0)
      throw Error("uniform '" + name + "' is not an active uniform of the program (misspelled, or removed by the "
                  "compiler because it is unused)");
    return loc;
  }
};

}  // namespace snell::gpu
