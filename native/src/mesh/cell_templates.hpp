#pragma once
// The four standard volume elements as face templates over their corners, and the rule that turns
// an element whose corners repeat (as At-Most-Hexa and converters write prisms, pyramids and tets
// as hexahedra) into the polyhedron it stands for (docs/concepts.md, "Hex cell"). Shared by every reader of
// element-list formats (MEDIT, Gmsh, VTK, VTU) so that all give the same cells, and by the
// builder, which reads the faces of an element straight from its corners.
#include <array>
#include <cstdint>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc::detail {

// Corner orders are MEDIT's, which Gmsh shares (see hbc::CellShape).
using Element = CellShape;
using hbc::corner_count;

// The faces of an element as loops of local corner numbers, outward for an element of positive
// orientation in MEDIT's convention.
struct ShapeFaces {
  int nfaces;
  std::array<int8_t, 6> size;
  std::array<std::array<int8_t, 4>, 6> corner;
};
// Indexed by CellShape (inline: the builder reads it for every face of every element).
inline constexpr ShapeFaces kShapeFaces[5] = {
    {0, {}, {}},
    {4, {3, 3, 3, 3}, {{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}}},
    {5, {4, 3, 3, 3, 3}, {{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}}},
    {5, {3, 3, 4, 4, 4}, {{{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}}},
    {6, {4, 4, 4, 4, 4, 4}, {{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}}},
};
inline const ShapeFaces& shape_faces(CellShape s) { return kShapeFaces[static_cast<int>(s)]; }

// Appends cells to a MeshInput (and keeps its cell_shape filled). Reuse one appender for a whole
// file: it keeps scratch buffers.
class CellAppender {
 public:
  explicit CellAppender(MeshInput& in) : in_(in) {}
  // `v` holds corner_count(e) 0-based vertex ids, already checked to be in range. Distinct ids
  // make an element cell. Repeated ids collapse each template face (first occurrence kept); faces
  // left with fewer than 3 distinct vertices vanish and a face repeated within the cell is kept
  // once: the cell becomes a Faces cell over those loops.
  void element(Element e, const int32_t* v, int64_t loc);
  // A general polyhedron: `face_sizes[f]` vertices for face f taken in turn from `ids`. Loops are
  // taken as written; build_mesh checks that they close.
  void polyhedron(const std::vector<int32_t>& face_sizes, const std::vector<int32_t>& ids, int64_t loc);
  // Vertex v is a higher-order (non-corner) node of an element.
  void midside(int32_t v);
  // Drops the vertices that are only higher-order nodes, so that a quadratic mesh gives the same
  // mesh as its linear version; renumbers faces and corners. Call once after the last cell.
  void finish();

 private:
  void end_cell(CellShape shape, int64_t loc);
  MeshInput& in_;
  std::vector<int32_t> loop_;
  std::vector<std::array<int32_t, 8>> sets_;
  std::vector<uint8_t> midside_;  // by vertex id, 1 = seen as a higher-order node
};

}  // namespace hbc::detail
