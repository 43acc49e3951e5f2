#pragma once
// Surfaces made of selected mesh faces (face_selection.hpp: the boundary, patches, components,
// sheets) as OpenMesh polygon meshes, for viewing in any mesh viewer.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "hbc/face_selection.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// Names of the per-face properties of a SurfaceMesh built here.
inline constexpr const char* kSurfaceIdProperty = "hbc_id";      // int: the selection's id
inline constexpr const char* kSurfaceFaceProperty = "hbc_face";  // int: the mesh face id

// Fixed palette (12 colours, repeated); negative ids map to grey. RGB in 0..255.
std::array<uint8_t, 3> palette_color(int32_t id);

struct SurfaceStats {
  int64_t faces = 0;
  int64_t unwelded_faces = 0;  // faces OpenMesh could not attach to their neighbours (a
                               // non-manifold edge or vertex): added with their own vertex copies
};

// Builds the surface: mesh vertices used by the selection become one OpenMesh vertex each
// (shared between faces, so the surface is welded), faces follow the selection's order with
// face colours from palette_color(id) and the two int properties named above.
SurfaceMesh build_surface(const Mesh& mesh, const FaceSelection& sel, SurfaceStats* stats = nullptr);

// Writes .obj, .ply or .off (by extension) with face colours (OBJ: materials in a .mtl beside it).
// Throws std::invalid_argument for another extension, std::runtime_error when writing fails.
void write_surface(const SurfaceMesh& surface, const std::string& path);

}  // namespace hbc
