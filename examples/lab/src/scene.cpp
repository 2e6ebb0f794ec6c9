#include "lab/scene.hpp"

#include "json_lines.hpp"
#include "json_reader.hpp"
#include "lab/error.hpp"
#include "lab/file_util.hpp"
#include "lab/gltf_loader.hpp"
#include "lab/image_io.hpp"
#include "lab/obj_loader.hpp"

#include <snell/shade.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

namespace snell::lab {

using detail::Json;
using detail::ObjectReader;
using detail::Range;

namespace {

constexpr int kMaxResolution = 16384;
// Each painting holds a texture (4 MB at the default 512 x 512): a scene file
// listing 100,000 of them ran out of memory instead of failing with a message.
constexpr std::size_t kMaxPaintings = 64;
const Range kColor = Range::nonNegative();
constexpr double kMaxFarOverNear = 1e7;

Camera readCamera(ObjectReader r) {
  Camera c;
  c.position = r.vector3("position", c.position, Range::any(), true);
  c.target = r.vector3("target", c.target);
  c.up = r.vector3("up", c.up);
  c.fovYDegrees = static_cast<float>(r.number("fov", c.fovYDegrees, Range::open(0.0, 180.0)));
  const ivec2 res = r.integer2("resolution", ivec2(c.width, c.height), kMinRenderSize, kMaxRenderSize);
  c.width = res.x;
  c.height = res.y;
  c.zNear = static_cast<float>(r.number("near", c.zNear, Range::positive()));
  c.zFar = static_cast<float>(r.number("far", c.zFar, Range::positive()));
  if (!(c.zFar > c.zNear))
    r.fail("far", "expected a number > near (" + std::to_string(c.zNear) + "), got " + std::to_string(c.zFar));
  // The GL passes keep depth in a 32-bit float buffer: window depth is about
  // 1 - near / distance, so past far / near = 2^24 every depth rounds to 1,
  // the cleared value, and nothing draws (the lab then ran the tracer and only
  // afterwards blamed the near plane).
  if (static_cast<double>(c.zFar) / static_cast<double>(c.zNear) > kMaxFarOverNear)
    r.fail("near", "far / near is " + detail::formatNumber(static_cast<double>(c.zFar) / static_cast<double>(c.zNear)) +
                       "; at most " + detail::formatNumber(kMaxFarOverNear) +
                       " keeps depths apart in the float depth buffer (raise near or lower far)");
  // Derived values, in float as glm::lookAt computes them: the components can
  // be finite floats while target - position or its squared length overflow.
  const vec3 forward = c.target - c.position;
  const char* farther = glm::length(glm::dvec3(c.position)) >= glm::length(glm::dvec3(c.target)) ? "position" : "target";
  if (!std::isfinite(forward.x) || !std::isfinite(forward.y) || !std::isfinite(forward.z) ||
      !std::isfinite(length(forward)))
    r.fail(farther, "target - position is too long for float arithmetic (its squared length overflows a float)");
  if (!(length(forward) > 0.0f))
    r.fail("target", "must differ from camera.position (by more than float rounding: the squared distance must not "
                     "round to 0)");
  // up is a direction: scaled so that its largest component is 1, which keeps
  // its squared length from overflowing (up [0, 1e20, 0] is [0, 1, 0]).
  const float upScale = std::max({std::fabs(c.up.x), std::fabs(c.up.y), std::fabs(c.up.z)});
  if (upScale > 0.0f) c.up /= upScale;
  if (!(upScale > 0.0f) || length(cross(normalize(forward), normalize(c.up))) < 1e-6f)
    r.fail("up", "must be non-zero and not parallel to the view direction (target - position)");
  const std::string problem = cameraProblem(c);
  if (problem.rfind("the projection", 0) == 0) {
    const float tanHalf = std::tan(0.5f * c.fovYRadians());
    r.fail(std::isnormal(tanHalf) && std::isnormal(1.0f / tanHalf) ? "near" : "fov", problem);
  }
  if (!problem.empty()) r.fail(farther, problem);
  r.finish();
  return c;
}

MeshSpec readMesh(ObjectReader r, const std::string& sceneFile) {
  MeshSpec m;
  const std::string type = r.choice("type", {"obj", "sphere", "icosphere", "torus", "blob", "box"}, "", true);
  if (type == "obj") {
    m.kind = MeshKind::Obj;
    m.path = resolvePath(r.requiredString("path"), sceneFile);
    m.fitSize = static_cast<float>(r.number("fit_size", 0.0, Range::nonNegative()));
  } else if (type == "sphere") {
    m.kind = MeshKind::Sphere;
    m.radius = static_cast<float>(r.number("radius", 1.0, Range::positive()));
    m.segments = r.integer("segments", m.segments, 3, 4096);
    m.rings = r.integer("rings", m.rings, 2, 4096);
  } else if (type == "box") {
    m.kind = MeshKind::Box;
    m.size = r.vector3OrScalar("size", m.size, Range::positive());
  } else if (type == "icosphere") {
    m.kind = MeshKind::Icosphere;
    m.radius = static_cast<float>(r.number("radius", 1.0, Range::positive()));
    m.subdivisions = r.integer("subdivisions", m.subdivisions, 0, 8);
  } else if (type == "torus") {
    m.kind = MeshKind::Torus;
    m.majorRadius = static_cast<float>(r.number("major_radius", m.majorRadius, Range::positive()));
    m.minorRadius = static_cast<float>(r.number("minor_radius", m.minorRadius, Range::positive()));
    if (!(m.minorRadius < m.majorRadius))
      r.fail("minor_radius", "expected a number < major_radius (" + std::to_string(m.majorRadius) + ")");
    m.majorSegments = r.integer("major_segments", m.majorSegments, 3, 4096);
    m.minorSegments = r.integer("minor_segments", m.minorSegments, 3, 4096);
  } else {
    m.kind = MeshKind::Blob;
    m.blob.radius = m.radius = static_cast<float>(r.number("radius", 1.0, Range::positive()));
    m.blob.subdivisions = m.subdivisions = r.integer("subdivisions", m.subdivisions, 0, 8);
    m.blob.amplitude = static_cast<float>(r.number("amplitude", m.blob.amplitude, Range{0.0, 1.0, false, true}));
    m.blob.frequency = static_cast<float>(r.number("frequency", m.blob.frequency, Range::nonNegative()));
    m.blob.speed = static_cast<float>(r.number("speed", m.blob.speed, Range::any()));
  }
  r.finish();
  return m;
}

Transform readTransform(ObjectReader r) {
  Transform t;
  t.translate = r.vector3("translate", t.translate);
  t.rotateDegrees = r.vector3("rotate", t.rotateDegrees);
  t.scale = r.vector3OrScalar("scale", t.scale, Range::positive());
  r.finish();
  return t;
}

RefractiveObject readObject(ObjectReader r, std::string field, const std::string& sceneFile) {
  RefractiveObject o;
  o.field = std::move(field);
  o.mesh = readMesh(r.object("mesh"), sceneFile);
  if (r.has("transform")) o.transform = readTransform(r.object("transform"));
  o.ior = static_cast<float>(r.number("ior", o.ior, Range{0.0, 10.0, true, false}));
  o.absorption = r.vector3("absorption", o.absorption, kColor);
  o.abbe = static_cast<float>(r.number("abbe", o.abbe, Range{1.0, 1e4, false, false}));
  o.roughness = static_cast<float>(r.number("roughness", o.roughness, Range{0.0, 1.0, false, false}));
  r.finish();
  return o;
}

EnvironmentSpec readEnvironment(ObjectReader r, const std::string& sceneFile) {
  EnvironmentSpec e;
  const std::string type = r.choice("type", {"sky", "image", "color"}, "", true);
  e.rotationDegrees = static_cast<float>(r.number("rotation", 0.0, Range::any()));
  e.intensity = static_cast<float>(r.number("intensity", 1.0, Range::nonNegative()));
  if (type == "sky") {
    e.kind = EnvironmentKind::Sky;
    SkyParams& s = e.sky;
    s.zenith = r.vector3("zenith", s.zenith, kColor);
    s.horizon = r.vector3("horizon", s.horizon, kColor);
    s.ground = r.vector3("ground", s.ground, kColor);
    s.sunAzimuthDegrees = static_cast<float>(r.number("sun_azimuth", s.sunAzimuthDegrees, Range::any()));
    s.sunElevationDegrees = static_cast<float>(r.number("sun_elevation", s.sunElevationDegrees, Range::closed(-90.0, 90.0)));
    s.sunColor = r.vector3("sun_color", s.sunColor, kColor);
    s.sunRadiusDegrees = static_cast<float>(r.number("sun_radius", s.sunRadiusDegrees, Range::closed(0.0, 90.0)));
    s.gridSpacingDegrees = static_cast<float>(r.number("grid_spacing", s.gridSpacingDegrees, Range::closed(0.0, 90.0)));
    s.gridColor = r.vector3("grid_color", s.gridColor, kColor);
    s.gridWidthDegrees = static_cast<float>(r.number("grid_width", s.gridWidthDegrees, Range::open(0.0, 10.0)));
    e.bakeSize = r.integer2("resolution", e.bakeSize, 2, kMaxResolution);
  } else if (type == "image") {
    e.kind = EnvironmentKind::Image;
    e.path = resolvePath(r.requiredString("path"), sceneFile);
  } else {
    e.kind = EnvironmentKind::Color;
    e.color = r.vector3("color", e.color, kColor, true);
  }
  r.finish();
  return e;
}

TextureSpec readTexture(ObjectReader r, const std::string& sceneFile) {
  TextureSpec t;
  const std::string type = r.choice("type", {"checker", "gradient", "pattern", "image"}, "", true);
  if (type == "image") {
    t.kind = TextureKind::Image;
    t.path = resolvePath(r.requiredString("path"), sceneFile);
    t.intensity = static_cast<float>(r.number("intensity", 1.0, Range::nonNegative()));
  } else {
    t.resolution = r.integer2("resolution", t.resolution, 1, kMaxResolution);
    if (type == "checker") {
      t.kind = TextureKind::Checker;
      t.squares = r.integer2("squares", t.squares, 1, 4096);
      t.colorA = r.vector3("color_a", t.colorA, kColor);
      t.colorB = r.vector3("color_b", t.colorB, kColor);
    } else if (type == "gradient") {
      t.kind = TextureKind::Gradient;
      if (!r.has("colors")) r.failMissing("colors", "an array of at least 2 colours [r, g, b]");
      t.colors = r.colorList("colors", 2, kColor);
      const std::string dir = r.choice("direction", {"horizontal", "vertical", "diagonal"}, "horizontal");
      t.direction = dir == "horizontal" ? 0 : dir == "vertical" ? 1 : 2;
    } else {
      t.kind = TextureKind::Pattern;
    }
  }
  r.finish();
  return t;
}

PaintingSpec readPainting(ObjectReader r, const std::string& sceneFile) {
  PaintingSpec p;
  r.choice("type", {"painting"}, "painting", true);
  p.center = r.vector3("center", p.center, Range::any(), true);
  p.size = r.vector2("size", p.size, Range::positive());
  p.rotateDegrees = r.vector3("rotate", p.rotateDegrees);
  // The corners, center +- the rotated half size, are what the tracer and the
  // GL passes draw: each a finite float.
  for (const vec3& corner : makePainting(p.center, p.size, p.rotateDegrees, Image(1, 1)).positions)
    if (!std::isfinite(corner.x) || !std::isfinite(corner.y) || !std::isfinite(corner.z))
      r.fail("size", "center +- size / 2 overflows a float (a corner of the painting is not finite)");
  if (r.has("texture")) p.texture = readTexture(r.object("texture"), sceneFile);
  r.finish();
  return p;
}

// `s` with each byte of an ill-formed UTF-8 sequence written as the text \xHH.
// The name goes into table.json, and nlohmann::json refuses to write a string
// that is not UTF-8, while a Linux file name is any bytes: a scene file named
// with byte 0xFF made snell-lab fail after rendering.
std::string readableUtf8(const std::string& s) {
  static const std::uint32_t kMinCodePoint[5] = {0, 0, 0x80, 0x800, 0x10000};  // shorter forms are overlong
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const auto lead = static_cast<unsigned char>(s[i]);
    const std::size_t n = lead < 0x80           ? 1
                          : (lead >> 5) == 0x6  ? 2
                          : (lead >> 4) == 0xE  ? 3
                          : (lead >> 3) == 0x1E ? 4
                                                : 0;  // a continuation byte or 0xF8..0xFF cannot lead
    bool ok = n > 0 && i + n <= s.size();
    std::uint32_t cp = n == 1 ? lead : lead & (0x7Fu >> n);
    for (std::size_t k = 1; ok && k < n; ++k) {
      const auto c = static_cast<unsigned char>(s[i + k]);
      ok = (c >> 6) == 0x2;
      cp = (cp << 6) | (c & 0x3Fu);
    }
    ok = ok && cp >= kMinCodePoint[n] && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
    if (ok) {
      out.append(s, i, n);
      i += n;
    } else {
      static const char kHex[] = "0123456789ABCDEF";
      out += std::string("\\x") + kHex[lead >> 4] + kHex[lead & 0xF];
      ++i;
    }
  }
  return out;
}

AnimationSpec readAnimation(ObjectReader r, const Camera& camera) {
  AnimationSpec a;
  a.frames = r.integer("frames", a.frames, 1, 100000);
  a.timeStart = static_cast<float>(r.number("time_start", a.timeStart, Range::any()));
  a.timeStep = static_cast<float>(r.number("time_step", a.timeStep, Range::any()));
  // Frame f is at time_start + f * time_step, in float (Scene::frameTime):
  // linear in f, so the last frame's time being finite covers every frame.
  const float last = a.timeStart + static_cast<float>(a.frames - 1) * a.timeStep;
  if (!std::isfinite(static_cast<float>(a.frames - 1) * a.timeStep) || !std::isfinite(last))
    r.fail("time_step", "the last frame's time, time_start + (frames - 1) * time_step, overflows a float");
  a.cameraPanPixels = r.vector2("camera_pan_pixels", a.cameraPanPixels, Range::any());
  // The camera moves farthest in the last frame; a pan that carries it beyond float arithmetic is refused here,
  // not left to the ray tracer and GL.
  const std::string far = cameraProblem(pannedCamera(camera, a.cameraPanPixels * static_cast<float>(a.frames - 1)));
  if (!far.empty()) r.fail("camera_pan_pixels", "the last frame's camera (panned by (frames - 1) times it): " + far);
  r.finish();
  return a;
}

// How messages name a scene file ("" when the scene was parsed from text).
std::string sceneWhere(const std::string& file) { return file.empty() ? std::string("<scene>") : file; }

std::vector<Mesh> loadedMeshes(const Scene& s) {
  std::vector<Mesh> meshes;
  for (const RefractiveObject& o : s.objects)
    if (o.mesh.loaded) meshes.push_back(*o.mesh.loaded);
  return meshes;
}

std::vector<Painting> loadedPaintings(const Scene& s) {
  std::vector<Painting> paintings;
  for (const PaintingSpec& p : s.paintings)
    if (p.loaded) paintings.push_back(*p.loaded);
  return paintings;
}

Camera gltfFramingCamera(const Scene& s) { return framingCamera(loadedMeshes(s), loadedPaintings(s)); }

// A glTF camera without zfar (infinite): twice the distance to the farthest vertex of the asset, kept within
// the far / near ratio the depth buffer resolves.
void completeFar(Camera& c, const Scene& s) {
  if (c.zFar > 0.0f) return;
  double farthest = 1.0;
  const auto reach = [&](const std::vector<vec3>& positions) {
    for (const vec3& v : positions) farthest = std::max(farthest, glm::length(glm::dvec3(v) - glm::dvec3(c.position)));
  };
  // Read in place: the meshes and the paintings' textures are large, and only positions are needed.
  for (const RefractiveObject& o : s.objects)
    if (o.mesh.loaded) reach(o.mesh.loaded->positions);
  for (const PaintingSpec& p : s.paintings)
    if (p.loaded) reach(p.loaded->positions);
  c.zFar = static_cast<float>(std::min(2.0 * farthest, 0.5 * kMaxFarOverNear * static_cast<double>(c.zNear)));
}

}  // namespace

