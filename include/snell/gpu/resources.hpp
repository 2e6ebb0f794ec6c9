// RAII GL resources that move data between snell's CPU types and the GPU
// without changing a bit: floats go up and come back as RGBA32F / std430
// vec4, images keep snell::Image's bottom-row-first order (GL's own), and a
// texture carries the very filter state snell::Texture2D emulates on the CPU,
// so a parity test samples the same thing on both sides.
#pragma once

#include "error.hpp"
#include "gl_api.hpp"

#include <snell/bridge.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace snell::gpu {

// A GL object name plus the table that deletes it; move-only.
template <class Deleter>
class GlHandle {
 public:
  GlHandle() = default;
  GlHandle(const GlApi& gl, GLuint id) : gl_(&gl), id_(id) {}
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& o) noexcept : gl_(o.gl_), id_(std::exchange(o.id_, 0u)) {}
  GlHandle& operator=(GlHandle&& o) noexcept {
    if (this != &o) {
      reset();
      gl_ = o.gl_;
      id_ = std::exchange(o.id_, 0u);
    }
    return *this;
  }
  GLuint id() const { return id_; }
  const GlApi& gl() const { return *gl_; }
  void reset() {
    if (id_) Deleter{}(*gl_, id_);
    id_ = 0;
  }

 private:
  const GlApi* gl_ = nullptr;
  GLuint id_ = 0;
};

namespace detail {
// Restores the active unit's GL_TEXTURE_2D binding on scope exit.
class BindingRestorer {
 public:
  explicit BindingRestorer(const GlApi& gl) : gl_(gl) { gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &previous_); }
  ~BindingRestorer() { gl_.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous_)); }
  BindingRestorer(const BindingRestorer&) = delete;
  BindingRestorer& operator=(const BindingRestorer&) = delete;

 private:
  const GlApi& gl_;
  GLint previous_ = 0;
};

struct DeleteBuffer {
  void operator()(const GlApi& gl, GLuint id) const { gl.DeleteBuffers(1, &id); }
};
struct DeleteTexture {
  void operator()(const GlApi& gl, GLuint id) const { gl.DeleteTextures(1, &id); }
};
struct DeleteFramebuffer {
  void operator()(const GlApi& gl, GLuint id) const { gl.DeleteFramebuffers(1, &id); }
};
struct DeleteVertexArray {
  void operator()(const GlApi& gl, GLuint id) const { gl.DeleteVertexArrays(1, &id); }
};
}  // namespace detail

// A shader storage buffer (std430). vec4 arrays are the safe element type:
// std430 pads vec3 to 16 bytes, so vec3 arrays would not match the C++ layout.
class StorageBuffer {
 public:
  explicit StorageBuffer(const GlApi& gl) : handle_(gl, create(gl)) {}
  StorageBuffer(const GlApi& gl, const std::vector<glm::vec4>& data) : StorageBuffer(gl) { upload(data); }

  // Replaces the contents (and size). nullptr data gives zeros, never garbage.
  void upload(const void* data, std::size_t bytes) {
    const GlApi& gl = handle_.gl();
    std::vector<unsigned char> zeros;
    if (data == nullptr) {
      zeros.assign(bytes, 0);
      data = zeros.data();
    }
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, handle_.id());
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), bytes ? data : nullptr, GL_DYNAMIC_COPY);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    checkGl(gl, "StorageBuffer upload (glBufferData)");
    size_ = bytes;
  }
  void upload(const std::vector<glm::vec4>& data) { upload(data.data(), data.size() * sizeof(glm::vec4)); }
  void upload(const std::vector<float>& data) { upload(data.data(), data.size() * sizeof(float)); }
  void allocate(std::size_t bytes) { upload(nullptr, bytes); }

  // Reads back `bytes` from `offset`. Call glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT)
  // after a shader wrote the buffer.
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const {
    if (offset + bytes > size_)
      throw Error("StorageBuffer download: range " + std::to_string(offset) + "+" + std::to_string(bytes) +
                  " exceeds the buffer size " + std::to_string(size_));
    if (bytes == 0) return;
    const GlApi& gl = handle_.gl();
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, handle_.id());
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                        data);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    checkGl(gl, "StorageBuffer download (glGetBufferSubData)");
  }
  std::vector<glm::vec4> downloadVec4() const {
    std::vector<glm::vec4> v(size_ / sizeof(glm::vec4));
    download(v.data(), v.size() * sizeof(glm::vec4));
    return v;
  }
  std::vector<float> downloadFloats() const {
    std::vector<float> v(size_ / sizeof(float));
    download(v.data(), v.size() * sizeof(float));
    return v;
  }

  // Binds to `layout(std430, binding = N) buffer`.
  void bindBase(GLuint binding) const {
    handle_.gl().BindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, handle_.id());
    checkGl(handle_.gl(), "glBindBufferBase(GL_SHADER_STORAGE_BUFFER, " + std::to_string(binding) + ")");
  }
  std::size_t size() const { return size_; }
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<detail::DeleteBuffer> handle_;
  std::size_t size_ = 0;

  static GLuint create(const GlApi& gl) {
    GLuint id = 0;
    gl.GenBuffers(1, &id);
    if (id == 0) throw Error("glGenBuffers failed; is a context current?");
    return id;
  }
};

