// tinygltf parses the JSON and the GLB container and decodes data URIs; this
// file does everything that touches memory a file's numbers point into
// (accessors, buffer views, images), each bound checked first: tinygltf 2.7
// does not check an image's buffer view against its buffer, so its bytes are
// never read through tinygltf.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include "lab/gltf_loader.hpp"

#include "lab/error.hpp"
#include "lab/image_io.hpp"
#include "lab/mesh.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

// The supported extensions: a file that requires any other is refused (it would render wrongly).
const std::set<std::string> kReadExtensions = {"KHR_materials_transmission", "KHR_materials_volume",
                                               "KHR_materials_ior", "KHR_materials_dispersion"};
constexpr int kMaxNodeDepth = 256;

// A number as a reader writes it: 0.3, 1, 1e+06.
std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string quoted(const std::string& name) { return name.empty() ? std::string() : " '" + name + "'"; }

// The folder external files must lie in, and the file-size rule, for tinygltf's file callbacks.
struct FileRules {
  fs::path folder;    // canonical; empty: no external files at all
  std::string refused;  // why the last file was refused
};

// The file `abs` (tinygltf joins the folder and the URI) when it names a regular file inside the folder
// by a relative path without "..", else "" with the reason in rules.refused.
fs::path allowedFile(const std::string& abs, FileRules& rules) {
  if (rules.folder.empty()) {
    rules.refused = "external files are not read here";
    return {};
  }
  const std::string prefix = rules.folder.string() + "/";
  if (abs.compare(0, prefix.size(), prefix) != 0) {
    rules.refused = "not inside the asset's folder";
    return {};
  }
  const fs::path relative(abs.substr(prefix.size()));
  if (relative.empty() || relative.is_absolute()) {
    rules.refused = "an absolute path";
    return {};
  }
  for (const fs::path& part : relative)
    if (part == "..") {
      rules.refused = "a path through \"..\"";
      return {};
    }
  std::error_code ec;
  const fs::path real = fs::canonical(abs, ec);
  if (ec) {
    rules.refused = "no such file";
    return {};
  }
  const std::string realText = real.string();
  if (realText.compare(0, prefix.size(), prefix) != 0) {
    rules.refused = "a link out of the asset's folder";
    return {};
  }
  if (!fs::is_regular_file(real, ec)) {
    rules.refused = "not a regular file";
    return {};
  }
  const auto size = fs::file_size(real, ec);
  if (ec || size > static_cast<std::uintmax_t>(kMaxGltfBytes)) {
    rules.refused = "larger than " + std::to_string(kMaxGltfBytes >> 20) + " MiB";
    return {};
  }
  return real;
}

bool fileExists(const std::string& abs, void* user) { return !allowedFile(abs, *static_cast<FileRules*>(user)).empty(); }

std::string expandNothing(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& abs, void* user) {
  FileRules& rules = *static_cast<FileRules*>(user);
  const fs::path file = allowedFile(abs, rules);
  if (file.empty()) {
    if (err) *err += abs + ": refused: " + rules.refused + "\n";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  const auto size = static_cast<std::size_t>(fs::file_size(file));
  out->resize(size);
  if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    if (err) *err += abs + ": cannot read\n";
    return false;
  }
  return true;
}

bool writeNothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// tinygltf hands over a data URI's decoded bytes here; they are kept encoded, for the lab's decoders. An image
// in a buffer view is read later, with its bounds checked (see the top of the file).
bool keepEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                 int size, void*) {
  if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
  image->width = image->height = 0;
  return true;
}

double numberOr(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
}

class Reader {
 public:
  Reader(const tinygltf::Model& model, std::string asset, FileRules& rules)
      : m_(model), asset_(std::move(asset)), rules_(rules) {}

