// The face and edge steps of build_mesh (see hbc/mesh_steps.hpp). Faces and edges are matched by
// a counting sort on their lowest-ranked vertex (see VertexRanks), then by sorting the few keys in
// each bucket: no hash table, and the buckets are small and independent, so threads split them by
// rank range.
#include "mesh/mesh_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "hbc/check.hpp"
#include "mesh/cell_templates.hpp"
#include "platform/huge_pages.hpp"
#include "parallel/parallel.hpp"
#include "parallel/small_table.hpp"

namespace hbc::mesh_steps {

std::string loop_text(std::span<const int32_t> loop) {
  std::ostringstream s;
  s << "(";
  for (size_t i = 0; i < loop.size(); ++i) s << (i ? " " : "") << loop[i];
  s << ")";
  return s.str();
}

namespace {

// Each check runs over ranges in parallel; a range stops at its first bad element and the lowest
// range's error is the one thrown, so the message names the first bad element in file order.
void validate_face(const MeshInput& in, size_t nv, size_t f, std::vector<int32_t>& stamp) {
  auto loop = in.faces[f];
  if (loop.size() < 3)
    throw InputError(in.source, in.loc_of(in.face_loc, f),
                     "a face with at least 3 vertices, face " + std::to_string(f) + " has " + std::to_string(loop.size()) + kSkipInvalidHint);
  for (int32_t v : loop) {
    if (v < 0 || static_cast<size_t>(v) >= nv)
      throw InputError(in.source, in.loc_of(in.face_loc, f),
                       "vertex index in [0, " + std::to_string(nv) + ") in face " + std::to_string(f) + ", found " +
                           std::to_string(v));
    if (stamp[static_cast<size_t>(v)] == static_cast<int32_t>(f))
      throw InputError(in.source, in.loc_of(in.face_loc, f),
                       "distinct vertices in face " + std::to_string(f) + ", vertex " + std::to_string(v) + " repeats in " +
                           loop_text(loop) + kSkipInvalidHint);
    stamp[static_cast<size_t>(v)] = static_cast<int32_t>(f);
  }
}

void validate_cell(const MeshInput& in, size_t nv, size_t c) {
  const auto row = in.cells[c];
  const CellShape shape = in.shape(c);
  if (shape != CellShape::Faces) {
    bool ok = row.size() == static_cast<size_t>(corner_count(shape));
    for (size_t i = 0; i < row.size() && ok; ++i) {
      ok = row[i] >= 0 && static_cast<size_t>(row[i]) < nv;
      for (size_t j = 0; j < i; ++j) ok = ok && row[i] != row[j];
    }
    if (!ok)
      throw InputError(in.source, in.loc_of(in.cell_loc, c),
                       std::to_string(corner_count(shape)) + " distinct vertex indices in [0, " + std::to_string(nv) +
                           ") for cell " + std::to_string(c) + ", found " + loop_text(row) + kSkipInvalidHint);
    return;
  }
  if (row.size() < 2)
    throw InputError(in.source, in.loc_of(in.cell_loc, c),
                     "a cell with at least 2 faces, cell " + std::to_string(c) + " has " + std::to_string(row.size()) + kSkipInvalidHint);
  const size_t nf = in.faces.rows();
  for (int32_t r : row) {
    const int32_t f = r >> 1;
    if (r < 0 || static_cast<size_t>(f) >= nf)
      throw InputError(in.source, in.loc_of(in.cell_loc, c),
                       "face index in [0, " + std::to_string(nf) + ") in cell " + std::to_string(c) + ", found " +
                           std::to_string(r < 0 ? r : f) + kSkipInvalidHint);
  }
}

}  // namespace

// Checks what a reader handed over: counts, index ranges, finite coordinates, proper polygons.
void validate_input(const MeshInput& in, const Threads& par) {
  const std::string& file = in.source;
  if (in.points.size() % 3 != 0) throw InputError(file, {}, "3 coordinates per vertex");
  const size_t nv = in.points.size() / 3;
  if (nv > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.faces.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.cells.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()))
    throw InputError(file, {}, "fewer than 2^31 vertices, face corners and cell faces");
  detail::parallel_ranges(in.points.size(), par, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i)
      if (!std::isfinite(in.points[i]))
        throw InputError(file, in.loc_of(in.vertex_loc, i / 3), "a finite coordinate for vertex " + std::to_string(i / 3));
  });
  detail::parallel_ranges(in.faces.rows(), par, [&](size_t b, size_t e, int) {
    std::vector<int32_t> stamp(e > b ? nv : 0, -1);  // the last face that named each vertex
    for (size_t f = b; f < e; ++f) validate_face(in, nv, f, stamp);
  });
  if (!in.cell_shape.empty() && in.cell_shape.size() != in.cells.rows())
    throw InputError(file, {}, "a shape for every cell");
  detail::parallel_ranges(in.cells.rows(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) validate_cell(in, nv, c);
  });
}