// A uniform buffer (std140) holding one host struct's bytes as they are; the
// struct must be laid out as std140 (Program::requireUniformBlock checks the
// size on the program's side).
class UniformBuffer {
 public:
  UniformBuffer(const GlApi& gl, const void* data, std::size_t bytes) : handle_(gl, create(gl)) { upload(data, bytes); }
  void upload(const void* data, std::size_t bytes) {
    const GlApi& gl = handle_.gl();
    // std140 rounds a block up to 16 bytes; the tail is zeros.
    std::vector<unsigned char> padded((bytes + 15u) / 16u * 16u, 0);
    if (data && bytes) std::copy_n(static_cast<const unsigned char*>(data), bytes, padded.begin());
    gl.BindBuffer(GL_UNIFORM_BUFFER, handle_.id());
    gl.BufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(padded.size()), padded.data(), GL_DYNAMIC_DRAW);
    gl.BindBuffer(GL_UNIFORM_BUFFER, 0);
    checkGl(gl, "UniformBuffer upload (glBufferData)");
  }
  // Binds to `layout(std140, binding = N) uniform`.
  void bindBase(GLuint binding) const {
    handle_.gl().BindBufferBase(GL_UNIFORM_BUFFER, binding, handle_.id());
    checkGl(handle_.gl(), "glBindBufferBase(GL_UNIFORM_BUFFER, " + std::to_string(binding) + ")");
  }
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<detail::DeleteBuffer> handle_;
  static GLuint create(const GlApi& gl) {
    GLuint id = 0;
    gl.GenBuffers(1, &id);
    if (id == 0) throw Error("glGenBuffers failed; is a context current?");
    return id;
  }
};

// GL filter enums for snell's CPU filter state (GL 4.5 sec. 8.14).
inline GLint glMagFilter(snell::Filter f) { return f == snell::Filter::Linear ? GL_LINEAR : GL_NEAREST; }
inline GLint glMinFilter(snell::Filter f, snell::MipFilter mip) {
  const bool lin = f == snell::Filter::Linear;
  switch (mip) {
    case snell::MipFilter::Nearest: return lin ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    case snell::MipFilter::Linear: return lin ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
    case snell::MipFilter::None:
    default: return lin ? GL_LINEAR : GL_NEAREST;
  }
}

// An RGBA32F 2D texture holding every level of a snell::Texture2D, with its
// filters, clamp-to-edge and GL_TEXTURE_MAX_LEVEL = levelCount - 1 (so a
// partial chain is still complete and textureLod clamps where the CPU does).
class Texture {
 public:
  Texture(const GlApi& gl, const snell::Texture2D& tex) : handle_(gl, create(gl)) {
    if (tex.levelCount() < 1) throw Error("snell::gpu::Texture: the snell::Texture2D has no levels");
    // GL takes a 0 x 0 level without an error (and samples the texture as
    // black), and would read past texels the size does not match.
    for (int lod = 0; lod < tex.levelCount(); ++lod) {
      const snell::Image& img = tex.level(lod);
      const std::string size = std::to_string(img.width) + "x" + std::to_string(img.height);
      if (img.width <= 0 || img.height <= 0)
        throw Error("snell::gpu::Texture: level " + std::to_string(lod) + " is " + size + "; sizes must be positive");
      if (img.texels.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
        throw Error("snell::gpu::Texture: level " + std::to_string(lod) + " is " + size + " but holds " +
                    std::to_string(img.texels.size()) + " texels");
    }
    levels_ = tex.levelCount();
    width_ = tex.level(0).width;
    height_ = tex.level(0).height;
    // No DSA in the table, so the upload borrows the active unit's binding;
    // restoring it keeps textures already bound there (say, by a previous
    // Texture::bind(0)) in place.
    const detail::BindingRestorer restore(gl);
    gl.BindTexture(GL_TEXTURE_2D, handle_.id());
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int lod = 0; lod < levels_; ++lod) {
      const snell::Image& img = tex.level(lod);
      gl.TexImage2D(GL_TEXTURE_2D, lod, GL_RGBA32F, img.width, img.height, 0, GL_RGBA, GL_FLOAT, img.texels.data());
      checkGl(gl, "glTexImage2D(level " + std::to_string(lod) + ", " + std::to_string(img.width) + "x" +
                      std::to_string(img.height) + ", GL_RGBA32F) in snell::gpu::Texture");
    }
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels_ - 1);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, glMagFilter(tex.magFilter));
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, glMinFilter(tex.minFilter, tex.mipFilter));
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    checkGl(gl, "glTexParameteri in snell::gpu::Texture");
  }

  // Binds to texture unit `unit`; pair with Program::setSampler(name, unit).
  void bind(int unit) const {
    const GlApi& gl = handle_.gl();
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    checkGl(gl, "glActiveTexture(GL_TEXTURE0 + " + std::to_string(unit) + ")");
    gl.BindTexture(GL_TEXTURE_2D, handle_.id());
    gl.ActiveTexture(GL_TEXTURE0);
  }
  GLuint id() const { return handle_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int levelCount() const { return levels_; }

 private:
  GlHandle<detail::DeleteTexture> handle_;
  int width_ = 0, height_ = 0, levels_ = 0;

  static GLuint create(const GlApi& gl) {
    GLuint id = 0;
    gl.GenTextures(1, &id);
    if (id == 0) throw Error("glGenTextures failed; is a context current?");
    return id;
  }
};