Scene parseScene(const std::string& text, const std::string& file) {
  const std::string where = sceneWhere(file);
  Json root;
  try {
    root = Json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const Json::exception& e) {
    // parse_error's message carries "at line L, column C"; a number too large
    // for a double ("1e400") is an out_of_range (406) thrown by the parser too.
    std::string what = e.what();
    const std::size_t cut = what.find("] ");
    if (cut != std::string::npos) what = what.substr(cut + 2);
    throw Error(ErrorKind::Parse, where + ": malformed JSON: " + what);
  }
  const detail::JsonLines lines(text);
  if (!lines.duplicate().path.empty()) {
    const detail::JsonLines::Duplicate& d = lines.duplicate();
    throw Error(ErrorKind::Schema, where + ":" +
                                       std::to_string(d.secondLine) + ": " + d.path + ": given twice (first on line " +
                                       std::to_string(d.firstLine) + "); each field may appear once");
  }
  const detail::SourceInfo src{file, &lines};
  ObjectReader r(root, "", src);
  Scene s;
  s.file = file;
  const std::string stem = file.empty() ? std::string("scene") : std::filesystem::path(file).stem().string();
  s.name = r.string("name", readableUtf8(stem));
  s.description = r.string("description", "");
  if (r.has("gltf")) {
    // A glTF asset brings the objects, its opaque meshes and (when it has one) the camera; the file adds an
    // environment, paintings and a camera of its own.
    if (r.has("object") || r.has("objects"))
      throw Error(ErrorKind::Schema, where + ": a scene with \"gltf\" takes its objects from the asset; remove "
                                             "\"object\"/\"objects\"");
    const std::string asset = resolvePath(r.string("gltf", ""), file);
    GltfScene g = loadGltf(asset);
    s.gltf = asset;
    s.objects = std::move(g.objects);
    s.paintings = std::move(g.paintings);
    s.warnings = std::move(g.warnings);
    if (r.has("camera")) {
      s.camera = readCamera(r.object("camera"));
    } else if (g.hasCamera) {
      s.camera = g.camera;
    } else {
      s.camera = gltfFramingCamera(s);
    }
    if (r.has("environment")) s.environment = readEnvironment(r.object("environment"), file);
    for (ObjectReader& p : r.objectArray("opaque", kMaxPaintings)) s.paintings.push_back(readPainting(p, file));
    if (s.paintings.size() > kMaxPaintings)
      throw Error(ErrorKind::Schema, where + ": the asset and the file hold " + std::to_string(s.paintings.size()) +
                                             " opaque surfaces; at most " + std::to_string(kMaxPaintings));
    r.finish();
    completeFar(s.camera, s);
    return s;
  }
  s.camera = readCamera(r.object("camera"));
  // One object or a list, not both: two ways of saying the same thing would let a file say both.
  if (r.has("object") && r.has("objects"))
    throw Error(ErrorKind::Schema, where +
                                       ": give either \"object\" (one refractive object) or \"objects\" (a list), not both");
  if (r.has("objects")) {
    std::vector<ObjectReader> list = r.objectArray("objects", kMaxObjects);
    if (list.empty())
      throw Error(ErrorKind::Schema, where +
                                         ": objects: the list is empty; a scene holds at least one refractive object");
    for (std::size_t i = 0; i < list.size(); ++i)
      s.objects.push_back(readObject(std::move(list[i]), "objects[" + std::to_string(i) + "]", file));
  } else {
    s.objects.push_back(readObject(r.object("object"), "object", file));
  }
  if (r.has("environment")) {
    s.environment = readEnvironment(r.object("environment"), file);
  }
  for (ObjectReader& p : r.objectArray("opaque", kMaxPaintings)) s.paintings.push_back(readPainting(p, file));
  if (r.has("animation")) s.animation = readAnimation(r.object("animation"), s.camera);
  r.finish();
  return s;
}