namespace {

// The lowest rank[v] of a soup face's vertices: the bucket face merging puts it in.
int32_t lowest_rank(std::span<const int32_t> loop, std::span<const int32_t> rank) {
  int32_t lo = std::numeric_limits<int32_t>::max();
  for (int32_t v : loop) lo = std::min(lo, rank[static_cast<size_t>(v)]);
  return lo;
}

// The loops of the slots of a MeshInput's cells, as the cells give them.
class SlotLoops {
 public:
  explicit SlotLoops(const MeshInput& in) : in_(in) {}
  int count(size_t c) const {
    const CellShape s = in_.shape(c);
    return s == CellShape::Faces ? in_.cells.count(c) : detail::shape_faces(s).nfaces;
  }
  // Loop of face j of cell c; `buf` holds it for an element.
  std::span<const int32_t> loop(size_t c, int j, std::array<int32_t, 4>& buf) const {
    const auto row = in_.cells[c];
    const CellShape s = in_.shape(c);
    if (s == CellShape::Faces) return in_.faces[static_cast<size_t>(row[static_cast<size_t>(j)] >> 1)];
    const detail::ShapeFaces& sf = detail::shape_faces(s);
    const int n = sf.size[static_cast<size_t>(j)];
    for (int i = 0; i < n; ++i) buf[static_cast<size_t>(i)] = row[static_cast<size_t>(sf.corner[static_cast<size_t>(j)][static_cast<size_t>(i)])];
    return {buf.data(), static_cast<size_t>(n)};
  }
  // emit(lowest rank[v] of its vertices) for each loop of cell c in order: what face merging
  // sorts by, found twice per slot, so each element shape gets its own unrolled loops.
  template <class Emit>
  void each_lowest(size_t c, std::span<const int32_t> rank, Emit&& emit) const {
    switch (in_.shape(c)) {
      case CellShape::Hex: return element_lowest<CellShape::Hex>(c, rank, emit);
      case CellShape::Prism: return element_lowest<CellShape::Prism>(c, rank, emit);
      case CellShape::Pyramid: return element_lowest<CellShape::Pyramid>(c, rank, emit);
      case CellShape::Tet: return element_lowest<CellShape::Tet>(c, rank, emit);
      case CellShape::Faces: break;
    }
    for (int32_t r : in_.cells[c]) emit(lowest_rank(in_.faces[static_cast<size_t>(r >> 1)], rank));
  }
  // f(v) for each vertex of cell c, in the order the file gives them (a Faces cell's by its loops).
  template <class F>
  void each_vertex(size_t c, F&& f) const {
    if (in_.shape(c) != CellShape::Faces) {
      for (int32_t v : in_.cells[c]) f(v);
      return;
    }
    for (int32_t r : in_.cells[c])
      for (int32_t v : in_.faces[static_cast<size_t>(r >> 1)]) f(v);
  }
  // The length of loop j of cell c.
  int size(size_t c, int j) const {
    const CellShape s = in_.shape(c);
    if (s == CellShape::Faces) return in_.faces.count(static_cast<size_t>(in_.cells[c][static_cast<size_t>(j)] >> 1));
    return detail::shape_faces(s).size[static_cast<size_t>(j)];
  }
  // 1 when cell c sees loop j reversed, as the file says.
  uint8_t flip(size_t c, int j) const {
    return in_.shape(c) == CellShape::Faces ? static_cast<uint8_t>(in_.cells[c][static_cast<size_t>(j)] & 1) : 0;
  }

