#include "gpu_lab.hpp"

#include "technique.hpp"

#include "lab/error.hpp"

#include <snell/gpu/context.hpp>
#include <snell/gpu/depth_pyramid_pass.hpp>
#include <snell/gpu/include_flattener.hpp>
#include <snell/gpu/program.hpp>
#include <snell/gpu/resources.hpp>
#include <snell/technique_table.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <limits>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {
// Whether any painting reaches inside the object: a 9 x 9 grid of points over each (the techniques then
// search the scene from the entry point too, SnellTechnique.insideScene).
bool paintingInsideMesh(const std::vector<Painting>& paintings, const Mesh& object) {
  for (const Painting& painting : paintings) {
    const std::array<vec3, 4> c = painting.corners();
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j) {
        const double u = i / 8.0, v = j / 8.0;
        const glm::dvec3 bottom = glm::mix(glm::dvec3(c[0]), glm::dvec3(c[1]), u);
        const glm::dvec3 top = glm::mix(glm::dvec3(c[3]), glm::dvec3(c[2]), u);
        if (pointInsideMesh(object, glm::mix(bottom, top, v))) return true;
      }
  }
  return false;
}
}  // namespace

ShadeConstants shadeConstants(const SceneFrame& frame, int margin) {
  // GL gets the camera's float matrices: refuse non-finite ones here (the
  // scene loader already does, naming the field) instead of drawing nothing.
  const std::string problem = cameraProblem(frame.camera);
  if (!problem.empty()) throw Error(ErrorKind::Render, "GL passes: camera: " + problem);
  ShadeConstants k;
  k.margin = std::max(0, margin);
  const float W = static_cast<float>(frame.camera.width), H = static_cast<float>(frame.camera.height);
  mat4 shrink(1.0f);
  shrink[0][0] = W / (W + 2.0f * static_cast<float>(k.margin));
  shrink[1][1] = H / (H + 2.0f * static_cast<float>(k.margin));
  k.viewFromWorld = frame.camera.viewFromWorld();
  k.clipFromView = frame.camera.clipFromView();
  k.params.clipFromView = shrink * k.clipFromView;
  k.params.zNear = frame.camera.zNear;
  k.params.zFar = frame.camera.zFar;
  k.params.ior = frame.ior;
  k.params.absorption = frame.absorption;
  // Environment lookups take world directions: world-from-view, then the
  // environment's rotation about +Y (environment.hpp: phi = atan2(x, -z) - rotation,
  // i.e. the direction turned by +rotation about Y).
  const mat3 worldFromView = mat3(frame.camera.worldFromView());
  const mat3 rotate = mat3(glm::rotate(mat4(1.0f), glm::radians(frame.environment.rotationDegrees()), vec3(0, 1, 0)));
  const mat3 m = rotate * worldFromView;
  k.params.envX = m[0];
  k.params.envY = m[1];
  k.params.envZ = m[2];
  const Bounds box = meshBounds(frame.object);
  k.params.backRange = box.diagonal();
  // The Behind layer's clip plane: the object's nearest vertex along the view axis.
  float nearest = std::numeric_limits<float>::max();
  for (const vec3& p : frame.object.positions) nearest = std::min(nearest, -(k.viewFromWorld * vec4(p, 1.0f)).z);
  k.objectNearDistance = frame.object.positions.empty() ? 0.0f : std::max(0.0f, nearest);
  // Every exit ray starts inside the object and ends on the object or the opaque scene (else it leaves
  // the scene): the diagonal of the box around both bounds how far it can travel to a hit.
  vec3 lo = box.lo, hi = box.hi;
  for (const Painting& painting : frame.paintings)
    for (const vec3& c : painting.corners()) {
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  k.params.exitRange = glm::length(hi - lo);
  k.params.insideScene = paintingInsideMesh(frame.paintings, frame.object) ? 1 : 0;
  const vec3 half = glm::max(0.5f * (hi - lo), vec3(1e-6f));
  k.params.proxyFromView = glm::scale(mat4(1.0f), 1.0f / half) * glm::translate(mat4(1.0f), -0.5f * (lo + hi)) *
                           frame.camera.worldFromView();
  return k;
}

Texture2D environmentTexture(const SceneFrame& frame) {
  Image img = frame.environment.image();
  const float s = frame.environment.intensity();
  for (vec4& t : img.texels) t = vec4(vec3(t) * s, 1.0f);
  return Texture2D(std::move(img), Filter::Linear);
}

namespace {

// lab_refract.frag's layout(std140, binding = 0) uniform LabUniforms { LabParams params; }: the C++ struct's
// bytes are its std140 layout, field by field (a vec3 starts on 16 bytes, a float after it fills the slot).
constexpr GLuint kLabUniformsBinding = 0;
static_assert(offsetof(LabParams, clipFromView) == 0 && offsetof(LabParams, proxyFromView) == 64 &&
                  offsetof(LabParams, absorption) == 128 && offsetof(LabParams, zNear) == 140 &&
                  offsetof(LabParams, envX) == 144 && offsetof(LabParams, zFar) == 156 &&
                  offsetof(LabParams, envY) == 160 && offsetof(LabParams, ior) == 172 &&
                  offsetof(LabParams, envZ) == 176 && offsetof(LabParams, backRange) == 188 &&
                  offsetof(LabParams, exitRange) == 192 && offsetof(LabParams, depthFilter) == 196 &&
                  offsetof(LabParams, reflectSource) == 200 && offsetof(LabParams, insideScene) == 204 &&
                  sizeof(LabParams) == 208,
              "LabParams must keep the std140 layout of the uniform block LabUniforms");

gpu::FlatSource flatten(const fs::path& file, const ShaderDirs& dirs, const std::vector<std::string>& defines = {}) {
  return gpu::flattenGlslFile(file, {dirs.snellGlsl, dirs.labGlsl}, defines);
}

}  // namespace

struct GpuLab::Impl {
  gpu::Context ctx;
  const gpu::GlApi& gl;
  int width, height;
  ShadeConstants k;
  int bufferWidth, bufferHeight;
  std::vector<LabShader> shaders;
  GLsizei vertexCount = 0;
  gpu::StorageBuffer positions, normals, indices;
  gpu::Texture environment;
  std::vector<gpu::Texture> paintingTextures;
  std::vector<std::array<vec3, 4>> paintingCorners;
  gpu::Program background, scene, back;
  gpu::DepthPyramidPass pyramidPass;
  std::vector<gpu::Program> refract;
  gpu::Framebuffer sceneFb, fullFb, backFb, objectFrontFb, frontFb;
  gpu::DepthPyramid scenePyramid, fullPyramid, backPyramid;
  gpu::VertexArray vao;
  gpu::UniformBuffer labUniforms;

  Impl(const std::string& backend, const SceneFrame& frame, const std::vector<float>& dN,
       const std::vector<LabShader>& programs, const ShaderDirs& dirs, const ShadeConstants& constants)
      : ctx(gpu::parseBackend(backend)),
        gl(ctx.gl()),
        width(frame.camera.width),
        height(frame.camera.height),
        k(constants),
        bufferWidth(width + 2 * k.margin),
        bufferHeight(height + 2 * k.margin),
        shaders(programs),
        positions(gl),
        normals(gl),
        indices(gl),
        environment(gl, environmentTexture(frame)),
        background(gpu::Program::graphics(gl, flatten(dirs.snellGlsl / "passes" / "fullscreen.vert", dirs),
                                          flatten(dirs.labGlsl / "lab_background.frag", dirs))),
        scene(gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_scene.vert", dirs),
                                     flatten(dirs.labGlsl / "lab_scene.frag", dirs))),
        back(gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_mesh.vert", dirs),
                                    flatten(dirs.labGlsl / "lab_back.frag", dirs))),
        pyramidPass(gl, dirs.snellGlsl),
        sceneFb(gl, bufferWidth, bufferHeight, 2, true),
        fullFb(gl, bufferWidth, bufferHeight, 2, true),
        backFb(gl, bufferWidth, bufferHeight, 1, true),
        objectFrontFb(gl, bufferWidth, bufferHeight, 1, true),
        frontFb(gl, width, height, 4, true),
        scenePyramid(gl, bufferWidth, bufferHeight),
        fullPyramid(gl, bufferWidth, bufferHeight),
        backPyramid(gl, bufferWidth, bufferHeight),
        vao(gl),
        labUniforms(gl, &k.params, sizeof(LabParams)) {
    // The mesh: positions (w = d_N), normals, indices, pulled by gl_VertexID.
    const Mesh& m = frame.object;
    std::vector<glm::vec4> p(m.vertexCount()), n(m.vertexCount());
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
      p[i] = glm::vec4(m.positions[i], i < dN.size() ? dN[i] : 0.0f);
      n[i] = glm::vec4(m.normals[i], 0.0f);
    }
    positions.upload(p);
    normals.upload(n);
    indices.upload(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
    vertexCount = static_cast<GLsizei>(m.indices.size());
    for (const Painting& painting : frame.paintings) {
      paintingTextures.emplace_back(gl, painting.texture);
      paintingCorners.push_back(painting.corners());
    }
    // The scene colour is read with bilinear filtering (no mips) on both sides.
    for (GLuint colorTexture : {sceneFb.colorTexture(0), fullFb.colorTexture(0)}) {
      gl.BindTexture(GL_TEXTURE_2D, colorTexture);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    const GLint normalGl = k.normalFilter == NormalFilter::Linear ? GL_LINEAR : GL_NEAREST;
    for (GLuint normalTexture :
         {backFb.colorTexture(0), objectFrontFb.colorTexture(0), sceneFb.colorTexture(1), fullFb.colorTexture(1)}) {
      gl.BindTexture(GL_TEXTURE_2D, normalTexture);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, normalGl);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, normalGl);
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);

    background.set("viewFromClip", glm::inverse(k.params.clipFromView));
    background.set("envX", k.params.envX);
    background.set("envY", k.params.envY);
    background.set("envZ", k.params.envZ);
    background.set("viewport", vec2(static_cast<float>(bufferWidth), static_cast<float>(bufferHeight)));
    scene.set("viewFromWorld", k.viewFromWorld);
    scene.set("clipFromView", k.params.clipFromView);
    back.set("viewFromWorld", k.viewFromWorld);
    back.set("clipFromView", k.params.clipFromView);

    // Both buffers come from the lab's perspective camera: the programs leave
    // out the general projection path (the same results; llvmpipe would run
    // both paths). Checked, so another camera would only cost time.
    const bool perspective =
        snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f).perspective;
    for (const LabShader& shader : shaders) {
      // Only the strategies the row's slots call: the same code paths, compiled in a fraction of the time. An
      // engine row's only slot is the reflection's: the normal plane (2 it.) preset's (lab_technique.glsl).
      const int id = shader.engineModel >= 0 ? SNELL_TECHNIQUE_PLANE_NORMAL_2 : shader.technique;
      if (snellFindTechnique(id) == nullptr) throw gpu::Error("snell-lab: no technique has id " + std::to_string(id));
      if (shader.engineModel >= SNELL_ENGINE_MODEL_COUNT)
        throw gpu::Error("snell-lab: no engine model has id " + std::to_string(shader.engineModel));
      const bool reference = shader.engineModel < 0 && shader.reference;
      std::vector<std::string> defines = {
          "LAB_TECHNIQUE " + std::to_string(id), std::string("LAB_REFERENCE ") + (reference ? "true" : "false"),
          "LAB_ENGINE_MODEL " + std::to_string(shader.engineModel),
          "SNELL_INTERSECT_STRATEGIES " +
              std::to_string(snellStrategiesUsed(labTechnique(id, reference, k.params), labMaterial(k.params)))};
      if (perspective) defines.push_back("SNELL_PERSPECTIVE_ONLY 1");
      gpu::Program prog = gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_mesh.vert", dirs),
                                                 flatten(dirs.labGlsl / "lab_refract.frag", dirs, defines));
      prog.set("viewFromWorld", k.viewFromWorld);
      prog.set("clipFromView", k.clipFromView);
      prog.requireUniformBlock("LabUniforms", kLabUniformsBinding, sizeof(LabParams));
      if (shader.engineModel >= 0) prog.set("labEngineParameter", 0.0f);
      refract.push_back(std::move(prog));
    }
    gpu::checkGl(gl, "lab setup");
  }

  void bindMesh() const {
    positions.bindBase(0);
    normals.bindBase(1);
    indices.bindBase(2);
  }

  // (1) The opaque scene: environment background (depth untouched), then the paintings, those nearer than
  // `clipNearerThan` (a view distance; 0: none) clipped away.
  void drawScene(const gpu::Framebuffer& fb, float clipNearerThan, bool peel = false) {
    fb.clearColor(0, vec4(0.0f));
    fb.clearColor(1, vec4(0.0f));
    fb.clearDepth(1.0f);
    fb.bind();
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_DEPTH_TEST);
    gl.DepthMask(GL_FALSE);
    environment.bind(0);
    background.use();
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    scene.use();
    scene.set("clipNearerThan", clipNearerThan);
    scene.set("peel", peel ? 1 : 0);
    if (peel) {
      gl.ActiveTexture(GL_TEXTURE1);
      gl.BindTexture(GL_TEXTURE_2D, backFb.depthTexture());
      gl.ActiveTexture(GL_TEXTURE0);
    }
    if (clipNearerThan > 0.0f) gl.Enable(GL_CLIP_DISTANCE0);
    for (std::size_t i = 0; i < paintingTextures.size(); ++i) {
      paintingTextures[i].bind(0);
      for (int c = 0; c < 4; ++c) scene.set("corners[" + std::to_string(c) + "]", paintingCorners[i][static_cast<std::size_t>(c)]);
      gl.DrawArrays(GL_TRIANGLES, 0, 6);
    }
    gl.Disable(GL_CLIP_DISTANCE0);
    gpu::checkGl(gl, "scene pass");
  }

  void drawStatic() {
    vao.bind();
    // (1) The whole opaque scene (the layer snell's rows read after the back faces: Peeled reads them).
    drawScene(fullFb, 0.0f);
    // (2) The object's back faces: nearest-to-camera test reversed.
    backFb.clearColor(0, vec4(0.0f));
    backFb.clearDepth(0.0f);
    backFb.bind();
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_GREATER);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_FRONT);
    back.use();
    bindMesh();
    gl.DrawArrays(GL_TRIANGLES, 0, vertexCount);
    gl.CullFace(GL_BACK);
    gl.DepthFunc(GL_LESS);
    gpu::checkGl(gl, "back-face pass");
    // (2b) The object's front faces, for the rays that bounce inside.
    objectFrontFb.clearColor(0, vec4(0.0f));
    objectFrontFb.clearDepth(1.0f);
    objectFrontFb.bind();
    gl.DrawArrays(GL_TRIANGLES, 0, vertexCount);
    gpu::checkGl(gl, "front-face pass");
    // (1b) The layer of the scene snell's rows read.
    drawScene(sceneFb, k.sceneLayer == SceneLayer::Behind ? k.objectNearDistance : 0.0f,
              k.sceneLayer == SceneLayer::Peeled);
    // (3) Both depth pyramids.
    pyramidPass.build(backPyramid, backFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f);
    pyramidPass.build(scenePyramid, sceneFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
    pyramidPass.build(fullPyramid, fullFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // Before pass 4 (not timed: an engine draws its glass into the depth its opaque pass left): the glass is
  // drawn where it is nearer than the whole opaque scene, whose depth (the viewport's part of the
  // guard-banded buffer, texel for texel) becomes the pass's depth.
  void prepareTechnique() {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fullFb.id());
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, frontFb.id());
    gl.BlitFramebuffer(k.margin, k.margin, k.margin + width, k.margin + height, 0, 0, width, height,
                       GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    gpu::checkGl(gl, "depth copy before the refraction pass");
  }

  void drawTechnique(std::size_t index) {
    frontFb.bind();
    const vec4 zero(0.0f);
    for (int a = 0; a < 4; ++a) gl.ClearBufferfv(GL_COLOR, a, &zero[0]);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_BACK);
    const gpu::Framebuffer& sceneRead = shaders.at(index).readsFullScene() ? fullFb : sceneFb;
    const gpu::DepthPyramid& pyramidRead = shaders.at(index).readsFullScene() ? fullPyramid : scenePyramid;
    const GLuint units[10] = {backFb.depthTexture(),     backFb.colorTexture(0),     backPyramid.texture(),
                              sceneRead.depthTexture(),  sceneRead.colorTexture(1),  pyramidRead.texture(),
                              sceneRead.colorTexture(0), environment.id(),           objectFrontFb.depthTexture(),
                              objectFrontFb.colorTexture(0)};
    for (int u = 0; u < 10; ++u) {
      gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
      gl.BindTexture(GL_TEXTURE_2D, units[u]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
    vao.bind();
    bindMesh();
    labUniforms.bindBase(kLabUniformsBinding);
    refract.at(index).use();
    gl.DrawArrays(GL_TRIANGLES, 0, vertexCount);
  }
};

GpuLab::GpuLab(const std::string& backend, const SceneFrame& frame, const std::vector<float>& dN,
               const std::vector<LabShader>& shaders, const ShaderDirs& dirs, const ShadeConstants& k)
    : impl_(std::make_unique<Impl>(backend, frame, dN, shaders, dirs, k)) {}

GpuLab::~GpuLab() = default;

std::string GpuLab::description() const {
  return std::string(gpu::backendName(impl_->ctx.backend())) + ", " + impl_->ctx.renderer() + ", OpenGL " +
         impl_->ctx.version();
}

double GpuLab::renderStatic() {
  impl_->gl.Finish();
  const auto t0 = std::chrono::steady_clock::now();
  impl_->drawStatic();
  impl_->gl.Finish();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

StaticBuffers GpuLab::readStatic() const {
  StaticBuffers b;
  b.sceneColor = impl_->sceneFb.readColor(0);
  b.sceneNormal = impl_->sceneFb.readColor(1);
  b.sceneDepth = impl_->sceneFb.readDepth();
  b.fullColor = impl_->fullFb.readColor(0);
  b.fullNormal = impl_->fullFb.readColor(1);
  b.fullDepth = impl_->fullFb.readDepth();
  b.backNormal = impl_->backFb.readColor(0);
  b.backDepth = impl_->backFb.readDepth();
  b.frontNormal = impl_->objectFrontFb.readColor(0);
  b.frontDepth = impl_->objectFrontFb.readDepth();
  return b;
}

double GpuLab::renderTechnique(std::size_t index) {
  impl_->prepareTechnique();
  impl_->gl.Finish();
  const auto t0 = std::chrono::steady_clock::now();
  impl_->drawTechnique(index);
  impl_->gl.Finish();
  const auto t1 = std::chrono::steady_clock::now();
  gpu::checkGl(impl_->gl, "refraction pass");
  return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

void GpuLab::setEngineParameter(std::size_t index, float value) {
  if (index >= impl_->shaders.size() || impl_->shaders[index].engineModel < 0)
    throw gpu::Error("snell-lab: program " + std::to_string(index) + " runs no engine model");
  impl_->refract.at(index).set("labEngineParameter", value);
}

TechniqueBuffers GpuLab::readTechnique() const {
  TechniqueBuffers b;
  b.color = impl_->frontFb.readColor(0);
  b.stats = impl_->frontFb.readColor(1);
  b.position = impl_->frontFb.readColor(2);
  b.normal = impl_->frontFb.readColor(3);
  return b;
}

}  // namespace snell::lab