  GltfScene read() {
    for (const std::string& e : m_.extensionsRequired)
      if (!kReadExtensions.count(e))
        fail(ErrorKind::Schema, "extensionsRequired: " + e + " is not read by the lab (it reads " + readList() + ")");
    for (const std::string& e : m_.extensionsUsed)
      if (!kReadExtensions.count(e) && e.rfind("KHR_materials_", 0) == 0)
        warn("extensionsUsed: " + e + " is ignored: the lab renders glass and unlit opaque colour only");
    if (m_.scenes.empty()) fail(ErrorKind::Schema, "scenes: the file has no scene: nothing to render");
    const int sceneIndex = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (static_cast<std::size_t>(sceneIndex) >= m_.scenes.size())
      fail(ErrorKind::Schema, "scene: " + std::to_string(sceneIndex) + " is past the " +
                                  std::to_string(m_.scenes.size()) + " scenes");
    visited_.assign(m_.nodes.size(), false);
    for (int root : m_.scenes[static_cast<std::size_t>(sceneIndex)].nodes) walk(root, glm::dmat4(1.0), 0);
    if (out_.objects.empty())
      fail(ErrorKind::Schema, "no primitive has a transmissive material (KHR_materials_transmission with "
                              "transmissionFactor > 0): nothing for snell to refract");
    if (out_.objects.size() > kMaxObjects)
      fail(ErrorKind::Schema, std::to_string(out_.objects.size()) + " transmissive primitives; the lab renders at most " +
                                  std::to_string(kMaxObjects) + " refractive objects");
    return std::move(out_);
  }

 private:
  const tinygltf::Model& m_;
  std::string asset_;
  FileRules& rules_;
  GltfScene out_;
  std::vector<bool> visited_;
  std::map<int, std::shared_ptr<const Image>> images_;

  static std::string readList() {
    std::string s;
    for (const std::string& e : kReadExtensions) s += (s.empty() ? "" : ", ") + e;
    return s;
  }

  [[noreturn]] void fail(ErrorKind kind, const std::string& what) const { throw Error(kind, asset_ + ": " + what); }
  void warn(const std::string& what) { out_.warnings.push_back(asset_ + ": " + what); }

  std::string nodeName(int i) const { return "nodes[" + std::to_string(i) + "]" + quoted(m_.nodes[static_cast<std::size_t>(i)].name); }