Scene loadScene(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".gltf" || ext == ".glb") {
    GltfScene g = loadGltf(path);
    Scene s;
    s.file = path;
    s.gltf = path;
    s.name = readableUtf8(std::filesystem::path(path).stem().string());
    s.description = "glTF asset " + readableUtf8(std::filesystem::path(path).filename().string());
    s.objects = std::move(g.objects);
    s.paintings = std::move(g.paintings);
    s.warnings = std::move(g.warnings);
    s.camera = g.hasCamera ? g.camera : gltfFramingCamera(s);
    completeFar(s.camera, s);
    return s;
  }
  return parseScene(readTextFile(path, "scene"), path);
}

namespace {


// The first vertex of `mesh` with a non-finite position, or -1.
long firstNonFiniteVertex(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const vec3& p = mesh.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return static_cast<long>(i);
  }
  return -1;
}

// Which field of object.transform takes vertex `i` of `before` out of the
// float range: the transform applies scale, then rotate, then translate.
std::string transformCulprit(const std::vector<vec3>& before, std::size_t i, const Transform& t) {
  Transform partial;
  partial.scale = t.scale;
  const auto finite = [&](const Transform& tr) {
    const vec3 p = vec3(tr.matrix() * vec4(before[i], 1.0f));
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  };
  if (!finite(partial)) return "scale";
  partial.rotateDegrees = t.rotateDegrees;
  if (!finite(partial)) return "rotate";
  return "translate";
}

}  // namespace

