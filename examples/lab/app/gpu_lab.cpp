#include "gpu_lab.hpp"

#include "technique.hpp"

#include "lab/error.hpp"

#include <snell/color_pyramid.hpp>
#include <snell/gpu/color_pyramid_pass.hpp>
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
// Whether any painting reaches inside the object (the techniques then search the scene from the entry
// point too, SnellTechnique.insideScene): on a quad, or any painting of two triangles, a grid of 1/8 steps
// over each triangle (over a parallelogram, the 9 x 9 grid of its corners' bilinear blend); on a larger
// mesh, up to 256 of its vertices spread over the list.
bool paintingInsideMesh(const std::vector<Painting>& paintings, const Mesh& object) {
  for (const Painting& painting : paintings) {
    if (painting.triangleCount() <= 2) {
      for (std::size_t t = 0; t < painting.triangleCount(); ++t) {
        const glm::dvec3 a(painting.positions[painting.indices[3 * t]]);
        const glm::dvec3 b(painting.positions[painting.indices[3 * t + 1]]);
        const glm::dvec3 c(painting.positions[painting.indices[3 * t + 2]]);
        for (int i = 0; i <= 8; ++i)
          for (int j = 0; i + j <= 8; ++j)
            if (pointInsideMesh(object, a + (i / 8.0) * (b - a) + (j / 8.0) * (c - a))) return true;
      }
      continue;
    }
    const std::size_t n = painting.positions.size(), step = std::max<std::size_t>(1, n / 256);
    for (std::size_t i = 0; i < n; i += step)
      if (pointInsideMesh(object, glm::dvec3(painting.positions[i]))) return true;
  }
  return false;
}

// Whether `inner` lies inside `outer`: up to 64 of its vertices, spread over the list, all inside.
bool meshInsideMesh(const Mesh& inner, const Mesh& outer) {
  const std::size_t n = inner.positions.size(), step = std::max<std::size_t>(1, n / 64);
  for (std::size_t i = 0; i < n; i += step)
    if (!pointInsideMesh(outer, glm::dvec3(inner.positions[i]))) return false;
  return n > 0;
}

// Whether any vertex of `inner` lies inside `outer` (an object reaching into another).
bool meshReachesInto(const Mesh& inner, const Mesh& outer) {
  const std::size_t n = inner.positions.size(), step = std::max<std::size_t>(1, n / 256);
  for (std::size_t i = 0; i < n; i += step)
    if (pointInsideMesh(outer, glm::dvec3(inner.positions[i]))) return true;
  return false;
}
}  // namespace

