// Wavefront OBJ loading through tinyobjloader: every shape of the file merged
// into one mesh, polygons triangulated, vertices unified per (position, normal)
// pair, smooth normals computed when the file has none, winding made outward.
#pragma once
#include "lab/mesh.hpp"

#include <string>

namespace snell::lab {

// Throws Error(Io) naming the path when it cannot be opened; Error(Parse) for
// a malformed v/vn/f line (a coordinate that is not a number, fewer than 3
// coordinates or face vertices, index 0) or when tinyobjloader rejects it;
// Error(Mesh) when it has no triangles, a non-finite coordinate or an index
// past the vertices/normals. Line errors read "<path>:<line>: ...".
Mesh loadObj(const std::string& path);

// The same from OBJ text already in memory (`name` is used in messages).
Mesh parseObj(const std::string& text, const std::string& name);

}  // namespace snell::lab