inline const char* framebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "unknown framebuffer status";
  }
}

// Throws Error unless the framebuffer bound to GL_FRAMEBUFFER is complete:
// "<what>: glCheckFramebufferStatus returned GL_FRAMEBUFFER_INCOMPLETE_...".
inline void checkFramebufferComplete(const GlApi& gl, const std::string& what) {
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Error(what + ": glCheckFramebufferStatus returned " + framebufferStatusName(status) +
                (status == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT
                     ? " (an attachment has a zero size or a format that cannot be rendered to)"
                     : ""));
}

// A framebuffer that draws into level `lod` of a 2D texture through colour attachment 0 (a pyramid's level),
// checked complete; GL_FRAMEBUFFER is left unbound. `what` names it in errors.
inline GlHandle<detail::DeleteFramebuffer> levelFramebuffer(const GlApi& gl, GLuint texture, int lod,
                                                           const std::string& what) {
  GLuint fbo = 0;
  gl.GenFramebuffers(1, &fbo);
  GlHandle<detail::DeleteFramebuffer> handle(gl, fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, lod);
  const GLenum buf = GL_COLOR_ATTACHMENT0;
  gl.DrawBuffers(1, &buf);
  checkFramebufferComplete(gl, what + " level " + std::to_string(lod) + " framebuffer");
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  return handle;
}

// The RGBA float texels of a size.x x size.y level drawn by `fbo` (levelFramebuffer), read back.
inline snell::Image readLevelFramebuffer(const GlApi& gl, GLuint fbo, glm::ivec2 size, const std::string& what) {
  snell::Image img(size.x, size.y);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.ReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, img.texels.data());
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGl(gl, what + " (glReadPixels)");
  return img;
}