ShadeConstants shadeConstants(const SceneFrame& frame, std::size_t object, int margin) {
  // GL gets the camera's float matrices: refuse non-finite ones here (the
  // scene loader already does, naming the field) instead of drawing nothing.
  const std::string problem = cameraProblem(frame.camera);
  if (!problem.empty()) throw Error(ErrorKind::Render, "GL passes: camera: " + problem);
  if (object >= frame.objects.size())
    throw Error(ErrorKind::Render, "GL passes: no refractive object " + std::to_string(object) + " (the frame has " +
                                       std::to_string(frame.objects.size()) + ")");
  const FrameObject& o = frame.objects[object];
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
  // Nested media: the innermost object that holds this one (the smallest by volume).
  double enclosingVolume = 0.0;
  for (std::size_t j = 0; j < frame.objects.size(); ++j) {
    if (j == object || !meshInsideMesh(o.mesh, frame.objects[j].mesh)) continue;
    const double volume = signedVolume(frame.objects[j].mesh);
    if (k.enclosing < 0 || volume < enclosingVolume) {
      k.enclosing = static_cast<int>(j);
      enclosingVolume = volume;
    }
  }
  // An object inside another is drawn with its own index against air, not the ratio to the outer one's:
  // its pass sees camera rays, which the outer wall has not bent, and the tangential part of a ray that
  // Snell keeps across a thin or flat outer wall makes n_outer sin(a_outer) = sin(a_air), so the ratio
  // n_inner / n_outer on the bent ray is the index n_inner on the unbent one. Measured on the bundled
  // nested scenes (the composited floor vs the full ray trace): snow_globe 0.098 with the index against
  // air, 0.171 with the ratio; cube_sphere 0.145 and 0.148.
  k.params.ior = o.ior;
  k.params.iors = channelIors(o);
  k.params.dispersion = dispersive(o) ? 1 : 0;
  k.params.absorption = o.absorption;
  // Rough: the blurred reads need the scene colour's and the environment's mip chains (what the lab builds
  // when an object is rough: GpuLab's scene layer and environmentTexture).
  k.params.roughness = o.roughness;
  if (roughObjects(frame)) {
    k.params.sceneColorLevels = mipLevels(frame.camera.width + 2 * k.margin, frame.camera.height + 2 * k.margin);
    k.params.environmentLevels = mipLevels(frame.environment.image().width, frame.environment.image().height);
  }
  // Environment lookups take world directions: world-from-view, then the
  // environment's rotation about +Y (environment.hpp: phi = atan2(x, -z) - rotation,
  // i.e. the direction turned by +rotation about Y).
  const mat3 worldFromView = mat3(frame.camera.worldFromView());
  const mat3 rotate = mat3(glm::rotate(mat4(1.0f), glm::radians(frame.environment.rotationDegrees()), vec3(0, 1, 0)));
  const mat3 m = rotate * worldFromView;
  k.params.envX = m[0];
  k.params.envY = m[1];
  k.params.envZ = m[2];
  const Bounds box = meshBounds(o.mesh);
  k.params.backRange = box.diagonal();
  // The Behind layer's clip plane: the object's nearest vertex along the view axis.
  float nearest = std::numeric_limits<float>::max();
  for (const vec3& p : o.mesh.positions) nearest = std::min(nearest, -(k.viewFromWorld * vec4(p, 1.0f)).z);
  k.objectNearDistance = o.mesh.positions.empty() ? 0.0f : std::max(0.0f, nearest);
  // Every exit ray starts inside the object and ends on an object or the opaque scene (else it leaves
  // the scene): the diagonal of the box around them all bounds how far it can travel to a hit.
  vec3 lo = box.lo, hi = box.hi;
  for (const FrameObject& other : frame.objects) {
    const Bounds b = meshBounds(other.mesh);
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  for (const Painting& painting : frame.paintings)
    for (const vec3& c : painting.positions) {
      lo = glm::min(lo, c);
      hi = glm::max(hi, c);
    }
  k.params.exitRange = glm::length(hi - lo);
  bool inside = paintingInsideMesh(frame.paintings, o.mesh);
  for (std::size_t j = 0; j < frame.objects.size() && !inside; ++j)
    inside = j != object && meshReachesInto(frame.objects[j].mesh, o.mesh);
  k.params.insideScene = inside ? 1 : 0;
  const vec3 half = glm::max(0.5f * (hi - lo), vec3(1e-6f));
  k.params.proxyFromView = glm::scale(mat4(1.0f), 1.0f / half) * glm::translate(mat4(1.0f), -0.5f * (lo + hi)) *
                           frame.camera.worldFromView();
  return k;
}

std::vector<std::size_t> drawOrder(const std::vector<ShadeConstants>& objects) {
  std::vector<std::size_t> order(objects.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return objects[a].objectNearDistance > objects[b].objectNearDistance;
  });
  return order;
}

bool roughObjects(const SceneFrame& frame) {
  for (const FrameObject& o : frame.objects)
    if (o.roughness > 0.0f) return true;
  return false;
}

int mipLevels(int width, int height) {
  int levels = 1;
  for (int s = std::max(width, height); s > 1; s /= 2) ++levels;
  return levels;
}

Image environmentImage(const SceneFrame& frame) {
  Image img = frame.environment.image();
  const float s = frame.environment.intensity();
  for (vec4& t : img.texels) t = vec4(vec3(t) * s, 1.0f);
  return img;
}

Texture2D environmentTexture(const SceneFrame& frame) {
  if (!roughObjects(frame)) return Texture2D(environmentImage(frame), Filter::Linear);
  return snellBuildColorPyramid(environmentImage(frame));
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
                  offsetof(LabParams, iors) == 208 && offsetof(LabParams, dispersion) == 220 &&
                  offsetof(LabParams, roughness) == 224 && offsetof(LabParams, sceneColorLevels) == 228 &&
                  offsetof(LabParams, environmentLevels) == 232 && sizeof(LabParams) == 240,
              "LabParams must keep the std140 layout of the uniform block LabUniforms");

