// Scene files: JSON, checked against the schema documented in
// examples/scenes/README.md. Errors name the file, the line, the field and the
// reason: `sphere.json:4: camera.fov: expected a number in (0, 180), got "wide"`.
// Unknown fields are errors (typos are caught). Paths inside a scene (meshes,
// images) are relative to the scene file.
#pragma once
#include "lab/camera.hpp"
#include "lab/environment.hpp"
#include "lab/mesh.hpp"
#include "lab/mesh_generators.hpp"
#include "lab/painting.hpp"

#include <snell/bridge.hpp>

#include <memory>
#include <string>
#include <vector>

namespace snell::lab {

enum class MeshKind { Obj, Sphere, Icosphere, Torus, Blob, Box, Loaded };

struct MeshSpec {
  MeshKind kind = MeshKind::Icosphere;
  std::string path;  // Obj: resolved against the scene file; Loaded: where it came from, for messages
  std::shared_ptr<const Mesh> loaded;  // Loaded: the mesh, in world space (a glTF asset's primitive)
  float radius = 1.0f;
  int segments = 64, rings = 32;  // Sphere
  int subdivisions = 5;           // Icosphere, Blob
  float majorRadius = 1.0f, minorRadius = 0.4f;
  int majorSegments = 96, minorSegments = 48;
  BlobParams blob;  // Blob (radius and subdivisions copied in)
  vec3 size{1.0f};  // Box: edge lengths
  // Obj: fit the mesh's bounding box into a cube of this edge length centred at
  // the origin before the transform (0: keep the file's coordinates).
  float fitSize = 0.0f;
};

struct RefractiveObject {
  std::string field;  // where it stands in the file ("object", "objects[1]"), for messages
  MeshSpec mesh;
  Transform transform;
  float ior = 1.5f;       // at the helium d line (587.56 nm): the green channel's
  vec3 absorption{0.0f};  // Beer-Lambert sigma_a per world unit, linear RGB
  float abbe = 0.0f;      // Abbe number V_d of its dispersion; 0: none (one IOR for every channel)
  // Perceptual roughness of both interfaces (glTF's roughnessFactor): GGX alpha = roughness^2; 0: smooth.
  float roughness = 0.0f;
};

enum class EnvironmentKind { Sky, Image, Color };

struct EnvironmentSpec {
  EnvironmentKind kind = EnvironmentKind::Sky;
  SkyParams sky;
  ivec2 bakeSize{1024, 512};  // Sky: equirectangular bake resolution
  std::string path;           // Image: resolved
  vec3 color{0.5f};           // Color
  float rotationDegrees = 0.0f;
  float intensity = 1.0f;
};

enum class TextureKind { Checker, Gradient, Pattern, Image };

struct TextureSpec {
  TextureKind kind = TextureKind::Pattern;
  ivec2 resolution{512, 512};  // procedural kinds
  ivec2 squares{8, 8};         // Checker
  vec3 colorA{0.9f}, colorB{0.1f};
  std::vector<vec3> colors;  // Gradient
  int direction = 0;         // Gradient: 0 horizontal, 1 vertical, 2 diagonal
  std::string path;          // Image: resolved
  float intensity = 1.0f;    // Image
};

struct PaintingSpec {
  std::shared_ptr<const Painting> loaded;  // a glTF asset's opaque primitive (the fields below unused)
  vec3 center{0.0f, 0.0f, -2.0f};
  vec2 size{4.0f, 3.0f};
  vec3 rotateDegrees{0.0f};
  TextureSpec texture;
};

struct AnimationSpec {
  int frames = 1;
  float timeStart = 0.0f;
  float timeStep = 1.0f / 30.0f;
  // The camera's move per frame: pannedCamera (lab/camera.hpp) by this many pixels times the frame index.
  vec2 cameraPanPixels{0.0f};
};

struct Scene {
  std::string file;  // the scene file ("" when parsed from text)
  std::string gltf;  // the glTF asset it comes from (the file itself, or its "gltf"), else ""
  std::string name;
  std::string description;
  Camera camera;
  // The glass: `object` in the file (one), or `objects` (a list of 1 to kMaxObjects).
  std::vector<RefractiveObject> objects;
  EnvironmentSpec environment;
  std::vector<PaintingSpec> paintings;
  AnimationSpec animation;
  // What the lab reads differently from the file (a glTF asset's extensions it does not render, say),
  // each a sentence; the lab prints them.
  std::vector<std::string> warnings;

  float frameTime(int frame) const { return animation.timeStart + static_cast<float>(frame) * animation.timeStep; }
  // The camera of frame `frame`: `camera` panned by animation.cameraPanPixels per frame.
  Camera frameCamera(int frame) const;
};

// Reads and checks a scene file. Error(Io) when it is missing, Error(Parse) for
// malformed JSON (with line and column), Error(Schema) for a bad field. A
// .gltf or .glb file is a scene too (gltf_loader.hpp): its objects, opaque
// meshes and camera (else a framing camera) under the default sky.
Scene loadScene(const std::string& path);

// The same from text; `file` is used in messages and to resolve relative paths.
Scene parseScene(const std::string& text, const std::string& file);

// How many refractive objects a scene may hold.
constexpr std::size_t kMaxObjects = 16;

// Resources, built from a checked scene. Errors name the missing file.
Mesh buildObjectMesh(const Scene& scene, std::size_t index, float time = 0.0f);  // world space
Environment buildEnvironment(const Scene& scene);
std::vector<Painting> buildPaintings(const Scene& scene);

// One refractive object of a frame.
struct FrameObject {
  Mesh mesh;  // world space
  float ior = 1.5f;
  vec3 absorption{0.0f};
  float abbe = 0.0f;  // RefractiveObject::abbe
  float roughness = 0.0f;  // RefractiveObject::roughness
};
// The IOR per colour channel (red, green, blue) of an object: snellDispersionIors (shade/dispersion.glsl:
// red at the C line, green at the d line, so green is `ior`, blue at the F line) with an Abbe number,
// (ior, ior, ior) without one. Every renderer of the lab (ray tracer, GL rows, the page) takes them from here.
vec3 channelIors(const FrameObject& o);
bool dispersive(const FrameObject& o);

// Everything a renderer needs for one frame.
struct SceneFrame {
  Camera camera;
  std::vector<FrameObject> objects;  // at least one, in the file's order
  Environment environment;
  std::vector<Painting> paintings;
};
SceneFrame buildFrame(const Scene& scene, float time = 0.0f);
// Frame `frame` of the scene's animation: the meshes at frameTime(frame), the camera frameCamera(frame).
SceneFrame buildAnimationFrame(const Scene& scene, int frame);

}  // namespace snell::lab
