#include "hbc/cell_complex.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include "parallel/parallel.hpp"
#include "platform/atomic_ref.hpp"

namespace hbc {

namespace {

using detail::parallel_ranges;
using detail::set_flag;

// Which mesh faces / edges / vertices lie on the boundary of the region of mesh cells flagged in
// `in_cell`: a face is a boundary face when exactly one of its cells is in the region, so the
// mesh boundary and the seams to cells outside the region are treated alike.
struct RegionBoundary {
  std::vector<uint8_t> face_in, face_boundary, edge_boundary, vert_boundary;
};

RegionBoundary region_boundary(const Mesh& m, const std::vector<uint8_t>& in_cell, const Threads& par) {
  RegionBoundary r;
  const size_t nf = m.num_faces();
  r.face_in.assign(nf, 0);
  r.face_boundary.assign(nf, 0);
  r.edge_boundary.assign(m.num_edges(), 0);
  r.vert_boundary.assign(m.num_vertices(), 0);
  parallel_ranges(nf, par, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const auto [c0, c1] = m.face_cells[f];
      const int n = in_cell[c0] + (c1 >= 0 ? in_cell[c1] : 0);
      r.face_in[f] = n > 0;
      if (n != 1) continue;
      r.face_boundary[f] = 1;
      for (int32_t x : m.face_edges(f)) set_flag(r.edge_boundary, x);
      for (int32_t v : m.face_verts[f]) set_flag(r.vert_boundary, v);
    }
  });
  return r;
}

std::vector<uint8_t> flags_of(std::span<const int32_t> ids, size_t n, const char* what) {
  std::vector<uint8_t> in(n, 0);
  for (int32_t i : ids) {
    if (i < 0 || static_cast<size_t>(i) >= n)
      throw std::invalid_argument(std::string("region ") + what + " id out of range: " +
                                  std::to_string(i));
    in[i] = 1;
  }
  return in;
}

// Compact ids for the flagged entries, in increasing order of the original ids, by ranges of
// entries: each numbers its own from where the earlier ranges' end.
std::vector<int32_t> compact(const std::vector<uint8_t>& keep, std::vector<int32_t>& source, const Threads& par) {
  const size_t n = keep.size();
  const std::vector<int64_t> at = detail::range_starts<int64_t>(n, par, [&](size_t b, size_t e) {
    return static_cast<int64_t>(std::count_if(keep.begin() + static_cast<ptrdiff_t>(b), keep.begin() + static_cast<ptrdiff_t>(e),
                                              [](uint8_t k) { return k != 0; }));
  });
  std::vector<int32_t> map(n);
  source.resize(static_cast<size_t>(at.back()));
  parallel_ranges(n, par, [&](size_t b, size_t e, int r) {
    auto id = static_cast<int32_t>(at[static_cast<size_t>(r)]);
    for (size_t i = b; i < e; ++i) {
      map[i] = keep[i] ? id : -1;
      if (keep[i]) source[static_cast<size_t>(id++)] = static_cast<int32_t>(i);
    }
  });
  return map;
}

// Sizes the view's per-edge arrays to its edges (edge_source): the flags start at "no non-hex
// cell" and "all faces quads", which the fills then clear edge by edge. Returns the edge count.
size_t size_edge_arrays(CellComplex& cx) {
  const size_t nx = cx.edge_source.size();  // edge_verts is not sized yet
  cx.edge_verts.resize(nx);
  cx.edge_valence.resize(nx);
  cx.edge_boundary.resize(nx);
  cx.edge_non_hex.assign(nx, 0);
  cx.edge_all_quad.assign(nx, 1);
  return nx;
}

void sort_unique_ids(std::vector<int32_t>& buf) {
  // Rows mapped through monotonic id maps mostly come sorted already: checking is cheaper.
  if (!std::is_sorted(buf.begin(), buf.end())) std::sort(buf.begin(), buf.end());
  buf.erase(std::unique(buf.begin(), buf.end()), buf.end());
}

void sort_unique_row(std::vector<int32_t>& buf, Csr<int32_t>& out) {
  sort_unique_ids(buf);
  out.push_row(buf.begin(), buf.end());
}