Mesh buildObjectMesh(const Scene& scene, std::size_t index, float time) {
  if (index >= scene.objects.size())
    throw Error(ErrorKind::Schema, sceneWhere(scene.file) + ": no refractive object " + std::to_string(index) + " (the scene has " +
                                       std::to_string(scene.objects.size()) + ")");
  const RefractiveObject& object = scene.objects[index];
  const MeshSpec& m = object.mesh;
  Mesh mesh;
  switch (m.kind) {
    case MeshKind::Obj: {
      mesh = loadObj(m.path);
      if (m.fitSize > 0.0f) {
        const Bounds b = meshBounds(mesh);
        const vec3 ext = b.hi - b.lo;
        const float largest = std::max(ext.x, std::max(ext.y, ext.z));
        Transform fit;
        fit.scale = vec3(m.fitSize / largest);
        for (vec3& p : mesh.positions) p -= b.center();
        applyTransform(mesh, fit);
        const long bad = firstNonFiniteVertex(mesh);
        if (bad >= 0)
          throw Error(ErrorKind::Schema, sceneWhere(scene.file) + ": " + object.field + ".mesh.fit_size: the fitted mesh (" + m.path +
                                             ") has non-finite vertex " + std::to_string(bad) +
                                             " (its bounding box is empty or too large for float arithmetic)");
      }
      break;
    }
    case MeshKind::Sphere: mesh = makeUvSphere(m.radius, m.segments, m.rings); break;
    case MeshKind::Icosphere: mesh = makeIcosphere(m.radius, m.subdivisions); break;
    case MeshKind::Torus: mesh = makeTorus(m.majorRadius, m.minorRadius, m.majorSegments, m.minorSegments); break;
    case MeshKind::Blob: mesh = makeBlob(m.blob, time); break;
    case MeshKind::Box: mesh = makeBox(m.size); break;
    case MeshKind::Loaded: mesh = *m.loaded; break;
  }
  const std::string what = m.kind == MeshKind::Obj || m.kind == MeshKind::Loaded ? m.path : std::string("built-in mesh");
  // The untransformed mesh first, so that a transform that overflows is named
  // as such rather than as a bad mesh.
  const long badBefore = firstNonFiniteVertex(mesh);
  if (badBefore >= 0)
    throw Error(ErrorKind::Mesh, sceneWhere(scene.file) + ": " + object.field + ".mesh: " + what + ": vertex " +
                                     std::to_string(badBefore) + " is not finite" +
                                     (m.kind == MeshKind::Blob ? " at time " + detail::formatNumber(time) : ""));
  const std::vector<vec3> before = mesh.positions;
  applyTransform(mesh, object.transform);
  const long bad = firstNonFiniteVertex(mesh);
  if (bad >= 0)
    throw Error(ErrorKind::Schema, sceneWhere(scene.file) + ": " + object.field + ".transform." +
                                       transformCulprit(before, static_cast<std::size_t>(bad), object.transform) +
                                       ": the transformed mesh has non-finite vertex " + std::to_string(bad));
  validateMesh(mesh, what);
  return mesh;
}

