#pragma once
// The mesh and its analysis as VTK XML UnstructuredGrid files for ParaView.
//
// OUT.vtu holds the cells, each as its own VTK type: hexahedra VTK_HEXAHEDRON (12), prisms
// VTK_WEDGE (13), pyramids VTK_PYRAMID (14), tetrahedra VTK_TETRA (10), in VTK's corner order and
// with a positive volume in VTK's convention (VTK 9.7's vtkCellSizeFilter and vtkMeshQuality:
// tests/vtk); only general polyhedra as VTK_POLYHEDRON (42) with outward faces (meshio 5 cannot
// read a file mixing 42 with other types; VTK and ParaView can) with
//   cell data  component   Int32  base-complex component id
//              is_hex      UInt8  1 for a hexahedron
//              cell_type   UInt8  hbc's CellType: 0 hex, 1 tet, 2 prism, 3 pyramid, 4 polyhedron
//              sheet       Int32  lowest id of a sheet holding the cell, -1 for none (when sheets ran)
//              sheet_count Int32  number of sheets holding the cell
//   and with a chosen sheet N:
//              in_sheet    UInt8  1 for the cells of sheet N
//              subsheet    Int32  lowest subsheet of sheet N holding the cell (-1: none, or sheet N
//                                 is not self-intersecting)
//              subsheet_count Int32
//   point data singular, pseudo_singular, corner  UInt8  singular / pseudo-singular vertex,
//                                                 base-complex corner
// Edge flags have no place in a cell grid, so the singularity graph goes to a second file,
// OUT_graph.vtu: the same points and one VTK_LINE per singular, pseudo-singular or non-manifold
// edge, with cell data edge_class (UInt8: 1 singular, 2 pseudo-singular, 3 non-manifold),
// valence (Int32, cells around the edge) and singularity (Int32, chain id, -1 for none).
// Arrays are zlib-compressed base64 (UInt64 headers) unless ascii is asked for.
#include <cstdint>
#include <optional>
#include <string>

#include "hbc/analysis.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

struct VtuExportOptions {
  bool ascii = false;
  std::optional<int32_t> sheet;  // the chosen sheet, if any
};

std::string vtu_cells_text(const Mesh& mesh, const Analysis& analysis, const VtuExportOptions& options = {});
std::string vtu_graph_text(const Mesh& mesh, const Analysis& analysis, const VtuExportOptions& options = {});
// "dir/out.vtu" -> "dir/out_graph.vtu".
std::string vtu_graph_path(const std::string& path);
// Writes both files; throws std::invalid_argument for a sheet id out of range and
// std::runtime_error when a file cannot be written.
void export_vtu(const Mesh& mesh, const Analysis& analysis, const std::string& path, const VtuExportOptions& options = {});

}  // namespace hbc
