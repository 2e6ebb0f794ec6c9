/*
description: cube-map face selection: which face of a cube map a direction
  reads, and the face coordinates (s, t) there, as the GL specification defines
  it. The C++ snell::TextureCube (include/snell/texture_cube.hpp) samples
  through this function, so its face choice and the GPU's cannot drift apart.
use: SnellCubeFace f = snellCubeFaceUv(dir);  // f.face 0..5 = +X -X +Y -Y +Z -Z
                                             // (GL_TEXTURE_CUBE_MAP_POSITIVE_X + f.face)
  dir  direction (any length)
options: -
contract:
  - the major axis is the component of largest magnitude; ties go to x over y
    over z (|x| >= |y| and |x| >= |z| selects x; else |y| >= |z| selects y);
    GL leaves ties to the implementation, so a texel exactly on a cube edge may
    read the neighbouring face on a GPU;
  - (sc, tc, ma) per face as the table below; s = 0.5 (sc / |ma| + 1),
    t = 0.5 (tc / |ma| + 1), in [0, 1];
      +X: (-z, -y, x)  -X: (+z, -y, x)  +Y: (+x, +z, y)
      -Y: (+x, -z, y)  +Z: (+x, -y, z)  -Z: (-x, -y, z)
  - valid = false, face 0, uv (0.5, 0.5) when dir is zero, denormal-small (every
    component below the smallest normal float) or has a NaN/Inf component.
source: OpenGL 4.5 core specification, sec. 8.13 "Cube Map Texture
  Selection", table 8.19, equations 8.6-8.7.
*/
#ifndef SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL
#define SNELL_SHADE_ENVIRONMENT_CUBE_FACE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"

struct SnellCubeFace {
  int face;
  vec2 uv;
  bool valid;
};

/* GL 4.5 core, sec. 8.13, table 8.19 */
SNELL_FN SnellCubeFace snellCubeFaceUv(vec3 dir) {
  SnellCubeFace r;
  r.face = 0;
  r.uv = vec2(0.5f, 0.5f);
  r.valid = false;
  if (!SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z)) {
    return r;
  }
  float ax = abs(dir.x);
  float ay = abs(dir.y);
  float az = abs(dir.z);
  float sc = 0.0f;
  float tc = 0.0f;
  float ma = 0.0f;
  if (ax >= ay && ax >= az) {
    ma = ax;
    r.face = dir.x >= 0.0f ? 0 : 1;
    sc = dir.x >= 0.0f ? -dir.z : dir.z;
    tc = -dir.y;
  } else if (ay >= az) {
    ma = ay;
    r.face = dir.y >= 0.0f ? 2 : 3;
    sc = dir.x;
    tc = dir.y >= 0.0f ? dir.z : -dir.z;
  } else {
    ma = az;
    r.face = dir.z >= 0.0f ? 4 : 5;
    sc = dir.z >= 0.0f ? dir.x : -dir.x;
    tc = -dir.y;
  }
  if (!(ma >= SNELL_FLT_MIN)) {
    r.face = 0;
    return r;
  }
  r.uv = vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
  r.valid = true;
  return r;
}

#endif