// vert_edges from edge_verts (closed edges have no vertices); self-loops appear once. Each
// vertex's edges in increasing order, as the edges are visited in order.
void build_vert_edges(CellComplex& cx, const Threads& par) {
  cx.vert_edges = detail::group_values_by_key(cx.edge_verts.size(), cx.num_vertices(), par, [&](size_t i, auto&& emit) {
    const auto ab = cx.edge_verts[i];
    if (ab[0] < 0) return;
    emit(ab[0], static_cast<int32_t>(i));
    if (ab[1] != ab[0]) emit(ab[1], static_cast<int32_t>(i));
  });
}

// The region cells on the two sides of each kept face (compact ids; -1 for a side outside the
// region or off the mesh), lower first.
std::vector<std::array<int32_t, 2>> region_face_cells(const std::vector<int32_t>& face_source,
                                                      const std::vector<std::array<int32_t, 2>>& sides,
                                                      const std::vector<int32_t>& cell_map, const Threads& par) {
  std::vector<std::array<int32_t, 2>> out(face_source.size());
  parallel_ranges(out.size(), par, [&](size_t begin, size_t end, int) {
    for (size_t i = begin; i < end; ++i) {
      const auto [a, b] = sides[face_source[i]];
      std::array<int32_t, 2> s{a >= 0 ? cell_map[a] : -1, b >= 0 ? cell_map[b] : -1};
      if (s[0] < 0 || (s[1] >= 0 && s[1] < s[0])) std::swap(s[0], s[1]);
      out[i] = s;
    }
  });
  return out;
}

// The whole-mesh adjacency of a proper region (CellComplex::edge_all_faces and co.), from the
// mesh-level rows of each complex edge's mesh edges mapped by `face_id` / `cell_id` (identity at
// the mesh level, patch / component at the complex level).
template <class EdgeMeshEdges, class FaceId, class CellId>
void fill_whole_mesh_adjacency(const Mesh& m, CellComplex& cx, const EdgeMeshEdges& mesh_edges_of, const FaceId& face_id,
                               const CellId& cell_id, const std::vector<std::array<int32_t, 2>>& face_sides,
                               const Threads& par) {
  std::vector<uint8_t> all(m.num_cells(), 1);
  const RegionBoundary mb = region_boundary(m, all, par);
  std::vector<int32_t> fbuf, cbuf;
  EdgeFan fan;
  const size_t ne = cx.num_edges();
  cx.edge_mesh_boundary.assign(ne, 0);
  cx.edge_all_non_hex.assign(ne, 0);
  for (size_t i = 0; i < ne; ++i) {
    fbuf.clear();
    cbuf.clear();
    for (int32_t e : mesh_edges_of(i)) {
      cx.edge_mesh_boundary[i] = cx.edge_mesh_boundary[i] || mb.edge_boundary[e];
      edge_fan(m, e, fan);
      for (int32_t f : fan.faces)
        if (face_id(f) >= 0) fbuf.push_back(face_id(f));
      for (int32_t c : fan.cells) {
        cbuf.push_back(cell_id(c));
        cx.edge_all_non_hex[i] = cx.edge_all_non_hex[i] || !m.is_hex(c);
      }
    }
    sort_unique_row(fbuf, cx.edge_all_faces);
    sort_unique_row(cbuf, cx.edge_all_cells);
  }
  cx.face_all_cells.resize(cx.num_faces());
  for (size_t i = 0; i < cx.num_faces(); ++i) cx.face_all_cells[i] = face_sides[cx.face_source[i]];
}

}  // namespace

CellComplex complex_from_mesh(const Mesh& m, const Threads& threads) {
  std::vector<int32_t> all(m.num_cells());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int32_t>(c);
  return complex_from_mesh(m, all, threads);
}