Environment buildEnvironment(const Scene& scene) {
  const EnvironmentSpec& e = scene.environment;
  switch (e.kind) {
    case EnvironmentKind::Sky:
      return Environment(bakeSky(e.sky, e.bakeSize.x, e.bakeSize.y), e.rotationDegrees, e.intensity);
    case EnvironmentKind::Image:
      return Environment(readImage(e.path), e.rotationDegrees, e.intensity);
    case EnvironmentKind::Color:
    default:
      return Environment(Image(1, 1, vec4(e.color, 1.0f)), e.rotationDegrees, e.intensity);
  }
}

std::vector<Painting> buildPaintings(const Scene& scene) {
  std::vector<Painting> out;
  for (const PaintingSpec& p : scene.paintings) {
    if (p.loaded) {
      out.push_back(*p.loaded);
      continue;
    }
    const TextureSpec& t = p.texture;
    Image tex;
    switch (t.kind) {
      case TextureKind::Checker:
        tex = makeCheckerTexture(t.resolution.x, t.resolution.y, t.squares, t.colorA, t.colorB);
        break;
      case TextureKind::Gradient:
        tex = makeGradientTexture(t.resolution.x, t.resolution.y, t.colors, t.direction);
        break;
      case TextureKind::Pattern: tex = makePatternTexture(t.resolution.x, t.resolution.y); break;
      case TextureKind::Image:
        tex = readImage(t.path);
        if (t.intensity != 1.0f)
          for (vec4& c : tex.texels) c = vec4(vec3(c) * t.intensity, c.w);
        break;
    }
    out.push_back(makePainting(p.center, p.size, p.rotateDegrees, std::move(tex)));
  }
  return out;
}

Camera Scene::frameCamera(int frame) const {
  return pannedCamera(camera, animation.cameraPanPixels * static_cast<float>(frame));
}

SceneFrame buildAnimationFrame(const Scene& scene, int frame) {
  SceneFrame f = buildFrame(scene, scene.frameTime(frame));
  f.camera = scene.frameCamera(frame);
  return f;
}

bool dispersive(const FrameObject& o) { return o.abbe > 0.0f; }

vec3 channelIors(const FrameObject& o) {
  return dispersive(o) ? snellDispersionIors(o.ior, o.abbe) : vec3(o.ior);
}

SceneFrame buildFrame(const Scene& scene, float time) {
  SceneFrame f;
  f.camera = scene.camera;
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    f.objects.push_back(FrameObject{buildObjectMesh(scene, i, time), scene.objects[i].ior, scene.objects[i].absorption,
                                       scene.objects[i].abbe, scene.objects[i].roughness});
  f.environment = buildEnvironment(scene);
  f.paintings = buildPaintings(scene);
  return f;
}

}  // namespace snell::lab
