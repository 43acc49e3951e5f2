#pragma once
// What is wrong with the cells of a file, defect class by defect class (docs/check.md): the
// validator behind `hbc check` and hbc.check(), and the load that drops the cells build_mesh
// refuses instead of refusing the file (--skip-invalid, skip_invalid=True). Both work on the
// MeshInput any reader produces, so every format gets them, with the file line (byte offset for
// binary files) wherever the reader recorded one.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hbc/error.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

// The defect classes in report order. Every element of the defect_refused classes makes build_mesh
// refuse the file, and a load with skip_invalid drops the cells they name instead; FewFaces and
// DuplicateCells are refused only in part (a one-face cell is open, a duplicate at a face of 3+
// cells goes), the others load as they always did. A dropped cell's reason is the first class of
// the list it falls in, FewFaces included.
enum class Defect : uint8_t {
  BadIndex,            // a cell names a face or vertex the file does not have, or an element repeats a corner
  DegenerateFaces,     // faces with fewer than 3 corners or a corner twice (ids: faces)
  FewFaces,            // cells with fewer than 4 faces
  FaceTwice,           // cells listing one face twice
  OpenCells,           // cells whose faces do not close: an edge not in exactly 2 of the cell's faces
  SharedFaces,         // cells using a face that two earlier kept cells already share (a face in 3+ cells)
  NotSimple,           // closed cells that are no simple polyhedron: a vertex in fewer than 3 of their faces,
                       // or V - E + F != 2 (the four-quad and (3,3,4,4) cells)
  Inverted,            // cells with a negative volume once neighbours agree (docs/concepts.md)
  ZeroVolume,          // cells with |volume| <= 1e-9 x the mean |volume|
  DuplicateCells,      // cells with the vertex set of an earlier cell
  CoincidentVertices,  // vertices at exactly the position of a lower-numbered vertex (ids: vertices)
  UnusedVertices,      // vertices in no kept cell (ids: vertices)
  DisconnectedPieces,  // face-connected pieces of cells beyond the one of cell 0 (ids: each piece's lowest cell)
};
constexpr size_t kDefectCount = 13;
const char* defect_key(Defect d);      // the JSON key: "bad_index", "degenerate_faces", ...
const char* defect_title(Defect d);    // words for the text report
const char* defect_subject(Defect d);  // what the ids number: "cells", "faces" or "vertices"
constexpr bool defect_refused(Defect d) { return d <= Defect::SharedFaces && d != Defect::FewFaces; }

// A cell a skip_invalid load dropped: its id in the file, why, and where it is.
struct DroppedCell {
  int32_t cell = -1;
  Defect reason = Defect::BadIndex;
  SourceLoc loc;
  bool operator==(const DroppedCell& o) const {
    return cell == o.cell && reason == o.reason && loc.line == o.loc.line && loc.byte_offset == o.loc.byte_offset;
  }
};

// One listed defect: the element's id in the file (0-based, file order), where it is in the file
// (unset when the reader records none), and for Inverted / ZeroVolume the cell's volume.
struct DefectItem {
  int64_t id = -1;
  SourceLoc loc;
  double volume = 0;
};
struct DefectClass {
  int64_t count = 0;
  int64_t dropped = 0;            // of these `count` elements, those a skip_invalid load drops
  std::vector<DefectItem> first;  // the lowest ids, at most `listed` of them
};
struct CheckReport {
  std::string source;
  int64_t vertices = 0, cells = 0;  // as the file has them
  std::array<DefectClass, kDefectCount> defects;
  std::vector<DroppedCell> dropped;  // exactly what a skip_invalid load drops (refused_cells)
  const DefectClass& operator[](Defect d) const { return defects[static_cast<size_t>(d)]; }
  bool clean() const;
};

// Every defect class of `in`, each with its count, how many of them a skip_invalid load drops and
// its first `listed` elements, and the load's `dropped` list itself (refused_cells' very rule: the
// report and the load cannot disagree). The classes from NotSimple on are found on the mesh
// build_mesh makes of the cells a skip_invalid load keeps.
// Throws InputError only for what no dropping of cells mends (a non-finite coordinate).
CheckReport check_input(MeshInput in, size_t listed = 10, const Threads& threads = {});

// The cells build_mesh would refuse, in file order. Which cells go is decided in file order and
// so is the same on every run: first each cell alone (BadIndex, DegenerateFaces, FaceTwice,
// OpenCells; FewFaces names the reason where it holds too); then, of a face that more than two of
// the remaining cells use, a cell with the vertex set of an earlier remaining cell (DuplicateCells);
// then each cell whose face two earlier kept cells already share (SharedFaces). A file that
// build_mesh accepts gives none.
std::vector<DroppedCell> refused_cells(const MeshInput& in);

// `in` without the `dropped` cells (the others keep their order, numbered from 0 again) and
// without the soup faces that are not polygons.
MeshInput without_cells(MeshInput in, const std::vector<DroppedCell>& dropped);

// build_mesh on the cells refused_cells keeps; `dropped` gets the others, and the mesh a warning
// counting them by reason. Without refused cells, exactly build_mesh(in).
Mesh build_mesh_skipping_invalid(MeshInput in, std::vector<DroppedCell>& dropped, const Threads& threads = {});

// "3 cells dropped (2 few_faces, 1 open_cells): cell 4 (line 17), cell 9 (line 30), ..." for
// warnings and messages.
std::string dropped_summary(const std::vector<DroppedCell>& dropped, size_t listed = 10);

// What an error about a refused cell adds: the option that loads the other cells.
inline constexpr const char* kSkipInvalidHint =
    " (`hbc check FILE` lists every defect; --skip-invalid, in Python skip_invalid=True, loads the other cells)";

}  // namespace hbc