  static glm::dmat4 localMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glTF stores it
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (n.translation.size() == 3) t = glm::translate(glm::dmat4(1.0), glm::make_vec3(n.translation.data()));
    if (n.rotation.size() == 4)
      r = glm::mat4_cast(glm::normalize(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2])));
    if (n.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::make_vec3(n.scale.data()));
    return t * r * s;
  }

  static bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(m[c][r]) || std::fabs(m[c][r]) > 1e30) return false;
    return true;
  }

  void walk(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || static_cast<std::size_t>(index) >= m_.nodes.size())
      fail(ErrorKind::Schema, "nodes[" + std::to_string(index) + "]: no such node (the file has " +
                                  std::to_string(m_.nodes.size()) + ")");
    if (visited_[static_cast<std::size_t>(index)])
      fail(ErrorKind::Schema, nodeName(index) + ": reached twice (a cycle, or a node with two parents): glTF nodes "
                                                "form trees");
    if (depth > kMaxNodeDepth)
      fail(ErrorKind::Schema, nodeName(index) + ": nested deeper than " + std::to_string(kMaxNodeDepth) + " nodes");
    visited_[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = m_.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * localMatrix(node);
    if (!finite(world))
      fail(ErrorKind::Schema, nodeName(index) + ": its world transform is not finite (or beyond 1e30)");
    if (node.camera >= 0 && !out_.hasCamera) readCamera(index, world);
    if (node.mesh >= 0) readMesh(index, world);
    for (int child : node.children) walk(child, world, depth + 1);
  }

  void readCamera(int nodeIndex, const glm::dmat4& world) {
    const std::string where = nodeName(nodeIndex) + " -> cameras[" + std::to_string(m_.nodes[static_cast<std::size_t>(nodeIndex)].camera) + "]";
    if (static_cast<std::size_t>(m_.nodes[static_cast<std::size_t>(nodeIndex)].camera) >= m_.cameras.size())
      fail(ErrorKind::Schema, where + ": no such camera");
    const tinygltf::Camera& cam = m_.cameras[static_cast<std::size_t>(m_.nodes[static_cast<std::size_t>(nodeIndex)].camera)];
    if (cam.type != "perspective") {
      warn(where + ": a " + cam.type + " camera; the lab frames the glass with its own perspective camera");
      return;
    }
    const tinygltf::PerspectiveCamera& p = cam.perspective;
    if (!(p.yfov > 0.0 && p.yfov < 3.14) || !(p.znear > 0.0) || !(p.zfar == 0.0 || p.zfar > p.znear) ||
        !(p.aspectRatio >= 0.0 && p.aspectRatio < 1e3))
      fail(ErrorKind::Schema, where + ": expected 0 < yfov < pi, znear > 0, zfar absent or > znear and a positive "
                                      "aspectRatio");
    Camera c;
    c.position = vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 forward = glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const glm::dvec3 up = glm::dvec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    if (!(glm::length(forward) > 1e-12) || !(glm::length(glm::cross(forward, up)) > 1e-12 * glm::length(forward) * glm::length(up)))
      fail(ErrorKind::Schema, where + ": its node's transform collapses the view direction or its up vector");
    c.target = vec3(glm::dvec3(c.position) + glm::normalize(forward));
    c.up = vec3(glm::normalize(up));
    c.fovYDegrees = static_cast<float>(glm::degrees(p.yfov));
    c.height = 512;
    c.width = p.aspectRatio > 0.0
                  ? std::clamp(static_cast<int>(std::lround(512.0 * p.aspectRatio)), kMinRenderSize, kMaxRenderSize)
                  : 512;
    c.zNear = static_cast<float>(p.znear);
    c.zFar = static_cast<float>(p.zfar);  // 0 (infinite) is replaced once the scene's extent is known
    // As for a scene file's camera: past far / near = 1e7 the float depth buffer rounds every depth to 1.
    if (p.zfar > 1e7 * p.znear)
      fail(ErrorKind::Schema, where + ": zfar / znear is " + number(p.zfar / p.znear) +
                                  "; at most 1e7 keeps depths apart in the float depth buffer");
    const std::string problem = p.zfar > 0.0 ? cameraProblem(c) : std::string();
    if (!problem.empty()) fail(ErrorKind::Schema, where + ": " + problem);
    out_.camera = c;
    out_.hasCamera = true;
  }

  // An accessor's elements as doubles, `width` per element (VEC3: 3), every byte checked against its buffer.
  std::vector<double> readAccessor(int index, const std::string& where, std::initializer_list<int> types,
                                   std::initializer_list<int> componentTypes) const {
    const std::string at = where + " -> accessors[" + std::to_string(index) + "]";
    if (index < 0 || static_cast<std::size_t>(index) >= m_.accessors.size()) fail(ErrorKind::Schema, at + ": no such accessor");
    const tinygltf::Accessor& a = m_.accessors[static_cast<std::size_t>(index)];
    if (std::find(types.begin(), types.end(), a.type) == types.end())
      fail(ErrorKind::Schema, at + ": type " + std::to_string(a.type) + " is not what this attribute takes");
    if (std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end())
      fail(ErrorKind::Schema, at + ": componentType " + std::to_string(a.componentType) + " is not what this attribute takes");
    if (a.sparse.isSparse) fail(ErrorKind::Schema, at + ": sparse accessors are not read by the lab");
    if (a.count == 0 || a.count > static_cast<std::size_t>(kMaxGltfElements))
      fail(ErrorKind::Schema, at + ": count " + std::to_string(a.count) + " is not in [1, " +
                                  std::to_string(kMaxGltfElements) + "]");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= m_.bufferViews.size())
      fail(ErrorKind::Schema, at + ": bufferView " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& v = m_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    const std::string viewAt = at + " -> bufferViews[" + std::to_string(a.bufferView) + "]";
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= m_.buffers.size())
      fail(ErrorKind::Schema, viewAt + ": buffer " + std::to_string(v.buffer) + " does not exist");
    const std::vector<unsigned char>& data = m_.buffers[static_cast<std::size_t>(v.buffer)].data;
    const int width = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const int component = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (width <= 0 || component <= 0) fail(ErrorKind::Schema, at + ": unknown type or componentType");
    const std::size_t element = static_cast<std::size_t>(width) * static_cast<std::size_t>(component);
    const std::size_t stride = v.byteStride ? v.byteStride : element;
    // Every size below is at most 2^32 or so; sums of a few cannot overflow 64 bits.
    if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
      fail(ErrorKind::Schema, viewAt + ": byteOffset " + std::to_string(v.byteOffset) + " + byteLength " +
                                  std::to_string(v.byteLength) + " is past the buffer's " + std::to_string(data.size()) +
                                  " bytes");
    if (stride < element || stride > 252 || a.byteOffset > v.byteLength ||
        (a.count - 1) * stride + element > v.byteLength - a.byteOffset)
      fail(ErrorKind::Schema, at + ": byteOffset " + std::to_string(a.byteOffset) + ", " + std::to_string(a.count) +
                                  " elements of " + std::to_string(element) + " bytes every " + std::to_string(stride) +
                                  " do not fit the buffer view's " + std::to_string(v.byteLength) + " bytes");
    if (a.byteOffset % static_cast<std::size_t>(component) != 0 || v.byteOffset % static_cast<std::size_t>(component) != 0)
      fail(ErrorKind::Schema, at + ": not aligned to its component size");
    std::vector<double> out(a.count * static_cast<std::size_t>(width));
    const unsigned char* base = data.data() + v.byteOffset + a.byteOffset;
    for (std::size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < width; ++c) {
        const unsigned char* p = base + i * stride + static_cast<std::size_t>(c * component);
        double x = 0.0;
        switch (a.componentType) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            x = f;
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: x = a.normalized ? *p / 255.0 : *p; break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t u;
            std::memcpy(&u, p, 2);
            x = a.normalized ? u / 65535.0 : u;
            break;
          }
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t u;
            std::memcpy(&u, p, 4);
            x = u;
            break;
          }
          default: fail(ErrorKind::Schema, at + ": componentType " + std::to_string(a.componentType) + " is not read");
        }
        if (!std::isfinite(x)) fail(ErrorKind::Schema, at + ": element " + std::to_string(i) + " is not finite");
        out[i * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] = x;
      }
    return out;
  }

  // The primitive's triangles as an index list (a strip or fan unrolled), each index below `vertices`.
  std::vector<std::uint32_t> triangles(const tinygltf::Primitive& p, std::size_t vertices, const std::string& where) const {
    std::vector<std::uint32_t> order;
    if (p.indices >= 0) {
      for (double x : readAccessor(p.indices, where + " indices", {TINYGLTF_TYPE_SCALAR},
                                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT})) {
        if (x >= static_cast<double>(vertices))
          fail(ErrorKind::Schema, where + ": index " + std::to_string(static_cast<long long>(x)) + " is past its " +
                                      std::to_string(vertices) + " vertices");
        order.push_back(static_cast<std::uint32_t>(x));
      }
    } else {
      for (std::size_t i = 0; i < vertices; ++i) order.push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<std::uint32_t> out;
    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (order.size() % 3 != 0)
        fail(ErrorKind::Schema, where + ": " + std::to_string(order.size()) + " indices do not make whole triangles");
      return order;
    }
    for (std::size_t i = 2; i < order.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        const bool odd = i % 2 == 1;
        out.insert(out.end(), {order[i - 2], order[odd ? i : i - 1], order[odd ? i - 1 : i]});
      } else {
        out.insert(out.end(), {order[0], order[i - 1], order[i]});
      }
    }
    return out;
  }

  std::vector<glm::dvec3> vec3s(const std::vector<double>& flat) const {
    std::vector<glm::dvec3> v(flat.size() / 3);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = glm::dvec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
    return v;
  }

  void readMesh(int nodeIndex, const glm::dmat4& world) {
    const tinygltf::Node& node = m_.nodes[static_cast<std::size_t>(nodeIndex)];
    const std::string nodeAt = nodeName(nodeIndex) + " -> meshes[" + std::to_string(node.mesh) + "]";
    if (static_cast<std::size_t>(node.mesh) >= m_.meshes.size()) fail(ErrorKind::Schema, nodeAt + ": no such mesh");
    const tinygltf::Mesh& mesh = m_.meshes[static_cast<std::size_t>(node.mesh)];
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
      const tinygltf::Primitive& p = mesh.primitives[k];
      const std::string where = nodeAt + quoted(mesh.name) + " primitives[" + std::to_string(k) + "]";
      const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        warn(where + ": points or lines (mode " + std::to_string(mode) + ") are not a surface; skipped");
        continue;
      }
      const auto position = p.attributes.find("POSITION");
      if (position == p.attributes.end()) fail(ErrorKind::Schema, where + ": no POSITION attribute");
      const std::vector<glm::dvec3> local =
          vec3s(readAccessor(position->second, where + " POSITION", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}));
      std::vector<std::uint32_t> indices = triangles(p, local.size(), where);
      if (indices.empty()) {
        warn(where + ": no triangles; skipped");
        continue;
      }
      if (mirrored)
        for (std::size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
      std::vector<vec3> positions(local.size());
      for (std::size_t i = 0; i < local.size(); ++i) {
        const glm::dvec3 w = glm::dvec3(world * glm::dvec4(local[i], 1.0));
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z) || glm::length(w) > 1e30)
          fail(ErrorKind::Schema, where + ": vertex " + std::to_string(i) + " is not finite in world space");
        positions[i] = vec3(w);
      }
      std::vector<vec3> normals;
      const auto normal = p.attributes.find("NORMAL");
      if (normal != p.attributes.end()) {
        const std::vector<glm::dvec3> n =
            vec3s(readAccessor(normal->second, where + " NORMAL", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT}));
        if (n.size() != local.size())
          fail(ErrorKind::Schema, where + ": NORMAL has " + std::to_string(n.size()) + " elements for " +
                                      std::to_string(local.size()) + " positions");
        for (const glm::dvec3& x : n) {
          const glm::dvec3 w = normalMatrix * x;
          normals.push_back(glm::length(w) > 0.0 ? vec3(glm::normalize(w)) : vec3(0.0f, 0.0f, 1.0f));
        }
      }
      const tinygltf::Material* material = nullptr;
      std::string materialAt = "the default material";
      if (p.material >= 0) {
        if (static_cast<std::size_t>(p.material) >= m_.materials.size())
          fail(ErrorKind::Schema, where + ": material " + std::to_string(p.material) + " does not exist");
        material = &m_.materials[static_cast<std::size_t>(p.material)];
        materialAt = "materials[" + std::to_string(p.material) + "]" + quoted(material->name);
      }
      const auto ext = [&](const char* name) -> const tinygltf::Value* {
        if (!material) return nullptr;
        const auto it = material->extensions.find(name);
        return it == material->extensions.end() ? nullptr : &it->second;
      };
      const tinygltf::Value* transmission = ext("KHR_materials_transmission");
      const double transmissionFactor = transmission ? numberOr(*transmission, "transmissionFactor", 0.0) : 0.0;
      if (!(transmissionFactor >= 0.0 && transmissionFactor <= 1.0))
        fail(ErrorKind::Schema, materialAt + ": KHR_materials_transmission.transmissionFactor must be in [0, 1]");
      if (transmissionFactor > 0.0)
        readGlass(where, materialAt, *material, transmissionFactor, std::move(positions), std::move(normals),
                  std::move(indices), ext);
      else
        readOpaque(where, materialAt, material, p, std::move(positions), std::move(normals), std::move(indices));
    }
  }

  template <class Ext>
  void readGlass(const std::string& where, const std::string& materialAt, const tinygltf::Material& material,
                 double transmissionFactor, std::vector<vec3> positions, std::vector<vec3> normals,
                 std::vector<std::uint32_t> indices, const Ext& ext) {
    const tinygltf::Value* volume = ext("KHR_materials_volume");
    const double thickness = volume ? numberOr(*volume, "thicknessFactor", 0.0) : 0.0;
    if (!(thickness > 0.0))
      fail(ErrorKind::Schema, materialAt + ": transmissive but thin-walled (" +
                                  (volume ? std::string("KHR_materials_volume.thicknessFactor is 0")
                                          : std::string("no KHR_materials_volume")) +
                                  "): glTF then models a surface of no thickness that does not bend light, and snell "
                                  "refracts through closed volumes only; give the material KHR_materials_volume with "
                                  "thicknessFactor > 0 (and a closed mesh)");
    const tinygltf::Value* iorExt = ext("KHR_materials_ior");
    const double ior = iorExt ? numberOr(*iorExt, "ior", 1.5) : 1.5;
    if (!(ior >= 1.0 && ior <= 4.0))
      fail(ErrorKind::Schema, materialAt + ": KHR_materials_ior.ior " + number(ior) +
                                  " is outside the [1, 4] the lab renders");
    glm::dvec3 color(1.0);
    if (volume->IsObject() && volume->Has("attenuationColor")) {
      const tinygltf::Value& c = volume->Get("attenuationColor");
      if (!c.IsArray() || c.ArrayLen() != 3) fail(ErrorKind::Schema, materialAt + ": attenuationColor is not 3 numbers");
      for (int i = 0; i < 3; ++i) color[i] = c.Get(i).IsNumber() ? c.Get(i).GetNumberAsDouble() : std::nan("");
    }
    const double distance = numberOr(*volume, "attenuationDistance", HUGE_VAL);
    if (!(color.x >= 0.0 && color.x <= 1.0 && color.y >= 0.0 && color.y <= 1.0 && color.z >= 0.0 && color.z <= 1.0) ||
        !(distance > 0.0))
      fail(ErrorKind::Schema, materialAt + ": KHR_materials_volume needs attenuationColor in [0, 1] and "
                                           "attenuationDistance > 0");
    // sigma = -ln(c) / d; a colour of 0 (no light at any depth) is taken as 1e-6.
    glm::dvec3 sigma(0.0);
    if (std::isfinite(distance))
      for (int i = 0; i < 3; ++i) sigma[i] = -std::log(std::max(color[i], 1e-6)) / distance;
    if (transmissionFactor < 1.0)
      warn(materialAt + ": transmissionFactor " + number(transmissionFactor) +
           " is rendered as 1 (the lab has no diffuse part under the glass)");
    // glTF's perceptual roughness is the scene file's (GGX alpha = roughness^2 in both); its texture is not read.
    const double roughness = material.pbrMetallicRoughness.roughnessFactor;
    if (!(roughness >= 0.0 && roughness <= 1.0))
      fail(ErrorKind::Schema, materialAt + ": roughnessFactor must be in [0, 1], got " + number(roughness));
    if (material.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
      warn(materialAt + ": metallicRoughnessTexture is not read (roughnessFactor " + number(roughness) +
           " is used everywhere)");
    // KHR_materials_dispersion: the Abbe number V_d = 20 / dispersion. Its n(lambda) = n_d + (n_d - 1) / V_d *
    // (523655 / lambda^2 - 1.5168) is the Cauchy fit of snellDispersionIors (the constants are 1 / (1/l_F^2 -
    // 1/l_C^2) and that over l_d^2, lambda in nm). Above V_d 10^4 the channels differ by less than 1e-4 of
    // n_d - 1: rendered with one IOR.
    double abbe = 0.0;
    if (const tinygltf::Value* dispersionExt = ext("KHR_materials_dispersion")) {
      const double dispersion = numberOr(*dispersionExt, "dispersion", 0.0);
      if (!(dispersion >= 0.0 && dispersion <= 20.0))
        fail(ErrorKind::Schema, materialAt + ": KHR_materials_dispersion.dispersion " + number(dispersion) +
                                    " is outside the [0, 20] the lab renders (an Abbe number of at least 1)");
      if (dispersion >= 20.0 / 1e4) abbe = 20.0 / dispersion;
    }
    Mesh mesh;
    mesh.positions = std::move(positions);
    mesh.indices = std::move(indices);
    if (normals.empty()) {
      computeSmoothNormals(mesh);
    } else {
      mesh.normals = std::move(normals);
    }
    validateMesh(mesh, asset_ + ": " + where);
    orientOutward(mesh);
    const std::size_t open = openEdges(mesh);
    if (open > 0)
      warn(where + ": the glass mesh is open (" + std::to_string(open) +
           " edges with one triangle): rays through its holes find no back face");
    RefractiveObject o;
    o.field = where;
    o.mesh.kind = MeshKind::Loaded;
    o.mesh.path = asset_ + ": " + where;
    o.mesh.loaded = std::make_shared<const Mesh>(std::move(mesh));
    o.ior = static_cast<float>(ior);
    o.absorption = vec3(sigma);
    o.abbe = static_cast<float>(abbe);
    o.roughness = static_cast<float>(roughness);
    out_.objects.push_back(std::move(o));
  }

  void readOpaque(const std::string& where, const std::string& materialAt, const tinygltf::Material* material,
                  const tinygltf::Primitive& p, std::vector<vec3> positions, std::vector<vec3> normals,
                  std::vector<std::uint32_t> indices) {
    if (out_.paintings.size() >= 64)
      fail(ErrorKind::Schema, where + ": more than 64 opaque primitives; the lab draws at most 64");
    glm::dvec4 factor(1.0);
    int textureIndex = -1, texCoord = 0;
    if (material) {
      const std::vector<double>& f = material->pbrMetallicRoughness.baseColorFactor;
      if (f.size() == 4) factor = glm::dvec4(f[0], f[1], f[2], f[3]);
      for (int i = 0; i < 4; ++i)
        if (!(factor[i] >= 0.0 && factor[i] <= 1.0)) fail(ErrorKind::Schema, materialAt + ": baseColorFactor is not in [0, 1]");
      textureIndex = material->pbrMetallicRoughness.baseColorTexture.index;
      texCoord = material->pbrMetallicRoughness.baseColorTexture.texCoord;
      if (material->alphaMode != "OPAQUE")
        warn(materialAt + ": alphaMode " + material->alphaMode + " is drawn opaque");
    }
    auto painting = std::make_shared<Painting>();
    painting->positions = std::move(positions);
    painting->indices = std::move(indices);
    std::shared_ptr<const Image> image;
    if (textureIndex >= 0) {
      const std::string attribute = "TEXCOORD_" + std::to_string(texCoord);
      const auto uv = p.attributes.find(attribute);
      if (uv == p.attributes.end())
        fail(ErrorKind::Schema, where + ": " + materialAt + " has a base colour texture but the primitive has no " + attribute);
      const std::vector<double> flat =
          readAccessor(uv->second, where + " " + attribute, {TINYGLTF_TYPE_VEC2},
                       {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
      if (flat.size() != 2 * painting->positions.size())
        fail(ErrorKind::Schema, where + ": " + attribute + " has " + std::to_string(flat.size() / 2) + " elements for " +
                                    std::to_string(painting->positions.size()) + " positions");
      bool outside = false;
      for (std::size_t i = 0; i < painting->positions.size(); ++i) {
        // glTF's uv origin is the image's first (top) row; the lab's v = 0 is its bottom row.
        const vec2 t(static_cast<float>(flat[2 * i]), static_cast<float>(1.0 - flat[2 * i + 1]));
        outside = outside || t.x < 0.0f || t.x > 1.0f || t.y < 0.0f || t.y > 1.0f;
        painting->uvs.push_back(t);
      }
      if (outside) warn(where + ": texture coordinates outside [0, 1] are clamped to the edge (not repeated)");
      image = textureImage(textureIndex, materialAt);
    } else {
      painting->uvs.assign(painting->positions.size(), vec2(0.5f));
    }
    Image texels = image ? *image : Image(1, 1, vec4(1.0f));
    for (vec4& t : texels.texels) t = vec4(vec3(t) * vec3(factor), 1.0f);
    painting->texture = Texture2D(std::move(texels), Filter::Linear, MipFilter::None);
    if (normals.empty()) {
      Mesh m;
      m.positions = painting->positions;
      m.indices = painting->indices;
      computeSmoothNormals(m);
      normals = std::move(m.normals);
    }
    painting->normals = std::move(normals);
    PaintingSpec spec;
    spec.loaded = std::move(painting);
    out_.paintings.push_back(std::move(spec));
  }

  // A texture's image, decoded once (sRGB to linear) by the lab's decoders.
  std::shared_ptr<const Image> textureImage(int textureIndex, const std::string& materialAt) {
    const std::string at = materialAt + " -> textures[" + std::to_string(textureIndex) + "]";
    if (static_cast<std::size_t>(textureIndex) >= m_.textures.size()) fail(ErrorKind::Schema, at + ": no such texture");
    const int source = m_.textures[static_cast<std::size_t>(textureIndex)].source;
    if (source < 0 || static_cast<std::size_t>(source) >= m_.images.size())
      fail(ErrorKind::Schema, at + ": source image " + std::to_string(source) + " does not exist");
    const auto cached = images_.find(source);
    if (cached != images_.end()) return cached->second;
    const tinygltf::Image& img = m_.images[static_cast<std::size_t>(source)];
    const std::string imageAt = "images[" + std::to_string(source) + "]" + quoted(img.name);
    std::string bytes;
    if (img.bufferView >= 0) {
      if (static_cast<std::size_t>(img.bufferView) >= m_.bufferViews.size())
        fail(ErrorKind::Schema, imageAt + ": bufferView " + std::to_string(img.bufferView) + " does not exist");
      const tinygltf::BufferView& v = m_.bufferViews[static_cast<std::size_t>(img.bufferView)];
      if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= m_.buffers.size())
        fail(ErrorKind::Schema, imageAt + ": its buffer view's buffer does not exist");
      const std::vector<unsigned char>& data = m_.buffers[static_cast<std::size_t>(v.buffer)].data;
      if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
        fail(ErrorKind::Schema, imageAt + ": its buffer view reaches past its buffer");
      bytes.assign(reinterpret_cast<const char*>(data.data() + v.byteOffset), v.byteLength);
    } else if (!img.image.empty()) {
      bytes.assign(img.image.begin(), img.image.end());  // a data URI, decoded by tinygltf
    } else {
      std::vector<unsigned char> file;
      std::string err;
      const std::string uri = tinygltf::dlib::urldecode(img.uri);
      if (uri.empty() || !readWholeFile(&file, &err, rules_.folder.string() + "/" + uri, &rules_))
        fail(ErrorKind::Io, imageAt + ": cannot read \"" + img.uri + "\": " + rules_.refused);
      bytes.assign(file.begin(), file.end());
    }
    auto image = std::make_shared<const Image>(decodeImage(bytes, asset_ + ": " + imageAt));
    images_[source] = image;
    return image;
  }
};

}  // namespace