CellComplex complex_from_mesh(const Mesh& m, std::span<const int32_t> region_cells, const Threads& threads) {
  CellComplex cx;
  cx.level = Level::Mesh;
  const Threads par = resolved(threads);
  const std::vector<uint8_t> in_cell = flags_of(region_cells, m.num_cells(), "cell");
  const RegionBoundary rb = region_boundary(m, in_cell, par);
  const size_t ne = m.num_edges(), nv = m.num_vertices();

  const std::vector<int32_t> cmap = compact(in_cell, cx.cell_source, par);
  const std::vector<int32_t> fmap = compact(rb.face_in, cx.face_source, par);
  // Edges and vertices of the region's cells (those of their faces).
  std::vector<uint8_t> edge_in(ne, 0), vert_in(nv, 0);
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (in_cell[c])
      for (int32_t f : m.cell_faces[c])
        for (int32_t e : m.face_edges(static_cast<size_t>(f))) edge_in[static_cast<size_t>(e)] = 1;
  for (size_t e = 0; e < ne; ++e)
    if (edge_in[e]) vert_in[m.edge_verts[e][0]] = vert_in[m.edge_verts[e][1]] = 1;
  const std::vector<int32_t> emap = compact(edge_in, cx.edge_source, par);
  const std::vector<int32_t> vmap = compact(vert_in, cx.vert_mesh, par);

  cx.cell_non_hex.resize(cx.num_cells());
  cx.cell_kind.assign(cx.num_cells(), 0);
  for (size_t i = 0; i < cx.num_cells(); ++i) {
    const int32_t c = cx.cell_source[i];
    cx.cell_non_hex[i] = !m.is_hex(c);
    if (cx.cell_non_hex[i]) cx.cell_kind[i] = non_hex_kind(m.cell_type[c], static_cast<size_t>(m.cell_faces.count(c)));
  }

  std::vector<int32_t> buf;
  cx.face_quad.resize(cx.num_faces());
  for (size_t i = 0; i < cx.num_faces(); ++i) {
    const int32_t f = cx.face_source[i];
    buf.clear();
    for (int32_t e : m.face_edges(static_cast<size_t>(f))) buf.push_back(emap[e]);
    sort_unique_row(buf, cx.face_edges);
    cx.face_quad[i] = m.face_verts.count(f) == 4;
  }
  cx.face_cells = region_face_cells(cx.face_source, m.face_cells, cmap, par);

  const size_t nx = size_edge_arrays(cx);
  cx.edge_points.items.reserve(2 * nx);
  EdgeFan fan;
  for (size_t i = 0; i < nx; ++i) {
    const int32_t e = cx.edge_source[i];
    const auto [a, b] = m.edge_verts[e];
    cx.edge_verts[i] = {vmap[a], vmap[b]};
    const int32_t pts[2] = {a, b};
    cx.edge_points.push_row(pts, pts + 2);
    buf.clear();
    edge_fan(m, e, fan);
    for (int32_t c : fan.cells) {
      if (!in_cell[c]) continue;
      buf.push_back(cmap[c]);
      cx.edge_non_hex[i] = cx.edge_non_hex[i] || !m.is_hex(c);
    }
    sort_unique_row(buf, cx.edge_cells);
    cx.edge_valence[i] = cx.edge_cells.count(i);
    cx.edge_boundary[i] = rb.edge_boundary[e];
    buf.clear();
    for (int32_t f : fan.faces) {
      if (!rb.face_in[f]) continue;
      buf.push_back(fmap[f]);
      cx.edge_all_quad[i] = cx.edge_all_quad[i] && m.face_verts.count(f) == 4;
    }
    sort_unique_row(buf, cx.edge_faces);
  }

  const size_t nvx = cx.num_vertices();
  cx.vert_boundary.resize(nvx);
  cx.vert_cell_count.assign(nvx, 0);
  cx.vert_all_quad.assign(nvx, 1);
  for (size_t i = 0; i < nvx; ++i) cx.vert_boundary[i] = rb.vert_boundary[cx.vert_mesh[i]];
  // Region cells and non-quad region faces at each vertex, from the cells' and faces' side.
  for (size_t c = 0; c < m.num_cells(); ++c) {
    if (!in_cell[c]) continue;
    cell_vertices(m, c, buf);
    for (int32_t v : buf) ++cx.vert_cell_count[static_cast<size_t>(vmap[v])];
  }
  for (size_t f = 0; f < m.num_faces(); ++f)
    if (rb.face_in[f] && m.face_verts.count(f) != 4)
      for (int32_t v : m.face_verts[f]) cx.vert_all_quad[static_cast<size_t>(vmap[v])] = 0;
  if (cx.num_cells() < m.num_cells())
    fill_whole_mesh_adjacency(
        m, cx, [&](size_t i) { return std::span<const int32_t>(&cx.edge_source[i], 1); },
        [](int32_t f) { return f; }, [](int32_t c) { return c; }, m.face_cells, par);
  build_vert_edges(cx, par);
  return cx;
}

