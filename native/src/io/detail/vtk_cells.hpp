#pragma once
// VTK's cell types as hbc cells, shared by the legacy .vtk and the XML .vtu readers: linear and
// quadratic volume cells by their corners (VTK lists corners first; VTK's corner orders are MEDIT's
// but for the voxel's), VTK_POLYHEDRON (42) from its face stream; points, lines and surface cells
// skipped and counted.
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/cell_templates.hpp"
#include "io/detail/element_tally.hpp"
#include "hbc/mesh.hpp"

namespace hbc::detail {

class VtkCells {
 public:
  // `nv`: number of points, for the range check of point ids.
  VtkCells(MeshInput& in, int64_t nv) : in_(in), nv_(nv), cells_(in) {}
  // One cell: `items` are its point ids, or for type 42 the face stream
  // (nfaces, n0, ids of face 0, n1, ...). `loc` is where the cell is in the file (line or byte).
  void add(int64_t type, const int64_t* items, size_t n, int64_t loc);
  // Warns about skipped cells and checks that some volume cell was read.
  void finish(int64_t loc);

 private:
  [[noreturn]] void fail(int64_t loc, const std::string& expected) const;
  int32_t point(int64_t id, int64_t loc) const;
  void polyhedron(const int64_t* items, size_t n, int64_t loc);
  MeshInput& in_;
  int64_t nv_;
  CellAppender cells_;
  ElementTally tally_;
  std::vector<int32_t> face_sizes_, ids_;
};

}  // namespace hbc::detail