GltfScene parseGltf(const std::string& bytes, const std::string& path) {
  const std::string name = path.empty() ? std::string("<glTF data>") : path;
  if (bytes.size() > static_cast<std::size_t>(kMaxGltfBytes))
    throw Error(ErrorKind::Parse, name + ": larger than " + std::to_string(kMaxGltfBytes >> 20) + " MiB");
  FileRules rules;
  if (!path.empty()) {
    std::error_code ec;
    const fs::path folder = fs::canonical(fs::absolute(fs::path(path), ec).parent_path(), ec);
    if (!ec) rules.folder = folder;
  }
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&fileExists, &expandNothing, &readWholeFile, &writeNothing, &rules});
  loader.SetImageLoader(&keepEncoded, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  const std::string base = rules.folder.empty() ? std::string("/nonexistent-folder") : rules.folder.string();
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                                       reinterpret_cast<const unsigned char*>(bytes.data()),
                                                       static_cast<unsigned int>(bytes.size()), base)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                      static_cast<unsigned int>(bytes.size()), base);
  if (!ok) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    std::replace(err.begin(), err.end(), '\n', ';');
    if (!rules.refused.empty()) err += " (an external file: " + rules.refused + ")";
    throw Error(ErrorKind::Parse, name + ": not a glTF file the lab can read: " + (err.empty() ? warn : err));
  }
  Reader reader(model, name, rules);
  return reader.read();
}