gpu::FlatSource flatten(const fs::path& file, const ShaderDirs& dirs, const std::vector<std::string>& defines = {}) {
  return gpu::flattenGlslFile(file, {dirs.snellGlsl, dirs.labGlsl}, defines);
}

}  // namespace

// The buffer texels an object's faces can cover: the rectangle around its vertices' projections through
// clipFromView (x0, y0, x1, y1, exclusive ends), one texel wider on every side for rasterization at its
// edges, clamped to the buffer; the whole buffer when a vertex lies on or behind the camera plane.
ivec4 screenRectangle(const Mesh& m, const mat4& viewFromWorld, const mat4& clipFromView, int width, int height) {
  const ivec4 whole(0, 0, width, height);
  if (m.positions.empty()) return ivec4(0);
  vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const vec3& p : m.positions) {
    const vec4 c = clipFromView * (viewFromWorld * vec4(p, 1.0f));
    if (!(c.w > 1e-6f)) return whole;
    const vec2 ndc = vec2(c) / c.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  const vec2 size(static_cast<float>(width), static_cast<float>(height));
  const vec2 a = glm::floor((lo * 0.5f + 0.5f) * size) - 1.0f, b = glm::ceil((hi * 0.5f + 0.5f) * size) + 1.0f;
  const ivec2 x0 = glm::clamp(ivec2(glm::max(a, vec2(-1.0f))), ivec2(0), ivec2(width, height));
  const ivec2 x1 = glm::clamp(ivec2(glm::min(b, size + 1.0f)), ivec2(0), ivec2(width, height));
  return ivec4(x0, x1);
}

// One refractive object's own GPU state: its mesh, constants, back and front faces.
struct ObjectPasses {
  ShadeConstants k;
  // Where its back- and front-face passes and back-face pyramid run (screenRectangle): outside it, its
  // buffers stay as cleared when they were made.
  ivec4 rect;
  gpu::StorageBuffer positions, normals, indices;
  GLsizei vertexCount = 0;
  gpu::Framebuffer backFb, frontFb;
  gpu::DepthPyramid backPyramid;
  gpu::UniformBuffer uniforms;
  std::size_t meshBytes = 0;

  ObjectPasses(const gpu::GlApi& gl, const Mesh& m, const std::vector<float>& dN, const ShadeConstants& constants,
               int bufferWidth, int bufferHeight)
      : k(constants),
        rect(screenRectangle(m, constants.viewFromWorld, constants.params.clipFromView, bufferWidth, bufferHeight)),
        positions(gl),
        normals(gl),
        indices(gl),
        backFb(gl, bufferWidth, bufferHeight, 1, true),
        frontFb(gl, bufferWidth, bufferHeight, 1, true),
        backPyramid(gl, bufferWidth, bufferHeight),
        uniforms(gl, &k.params, sizeof(LabParams)) {
    // The mesh: positions (w = d_N), normals, indices, pulled by gl_VertexID.
    std::vector<glm::vec4> p(m.vertexCount()), n(m.vertexCount());
    for (std::size_t i = 0; i < m.vertexCount(); ++i) {
      p[i] = glm::vec4(m.positions[i], i < dN.size() ? dN[i] : 0.0f);
      n[i] = glm::vec4(m.normals[i], 0.0f);
    }
    positions.upload(p);
    normals.upload(n);
    indices.upload(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
    vertexCount = static_cast<GLsizei>(m.indices.size());
    meshBytes = 2 * p.size() * sizeof(glm::vec4) + m.indices.size() * sizeof(std::uint32_t);
  }

  void bindMesh() const {
    positions.bindBase(0);
    normals.bindBase(1);
    indices.bindBase(2);
  }
};

// One painting on the GPU: its vertices pulled by gl_VertexID as the objects' are (lab_scene.vert).
struct PaintingBuffers {
  gpu::Texture texture;
  gpu::StorageBuffer positions, normals, indices;  // positions' w holds the uv's u, normals' w its v
  GLsizei vertexCount = 0;

