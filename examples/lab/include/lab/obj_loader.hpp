// Wavefront OBJ loading through tinyobjloader: every shape of the file merged
// into one mesh, polygons triangulated, vertices unified per (position, normal)
// pair, smooth normals computed when the file has none, winding made outward.
#pragma once
#include "lab/mesh.hpp"

#include <string>

namespace snell::lab {

// Throws Error(Io) naming the path when it cannot be opened, Error(Parse) when
// tinyobjloader rejects it, Error(Mesh) when it has no triangles or bad indices.
Mesh loadObj(const std::string& path);

// The same from OBJ text already in memory (`name` is used in messages).
Mesh parseObj(const std::string& text, const std::string& name);

}  // namespace snell::lab