GltfScene loadGltf(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(ErrorKind::Io, "glTF file not found: " + path);
  const auto size = fs::file_size(path, ec);
  if (ec) throw Error(ErrorKind::Io, "cannot read glTF file " + path + " (" + ec.message() + ")");
  if (size > static_cast<std::uintmax_t>(kMaxGltfBytes))
    throw Error(ErrorKind::Parse, path + ": larger than " + std::to_string(kMaxGltfBytes >> 20) + " MiB");
  std::ifstream in(path, std::ios::binary);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) throw Error(ErrorKind::Io, "cannot read glTF file " + path);
  return parseGltf(bytes, path);
}

Camera framingCamera(const std::vector<Mesh>& objects, const std::vector<Painting>& paintings) {
  Bounds glass{vec3(HUGE_VALF), vec3(-HUGE_VALF)};
  for (const Mesh& m : objects) {
    const Bounds b = meshBounds(m);
    glass.lo = glm::min(glass.lo, b.lo);
    glass.hi = glm::max(glass.hi, b.hi);
  }
  const glm::dvec3 centre(glass.center());
  const double radius = std::max(1e-3, 0.5 * glm::length(glm::dvec3(glass.hi - glass.lo)));
  Camera c;
  c.fovYDegrees = 40.0f;
  const double distance = radius / (0.8 * std::sin(glm::radians(20.0)));
  const glm::dvec3 from = glm::normalize(glm::dvec3(0.0, 0.15, 1.0));
  c.position = vec3(centre + distance * from);
  c.target = vec3(centre);
  c.up = vec3(0.0f, 1.0f, 0.0f);
  double farthest = distance + radius;
  for (const Painting& p : paintings)
    for (const vec3& v : p.positions) farthest = std::max(farthest, glm::length(glm::dvec3(v) - glm::dvec3(c.position)));
  c.zNear = static_cast<float>(std::max(1e-4, 0.1 * (distance - radius)));
  c.zFar = static_cast<float>(std::min(2.0 * farthest, 1e6 * static_cast<double>(c.zNear)));
  return c;
}

}  // namespace snell::lab
