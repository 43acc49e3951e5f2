// The validator and the skip_invalid load (hbc/check.hpp). Cells are judged on the MeshInput, one
// at a time and in file order, before any merging, so that a defect build_mesh would stop at does
// not hide the others; the classes that need a mesh (volumes, pieces) are found on the mesh made
// of the cells that pass. Serial and sorted throughout: the same report for any thread count.
#include "hbc/check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <bit>
#include <numeric>

#include "mesh/cell_templates.hpp"

namespace hbc {

namespace {

struct DefectName {
  const char* key;
  const char* title;
  const char* subject;
};
constexpr DefectName kDefectNames[kDefectCount] = {
    {"bad_index", "cells naming a face or vertex the file lacks, or repeating a corner", "cells"},
    {"degenerate_faces", "faces with fewer than 3 corners or a corner twice", "faces"},
    {"few_faces", "cells with fewer than 4 faces", "cells"},
    {"face_twice", "cells listing one face twice", "cells"},
    {"open_cells", "cells whose faces do not close", "cells"},
    {"shared_faces", "cells using a face two earlier cells share (a face in 3+ cells)", "cells"},
    {"not_simple", "closed cells that are no simple polyhedron", "cells"},
    {"inverted", "inverted cells (negative volume)", "cells"},
    {"zero_volume", "cells of zero volume", "cells"},
    {"duplicate_cells", "cells with the vertices of an earlier cell", "cells"},
    {"coincident_vertices", "vertices at the position of an earlier vertex", "vertices"},
    {"unused_vertices", "vertices in no cell", "vertices"},
    {"disconnected_pieces", "pieces not connected to cell 0 through faces", "cells"},
};

using Mask = uint16_t;
constexpr Mask bit(Defect d) { return static_cast<Mask>(1u << static_cast<unsigned>(d)); }
constexpr Mask kRefused = bit(Defect::BadIndex) | bit(Defect::DegenerateFaces) | bit(Defect::FaceTwice) |
                          bit(Defect::OpenCells) | bit(Defect::SharedFaces) | bit(Defect::DuplicateCells);

// The first class of `mask` in report order.
Defect first_of(Mask mask) { return static_cast<Defect>(std::countr_zero(static_cast<unsigned>(mask))); }

// Per soup face: 0 fine, else the class it falls in (out-of-range vertex: BadIndex).
std::vector<Mask> judge_faces(const MeshInput& in) {
  const size_t nv = in.points.size() / 3;
  std::vector<Mask> out(in.faces.rows(), 0);
  std::vector<int32_t> sorted;
  for (size_t f = 0; f < in.faces.rows(); ++f) {
    const auto loop = in.faces[f];
    for (int32_t v : loop)
      if (v < 0 || static_cast<size_t>(v) >= nv) out[f] = bit(Defect::BadIndex);
    if (out[f]) continue;
    sorted.assign(loop.begin(), loop.end());
    std::sort(sorted.begin(), sorted.end());
    if (loop.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) out[f] = bit(Defect::DegenerateFaces);
  }
  return out;
}

// The loops of cell c (soup faces, or the element's template faces) appended to `loops`.
void cell_loops(const MeshInput& in, size_t c, Csr<int32_t>& loops) {
  loops.offsets.assign(1, 0);
  loops.items.clear();
  const auto row = in.cells[c];
  const CellShape s = in.shape(c);
  if (s == CellShape::Faces) {
    for (int32_t r : row) {
      const auto loop = in.faces[static_cast<size_t>(r >> 1)];
      loops.items.insert(loops.items.end(), loop.begin(), loop.end());
      loops.offsets.push_back(static_cast<int32_t>(loops.items.size()));
    }
    return;
  }
  const detail::ShapeFaces& sf = detail::shape_faces(s);
  for (int j = 0; j < sf.nfaces; ++j) {
    for (int i = 0; i < sf.size[static_cast<size_t>(j)]; ++i)
      loops.items.push_back(row[static_cast<size_t>(sf.corner[static_cast<size_t>(j)][static_cast<size_t>(i)])]);
    loops.offsets.push_back(static_cast<int32_t>(loops.items.size()));
  }
}

// What judge_cell reuses from cell to cell (its vectors keep their room).
struct CellScratch {
  Csr<int32_t> loops;
  std::vector<std::vector<int32_t>> sets;
  std::vector<uint64_t> edges;
};

// The classes cell c falls in on its own; `x.loops` gets its loops when its indices are sound.
Mask judge_cell(const MeshInput& in, size_t c, const std::vector<Mask>& face_mask, CellScratch& x) {
  Csr<int32_t>& loops = x.loops;
  const auto row = in.cells[c];
  const size_t nv = in.points.size() / 3, nf = in.faces.rows();
  Mask m = 0;
  if (in.shape(c) == CellShape::Faces) {
    if (row.size() < 4) m |= bit(Defect::FewFaces);
    if (row.empty()) m |= bit(Defect::OpenCells);  // no edge to find open, and nothing closed
    for (int32_t r : row) m |= r < 0 || static_cast<size_t>(r >> 1) >= nf ? bit(Defect::BadIndex) : face_mask[static_cast<size_t>(r >> 1)];
  } else {
    bool ok = row.size() == static_cast<size_t>(corner_count(in.shape(c)));
    for (size_t i = 0; i < row.size() && ok; ++i) {
      ok = row[i] >= 0 && static_cast<size_t>(row[i]) < nv;
      for (size_t j = 0; j < i; ++j) ok = ok && row[i] != row[j];
    }
    if (!ok) m |= bit(Defect::BadIndex);
  }
  if (m & (bit(Defect::BadIndex) | bit(Defect::DegenerateFaces))) return m;
  cell_loops(in, c, loops);
  // Face twice: two loops over one vertex set. Open: an edge not in exactly two loops.
  auto& sets = x.sets;
  auto& edges = x.edges;
  sets.resize(loops.rows());
  edges.clear();
  for (size_t j = 0; j < loops.rows(); ++j) {
    const auto loop = loops[j];
    sets[j].assign(loop.begin(), loop.end());
    std::sort(sets[j].begin(), sets[j].end());
    for (size_t i = 0; i < loop.size(); ++i) {
      const auto a = static_cast<uint32_t>(loop[i]), b = static_cast<uint32_t>(loop[(i + 1) % loop.size()]);
      edges.push_back(static_cast<uint64_t>(std::min(a, b)) << 32 | std::max(a, b));
    }
  }
  std::sort(sets.begin(), sets.end());  // (a cell's few loops)
  if (std::adjacent_find(sets.begin(), sets.end()) != sets.end()) m |= bit(Defect::FaceTwice);
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) m |= bit(Defect::OpenCells);
    i = j;
  }
  return m;
}