  PaintingBuffers(const gpu::GlApi& gl, const Painting& painting)
      : texture(gl, painting.texture), positions(gl), normals(gl), indices(gl) {
    std::vector<glm::vec4> p(painting.positions.size()), n(painting.positions.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      p[i] = glm::vec4(painting.positions[i], painting.uvs[i].x);
      n[i] = glm::vec4(painting.normals[i], painting.uvs[i].y);
    }
    positions.upload(p);
    normals.upload(n);
    indices.upload(painting.indices.data(), painting.indices.size() * sizeof(std::uint32_t));
    vertexCount = static_cast<GLsizei>(painting.indices.size());
  }

  void bind() const {
    texture.bind(0);
    positions.bindBase(0);
    normals.bindBase(1);
    indices.bindBase(2);
  }
};

// Bytes of a depth pyramid's RGBA32F levels.
std::size_t pyramidBytes(const gpu::DepthPyramid& pyramid) {
  std::size_t bytes = 0;
  for (int lod = 0; lod < pyramid.levels(); ++lod)
    bytes += static_cast<std::size_t>(pyramid.size(lod).x) * static_cast<std::size_t>(pyramid.size(lod).y) * 16u;
  return bytes;
}

struct GpuLab::Impl {
  gpu::Context ctx;
  const gpu::GlApi& gl;
  int width, height;
  ShadeConstants k;  // what every object shares (camera, guard band, read modes); the object's own in objects[i]
  int bufferWidth, bufferHeight;
  bool rough = false;  // an object is rough: the scene layer's colour carries its mip chain
  std::vector<LabShader> shaders;
  gpu::Texture environment;
  std::vector<std::unique_ptr<PaintingBuffers>> paintings;
  gpu::Program background, scene, back, layer;
  gpu::DepthPyramidPass pyramidPass;
  std::vector<gpu::Program> refract;
  gpu::Framebuffer sceneFb, fullFb, passFb;
  gpu::DepthPyramid scenePyramid, fullPyramid;
  // With a rough object: the colour chains of the scene layer and of the whole scene (shade/color_pyramid.glsl),
  // over sceneFb's and fullFb's colour textures: declared after them, so destroyed first.
  std::unique_ptr<gpu::ColorPyramidPass> colorPyramidPass;
  std::unique_ptr<gpu::ColorPyramid> sceneColorPyramid, fullColorPyramid;
  gpu::VertexArray vao;
  std::vector<std::unique_ptr<ObjectPasses>> objects;
  std::unique_ptr<gpu::Texture> colorCopy;  // setColorCopy: what the engine rows read instead of fullFb's colour