CellComplex complex_from_base(const Mesh& m, const BaseComplex& bc, const Threads& threads) {
  std::vector<int32_t> all(bc.num_components());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int32_t>(k);
  return complex_from_base(m, bc, all, threads);
}

BaseViewFacts base_view_facts(const Mesh& m, const BaseComplex& bc, const Threads& threads) {
  std::vector<int32_t> all(bc.num_components());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int32_t>(k);
  return base_view_facts(m, bc, all, threads);
}

bool BaseViewFacts::whole() const {
  return std::find(component_in.begin(), component_in.end(), 0) == component_in.end();
}

namespace {

// Rows of the curves in the view (compact ids, `curve_map`) listing the region owners of each
// (compact ids, `owner_map`, monotonic), from `owner_curves` (owner -> its curves, sorted,
// distinct): a transpose restricted to the region, so its rows come out sorted and distinct.
Csr<int32_t> curve_owner_rows(const Csr<int32_t>& owner_curves, const std::vector<int32_t>& owner_map,
                              const std::vector<int32_t>& curve_map, size_t ncurves_in_view, const Threads& par) {
  return detail::transpose_mapped(
      owner_curves, ncurves_in_view, par, [&](size_t o) { return owner_map[o]; },
      [&](int32_t k) { return curve_map[static_cast<size_t>(k)]; });
}

// Per corner in the view (vmap >= 0): the region components with a cell there. A cell at a
// vertex has a face there; components are visited one by one, so a stamp per vertex (the last
// component that counted it) counts each component once without sorting (vertex, component)
// pairs. Ranges of components count with stamps of their own into the shared counts, whose sums
// do not depend on the order of the additions.
void count_corner_components(const Mesh& m, const BaseComplex& bc, const std::vector<uint8_t>& component_in,
                             const std::vector<int32_t>& vmap, std::vector<int32_t>& count, const Threads& par) {
  detail::parallel_rows(bc.component_cells, par, [&](size_t kb, size_t ke, int) {
    std::vector<int32_t> stamp(m.num_vertices(), -1);
    for (size_t k = kb; k < ke; ++k) {
      if (!component_in[k]) continue;
      for (int32_t c : bc.component_cells[k])
        for (int32_t f : m.cell_faces[static_cast<size_t>(c)])
          for (int32_t v : m.face_verts[static_cast<size_t>(f)]) {
            const int32_t x = vmap[static_cast<size_t>(v)];
            if (x < 0 || stamp[static_cast<size_t>(v)] == static_cast<int32_t>(k)) continue;
            stamp[static_cast<size_t>(v)] = static_cast<int32_t>(k);
            ::hbc::detail::atomic_ref<int32_t>(count[static_cast<size_t>(x)]).fetch_add(1, std::memory_order_relaxed);
          }
    }
  });
}

// Which curves are in the view, their valence and boundary flag. A curve is in the view when a
// region cell lies at its first mesh edge (every mesh edge has a cell, so with the whole region
// every curve is). The valence is that of the curve's first mesh edge: every face around a curve
// separates, so each mesh cell there is a corner of a different coarse cell.
void curve_facts(const Mesh& m, const BaseComplex& bc, const std::vector<uint8_t>& in_cell, const RegionBoundary& rb,
                 bool whole, BaseViewFacts& f, const Threads& par) {
  const size_t ncurve = bc.num_curves();
  f.curve_in.assign(ncurve, whole ? 1 : 0);
  f.curve_valence.assign(ncurve, 0);
  f.curve_boundary.assign(ncurve, 0);
  parallel_ranges(ncurve, par, [&](size_t b, size_t e, int) {
    EdgeFan fan;
    for (size_t k = b; k < e; ++k) {
      const auto es = bc.curve_edges[k];
      if (whole) {
        f.curve_valence[k] = m.edge_valence(static_cast<size_t>(es[0]));
      } else {
        edge_fan(m, es[0], fan);
        f.curve_valence[k] = static_cast<int32_t>(std::count_if(fan.cells.begin(), fan.cells.end(), [&](int32_t c) { return in_cell[c] != 0; }));
        f.curve_in[k] = f.curve_valence[k] > 0;
      }
      if (!f.curve_in[k]) continue;
      for (int32_t x : es) f.curve_boundary[k] = f.curve_boundary[k] || rb.edge_boundary[x];
    }
  });
}

// The view's vertices (the ends of its open curves) and, per vertex, its boundary flag, the
// region components there and whether every region patch there is a quad.
void corner_facts(const Mesh& m, const BaseComplex& bc, const RegionBoundary& rb, BaseViewFacts& f, const Threads& par) {
  std::vector<uint8_t> corner_in(m.num_vertices(), 0);
  parallel_ranges(f.curve_in.size(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k) {
      if (!f.curve_in[k] || bc.curve_closed[k]) continue;
      const auto vs = bc.curve_verts[k];
      set_flag(corner_in, vs.front());
      set_flag(corner_in, vs.back());
    }
  });
  const std::vector<int32_t> vmap = compact(corner_in, f.corners, par);
  const size_t n = f.corners.size();
  f.corner_boundary.resize(n);
  for (size_t i = 0; i < n; ++i) f.corner_boundary[i] = rb.vert_boundary[f.corners[i]];
  f.corner_cells.assign(n, 0);
  count_corner_components(m, bc, f.component_in, vmap, f.corner_cells, par);
  // Non-quad patches at each corner, from the faces' side.
  f.corner_all_quad.assign(n, 1);
  parallel_ranges(m.num_faces(), par, [&](size_t b, size_t e, int) {
    for (size_t x = b; x < e; ++x)
      if (rb.face_in[x] && bc.face_patch[x] >= 0 && !f.patch_quad[bc.face_patch[x]])
        for (int32_t v : m.face_verts[x])
          if (corner_in[static_cast<size_t>(v)]) set_flag(f.corner_all_quad, vmap[v], 0);
  });
}

