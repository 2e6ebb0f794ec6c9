// snell::TextureCube: a cube map as GL samples it without seamless filtering
// (GL_TEXTURE_CUBE_MAP_SEAMLESS off, the GL 4.5 core default): the face and
// face coordinates from snellCubeFaceUv (glsl/snell/shade/environment_cube_face.glsl,
// GL 4.5 core sec. 8.13, table 8.19), then that face sampled as a
// snell::Texture2D (clamp to edge, the face's own filters and mips).
// Faces are indexed as GL_TEXTURE_CUBE_MAP_POSITIVE_X + i: +X -X +Y -Y +Z -Z;
// each face image is stored as glTexImage2D receives it (row 0 = t = 0).
//
// To run the techniques on a cube environment in C++, include this header
// first and define the environment hook before <snell/snell.hpp>:
//   #include <snell/texture_cube.hpp>
//   #define SNELL_ENVIRONMENT_TEX SNELL_TEXCUBE
//   #define SNELL_SAMPLE_ENVIRONMENT(tex, dir, lod) SNELL_SAMPLE_CUBE_LOD(tex, dir, lod)
//   #include <snell/snell.hpp>
#pragma once
#include "bridge.hpp"

#include <array>

namespace snell {
#include "snell/shade/environment_cube_face.glsl"

class TextureCube {
 public:
  std::array<Texture2D, 6> faces;

  TextureCube() = default;
  explicit TextureCube(std::array<Texture2D, 6> f) : faces(std::move(f)) {}

  // textureLod(samplerCube, dir, lod); a zero or non-finite direction reads
  // the centre of face +X (GL leaves it undefined).
  vec4 sampleLod(vec3 dir, float lod) const {
    const SnellCubeFace f = snellCubeFaceUv(dir);
    return faces[static_cast<std::size_t>(f.face)].sampleLod(f.uv, lod);
  }
};

}  // namespace snell

#ifndef SNELL_TEXCUBE
#  define SNELL_TEXCUBE const ::snell::TextureCube&
#endif
#ifndef SNELL_SAMPLE_CUBE_LOD
#  define SNELL_SAMPLE_CUBE_LOD(tex, dir, lod) ((tex).sampleLod(dir, lod))
#endif