 private:
  template <CellShape S, class Emit>
  void element_lowest(size_t c, std::span<const int32_t> rank, Emit&& emit) const {
    constexpr detail::ShapeFaces sf = detail::kShapeFaces[static_cast<int>(S)];
    const int32_t* row = in_.cells.items.data() + in_.cells.offsets[c];
    constexpr int kCorners = corner_count(S);
    std::array<int32_t, kCorners> r;  // each corner's rank looked up once, not once per face
#pragma GCC unroll 8
    for (size_t i = 0; i < static_cast<size_t>(kCorners); ++i) r[i] = rank[static_cast<size_t>(row[i])];
#pragma GCC unroll 6
    for (size_t j = 0; j < static_cast<size_t>(sf.nfaces); ++j) {
      const auto& k = sf.corner[j];
      const int32_t lo = std::min({r[k[0]], r[k[1]], r[k[2]], sf.size[j] == 4 ? r[k[3]] : r[k[0]]});
      emit(lo);
    }
  }
  const MeshInput& in_;
};

// Vertices ranked by first use (rank[v]; vertex[r] = the vertex of rank r), vertices never used
// last in id order. Faces and edges are grouped by their lowest-ranked vertex rather than their
// lowest id, so that consecutive buckets hold the faces of neighbouring cells whatever order the
// file numbers its vertices in: a mesh numbered by coordinate (as np.unique leaves it) built its
// faces and edges about a third slower by id. The grouping's result (each face's and edge's lowest
// item) does not depend on the ranks.
struct VertexRanks {
  std::vector<int32_t> rank, vertex;
  // each_use(f) calls f(v) for the uses of vertices, in the order that ranks them.
  template <class EachUse>
  VertexRanks(size_t nv, EachUse&& each_use) : rank(nv, -1), vertex(nv) {
    int32_t next = 0;
    each_use([&](int32_t v) {
      int32_t& r = rank[static_cast<size_t>(v)];
      if (r < 0) vertex[static_cast<size_t>(next)] = v, r = next++;
    });
    for (size_t v = 0; v < nv; ++v)
      if (rank[v] < 0) vertex[static_cast<size_t>(next)] = static_cast<int32_t>(v), rank[v] = next++;
  }
};

// The cell of each slot. Cells come in runs with the same number of slots (a file's sections of
// one element), which locate a slot's cell without an array as large as the slots; where the
// runs are many (polyhedra of varying face counts) the array is kept.
class SlotCells {
 public:
  explicit SlotCells(const std::vector<int32_t>& slot_offsets) {
    const size_t nc = slot_offsets.size() - 1;
    for (size_t c = 0; c < nc && runs_.size() <= kMaxRuns; ++c) {
      const int32_t per = slot_offsets[c + 1] - slot_offsets[c];
      if (runs_.empty() || runs_.back().per_cell != per) runs_.push_back({slot_offsets[c], static_cast<int32_t>(c), per});
    }
    if (runs_.size() <= kMaxRuns) return;
    runs_.clear();
    detail::resize_huge(cell_, static_cast<size_t>(slot_offsets.back()));
    for (size_t c = 0; c < nc; ++c)
      std::fill(cell_.begin() + slot_offsets[c], cell_.begin() + slot_offsets[c + 1], static_cast<int32_t>(c));
  }
  size_t operator()(size_t s) const {
    if (!cell_.empty()) return static_cast<size_t>(cell_[s]);
    auto run = runs_.end() - 1;
    while (static_cast<size_t>(run->first_slot) > s) --run;
    const auto d = static_cast<uint32_t>(s - static_cast<size_t>(run->first_slot));
    // Constant divisors for the elements' face counts: a multiply instead of a division.
    uint32_t k = 0;
    switch (run->per_cell) {
      case 4: k = d / 4; break;
      case 5: k = d / 5; break;
      case 6: k = d / 6; break;
      default: k = d / static_cast<uint32_t>(run->per_cell);
    }
    return static_cast<size_t>(run->first_cell) + k;
  }