// Sorted vertex sets as rows, and which rows hold the same set.
struct SortedSets {
  Csr<int32_t> sets;
  void add(std::span<const int32_t> vs) {
    const size_t at = sets.items.size();
    sets.items.insert(sets.items.end(), vs.begin(), vs.end());
    std::sort(sets.items.begin() + static_cast<std::ptrdiff_t>(at), sets.items.end());
    sets.items.erase(std::unique(sets.items.begin() + static_cast<std::ptrdiff_t>(at), sets.items.end()), sets.items.end());
    sets.offsets.push_back(static_cast<int32_t>(sets.items.size()));
  }
  bool same(int32_t a, int32_t b) const {
    const auto x = sets[static_cast<size_t>(a)], y = sets[static_cast<size_t>(b)];
    return std::equal(x.begin(), x.end(), y.begin(), y.end());
  }
  // group[row] = the lowest row with the same set. Rows are sorted by a hash of their set and
  // their row (contiguous pairs: no lookup per comparison); a run of equal hashes is a handful
  // of rows, compared in full.
  std::vector<int32_t> groups() const {
    std::vector<std::pair<uint64_t, int32_t>> keys(sets.rows());
    for (size_t r = 0; r < sets.rows(); ++r) {
      uint64_t h = 1469598103934665603ull ^ sets[r].size();
      for (int32_t v : sets[r]) h = (h ^ static_cast<uint32_t>(v)) * 1099511628211ull;
      keys[r] = {h, static_cast<int32_t>(r)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<int32_t> group(sets.rows());
    for (size_t i = 0; i < keys.size();) {
      size_t e = i;
      while (e < keys.size() && keys[e].first == keys[i].first) ++e;
      for (size_t k = i; k < e; ++k) {
        const int32_t r = keys[k].second;
        group[static_cast<size_t>(r)] = r;
        for (size_t q = i; q < k; ++q)
          if (same(keys[q].second, r)) {
            group[static_cast<size_t>(r)] = group[static_cast<size_t>(keys[q].second)];
            break;
          }
      }
      i = e;
    }
    return group;
  }
};

// Per cell: the classes it falls in, refusing or not (FewFaces, DuplicateCells reported even when
// the cell loads).
struct Judgement {
  std::vector<Mask> cell;
  std::vector<Mask> face;          // per soup face
  std::vector<int32_t> duplicate_of;  // per cell: the lowest cell with its vertex set (itself when none), -1 for refused alone
};

Judgement judge(const MeshInput& in) {
  Judgement j;
  j.face = judge_faces(in);
  const size_t nc = in.cells.rows();
  j.cell.assign(nc, 0);
  CellScratch scratch;
  const Csr<int32_t>& loops = scratch.loops;
  SortedSets faces, cells;   // faces: every slot of the cells that pass alone; cells: their vertex sets
  std::vector<int32_t> slot_cell, sound;
  for (size_t c = 0; c < nc; ++c) {
    j.cell[c] = judge_cell(in, c, j.face, scratch);
    if (j.cell[c] & kRefused) continue;
    sound.push_back(static_cast<int32_t>(c));
    for (size_t k = 0; k < loops.rows(); ++k) {
      faces.add(loops[k]);
      slot_cell.push_back(static_cast<int32_t>(sound.size() - 1));
    }
    cells.add(loops.items);
  }
  const std::vector<int32_t> face_group = faces.groups(), cell_group = cells.groups();
  j.duplicate_of.assign(nc, -1);
  for (size_t s = 0; s < sound.size(); ++s) j.duplicate_of[static_cast<size_t>(sound[s])] = sound[static_cast<size_t>(cell_group[s])];
  // Users of each face among the sound cells; slots of one sound cell are consecutive.
  std::vector<int32_t> users(face_group.size(), 0);
  for (int32_t g : face_group) ++users[static_cast<size_t>(g)];
  std::vector<size_t> first_slot(sound.size() + 1, 0);
  for (size_t s = 0; s < slot_cell.size(); ++s) first_slot[static_cast<size_t>(slot_cell[s]) + 1] = s + 1;
  for (size_t s = 1; s <= sound.size(); ++s) first_slot[s] = std::max(first_slot[s], first_slot[s - 1]);
  auto slots = [&](size_t s) { return std::pair{first_slot[s], first_slot[s + 1]}; };
  // A duplicate at an overused face goes first, so that its neighbours keep their faces.
  for (size_t s = 0; s < sound.size(); ++s) {
    if (cell_group[s] == static_cast<int32_t>(s)) continue;
    bool overused = false;
    for (auto [k, k1] = slots(s); k < k1; ++k) overused = overused || users[static_cast<size_t>(face_group[k])] > 2;
    if (!overused) continue;
    j.cell[static_cast<size_t>(sound[s])] |= bit(Defect::DuplicateCells);
    for (auto [k, k1] = slots(s); k < k1; ++k) --users[static_cast<size_t>(face_group[k])];
  }
  std::vector<int32_t> kept(face_group.size(), 0);
  for (size_t s = 0; s < sound.size(); ++s) {
    Mask& m = j.cell[static_cast<size_t>(sound[s])];
    if (m & kRefused) continue;
    bool full = false;
    for (auto [k, k1] = slots(s); k < k1; ++k) full = full || kept[static_cast<size_t>(face_group[k])] >= 2;
    if (full) {
      m |= bit(Defect::SharedFaces);
      continue;
    }
    for (auto [k, k1] = slots(s); k < k1; ++k) ++kept[static_cast<size_t>(face_group[k])];
  }
  return j;
}

// The reason a refused cell is dropped for: its first class, FewFaces included.
Defect reason_of(Mask m) { return first_of(m & (kRefused | bit(Defect::FewFaces))); }

// The cells a skip_invalid load drops, in file order: the one rule of refused_cells and of the
// report of check_input, so that what `hbc check` says goes is what the load drops.
std::vector<DroppedCell> dropped_of(const Judgement& j, const MeshInput& in) {
  std::vector<DroppedCell> out;
  for (size_t c = 0; c < j.cell.size(); ++c)
    if (j.cell[c] & kRefused) out.push_back({static_cast<int32_t>(c), reason_of(j.cell[c]), in.loc_of(in.cell_loc, c)});
  return out;
}

}  // namespace

const char* defect_key(Defect d) { return kDefectNames[static_cast<size_t>(d)].key; }
const char* defect_title(Defect d) { return kDefectNames[static_cast<size_t>(d)].title; }
const char* defect_subject(Defect d) { return kDefectNames[static_cast<size_t>(d)].subject; }

bool CheckReport::clean() const {
  return std::all_of(defects.begin(), defects.end(), [](const DefectClass& d) { return d.count == 0; });
}

std::vector<DroppedCell> refused_cells(const MeshInput& in) { return dropped_of(judge(in), in); }

MeshInput without_cells(MeshInput in, const std::vector<DroppedCell>& dropped) {
  const std::vector<Mask> face_mask = judge_faces(in);
  const bool bad_faces = std::any_of(face_mask.begin(), face_mask.end(), [](Mask m) { return m != 0; });
  if (dropped.empty() && !bad_faces) return in;
  // Soup faces: the polygons kept, renumbered.
  std::vector<int32_t> face_id(in.faces.rows(), -1);
  Csr<int32_t> faces;
  std::vector<int64_t> face_loc;
  for (size_t f = 0; f < in.faces.rows(); ++f) {
    if (face_mask[f]) continue;
    face_id[f] = static_cast<int32_t>(faces.rows());
    const auto loop = in.faces[f];
    faces.items.insert(faces.items.end(), loop.begin(), loop.end());
    faces.offsets.push_back(static_cast<int32_t>(faces.items.size()));
    if (f < in.face_loc.size()) face_loc.push_back(in.face_loc[f]);
  }
  std::vector<uint8_t> drop(in.cells.rows(), 0);
  for (const DroppedCell& d : dropped) drop[static_cast<size_t>(d.cell)] = 1;
  Csr<int32_t> cells;
  std::vector<CellShape> shape;
  std::vector<int64_t> cell_loc;
  for (size_t c = 0; c < in.cells.rows(); ++c) {
    if (drop[c]) continue;
    const bool faces_cell = in.shape(c) == CellShape::Faces;
    for (int32_t r : in.cells[c]) cells.items.push_back(faces_cell ? 2 * face_id[static_cast<size_t>(r >> 1)] + (r & 1) : r);
    cells.offsets.push_back(static_cast<int32_t>(cells.items.size()));
    if (!in.cell_shape.empty()) shape.push_back(in.cell_shape[c]);
    if (c < in.cell_loc.size()) cell_loc.push_back(in.cell_loc[c]);
  }
  in.faces = std::move(faces);
  in.face_loc = std::move(face_loc);
  in.cells = std::move(cells);
  in.cell_shape = std::move(shape);
  in.cell_loc = std::move(cell_loc);
  return in;
}

std::string dropped_summary(const std::vector<DroppedCell>& dropped, size_t listed) {
  std::array<int64_t, kDefectCount> by{};
  for (const DroppedCell& d : dropped) ++by[static_cast<size_t>(d.reason)];
  std::string s = std::to_string(dropped.size()) + " cell(s) dropped (";
  bool first = true;
  for (size_t k = 0; k < kDefectCount; ++k)
    if (by[k]) s += (first ? "" : ", ") + std::to_string(by[k]) + " " + kDefectNames[k].key, first = false;
  s += ")";
  for (size_t i = 0; i < dropped.size() && i < listed; ++i) {
    s += (i ? ", " : ": ") + std::string("cell ") + std::to_string(dropped[i].cell);
    if (dropped[i].loc.line >= 0) s += " (line " + std::to_string(dropped[i].loc.line) + ")";
    else if (dropped[i].loc.byte_offset >= 0) s += " (byte " + std::to_string(dropped[i].loc.byte_offset) + ")";
  }
  if (dropped.size() > listed) s += ", ...";
  return s;
}

Mesh build_mesh_skipping_invalid(MeshInput in, std::vector<DroppedCell>& dropped, const Threads& threads) {
  dropped = refused_cells(in);
  // without_cells hands `in` back untouched when there is nothing to drop.
  Mesh m = build_mesh(without_cells(std::move(in), dropped), threads);
  if (!dropped.empty()) m.warnings.push_back(dropped_summary(dropped));
  return m;
}

}  // namespace hbc

