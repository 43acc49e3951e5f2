#pragma once
// Surfaces made of mesh faces (the boundary; later patches, components, sheets) as OpenMesh
// polygon meshes, for viewing in any mesh viewer and for Blender import.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "hbc/mesh.hpp"

namespace hbc {

using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// Names of the per-face properties of a SurfaceMesh built here.
inline constexpr const char* kSurfaceIdProperty = "hbc_id";      // int: the selection's id
inline constexpr const char* kSurfaceFaceProperty = "hbc_face";  // int: the mesh face id

// The faces to put on a surface, all arrays of the same length (one entry per surface face):
// `faces` mesh face ids (a face may appear once), `reversed` 1 when the face's stored loop is to
// be walked backwards, `ids` an integer per face (patch, component, sheet, ...) that sets its
// colour. An exporter of another kind of surface only fills these arrays differently.
struct FaceSelection {
  std::vector<int32_t> faces;
  std::vector<uint8_t> reversed;
  std::vector<int32_t> ids;
  // Weld vertices only between faces of the same id, so that each id (a patch, a component, a
  // sheet) is its own piece; faces of one id must then be consecutive.
  bool separate_ids = false;
};

// Whether face f's stored loop must be reversed to point out of `cell` (a cell of f): cells see
// their face loops outward once their cell_face_flip is applied.
bool reversed_for_outward(const Mesh& mesh, int32_t face, int32_t cell);

// Every boundary face in increasing id, oriented out of the mesh; id = the CellType (as int) of
// its cell, so non-hex cells show on the surface.
FaceSelection boundary_selection(const Mesh& mesh);

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