 private:
  static constexpr size_t kMaxRuns = 16;
  struct Run {
    int32_t first_slot, first_cell, per_cell;
  };
  std::vector<Run> runs_;
  std::vector<int32_t> cell_;
};

// What face merging sorts: every slot, then every soup face no cell uses (so that those whose
// vertex set no cell uses can be counted as dropped). item < nslots is a slot, else unused soup
// face unused[item - nslots].
struct FaceItems {
  const MeshInput& in;
  const SlotLoops& loops;
  const std::vector<int32_t>& slot_offsets;  // per cell
  SlotCells slot_cell;
  std::vector<int32_t> unused;               // soup faces no cell uses
  size_t nslots() const { return static_cast<size_t>(slot_offsets.back()); }
  size_t size() const { return nslots() + unused.size(); }
  std::span<const int32_t> loop(size_t item, std::array<int32_t, 4>& buf) const {
    if (item >= nslots()) return in.faces[static_cast<size_t>(unused[item - nslots()])];
    const size_t c = slot_cell(item);
    return loops.loop(c, static_cast<int>(item - static_cast<size_t>(slot_offsets[c])), buf);
  }
};

// A triangle's or quadrangle's vertex set and its item as one sortable integer: the loop size, its
// vertices other than `shared` in increasing order (a triangle's third one above any id), the
// item. Faces of one bucket share a vertex (their lowest-ranked), so equal keys up to the item
// mean the same set. `shared` is in the loop exactly once (validate_input rejects repeated
// vertices), so at most 3 others remain.
__extension__ typedef unsigned __int128 FaceKey;
constexpr int kItemBits = 31;

FaceKey small_key(std::span<const int32_t> loop, int32_t shared, int32_t item) {
  std::array<uint32_t, 3> v{0x7fffffffu, 0x7fffffffu, 0x7fffffffu};
  size_t n = 0;
  for (int32_t x : loop)
    if (x != shared) v[n++] = static_cast<uint32_t>(x);
  // A sorting network for three values.
  auto order = [&](size_t i, size_t j) {
    if (v[j] < v[i]) std::swap(v[i], v[j]);
  };
  order(0, 1), order(1, 2), order(0, 1);
  return static_cast<FaceKey>(loop.size()) << (4 * kItemBits) | static_cast<FaceKey>(v[0]) << (3 * kItemBits) |
         static_cast<FaceKey>(v[1]) << (2 * kItemBits) | static_cast<FaceKey>(v[2]) << kItemBits | static_cast<uint32_t>(item);
}

// rep[item] for the items of one bucket (all with the vertex `shared`): the lowest item with the
// same vertex set.
void group_bucket(const FaceItems& items, std::span<const int32_t> bucket, int32_t shared, std::vector<int32_t>& rep,
                  std::vector<FaceKey>& small, std::vector<std::vector<int32_t>>& big) {
  std::array<int32_t, 4> buf;
  bool all_small = true;
  small.clear();
  for (int32_t it : bucket) {
    const auto loop = items.loop(static_cast<size_t>(it), buf);
    if (loop.size() > 4) {
      all_small = false;
      break;
    }
    small.push_back(small_key(loop, shared, it));
  }
  if (all_small) {
    detail::sort_small(small.begin(), small.end());  // buckets hold a handful of faces
    constexpr uint32_t kItem = (1u << kItemBits) - 1;
    for (size_t g = 0; g < small.size(); ++g) {
      const bool same = g > 0 && (small[g] >> kItemBits) == (small[g - 1] >> kItemBits);
      rep[static_cast<uint32_t>(small[g]) & kItem] = same ? rep[static_cast<uint32_t>(small[g - 1]) & kItem]
                                                         : static_cast<int32_t>(static_cast<uint32_t>(small[g]) & kItem);
    }
    return;
  }
  // Some polygon has more than 4 vertices: whole sorted vertex lists, then the item.
  big.resize(bucket.size());
  for (size_t i = 0; i < bucket.size(); ++i) {
    const auto loop = items.loop(static_cast<size_t>(bucket[i]), buf);
    big[i].assign(loop.begin(), loop.end());
    std::sort(big[i].begin(), big[i].end());
    big[i].insert(big[i].begin(), static_cast<int32_t>(loop.size()));
    big[i].push_back(bucket[i]);
  }
  std::sort(big.begin(), big.end());
  auto same_set = [](const std::vector<int32_t>& a, const std::vector<int32_t>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end() - 1, b.begin());
  };
  for (size_t g = 0; g < big.size(); ++g)
    rep[static_cast<size_t>(big[g].back())] = g > 0 && same_set(big[g], big[g - 1]) ? rep[static_cast<size_t>(big[g - 1].back())] : big[g].back();
}

// rep[item] = the lowest item with the same vertex set (see FaceItems).
// `ranks` is build_edges' grouping too.
std::vector<int32_t> face_representatives(const FaceItems& items, const VertexRanks& ranks, const Threads& par) {
  const size_t n = items.size(), nv = ranks.rank.size();
  // Units: the cells (their slots), then the unused soup faces.
  const size_t nc = items.slot_offsets.size() - 1;
  const std::span<const int32_t> rank = ranks.rank;
  const detail::RawRows by_lowest = detail::group_units_by_key<detail::RawRows>(
      nc + items.unused.size(), nv, par,
      [&](size_t u) { return u <= nc ? static_cast<size_t>(items.slot_offsets[u]) : items.nslots() + (u - nc); },
      [&](size_t u, auto&& emit) {
        if (u < nc) return items.loops.each_lowest(u, rank, [&](int32_t lo) { emit(lo); });
        emit(lowest_rank(items.in.faces[static_cast<size_t>(items.unused[u - nc])], rank));
      });
  std::vector<int32_t> rep;
  detail::resize_touched(rep, n, par);
  detail::parallel_rows(by_lowest, par, [&](size_t vb, size_t ve, int) {
    std::vector<FaceKey> small;
    std::vector<std::vector<int32_t>> big;
    for (size_t v = vb; v < ve; ++v) {
      const auto bucket = by_lowest[v];
      if (bucket.size() == 1) rep[static_cast<size_t>(bucket[0])] = bucket[0];
      else if (!bucket.empty()) group_bucket(items, bucket, ranks.vertex[v], rep, small, big);
    }
  });
  return rep;
}