namespace hbc {

namespace {

// Signed volume (x6) of cell c as build_mesh oriented it: positive for a cell that agrees with its
// face-connected group (mesh_cells.cpp), negative for an inverted one.
double volume6(const Mesh& m, size_t c) {
  const auto faces = m.cell_faces[c];
  const double* o = &m.points[3 * static_cast<size_t>(m.face_verts[static_cast<size_t>(faces[0])][0])];
  double vol = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto loop = m.face_verts[static_cast<size_t>(faces[i])];
    const bool flip = m.cell_face_flip[static_cast<size_t>(m.cell_faces.offsets[c]) + i] != 0;
    auto p = [&](size_t k, int a) { return m.points[3 * static_cast<size_t>(loop[k]) + static_cast<size_t>(a)] - o[a]; };
    for (size_t t = 1; t + 1 < loop.size(); ++t) {
      const size_t b = flip ? t + 1 : t, d = flip ? t : t + 1;
      vol += p(0, 0) * (p(b, 1) * p(d, 2) - p(b, 2) * p(d, 1)) - p(0, 1) * (p(b, 0) * p(d, 2) - p(b, 2) * p(d, 0)) +
             p(0, 2) * (p(b, 0) * p(d, 1) - p(b, 1) * p(d, 0));
    }
  }
  return vol;
}

// The two corners beside `v` in the first face of cell c that holds it, as (before, after).
std::array<int32_t, 2> corners_beside(const Mesh& m, size_t c, int32_t v) {
  for (int32_t f : m.cell_faces[c]) {
    const auto loop = m.face_verts[static_cast<size_t>(f)];
    for (size_t k = 0; k < loop.size(); ++k)
      if (loop[k] == v) return {loop[(k + loop.size() - 1) % loop.size()], loop[(k + 1) % loop.size()]};
  }
  return {v, v};
}

// A corner in only two faces of its cell is a corner on an edge when it lies on the straight line
// between the corners beside it: snappyHexMesh's split hexahedra have such corners wherever a
// neighbour was refined (a hanging node), and the cell is a true polyhedron. Folded by more than
// 10 degrees it is no longer on an edge: the two faces then bound no volume there.
bool on_straight_edge(const Mesh& m, size_t c, int32_t v) {
  const auto [a, b] = corners_beside(m, c, v);
  auto p = [&](int32_t x, int i) { return m.points[3 * static_cast<size_t>(x) + static_cast<size_t>(i)]; };
  double dot = 0, la = 0, lb = 0;
  for (int i = 0; i < 3; ++i) {
    const double u = p(a, i) - p(v, i), w = p(b, i) - p(v, i);
    dot += u * w, la += u * u, lb += w * w;
  }
  constexpr double kCos170 = -0.98480775301220802;
  return la > 0 && lb > 0 && dot <= kCos170 * std::sqrt(la * lb);
}

// A closed polyhedral cell that is no simple polyhedron: a vertex in fewer than 3 of its faces
// that is not a corner on a straight edge, or V - E + F != 2 (a corner on an edge leaves the sum
// as it is: it adds one vertex and one edge). The standard types are simple by the way build_mesh
// classifies them.
bool not_simple(const Mesh& m, size_t c, std::vector<int32_t>& scratch) {
  if (m.cell_type[c] != CellType::Polyhedron) return false;
  scratch.clear();
  for (int32_t f : m.cell_faces[c])
    for (int32_t v : m.face_verts[static_cast<size_t>(f)]) scratch.push_back(v);
  std::sort(scratch.begin(), scratch.end());
  int64_t nv = 0;
  for (size_t i = 0; i < scratch.size();) {
    size_t k = i;
    while (k < scratch.size() && scratch[k] == scratch[i]) ++k;
    if (k - i < 2 || (k - i == 2 && !on_straight_edge(m, c, scratch[i]))) return true;
    ++nv, i = k;
  }
  const auto nf = static_cast<int64_t>(m.cell_faces.count(c));
  const auto ne = static_cast<int64_t>(scratch.size()) / 2;  // each edge in two faces of a closed cell
  return nv - ne + nf != 2;
}

// Vertices at exactly the position of a lower-numbered vertex.
std::vector<uint8_t> coincident(const std::vector<double>& p) {
  const size_t nv = p.size() / 3;
  std::vector<int32_t> order(nv);
  std::iota(order.begin(), order.end(), 0);
  auto at = [&](int32_t v) { return std::array<double, 3>{p[3 * static_cast<size_t>(v)], p[3 * static_cast<size_t>(v) + 1], p[3 * static_cast<size_t>(v) + 2]}; };
  std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return at(a) != at(b) ? at(a) < at(b) : a < b; });
  std::vector<uint8_t> out(nv, 0);
  for (size_t i = 1; i < nv; ++i) out[static_cast<size_t>(order[i])] = at(order[i]) == at(order[i - 1]);
  return out;
}

