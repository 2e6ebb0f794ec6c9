// snell's two-interface refraction on one object's front faces, one technique of the table per program:
// PAGE_TECHNIQUE (a SNELL_TECHNIQUE_* id) and SNELL_INTERSECT_STRATEGIES (only the strategies its slots
// call on any object: most of the compile time) are defined by the page before this text; the object's
// buffers and constants are uniforms, set before each object's draw. Configured as snell-lab configures
// its rows (examples/glsl/lab_technique.glsl: labTechnique, labMaterial, labView), so the page and the lab
// render the same pixels; the page's test compares them. With PAGE_FRONT_FROM_TEXTURES the front faces'
// inputs come from textures (the lab's own front pass, drawn as a full-screen pass) instead of the
// rasterized mesh. The colour is linear: the frame holds it until the canvas pass encodes it, because the
// next object's scene layer reads it.
precision highp float;
precision highp int;
precision highp sampler2D;
#include <snell>

// The object's back faces (depth, normal, min/max pyramid) and front layer, then the opaque scene (depth,
// normal, pyramid, colour) and the environment: the names SNELL_OBJECT_BUFFER_ARGS and
// SNELL_SCENE_BUFFER_ARGS expect.
uniform sampler2D backDepth;
uniform sampler2D backNormal;
uniform sampler2D backPyramid;
uniform sampler2D frontLayerDepth;
uniform sampler2D frontLayerNormal;
uniform sampler2D sceneDepth;
uniform sampler2D sceneNormal;
uniform sampler2D scenePyramid;
uniform sampler2D sceneColor;
uniform sampler2D environment;

uniform mat4 bufferClipFromView;  // how the buffers were rendered (the guard band's projection)
uniform float zNear;
uniform float zFar;
uniform float ior;
uniform vec3 iors;        // the IOR per colour channel where dispersion is 1 (green is ior)
uniform int dispersion;   // 1: one path per colour channel
uniform vec3 absorption;  // Beer-Lambert, per unit length
uniform vec3 envX;        // world directions of the view axes, the environment's rotation folded in
uniform vec3 envY;
uniform vec3 envZ;
uniform float backRange;  // the marches' range in the back-face and inside slots: the object's diagonal
uniform int depthFilter;  // SNELL_DEPTH_FILTER_*: how every slot reads both depth buffers
uniform int reflectSource;  // SNELL_SOURCE_*: what the first surface reflects
uniform int insideScene;    // 1: the scene reaches inside the object (a painting or another object)

#ifdef PAGE_FRONT_FROM_TEXTURES
uniform sampler2D frontPositions;  // xyz view-space position, w Wyman's d_N
uniform sampler2D frontNormals;    // xyz interpolated normal, w 1 where the object covers the pixel
uniform int margin;  // the pass draws the frame's viewport, `margin` texels into the guard-banded target
#else
in vec3 vsPosition;
in vec3 vsNormal;
in float vsDn;
#endif
out vec4 color;

void main() {
#ifdef PAGE_FRONT_FROM_TEXTURES
  ivec2 px = ivec2(gl_FragCoord.xy) - ivec2(margin, margin);
  vec4 frontNormal = texelFetch(frontNormals, px, 0);
  if (frontNormal.w <= 0.0) discard;
  vec4 frontPosition = texelFetch(frontPositions, px, 0);
  vec3 position = frontPosition.xyz;
  vec3 normal = frontNormal.xyz;
  float dN = frontPosition.w;
#else
  vec3 position = vsPosition;
  vec3 normal = vsNormal;
  float dN = vsDn;
#endif
  // GL depth of a perspective projection; the back faces were drawn with depth test GREATER after
  // clearing depth to 0, so their "nothing there" is 0. Where the scene is empty the environment shows.
  SnellDepthSurface back = snellDepthSurface(bufferClipFromView, zNear, zFar, SNELL_DEPTH_GL, 0.0);
  SnellDepthSurface frontLayer = snellDepthSurface(bufferClipFromView, zNear, zFar, SNELL_DEPTH_GL, 1.0);
  SnellDepthSurface scene = snellDepthSurface(bufferClipFromView, zNear, zFar, SNELL_DEPTH_GL, 1.0);
  scene.closed = false;

  SnellTechnique t = snellTechniquePreset(PAGE_TECHNIQUE);
  t.back.intersect.marchMaxDistance = backRange;
  t.back.intersect.ddaMaxDistance = backRange;
  t.inside.intersect.marchMaxDistance = backRange;
  if (depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
    t.back.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
    t.exit.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  }
  t.exit.source = SNELL_SOURCE_BUFFERS;  // the exit ray looks for the opaque scene ...
  t.exit.fallback = SNELL_FALLBACK_ENVIRONMENT;  // ... and takes the environment where it finds none
  t.reflect = t.exit;
  t.reflect.source = reflectSource;
  t.insideScene = insideScene != 0;

  SnellMaterial m = snellMaterial();
  m.tirPolicy = SNELL_TIR_CRITICAL;
  m.ior = ior;
  m.iorOutside = 1.0;
  m.iors = iors;
  m.dispersion = dispersion != 0 ? 3 : 1;
  m.absorption = absorption;
  m.reflection = true;

  SnellView v = snellView();
  v.envX = envX;
  v.envY = envY;
  v.envZ = envZ;

  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(position, normal, dN, SNELL_OBJECT_BUFFER_ARGS,
                                                          SNELL_SCENE_BUFFER_ARGS, t, m, v);
  color = vec4(r.color, 1.0);
}