// Same direction of two loops over the same vertex set?
bool same_direction(std::span<const int32_t> a, std::span<const int32_t> b) {
  const size_t n = a.size();
  const size_t p = static_cast<size_t>(std::find(a.begin(), a.end(), b[0]) - a.begin());
  return a[p + 1 < n ? p + 1 : 0] == b[1];
}

// face_cells from cell_faces, in cell order, so that the first offending cell is reported.
void fill_face_cells(const MeshInput& in, Mesh& m, const Threads& par) {
  detail::assign_touched(m.face_cells, m.face_verts.rows(), {-1, -1}, par);
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int32_t ci = static_cast<int32_t>(c);
    for (int32_t u : m.cell_faces[c]) {
      auto& fc = m.face_cells[u];
      if (fc[0] == ci || fc[1] == ci)
        throw InputError(in.source, in.loc_of(in.cell_loc, c),
                         "each face once per cell, cell " + std::to_string(c) + " lists the face " +
                             loop_text(m.face_verts[u]) + " twice" + kSkipInvalidHint);
      if (fc[0] < 0) {
        fc[0] = ci;
      } else if (fc[1] < 0) {
        fc[1] = ci;
      } else {
        throw InputError(in.source, in.loc_of(in.cell_loc, c),
                         "a face shared by at most 2 cells, face " + loop_text(m.face_verts[u]) + " is in cells " +
                             std::to_string(fc[0]) + ", " + std::to_string(fc[1]) + " and " + std::to_string(c) + kSkipInvalidHint);
      }
    }
  }
}

// Slot offsets per cell and the soup faces no cell uses.
FaceItems face_items(const MeshInput& in, const SlotLoops& loops, std::vector<int32_t>& slot_offsets,
                     const Threads& par) {
  const size_t nc = in.cells.rows();
  detail::resize_touched(slot_offsets, nc + 1, par);
  slot_offsets[0] = 0;
  int64_t total = 0, corners = 0;
  for (size_t c = 0; c < nc; ++c) {
    const CellShape shape = in.shape(c);
    if (shape == CellShape::Faces) {
      for (int32_t r : in.cells[c]) corners += in.faces.count(static_cast<size_t>(r >> 1));
    } else {
      const detail::ShapeFaces& sf = detail::shape_faces(shape);
      for (int j = 0; j < sf.nfaces; ++j) corners += sf.size[static_cast<size_t>(j)];
    }
    total += loops.count(c);
    if (total > std::numeric_limits<int32_t>::max() || corners > std::numeric_limits<int32_t>::max())
      throw InputError(in.source, {}, "fewer than 2^31 cell faces and face corners");
    slot_offsets[c + 1] = static_cast<int32_t>(total);
  }
  FaceItems items{in, loops, slot_offsets, SlotCells(slot_offsets), {}};
  std::vector<uint8_t> used(in.faces.rows(), 0);
  for (size_t c = 0; c < nc; ++c)
    if (in.shape(c) == CellShape::Faces)
      for (int32_t r : in.cells[c]) used[static_cast<size_t>(r >> 1)] = 1;
  for (size_t f = 0; f < used.size(); ++f)
    if (!used[f]) items.unused.push_back(static_cast<int32_t>(f));
  return items;
}

// New faces and their corners, counted by a range of cells.
struct FaceCount {
  int64_t faces = 0, corners = 0;
  FaceCount& operator+=(const FaceCount& o) {
    faces += o.faces, corners += o.corners;
    return *this;
  }
};