// An off-screen render target: RGBA32F colour attachments (float, so shading
// results come back unquantized) and a DEPTH_COMPONENT32F depth texture
// (a texture, not a renderbuffer, so refraction passes can sample it).
class Framebuffer {
 public:
  Framebuffer(const GlApi& gl, int width, int height, int colorAttachments = 1, bool depth = true)
      : gl_(&gl), width_(width), height_(height) {
    if (width <= 0 || height <= 0)
      throw Error("snell::gpu::Framebuffer: size " + std::to_string(width) + "x" + std::to_string(height) +
                  "; both must be positive");
    GLuint fbo = 0;
    gl.GenFramebuffers(1, &fbo);
    if (fbo == 0) throw Error("glGenFramebuffers failed; is a context current?");
    fbo_ = GlHandle<detail::DeleteFramebuffer>(gl, fbo);
    GLint maxColor = 0;
    gl.GetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &maxColor);
    if (colorAttachments < 0 || colorAttachments > maxColor)
      throw Error("snell::gpu::Framebuffer: " + std::to_string(colorAttachments) + " colour attachments requested, " +
                  "the driver allows " + std::to_string(maxColor));
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> drawBuffers;
    for (int i = 0; i < colorAttachments; ++i) {
      colors_.push_back(makeTexture(GL_RGBA32F, GL_RGBA, GL_FLOAT, "GL_RGBA32F"));
      const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
      gl.FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, colors_.back().id(), 0);
      drawBuffers.push_back(attachment);
    }
    if (depth) {
      depth_ = makeTexture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, "GL_DEPTH_COMPONENT32F");
      gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
    }
    if (drawBuffers.empty()) drawBuffers.push_back(GL_NONE);
    gl.DrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    gl.ReadBuffer(colorAttachments > 0 ? GL_COLOR_ATTACHMENT0 : GL_NONE);
    checkFramebufferComplete(gl, "snell::gpu::Framebuffer " + std::to_string(width) + "x" + std::to_string(height));
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl(gl, "Framebuffer creation");
  }

  // Binds for drawing and reading and sets the viewport to the whole target.
  void bind() const {
    gl_->BindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    gl_->Viewport(0, 0, width_, height_);
  }
  void clearColor(int attachment, const glm::vec4& c) const {
    // GL ignores a clear of a draw buffer that has no attachment: say so instead.
    if (attachment < 0 || attachment >= static_cast<int>(colors_.size()))
      throw Error("snell::gpu::Framebuffer::clearColor: no colour attachment " + std::to_string(attachment));
    bind();
    gl_->ClearBufferfv(GL_COLOR, attachment, &c[0]);
  }
  void clearDepth(float d = 1.0f) const {
    bind();
    gl_->ClearBufferfv(GL_DEPTH, 0, &d);
  }

  // Colour attachment `attachment` as a snell::Image (bottom row first).
  snell::Image readColor(int attachment = 0) const {
    if (attachment < 0 || attachment >= static_cast<int>(colors_.size()))
      throw Error("snell::gpu::Framebuffer::readColor: no colour attachment " + std::to_string(attachment));
    snell::Image img(width_, height_);
    bind();
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(attachment));
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, img.texels.data());
    gl_->ReadBuffer(GL_COLOR_ATTACHMENT0);
    checkGl(*gl_, "Framebuffer::readColor (glReadPixels)");
    return img;
  }
  // The depth attachment as a snell::Image: depth in x, y = z = w = 0.
  snell::Image readDepth() const {
    if (!depth_.id()) throw Error("snell::gpu::Framebuffer::readDepth: the framebuffer has no depth attachment");
    std::vector<float> d(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    bind();
    gl_->PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_->ReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, d.data());
    checkGl(*gl_, "Framebuffer::readDepth (glReadPixels)");
    snell::Image img(width_, height_);
    for (std::size_t i = 0; i < d.size(); ++i) img.texels[i] = glm::vec4(d[i], 0.0f, 0.0f, 0.0f);
    return img;
  }

  GLuint id() const { return fbo_.id(); }
  GLuint colorTexture(int attachment = 0) const { return colors_.at(static_cast<std::size_t>(attachment)).id(); }
  GLuint depthTexture() const { return depth_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const GlApi* gl_;
  int width_, height_;
  GlHandle<detail::DeleteFramebuffer> fbo_;
  std::vector<GlHandle<detail::DeleteTexture>> colors_;
  GlHandle<detail::DeleteTexture> depth_;

  // `formatName` is for messages.
  GlHandle<detail::DeleteTexture> makeTexture(GLenum internalFormat, GLenum format, GLenum type,
                                              const char* formatName) const {
    GLuint id = 0;
    gl_->GenTextures(1, &id);
    if (id == 0) throw Error("glGenTextures failed; is a context current?");
    GlHandle<detail::DeleteTexture> texture(*gl_, id);
    const detail::BindingRestorer restore(*gl_);
    gl_->BindTexture(GL_TEXTURE_2D, id);
    gl_->TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width_, height_, 0, format, type, nullptr);
    // Past GL_MAX_TEXTURE_SIZE (or memory) the texture has no image: report
    // the call here, not as an incomplete framebuffer plus a stale GL error.
    checkGl(*gl_, std::string("glTexImage2D(") + formatName + ", " + std::to_string(width_) + "x" +
                      std::to_string(height_) + ") for a snell::gpu::Framebuffer attachment");
    // One level and NEAREST: complete without mips, and sampling it reads texels as stored.
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
  }
};

// Core profile draws need a bound vertex array object even when the vertex
// shader makes its vertices from gl_VertexID (the usual full-screen triangle).
class VertexArray {
 public:
  explicit VertexArray(const GlApi& gl) : handle_(gl, create(gl)) {}
  void bind() const { handle_.gl().BindVertexArray(handle_.id()); }
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle<detail::DeleteVertexArray> handle_;
  static GLuint create(const GlApi& gl) {
    GLuint id = 0;
    gl.GenVertexArrays(1, &id);
    if (id == 0) throw Error("glGenVertexArrays failed; is a context current?");
    return id;
  }
};

}  // namespace snell::gpu