// The view's mesh polylines: each curve's vertices, a closed one's first vertex repeated at its end.
Csr<int32_t> view_edge_points(const BaseComplex& bc, const std::vector<int32_t>& edge_source, const Threads& par) {
  const size_t nx = edge_source.size();
  Csr<int32_t> pts;
  pts.offsets.resize(nx + 1);
  pts.offsets[0] = 0;
  for (size_t i = 0; i < nx; ++i) {
    const auto k = static_cast<size_t>(edge_source[i]);
    pts.offsets[i + 1] = pts.offsets[i] + bc.curve_verts.count(k) + (bc.curve_closed[k] ? 1 : 0);
  }
  pts.items.resize(static_cast<size_t>(pts.offsets.back()));
  parallel_ranges(nx, par, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) {
      const auto k = static_cast<size_t>(edge_source[i]);
      const auto vs = bc.curve_verts[k];
      auto out = std::copy(vs.begin(), vs.end(), pts.items.begin() + pts.offsets[i]);
      if (bc.curve_closed[k]) *out = vs.front();
    }
  });
  return pts;
}

// The view's edges (curves): end vertices, mesh polylines, valence, boundary flag, cells and
// faces around, non-hex and all-quad flags.
void curve_edges_of_view(const BaseComplex& bc, const BaseViewFacts& f, const std::vector<int32_t>& kmap,
                         const std::vector<int32_t>& pmap, const std::vector<int32_t>& emap,
                         const std::vector<int32_t>& vmap, CellComplex& cx, const Threads& par) {
  const size_t nx = size_edge_arrays(cx);
  // Components and patches around a curve: a cell at a curve's mesh edge has its two faces there
  // among the separation faces (every face at a complex edge separates), so the curve is one of
  // its component's curves, and conversely; likewise a patch holds the curve exactly when one of
  // its faces lies at it. Hence the transposes of component_curves / patch_curves, filtered to
  // the region, hold what the fans around the curve's mesh edges hold, sorted and distinct.
  cx.edge_cells = curve_owner_rows(bc.component_curves, kmap, emap, nx, par);
  cx.edge_faces = curve_owner_rows(bc.patch_curves, pmap, emap, nx, par);
  cx.edge_points = view_edge_points(bc, cx.edge_source, par);
  parallel_ranges(nx, par, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) {
      const auto k = static_cast<size_t>(cx.edge_source[i]);
      const auto vs = bc.curve_verts[k];
      cx.edge_verts[i] = bc.curve_closed[k] ? std::array<int32_t, 2>{-1, -1} : std::array<int32_t, 2>{vmap[vs.front()], vmap[vs.back()]};
      cx.edge_valence[i] = f.curve_valence[k];
      cx.edge_boundary[i] = f.curve_boundary[k];
      for (int32_t x : cx.edge_cells[i]) cx.edge_non_hex[i] = cx.edge_non_hex[i] || cx.cell_non_hex[x];
      for (int32_t p : cx.edge_faces[i]) cx.edge_all_quad[i] = cx.edge_all_quad[i] && cx.face_quad[p];
    }
  });
}