// Faces numbered in slot order from rep (consumed: it becomes cell_faces.items). Ranges of slots
// count their new faces first, so that each then numbers its own from the right place; a face id
// is kept as -1 - id until every slot has one.
void number_faces(const FaceItems& items, std::vector<int32_t>&& rep, Mesh& m, const Threads& par) {
  const size_t nslots = items.nslots(), nc = items.slot_offsets.size() - 1;
  // Ranges of cells (their slots in order), which know their slots' loops without a lookup.
  auto each_new_face = [&](size_t cb, size_t ce, auto&& f) {
    for (size_t c = cb; c < ce; ++c)
      for (int j = 0; j < items.loops.count(c); ++j) {
        const auto s = static_cast<size_t>(items.slot_offsets[c] + j);
        if (rep[s] == static_cast<int32_t>(s)) f(s, c, j);
      }
  };
  const std::vector<FaceCount> first = detail::range_starts<FaceCount>(nc, par, [&](size_t b, size_t e) {
    FaceCount n;
    each_new_face(b, e, [&](size_t, size_t c, int j) {
      ++n.faces;
      n.corners += items.loops.size(c, j);
    });
    return n;
  });
  detail::assign_touched(m.face_verts.offsets, static_cast<size_t>(first.back().faces) + 1, 0, par);
  detail::resize_touched(m.face_verts.items, static_cast<size_t>(first.back().corners), par);
  detail::parallel_ranges(nc, par, [&](size_t b, size_t e, int r) {
    auto face = first[static_cast<size_t>(r)].faces;
    auto at = first[static_cast<size_t>(r)].corners;
    std::array<int32_t, 4> buf;
    each_new_face(b, e, [&](size_t s, size_t c, int j) {
      const auto loop = items.loops.loop(c, j, buf);
      std::copy(loop.begin(), loop.end(), m.face_verts.items.begin() + at);
      at += static_cast<int64_t>(loop.size());
      m.face_verts.offsets[static_cast<size_t>(face) + 1] = static_cast<int32_t>(at);
      rep[s] = static_cast<int32_t>(-1 - face++);
    });
  });
  // Other slots copy their representative's id (an earlier slot, which the pass above numbered).
  detail::parallel_ranges(nslots, par, [&](size_t b, size_t e, int) {
    for (size_t s = b; s < e; ++s)
      if (rep[s] >= 0) rep[s] = rep[static_cast<size_t>(rep[s])];
  });
  detail::parallel_ranges(nslots, par, [&](size_t b, size_t e, int) {
    for (size_t s = b; s < e; ++s) rep[s] = -1 - rep[s];
  });
  rep.resize(nslots);
  rep.shrink_to_fit();
  m.cell_faces.items = std::move(rep);
}

}  // namespace

std::vector<int32_t> merge_faces(MeshInput& in, Mesh& m, const Threads& par) {
  const SlotLoops loops(in);
  std::vector<int32_t> slot_offsets;
  FaceItems items = face_items(in, loops, slot_offsets, par);
  VertexRanks ranks(m.num_vertices(), [&](auto&& use) {
    for (size_t c = 0; c + 1 < slot_offsets.size(); ++c) items.loops.each_vertex(c, use);
  });
  std::vector<int32_t> rep = face_representatives(items, ranks, par);
  std::vector<int32_t>().swap(ranks.vertex);  // build_edges finds it again from the ranks
  for (size_t i = items.nslots(); i < items.size(); ++i) m.dropped_faces += rep[i] >= static_cast<int32_t>(items.nslots());
  if (m.dropped_faces > 0) m.warnings.push_back(std::to_string(m.dropped_faces) + " face(s) used by no cell dropped");
  number_faces(items, std::move(rep), m, par);
  m.cell_faces.offsets = std::move(slot_offsets);
  // The cell sees the stored loop reversed when exactly one of (the file's flip, its loop running
  // against the stored one) holds.
  detail::resize_touched(m.cell_face_flip, m.cell_faces.items.size(), par);
  detail::parallel_ranges(m.num_cells(), par, [&](size_t b, size_t e, int) {
    std::array<int32_t, 4> buf;
    for (size_t c = b; c < e; ++c)
      for (int j = 0; j < loops.count(c); ++j) {
        const size_t s = static_cast<size_t>(m.cell_faces.offsets[c] + j);
        const bool same = same_direction(m.face_verts[static_cast<size_t>(m.cell_faces.items[s])], loops.loop(c, j, buf));
        m.cell_face_flip[s] = static_cast<uint8_t>(loops.flip(c, j) ^ (same ? 0 : 1));
      }
  });
  // The input is not needed from here on; releasing it (clear() would keep the capacity) lowers
  // the peak memory.
  in.faces = Csr<int32_t>{};
  in.cells = Csr<int32_t>{};
  fill_face_cells(in, m, par);
  return std::move(ranks.rank);
}

namespace {

// rep[k] = the vertex after corner k along its loop, so that a corner's edge is known without its
// face.
void prefill_next(const Mesh& m, std::vector<int32_t>& rep, const Threads& par) {
  const std::vector<int32_t>& loops = m.face_verts.items;
  detail::resize_touched(rep, loops.size(), par);
  detail::parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const auto k0 = static_cast<size_t>(m.face_verts.offsets[f]), k1 = static_cast<size_t>(m.face_verts.offsets[f + 1]);
      for (size_t k = k0; k + 1 < k1; ++k) rep[k] = loops[k + 1];
      rep[k1 - 1] = loops[k0];
    }
  });
}