  Impl(const std::string& backend, const SceneFrame& frame, const std::vector<std::vector<float>>& dN,
       const std::vector<LabShader>& programs, const ShaderDirs& dirs, const std::vector<ShadeConstants>& constants)
      : ctx(gpu::parseBackend(backend)),
        gl(ctx.gl()),
        width(frame.camera.width),
        height(frame.camera.height),
        k(constants.at(0)),
        bufferWidth(width + 2 * k.margin),
        bufferHeight(height + 2 * k.margin),
        shaders(programs),
        environment(gl, environmentTexture(frame)),
        background(gpu::Program::graphics(gl, flatten(dirs.snellGlsl / "passes" / "fullscreen.vert", dirs),
                                          flatten(dirs.labGlsl / "lab_background.frag", dirs))),
        scene(gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_scene.vert", dirs),
                                     flatten(dirs.labGlsl / "lab_scene.frag", dirs))),
        back(gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_mesh.vert", dirs),
                                    flatten(dirs.labGlsl / "lab_back.frag", dirs))),
        layer(gpu::Program::graphics(gl, flatten(dirs.labGlsl / "lab_mesh.vert", dirs),
                                     flatten(dirs.labGlsl / "lab_layer.frag", dirs))),
        pyramidPass(gl, dirs.snellGlsl),
        sceneFb(gl, bufferWidth, bufferHeight, 3, true),
        fullFb(gl, bufferWidth, bufferHeight, 3, true),
        passFb(gl, width, height, 4, true),
        scenePyramid(gl, bufferWidth, bufferHeight),
        fullPyramid(gl, bufferWidth, bufferHeight),
        vao(gl) {
    if (constants.size() != frame.objects.size())
      throw gpu::Error("snell-lab: " + std::to_string(constants.size()) + " sets of constants for " +
                       std::to_string(frame.objects.size()) + " objects");
    rough = roughObjects(frame);
    for (std::size_t i = 0; i < frame.objects.size(); ++i) {
      objects.push_back(std::make_unique<ObjectPasses>(gl, frame.objects[i].mesh, i < dN.size() ? dN[i] : std::vector<float>{},
                                                       constants[i], bufferWidth, bufferHeight));
      // Empty once, whole: each frame's passes then rewrite only the object's rectangle (an object that
      // moves would rewrite the union with its last rectangle).
      ObjectPasses& o = *objects.back();
      o.backFb.clearColor(0, vec4(0.0f));
      o.backFb.clearDepth(0.0f);
      o.frontFb.clearColor(0, vec4(0.0f));
      o.frontFb.clearDepth(1.0f);
      pyramidPass.build(o.backPyramid, o.backFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f);
    }
    for (const Painting& painting : frame.paintings) paintings.push_back(std::make_unique<PaintingBuffers>(gl, painting));
    // The scene colour is read with bilinear filtering (no mips) on both sides; with a rough object, through
    // the trilinear chains that drawStatic and drawLayer rebuild after each draw.
    for (GLuint colorTexture : {sceneFb.colorTexture(0), fullFb.colorTexture(0)}) {
      gl.BindTexture(GL_TEXTURE_2D, colorTexture);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    // With a rough object both colours carry the colour pyramid (trilinear): the chain snell's rough reads
    // expect, and the whole scene's, which the engine rows read through their engines' blurs
    // (engine_rough.glsl; Filament, HDRP and Godot build Gaussian chains of their own, three.js a box one).
    if (rough) {
      colorPyramidPass = std::make_unique<gpu::ColorPyramidPass>(gl, dirs.snellGlsl);
      sceneColorPyramid = std::make_unique<gpu::ColorPyramid>(gl, sceneFb.colorTexture(0), bufferWidth, bufferHeight);
      fullColorPyramid = std::make_unique<gpu::ColorPyramid>(gl, fullFb.colorTexture(0), bufferWidth, bufferHeight);
    }
    const GLint normalGl = k.normalFilter == NormalFilter::Linear ? GL_LINEAR : GL_NEAREST;
    std::vector<GLuint> normalTextures = {sceneFb.colorTexture(1), fullFb.colorTexture(1)};
    for (const auto& o : objects) {
      normalTextures.push_back(o->backFb.colorTexture(0));
      normalTextures.push_back(o->frontFb.colorTexture(0));
    }
    for (GLuint normalTexture : normalTextures) {
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
    for (gpu::Program* p : {&scene, &back, &layer}) {
      p->set("viewFromWorld", k.viewFromWorld);
      p->set("clipFromView", k.params.clipFromView);
    }

    // Both buffers come from the lab's perspective camera: the programs leave
    // out the general projection path (the same results; llvmpipe would run
    // both paths). Checked, so another camera would only cost time.
    const bool perspective =
        snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f).perspective;
    for (const LabShader& shader : shaders) {
      // Only the strategies the row's slots call (on any object): the same code paths, compiled in a fraction
      // of the time. An engine row's only slot is the reflection's, LAB_ENGINE_REFLECTION_TECHNIQUE's.
      const int id = shader.engineModel >= 0 ? LAB_ENGINE_REFLECTION_TECHNIQUE : shader.technique;
      if (snellFindTechnique(id) == nullptr) throw gpu::Error("snell-lab: no technique has id " + std::to_string(id));
      if (shader.engineModel >= LAB_ENGINE_ROW_COUNT)
        throw gpu::Error("snell-lab: no engine model has id " + std::to_string(shader.engineModel));
      const bool reference = shader.engineModel < 0 && shader.reference;
      int strategies = 0;
      for (const auto& o : objects)
        strategies |= snellStrategiesUsed(labTechnique(id, reference, o->k.params), labMaterial(o->k.params));
      std::vector<std::string> defines = {
          "LAB_TECHNIQUE " + std::to_string(id), std::string("LAB_REFERENCE ") + (reference ? "true" : "false"),
          "LAB_ENGINE_MODEL " + std::to_string(shader.engineModel),
          "SNELL_INTERSECT_STRATEGIES " + std::to_string(strategies)};
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

  // The wall time of f's GL work in ms: glFinish on both sides, steady clock.
  template <class F>
  double timed(F&& f) {
    gl.Finish();
    const auto t0 = std::chrono::steady_clock::now();
    f();
    gl.Finish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }

  // (1) The opaque scene: environment background (depth untouched), then the paintings, those nearer than
  // `clipNearerThan` (a view distance; 0: none) clipped away; with `peelBy`, what is not behind that
  // object's back faces is discarded.
  // A scene-layer draw's clip plane (only what lies beyond `clipNearerThan`, a view distance; 0: all) and peel
  // (only what lies behind `peelBy`'s back faces), for `program`: lab_scene.frag and lab_layer.frag take the
  // same uniforms and read the back-face depth on unit 1. The caller disables GL_CLIP_DISTANCE0 after its draws.
  void clipAndPeel(const gpu::Program& program, float clipNearerThan, const ObjectPasses* peelBy) {
    program.set("clipNearerThan", clipNearerThan);
    program.set("peel", peelBy ? 1 : 0);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, peelBy ? peelBy->backFb.depthTexture() : 0);
    gl.ActiveTexture(GL_TEXTURE0);
    if (clipNearerThan > 0.0f) gl.Enable(GL_CLIP_DISTANCE0);
  }

  void drawScene(const gpu::Framebuffer& fb, float clipNearerThan, const ObjectPasses* peelBy = nullptr) {
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
    clipAndPeel(scene, clipNearerThan, peelBy);
    for (std::size_t i = 0; i < paintings.size(); ++i) {
      paintings[i]->bind();
      scene.set("surfaceId", static_cast<float>(i + 1));
      gl.DrawArrays(GL_TRIANGLES, 0, paintings[i]->vertexCount);
    }
    gl.Disable(GL_CLIP_DISTANCE0);
    gpu::checkGl(gl, "scene pass");
  }

  void drawStatic() {
    vao.bind();
    // (1) The whole opaque scene (the layer snell's rows read after the back faces: Peeled reads them).
    drawScene(fullFb, 0.0f);
    for (const auto& o : objects) {
      // Within the object's screen rectangle only: outside it its buffers hold what they were made with.
      gl.Enable(GL_SCISSOR_TEST);
      gl.Scissor(o->rect.x, o->rect.y, o->rect.z - o->rect.x, o->rect.w - o->rect.y);
      // (2) The object's back faces: nearest-to-camera test reversed.
      o->backFb.clearColor(0, vec4(0.0f));
      o->backFb.clearDepth(0.0f);
      o->backFb.bind();
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_GREATER);
      gl.Enable(GL_CULL_FACE);
      gl.CullFace(GL_FRONT);
      back.use();
      back.set("clipNearerThan", 0.0f);
      o->bindMesh();
      gl.DrawArrays(GL_TRIANGLES, 0, o->vertexCount);
      gl.CullFace(GL_BACK);
      gl.DepthFunc(GL_LESS);
      gpu::checkGl(gl, "back-face pass");
      // (2b) The object's front faces, for the rays that bounce inside.
      o->frontFb.clearColor(0, vec4(0.0f));
      o->frontFb.clearDepth(1.0f);
      o->frontFb.bind();
      gl.DrawArrays(GL_TRIANGLES, 0, o->vertexCount);
      gpu::checkGl(gl, "front-face pass");
      gl.Disable(GL_SCISSOR_TEST);
      // (3) Its depth pyramid, over what the rectangle reduces into.
      pyramidPass.build(o->backPyramid, o->backFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f,
                        o->rect);
    }
    pyramidPass.build(fullPyramid, fullFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
    if (rough) colorPyramidPass->build(*fullColorPyramid);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // (1b) The layer of the scene `object` reads: the opaque scene (SceneLayer), then the front faces of the
  // objects drawn before it, coloured from the frame so far, under the same clip plane and peel.
  void drawLayer(std::size_t object, const std::vector<std::size_t>& drawn, const gpu::Texture* composite) {
    vao.bind();
    const ObjectPasses& o = *objects.at(object);
    const float clip = k.sceneLayer == SceneLayer::Behind ? o.k.objectNearDistance : 0.0f;
    const ObjectPasses* peel = k.sceneLayer == SceneLayer::Peeled ? &o : nullptr;
    drawScene(sceneFb, clip, peel);
    if (!drawn.empty() && composite != nullptr) {
      sceneFb.bind();
      gl.Enable(GL_DEPTH_TEST);
      gl.DepthFunc(GL_LESS);
      gl.Enable(GL_CULL_FACE);
      gl.CullFace(GL_BACK);
      layer.use();
      composite->bind(0);
      clipAndPeel(layer, clip, peel);
      for (std::size_t d : drawn) {
        if (d == object) throw gpu::Error("snell-lab: object " + std::to_string(object) + " cannot lie behind itself");
        objects.at(d)->bindMesh();
        layer.set("surfaceId", -static_cast<float>(d + 1));
        gl.DrawArrays(GL_TRIANGLES, 0, objects.at(d)->vertexCount);
      }
      gl.Disable(GL_CLIP_DISTANCE0);
      gpu::checkGl(gl, "scene layer: objects drawn before");
    }
    pyramidPass.build(scenePyramid, sceneFb.depthTexture(), k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f);
    if (rough) colorPyramidPass->build(*sceneColorPyramid);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // Before pass 4 (not timed: an engine draws its glass into the depth its opaque pass left): the glass is
  // drawn where it is nearer than the whole opaque scene, whose depth (the viewport's part of the
  // guard-banded buffer, texel for texel) becomes the pass's depth.
  void prepareTechnique() {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fullFb.id());
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, passFb.id());
    gl.BlitFramebuffer(k.margin, k.margin, k.margin + width, k.margin + height, 0, 0, width, height,
                       GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    gpu::checkGl(gl, "depth copy before the refraction pass");
  }

  void drawTechnique(std::size_t index, std::size_t object, bool backSide) {
    const ObjectPasses& o = *objects.at(object);
    passFb.bind();
    const vec4 zero(0.0f);
    for (int a = 0; a < 4; ++a) gl.ClearBufferfv(GL_COLOR, a, &zero[0]);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(backSide ? GL_FRONT : GL_BACK);
    const gpu::Framebuffer& sceneRead = shaders.at(index).readsFullScene() ? fullFb : sceneFb;
    const gpu::DepthPyramid& pyramidRead = shaders.at(index).readsFullScene() ? fullPyramid : scenePyramid;
    const GLuint color =
        shaders.at(index).readsFullScene() && colorCopy ? colorCopy->id() : sceneRead.colorTexture(0);
    const GLuint units[10] = {o.backFb.depthTexture(),  o.backFb.colorTexture(0),  o.backPyramid.texture(),
                              sceneRead.depthTexture(), sceneRead.colorTexture(1), pyramidRead.texture(),
                              color,                    environment.id(),          o.frontFb.depthTexture(),
                              o.frontFb.colorTexture(0)};
    for (int u = 0; u < 10; ++u) {
      gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
      gl.BindTexture(GL_TEXTURE_2D, units[u]);
    }
    gl.ActiveTexture(GL_TEXTURE0);
    vao.bind();
    o.bindMesh();
    o.uniforms.bindBase(kLabUniformsBinding);
    refract.at(index).use();
    refract.at(index).set("labBackSide", backSide ? 1 : 0);
    gl.DrawArrays(GL_TRIANGLES, 0, o.vertexCount);
    gl.CullFace(GL_BACK);
  }
};

GpuLab::GpuLab(const std::string& backend, const SceneFrame& frame, const std::vector<std::vector<float>>& dN,
               const std::vector<LabShader>& shaders, const ShaderDirs& dirs, const std::vector<ShadeConstants>& k)
    : impl_(std::make_unique<Impl>(backend, frame, dN, shaders, dirs, k)) {}

GpuLab::~GpuLab() = default;

std::string GpuLab::description() const {
  return std::string(gpu::backendName(impl_->ctx.backend())) + ", " + impl_->ctx.renderer() + ", OpenGL " +
         impl_->ctx.version();
}

void GpuLab::makeCurrent() const { impl_->ctx.makeCurrent(); }

double GpuLab::renderStatic() {
  return impl_->timed([&] { impl_->drawStatic(); });
}

double GpuLab::renderLayer(std::size_t object, const std::vector<std::size_t>& drawn, const Image* composite) {
  if (!drawn.empty() && composite == nullptr)
    throw gpu::Error("snell-lab: the scene layer of object " + std::to_string(object) +
                     " needs the frame so far for the objects drawn before it");
  std::unique_ptr<gpu::Texture> texture;
  if (composite) texture = std::make_unique<gpu::Texture>(impl_->gl, Texture2D(*composite, Filter::Nearest));
  return impl_->timed([&] { impl_->drawLayer(object, drawn, texture.get()); });
}

StaticBuffers GpuLab::readStatic(std::size_t object) const {
  const ObjectPasses& o = *impl_->objects.at(object);
  StaticBuffers b;
  b.sceneColor = impl_->sceneFb.readColor(0);
  b.fullColor = impl_->fullFb.readColor(0);
  if (impl_->rough) {
    for (int lod = 1; lod < impl_->sceneColorPyramid->levels(); ++lod) {
      b.sceneColorMips.push_back(impl_->sceneColorPyramid->readLevel(lod));
      b.fullColorMips.push_back(impl_->fullColorPyramid->readLevel(lod));
    }
  }
  b.sceneNormal = impl_->sceneFb.readColor(1);
  b.sceneDepth = impl_->sceneFb.readDepth();
  b.sceneSurface = impl_->sceneFb.readColor(2);
  b.fullNormal = impl_->fullFb.readColor(1);
  b.fullDepth = impl_->fullFb.readDepth();
  b.fullSurface = impl_->fullFb.readColor(2);
  b.backNormal = o.backFb.readColor(0);
  b.backDepth = o.backFb.readDepth();
  b.frontNormal = o.frontFb.readColor(0);
  b.frontDepth = o.frontFb.readDepth();
  return b;
}

std::size_t GpuLab::objectBytes(std::size_t object) const {
  const ObjectPasses& o = *impl_->objects.at(object);
  const std::size_t texels = static_cast<std::size_t>(impl_->bufferWidth) * static_cast<std::size_t>(impl_->bufferHeight);
  // Back and front faces: an RGBA32F normal and a 32-bit depth each; the back faces' min/max pyramid.
  return o.meshBytes + 2 * texels * (16u + 4u) + pyramidBytes(o.backPyramid);
}

std::size_t GpuLab::sharedBytes() const {
  const std::size_t texels = static_cast<std::size_t>(impl_->bufferWidth) * static_cast<std::size_t>(impl_->bufferHeight);
  const std::size_t pass = static_cast<std::size_t>(impl_->width) * static_cast<std::size_t>(impl_->height);
  // Two scene layers (colour, normal, depth) with their pyramids; the pass's four RGBA32F targets and depth.
  return 2 * texels * (16u + 16u + 4u) + pyramidBytes(impl_->scenePyramid) + pyramidBytes(impl_->fullPyramid) +
         pass * (4u * 16u + 4u);
}

double GpuLab::renderTechnique(std::size_t index, std::size_t object, bool backSide) {
  if (backSide && impl_->shaders.at(index).engineModel < 0)
    throw gpu::Error("snell-lab: program " + std::to_string(index) + " is a technique; only an engine model shades back faces");
  impl_->prepareTechnique();
  const double ms = impl_->timed([&] { impl_->drawTechnique(index, object, backSide); });
  gpu::checkGl(impl_->gl, "refraction pass");
  return ms;
}

void GpuLab::setEngineParameter(std::size_t index, float value) {
  if (index >= impl_->shaders.size() || impl_->shaders[index].engineModel < 0)
    throw gpu::Error("snell-lab: program " + std::to_string(index) + " runs no engine model");
  impl_->refract.at(index).set("labEngineParameter", value);
}

void GpuLab::setColorCopy(const Image* frame) {
  impl_->colorCopy.reset();
  if (frame) impl_->colorCopy = std::make_unique<gpu::Texture>(impl_->gl, Texture2D(*frame, Filter::Linear));
}

TechniqueBuffers GpuLab::readTechnique() const {
  TechniqueBuffers b;
  b.color = impl_->passFb.readColor(0);
  b.stats = impl_->passFb.readColor(1);
  b.position = impl_->passFb.readColor(2);
  b.normal = impl_->passFb.readColor(3);
  return b;
}

}  // namespace snell::lab