// Everything of the view but the whole-mesh adjacency of a proper region, from `bc` and the facts
// alone (no mesh).
CellComplex view_from_facts(const BaseComplex& bc, const BaseViewFacts& f, const Threads& par) {
  CellComplex cx;
  cx.level = Level::Complex;
  const std::vector<int32_t> kmap = compact(f.component_in, cx.cell_source, par);
  cx.cell_non_hex.resize(cx.num_cells());
  cx.cell_kind.resize(cx.num_cells());
  for (size_t i = 0; i < cx.num_cells(); ++i) {
    cx.cell_non_hex[i] = bc.component_kind[cx.cell_source[i]] == ComponentKind::NonHex;
    cx.cell_kind[i] = f.component_kind[cx.cell_source[i]];
  }
  const std::vector<int32_t> pmap = compact(f.patch_in, cx.face_source, par);
  const std::vector<int32_t> emap = compact(f.curve_in, cx.edge_source, par);
  cx.vert_mesh = f.corners;
  std::vector<int32_t> vmap(f.num_mesh_vertices, -1);
  for (size_t i = 0; i < f.corners.size(); ++i) vmap[static_cast<size_t>(f.corners[i])] = static_cast<int32_t>(i);

  // A patch's edges are the curves on it (patch_curves), those off the view as -1.
  cx.face_quad.resize(cx.num_faces());
  cx.face_edges = detail::parallel_rows_of<int32_t, std::vector<int32_t>>(
      cx.num_faces(), par,
      [&](size_t i, Csr<int32_t>& out, std::vector<int32_t>& buf) {
        const int32_t p = cx.face_source[i];
        buf.clear();
        for (int32_t k : bc.patch_curves[p]) buf.push_back(emap[k]);
        sort_unique_ids(buf);
        out.items.insert(out.items.end(), buf.begin(), buf.end());
        cx.face_quad[i] = f.patch_quad[p];
      },
      [&](size_t b, size_t e) {  // the curves of the patches from the range's first to its last
        if (b == e) return size_t{0};
        return static_cast<size_t>(bc.patch_curves.offsets[static_cast<size_t>(cx.face_source[e - 1]) + 1] -
                                   bc.patch_curves.offsets[static_cast<size_t>(cx.face_source[b])]);
      });
  cx.face_cells = region_face_cells(cx.face_source, bc.patch_components, kmap, par);
  curve_edges_of_view(bc, f, kmap, pmap, emap, vmap, cx, par);
  cx.vert_boundary = f.corner_boundary;
  cx.vert_cell_count = f.corner_cells;
  cx.vert_all_quad = f.corner_all_quad;
  build_vert_edges(cx, par);
  return cx;
}

}  // namespace

