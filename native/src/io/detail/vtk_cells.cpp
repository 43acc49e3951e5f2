#include "io/detail/vtk_cells.hpp"

#include <array>

#include "hbc/error.hpp"

namespace hbc::detail {
namespace {

struct VtkType {
  int type, dim;
  int corners;                 // volume cells: corners read; others: 0 (any count)
  Element element;
  std::array<int8_t, 8> perm;  // MEDIT corner k is VTK corner perm[k]
};

// Wedges too: in VTK's reference wedge (vtkWedge and the quadratic ones, VTK 9.7), as in MEDIT
// and Gmsh, triangle 0-1-2 faces into the cell; VTK rates the mirror image, which older VTK
// documentation described and meshio, Gmsh's VTK writer and foamToVTK (v1912) write, as inverted.
// build_mesh turns such cells with their neighbours, so those files still give their mesh.
constexpr std::array<int8_t, 8> kId{0, 1, 2, 3, 4, 5, 6, 7};
// vtkVoxel numbers its corners along x, then y, then z.
constexpr std::array<int8_t, 8> kVoxel{0, 1, 3, 2, 4, 5, 7, 6};

constexpr VtkType kTypes[] = {
    {1, 0, 0, Element::Tet, kId},      {2, 0, 0, Element::Tet, kId},      {3, 1, 0, Element::Tet, kId},
    {4, 1, 0, Element::Tet, kId},      {5, 2, 0, Element::Tet, kId},      {6, 2, 0, Element::Tet, kId},
    {7, 2, 0, Element::Tet, kId},      {8, 2, 0, Element::Tet, kId},      {9, 2, 0, Element::Tet, kId},
    {10, 3, 4, Element::Tet, kId},     {11, 3, 8, Element::Hex, kVoxel},  {12, 3, 8, Element::Hex, kId},
    {13, 3, 6, Element::Prism, kId},  {14, 3, 5, Element::Pyramid, kId}, {21, 1, 0, Element::Tet, kId},
    {22, 2, 0, Element::Tet, kId},     {23, 2, 0, Element::Tet, kId},     {24, 3, 4, Element::Tet, kId},
    {25, 3, 8, Element::Hex, kId},     {26, 3, 6, Element::Prism, kId},  {27, 3, 5, Element::Pyramid, kId},
    {28, 2, 0, Element::Tet, kId},     {29, 3, 8, Element::Hex, kId},     {30, 2, 0, Element::Tet, kId},
    {31, 3, 6, Element::Prism, kId},  {32, 3, 6, Element::Prism, kId},  {33, 3, 8, Element::Hex, kId},
    {34, 2, 0, Element::Tet, kId},     {35, 1, 0, Element::Tet, kId},     {36, 2, 0, Element::Tet, kId},
    {68, 1, 0, Element::Tet, kId},     {69, 2, 0, Element::Tet, kId},     {70, 2, 0, Element::Tet, kId},
};

const VtkType* vtk_type(int64_t type) {
  for (const VtkType& t : kTypes)
    if (t.type == type) return &t;
  return nullptr;
}

}  // namespace

void VtkCells::fail(int64_t loc, const std::string& expected) const {
  throw InputError(in_.source, in_.binary ? SourceLoc::at_byte(loc) : SourceLoc::at_line(loc), "expected " + expected);
}

int32_t VtkCells::point(int64_t id, int64_t loc) const {
  if (id < 0 || id >= nv_) fail(loc, "a point id in [0, " + std::to_string(nv_ - 1) + "], found " + std::to_string(id));
  return static_cast<int32_t>(id);
}

void VtkCells::polyhedron(const int64_t* items, size_t n, int64_t loc) {
  face_sizes_.clear();
  ids_.clear();
  if (n == 0) fail(loc, "the face stream of a polyhedron (number of faces first), found no entries");
  const int64_t nfaces = items[0];
  if (nfaces < 4 || nfaces > static_cast<int64_t>(n)) fail(loc, "a polyhedron with 4 or more faces in its face stream, found " + std::to_string(nfaces));
  size_t at = 1;
  for (int64_t f = 0; f < nfaces; ++f) {
    const int64_t k = at < n ? items[at] : -1;
    if (k < 3 || static_cast<size_t>(k) > n - at - 1)
      fail(loc, "face " + std::to_string(f) + " of the polyhedron with 3 or more point ids within its " + std::to_string(n) +
                    " entries, found " + (k < 0 && at >= n ? std::string("the end of the cell") : std::to_string(k)));
    face_sizes_.push_back(static_cast<int32_t>(k));
    for (int64_t i = 0; i < k; ++i) ids_.push_back(point(items[at + 1 + static_cast<size_t>(i)], loc));
    at += 1 + static_cast<size_t>(k);
  }
  if (at != n) fail(loc, "a polyhedron face stream of " + std::to_string(at) + " entries as its face counts say, found " + std::to_string(n));
  cells_.polyhedron(face_sizes_, ids_, loc);
}

void VtkCells::add(int64_t type, const int64_t* items, size_t n, int64_t loc) {
  if (type == 42) return polyhedron(items, n, loc);
  const VtkType* t = vtk_type(type);
  if (!t) fail(loc, "a VTK cell type of a point, line, surface or volume cell (10, 12, 13, 14, 42, ...), found type " + std::to_string(type));
  if (t->dim < 3) {
    for (size_t k = 0; k < n; ++k) point(items[k], loc);  // a bad id is bad input wherever it is
    tally_.skip(t->dim);
    return;
  }
  if (n < static_cast<size_t>(t->corners))
    fail(loc, "at least " + std::to_string(t->corners) + " point ids for a cell of type " + std::to_string(type) + ", found " + std::to_string(n));
  std::array<int32_t, 8> v{};
  for (size_t k = 0; k < n; ++k)
    if (const int32_t id = point(items[k], loc); static_cast<int>(k) >= t->corners) cells_.midside(id);
  for (int k = 0; k < t->corners; ++k) v[k] = static_cast<int32_t>(items[t->perm[k]]);
  cells_.element(t->element, v.data(), loc);
}

void VtkCells::finish(int64_t loc) {
  if (in_.cells.rows() == 0) fail(loc, "at least one volume cell (VTK type 10, 12, 13, 14 or 42)");
  tally_.report(in_);
  cells_.finish();
}

}  // namespace hbc::detail