// Corners by the lower-ranked end of their edge (see VertexRanks), a corner of a boundary face
// tagged with kBoundary.
constexpr uint32_t kBoundary = 1u << 31, kCorner = kBoundary - 1;
detail::RawRows corners_by_lower_end(const Mesh& m, std::span<const int32_t> rank, const Threads& par) {
  const auto& off = m.face_verts.offsets;
  const auto& loops = m.face_verts.items;
  return detail::group_units_by_key<detail::RawRows>(
      m.num_faces(), m.num_vertices(), par, [&](size_t f) { return static_cast<size_t>(off[f]); },
      [&](size_t f, auto&& emit) {
        const uint32_t tag = m.face_cells[f][1] < 0 ? kBoundary : 0;
        const auto k0 = static_cast<size_t>(off[f]), k1 = static_cast<size_t>(off[f + 1]);
        const int32_t first = rank[static_cast<size_t>(loops[k0])];
        int32_t here = first;
        for (size_t k = k0; k < k1; ++k) {
          const int32_t next = k + 1 < k1 ? rank[static_cast<size_t>(loops[k + 1])] : first;
          emit(std::min(here, next), tag);
          here = next;
        }
      });
}

// rep[k] = the lowest corner with the same edge, bucket by bucket of by_lo (corners by the
// lower-ranked end of their edge, vertex[bucket], in increasing order, so the first corner met of
// each edge is its lowest). A vertex starts a few edges: a short list of (other end, first
// corner) finds them faster than sorting the bucket, whose order is random to the branch
// predictor; long buckets are sorted.
void edge_representatives(const Mesh& m, const detail::RawRows& by_lo, std::span<const int32_t> vertex, std::vector<int32_t>& rep,
                          const Threads& par) {
  const std::vector<int32_t>& loops = m.face_verts.items;
  constexpr size_t kListed = 64;  // longer buckets: sorted, as the list would grow quadratic
  detail::parallel_rows(by_lo, par, [&](size_t vb, size_t ve, int) {
    std::vector<uint64_t> other_corner;  // other end << 32 | corner
    for (size_t v = vb; v < ve; ++v) {
      const auto bucket = by_lo[v];
      const int32_t shared = vertex[v];
      // The end of corner kk's edge that is not `shared` (rep[kk] is the vertex after it).
      auto other = [&](size_t kk) { return static_cast<uint64_t>(loops[kk] == shared ? rep[kk] : loops[kk]); };
      other_corner.clear();
      if (bucket.size() <= kListed) {
        for (int32_t item : bucket) {
          const auto kk = static_cast<size_t>(static_cast<uint32_t>(item) & kCorner);
          const uint64_t o = other(kk);
          auto it = std::find_if(other_corner.begin(), other_corner.end(), [&](uint64_t x) { return x >> 32 == o; });
          if (it == other_corner.end()) it = other_corner.insert(it, o << 32 | kk);
          rep[kk] = static_cast<int32_t>(*it & 0xffffffffu);
        }
        continue;
      }
      for (int32_t item : bucket) {
        const auto kk = static_cast<size_t>(static_cast<uint32_t>(item) & kCorner);
        other_corner.push_back(other(kk) << 32 | kk);
      }
      std::sort(other_corner.begin(), other_corner.end());
      for (size_t i = 0; i < other_corner.size(); ++i) {
        const auto k = static_cast<size_t>(other_corner[i] & 0xffffffffu);
        const bool same = i > 0 && (other_corner[i - 1] >> 32) == (other_corner[i] >> 32);
        rep[k] = same ? rep[static_cast<size_t>(other_corner[i - 1] & 0xffffffffu)] : static_cast<int32_t>(k);
      }
    }
  });
}

// Edges numbered in corner order from rep (which becomes the edge of every corner), with
// edge_verts and fan_start = the face of each edge's first corner. Ranges of faces count their
// new edges first so that each numbers its own from the right place; an edge id is kept as
// -1 - id until every corner has one (a representative is an earlier corner, maybe of another
// range).
void number_edges(Mesh& m, std::vector<int32_t>& rep, const Threads& par) {
  const size_t nf = m.num_faces();
  const std::vector<int32_t>& loops = m.face_verts.items;
  auto corners = [&](size_t f) {
    return std::pair{static_cast<size_t>(m.face_verts.offsets[f]), static_cast<size_t>(m.face_verts.offsets[f + 1])};
  };
  const std::vector<int64_t> first = detail::range_starts<int64_t>(nf, par, [&](size_t b, size_t e) {
    int64_t count = 0;
    for (size_t f = b; f < e; ++f)
      for (auto [k, k1] = corners(f); k < k1; ++k) count += rep[k] == static_cast<int32_t>(k);
    return count;
  });
  detail::resize_touched(m.edge_verts, static_cast<size_t>(first.back()), par);
  detail::resize_touched(m.fan_start, static_cast<size_t>(first.back()), par);
  detail::parallel_ranges(nf, par, [&](size_t b, size_t e, int r) {
    auto id = first[static_cast<size_t>(r)];
    for (size_t f = b; f < e; ++f) {
      const auto [k0, k1] = corners(f);
      for (size_t k = k0; k < k1; ++k) {
        if (rep[k] != static_cast<int32_t>(k)) continue;
        const int32_t a = loops[k], c = loops[k + 1 < k1 ? k + 1 : k0];
        m.edge_verts[static_cast<size_t>(id)] = {std::min(a, c), std::max(a, c)};
        m.fan_start[static_cast<size_t>(id)] = static_cast<int32_t>(f);
        rep[k] = static_cast<int32_t>(-1 - id++);
      }
    }
  });
  detail::parallel_ranges(rep.size(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k)
      if (rep[k] >= 0) rep[k] = rep[static_cast<size_t>(rep[k])];
  });
  detail::parallel_ranges(rep.size(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k) rep[k] = -1 - rep[k];
  });
}