BaseViewFacts base_view_facts(const Mesh& m, const BaseComplex& bc, std::span<const int32_t> region_components,
                              const Threads& threads) {
  const Threads par = resolved(threads);
  BaseViewFacts f;
  f.num_mesh_vertices = m.num_vertices();
  f.component_in = flags_of(region_components, bc.num_components(), "component");
  // A non-hex component is one non-hex cell (docs/concepts.md): the view's cell takes its kind.
  f.component_kind.assign(bc.num_components(), 0);
  parallel_ranges(f.component_kind.size(), par, [&](size_t b, size_t e, int) {
    for (size_t k = b; k < e; ++k) {
      if (bc.component_kind[k] != ComponentKind::NonHex) continue;
      const int32_t c = bc.component_cells[k][0];
      f.component_kind[k] = non_hex_kind(m.cell_type[c], static_cast<size_t>(m.cell_faces.count(c)));
    }
  });
  std::vector<uint8_t> in_cell(m.num_cells());
  parallel_ranges(in_cell.size(), par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) in_cell[c] = f.component_in[bc.cell_component[c]];
  });
  const RegionBoundary rb = region_boundary(m, in_cell, par);
  const size_t npatch = bc.num_patches();
  // A patch is in the region when its faces are; all its faces have the same two components.
  f.patch_in.resize(npatch);
  f.patch_quad.resize(npatch);
  parallel_ranges(npatch, par, [&](size_t b, size_t e, int) {
    for (size_t p = b; p < e; ++p) {
      f.patch_in[p] = rb.face_in[bc.patch_faces[p][0]];
      f.patch_quad[p] = bc.patch_curves.count(p) == 4 && bc.patch_corners.count(p) == 4;
    }
  });
  curve_facts(m, bc, in_cell, rb, f.whole(), f, par);
  corner_facts(m, bc, rb, f, par);
  return f;
}

CellComplex complex_from_base(const BaseComplex& bc, const BaseViewFacts& facts, const Threads& threads) {
  if (!facts.whole()) throw std::invalid_argument("complex_from_base without the mesh: the facts are of a proper region");
  return view_from_facts(bc, facts, resolved(threads));
}

CellComplex complex_from_base(const Mesh& m, const BaseComplex& bc, std::span<const int32_t> region_components,
                              const Threads& threads) {
  const Threads par = resolved(threads);
  CellComplex cx = view_from_facts(bc, base_view_facts(m, bc, region_components, par), par);
  if (cx.num_cells() < bc.num_components())
    fill_whole_mesh_adjacency(
        m, cx, [&](size_t i) { return bc.curve_edges[cx.edge_source[i]]; },
        [&](int32_t f) { return bc.face_patch[f]; }, [&](int32_t c) { return bc.cell_component[c]; },
        bc.patch_components, par);
  return cx;
}

std::vector<int32_t> complex_edges_of(const CellComplex& cx, const BaseComplex& bc, std::span<const int32_t> mesh_edges) {
  std::vector<int32_t> out;
  for (int32_t e : mesh_edges) {
    const int32_t src = cx.level == Level::Complex ? bc.edge_curve[static_cast<size_t>(e)] : e;
    const auto it = std::lower_bound(cx.edge_source.begin(), cx.edge_source.end(), src);
    if (src >= 0 && it != cx.edge_source.end() && *it == src) out.push_back(static_cast<int32_t>(it - cx.edge_source.begin()));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int32_t> components_of_cells(const BaseComplex& bc, std::span<const int32_t> cells) {
  std::vector<int32_t> out;
  out.reserve(cells.size());
  for (int32_t c : cells) {
    if (c < 0 || static_cast<size_t>(c) >= bc.cell_component.size())
      throw std::invalid_argument("cell id out of range: " + std::to_string(c));
    out.push_back(bc.cell_component[c]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace hbc