// The lowest cell of each face-connected piece other than cell 0's.
std::vector<int32_t> other_pieces(const Mesh& m) {
  std::vector<int32_t> parent(m.num_cells());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int32_t x) {
    while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    return x;
  };
  for (const auto& fc : m.face_cells)
    if (fc[1] >= 0) {
      const int32_t a = find(fc[0]), b = find(fc[1]);
      parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);  // a piece's root: its lowest cell
    }
  std::vector<int32_t> out;
  for (size_t c = 1; c < m.num_cells(); ++c)
    if (find(static_cast<int32_t>(c)) == static_cast<int32_t>(c)) out.push_back(static_cast<int32_t>(c));
  return out;
}

// The classes found on the mesh of the kept cells (`kept`: each one's id in the file).
void check_mesh(const Mesh& m, const std::vector<int32_t>& kept, const auto& add_cell) {
  const size_t nc = m.num_cells();
  std::vector<double> vol(nc);
  double total = 0;
  for (size_t c = 0; c < nc; ++c) total += std::abs(vol[c] = volume6(m, c) / 6);
  const double tiny = nc ? 1e-9 * total / static_cast<double>(nc) : 0;
  std::vector<int32_t> scratch;
  for (size_t c = 0; c < nc; ++c) {
    if (not_simple(m, c, scratch)) add_cell(Defect::NotSimple, kept[c], 0.0);
    if (std::abs(vol[c]) <= tiny) add_cell(Defect::ZeroVolume, kept[c], vol[c]);
    else if (vol[c] < 0) add_cell(Defect::Inverted, kept[c], vol[c]);
  }
  for (int32_t c : other_pieces(m)) add_cell(Defect::DisconnectedPieces, kept[static_cast<size_t>(c)], 0.0);
}

}  // namespace