// The face whose loop holds corner k (offsets off: strictly increasing, from 0). A search over all
// faces per boundary edge cost more than the rest of count_edge_faces, and unevenly between threads
// (boundary faces crowd in some ranges); here it starts where an even spread of corners over faces
// puts k, which is the face itself when all faces have one size, and widens by doubling.
int32_t face_of_corner(const std::vector<int32_t>& off, int32_t k) {
  const size_t nf = off.size() - 1;
  size_t lo = std::min(nf - 1, static_cast<size_t>(int64_t{k} * static_cast<int64_t>(nf) / off.back()));
  size_t hi = lo + 1;  // until off[lo] <= k < off[hi]
  for (size_t step = 1; off[lo] > k; step *= 2) hi = lo, lo = lo > step ? lo - step : 0;
  for (size_t step = 1; off[hi] <= k; step *= 2) lo = hi, hi = std::min(nf, hi + step);
  return static_cast<int32_t>(std::upper_bound(off.begin() + static_cast<std::ptrdiff_t>(lo), off.begin() + static_cast<std::ptrdiff_t>(hi), k) - off.begin() - 1);
}

// Faces and boundary faces at each edge, and fan_start moved to the lowest boundary face at the
// edge where there is one. Each edge's corners are all in the bucket of its lower-ranked end, in
// increasing order, so a range of buckets counts its edges alone and meets each edge's lowest
// boundary corner first.
EdgeFaceCounts count_edge_faces(Mesh& m, const detail::RawRows& by_lo, const Threads& par) {
  EdgeFaceCounts count(m.num_edges());
  detail::advise_huge_pages(count.data(), count.size() * sizeof(EdgeFaceCount));
  detail::parallel_ranges(count.size(), par, [&](size_t b, size_t e, int) { std::fill(count.data() + b, count.data() + e, EdgeFaceCount{0, 0}); });
  const auto& off = m.face_verts.offsets;
  detail::parallel_rows(by_lo, par, [&](size_t vb, size_t ve, int) {
    for (size_t v = vb; v < ve; ++v)
      for (int32_t item : by_lo[v]) {
        const uint32_t k = static_cast<uint32_t>(item) & kCorner;
        const auto e = static_cast<size_t>(m.face_edge_ids[k]);
        ++count[e].faces;
        if (!(static_cast<uint32_t>(item) & kBoundary)) continue;
        uint8_t& nb = count[e].boundary_faces;
        if (nb == 0) m.fan_start[e] = face_of_corner(off, static_cast<int32_t>(k));
        if (nb < 255) ++nb;
      }
  });
  return count;
}

}  // namespace

EdgeFaceCounts build_edges(Mesh& m, std::vector<int32_t>&& rank, const Threads& par) {
  std::vector<int32_t>& rep = m.face_edge_ids;
  prefill_next(m, rep, par);
  detail::RawRows by_lo;
  {
    // The faces' ranks serve: a face's loop lists vertices of its first cell, so ranking them by
    // first use along the loops would give about the same order again, in a serial pass over
    // every corner.
    const std::vector<int32_t> vertex_ranks = std::move(rank);
    std::vector<int32_t> vertex;
    detail::resize_touched(vertex, vertex_ranks.size(), par);
    detail::parallel_ranges(vertex.size(), par, [&](size_t b, size_t e, int) {
      for (size_t v = b; v < e; ++v) vertex[static_cast<size_t>(vertex_ranks[v])] = static_cast<int32_t>(v);
    });
    by_lo = corners_by_lower_end(m, vertex_ranks, par);
    edge_representatives(m, by_lo, vertex, rep, par);
  }
  number_edges(m, rep, par);
  return count_edge_faces(m, by_lo, par);
}

}  // namespace hbc::mesh_steps