CheckReport check_input(MeshInput in, size_t listed, const Threads& threads) {
  CheckReport r;
  r.source = in.source;
  r.vertices = static_cast<int64_t>(in.points.size() / 3);
  r.cells = static_cast<int64_t>(in.cells.rows());
  const Judgement j = judge(in);
  MeshInput locs;  // where the elements are: build_mesh consumes `in`
  locs.binary = in.binary;
  locs.vertex_loc = in.vertex_loc;
  locs.face_loc = in.face_loc;
  locs.cell_loc = in.cell_loc;
  // `goes`: the element is one a skip_invalid load drops (without_cells drops every soup face that
  // is no polygon, and the cells of dropped_of).
  auto add = [&](Defect d, int64_t id, SourceLoc loc, double volume, bool goes = false) {
    DefectClass& k = r.defects[static_cast<size_t>(d)];
    if (k.first.size() < listed) k.first.push_back({id, loc, volume});
    ++k.count;
    k.dropped += goes;
  };
  auto add_cell = [&](Defect d, int64_t c, double volume, bool goes = false) {
    add(d, c, locs.loc_of(locs.cell_loc, static_cast<size_t>(c)), volume, goes);
  };
  for (size_t f = 0; f < j.face.size(); ++f)
    if (j.face[f] & bit(Defect::DegenerateFaces)) add(Defect::DegenerateFaces, static_cast<int64_t>(f), locs.loc_of(locs.face_loc, f), 0, true);
  r.dropped = dropped_of(j, in);
  for (size_t c = 0; c < j.cell.size(); ++c) {
    const bool goes = (j.cell[c] & kRefused) != 0;
    for (Defect d : {Defect::BadIndex, Defect::FewFaces, Defect::FaceTwice, Defect::OpenCells, Defect::SharedFaces})
      if (j.cell[c] & bit(d)) add_cell(d, static_cast<int64_t>(c), 0, goes);
    if (j.duplicate_of[c] >= 0 && j.duplicate_of[c] != static_cast<int32_t>(c)) add_cell(Defect::DuplicateCells, static_cast<int64_t>(c), 0, goes);
  }
  const std::vector<uint8_t> same_place = coincident(in.points);
  for (size_t v = 0; v < same_place.size(); ++v)
    if (same_place[v]) add(Defect::CoincidentVertices, static_cast<int64_t>(v), locs.loc_of(locs.vertex_loc, v), 0);
  std::vector<int32_t> kept;
  for (size_t c = 0, d = 0; c < j.cell.size(); ++c) {
    if (d < r.dropped.size() && r.dropped[d].cell == static_cast<int32_t>(c)) ++d;
    else kept.push_back(static_cast<int32_t>(c));
  }
  const Mesh m = build_mesh(without_cells(std::move(in), r.dropped), threads);
  std::vector<uint8_t> used(m.num_vertices(), 0);
  for (int32_t v : m.face_verts.items) used[static_cast<size_t>(v)] = 1;
  for (size_t v = 0; v < used.size(); ++v)
    if (!used[v]) add(Defect::UnusedVertices, static_cast<int64_t>(v), locs.loc_of(locs.vertex_loc, v), 0);
  check_mesh(m, kept, add_cell);
  return r;
}

}  // namespace hbc
