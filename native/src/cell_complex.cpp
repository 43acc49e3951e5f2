#include "hbc/cell_complex.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace hbc {

namespace {

// Which mesh faces / edges / vertices lie on the boundary of the region of mesh cells flagged in
// `in_cell`: a face is a boundary face when exactly one of its cells is in the region, so the
// mesh boundary and the seams to cells outside the region are treated alike.
struct RegionBoundary {
  std::vector<uint8_t> face_in, face_boundary, edge_boundary, vert_boundary;
};

RegionBoundary region_boundary(const Mesh& m, const std::vector<uint8_t>& in_cell) {
  RegionBoundary r;
  const size_t nf = m.num_faces();
  r.face_in.assign(nf, 0);
  r.face_boundary.assign(nf, 0);
  r.edge_boundary.assign(m.num_edges(), 0);
  r.vert_boundary.assign(m.num_vertices(), 0);
  for (size_t f = 0; f < nf; ++f) {
    const auto [a, b] = m.face_cells[f];
    const int n = in_cell[a] + (b >= 0 ? in_cell[b] : 0);
    r.face_in[f] = n > 0;
    if (n != 1) continue;
    r.face_boundary[f] = 1;
    for (int32_t e : m.face_edges(f)) r.edge_boundary[e] = 1;
    for (int32_t v : m.face_verts[f]) r.vert_boundary[v] = 1;
  }
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

// Compact ids for the flagged entries, in increasing order of the original ids.
std::vector<int32_t> compact(const std::vector<uint8_t>& keep, std::vector<int32_t>& source) {
  std::vector<int32_t> map(keep.size(), -1);
  source.clear();
  for (size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) {
      map[i] = static_cast<int32_t>(source.size());
      source.push_back(static_cast<int32_t>(i));
    }
  return map;
}

void sort_unique_row(std::vector<int32_t>& buf, Csr<int32_t>& out) {
  // Rows mapped through monotonic id maps mostly come sorted already: checking is cheaper.
  if (!std::is_sorted(buf.begin(), buf.end())) std::sort(buf.begin(), buf.end());
  buf.erase(std::unique(buf.begin(), buf.end()), buf.end());
  out.push_row(buf.begin(), buf.end());
}

// vert_edges from edge_verts (closed edges have no vertices); self-loops appear once.
void build_vert_edges(CellComplex& cx) {
  Csr<int32_t> ev;
  for (const auto& ab : cx.edge_verts) {
    if (ab[0] < 0) {
      ev.push_row(ab.begin(), ab.begin());
    } else if (ab[0] == ab[1]) {
      ev.push_row(ab.begin(), ab.begin() + 1);
    } else {
      ev.push_row(ab.begin(), ab.end());
    }
  }
  cx.vert_edges = transpose(ev, cx.num_vertices());
}

// The region cells on the two sides of each kept face (compact ids; -1 for a side outside the
// region or off the mesh), lower first.
std::vector<std::array<int32_t, 2>> region_face_cells(const std::vector<int32_t>& face_source,
                                                      const std::vector<std::array<int32_t, 2>>& sides,
                                                      const std::vector<int32_t>& cell_map) {
  std::vector<std::array<int32_t, 2>> out(face_source.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const auto [a, b] = sides[face_source[i]];
    std::array<int32_t, 2> s{a >= 0 ? cell_map[a] : -1, b >= 0 ? cell_map[b] : -1};
    if (s[0] < 0 || (s[1] >= 0 && s[1] < s[0])) std::swap(s[0], s[1]);
    out[i] = s;
  }
  return out;
}

// The whole-mesh adjacency of a proper region (CellComplex::edge_all_faces and co.), from the
// mesh-level rows of each complex edge's mesh edges mapped by `face_id` / `cell_id` (identity at
// the mesh level, patch / component at the complex level).
template <class EdgeMeshEdges, class FaceId, class CellId>
void fill_whole_mesh_adjacency(const Mesh& m, CellComplex& cx, const EdgeMeshEdges& mesh_edges_of, const FaceId& face_id,
                               const CellId& cell_id, const std::vector<std::array<int32_t, 2>>& face_sides) {
  std::vector<uint8_t> all(m.num_cells(), 1);
  const RegionBoundary mb = region_boundary(m, all);
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

CellComplex complex_from_mesh(const Mesh& m) {
  std::vector<int32_t> all(m.num_cells());
  for (size_t c = 0; c < all.size(); ++c) all[c] = static_cast<int32_t>(c);
  return complex_from_mesh(m, all);
}

CellComplex complex_from_mesh(const Mesh& m, std::span<const int32_t> region_cells) {
  CellComplex cx;
  cx.level = Level::Mesh;
  const std::vector<uint8_t> in_cell = flags_of(region_cells, m.num_cells(), "cell");
  const RegionBoundary rb = region_boundary(m, in_cell);
  const size_t ne = m.num_edges(), nv = m.num_vertices();

  const std::vector<int32_t> cmap = compact(in_cell, cx.cell_source);
  const std::vector<int32_t> fmap = compact(rb.face_in, cx.face_source);
  // Edges and vertices of the region's cells (those of their faces).
  std::vector<uint8_t> edge_in(ne, 0), vert_in(nv, 0);
  for (size_t c = 0; c < m.num_cells(); ++c)
    if (in_cell[c])
      for (int32_t f : m.cell_faces[c])
        for (int32_t e : m.face_edges(static_cast<size_t>(f))) edge_in[static_cast<size_t>(e)] = 1;
  for (size_t e = 0; e < ne; ++e)
    if (edge_in[e]) vert_in[m.edge_verts[e][0]] = vert_in[m.edge_verts[e][1]] = 1;
  const std::vector<int32_t> emap = compact(edge_in, cx.edge_source);
  const std::vector<int32_t> vmap = compact(vert_in, cx.vert_mesh);

  cx.cell_non_hex.resize(cx.num_cells());
  for (size_t i = 0; i < cx.num_cells(); ++i) cx.cell_non_hex[i] = !m.is_hex(cx.cell_source[i]);

  std::vector<int32_t> buf;
  cx.face_quad.resize(cx.num_faces());
  for (size_t i = 0; i < cx.num_faces(); ++i) {
    const int32_t f = cx.face_source[i];
    buf.clear();
    for (int32_t e : m.face_edges(static_cast<size_t>(f))) buf.push_back(emap[e]);
    sort_unique_row(buf, cx.face_edges);
    cx.face_quad[i] = m.face_verts.count(f) == 4;
  }
  cx.face_cells = region_face_cells(cx.face_source, m.face_cells, cmap);

  const size_t nx = cx.edge_source.size();  // edge_verts is not sized yet
  cx.edge_verts.resize(nx);
  cx.edge_valence.resize(nx);
  cx.edge_boundary.resize(nx);
  cx.edge_non_hex.assign(nx, 0);
  cx.edge_all_quad.assign(nx, 1);
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
        [](int32_t f) { return f; }, [](int32_t c) { return c; }, m.face_cells);
  build_vert_edges(cx);
  return cx;
}

CellComplex complex_from_base(const Mesh& m, const BaseComplex& bc) {
  std::vector<int32_t> all(bc.num_components());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int32_t>(k);
  return complex_from_base(m, bc, all);
}

BaseViewFacts base_view_facts(const Mesh& m, const BaseComplex& bc) {
  std::vector<int32_t> all(bc.num_components());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int32_t>(k);
  return base_view_facts(m, bc, all);
}

bool BaseViewFacts::whole() const {
  return std::find(component_in.begin(), component_in.end(), 0) == component_in.end();
}

namespace {

// Rows of the curves in the view (compact ids, `curve_map`) listing the region owners of each
// (compact ids, `owner_map`, monotonic), from `owner_curves` (owner -> its curves, sorted,
// distinct): a transpose restricted to the region, so its rows come out sorted and distinct.
Csr<int32_t> curve_owner_rows(const Csr<int32_t>& owner_curves, const std::vector<int32_t>& owner_map,
                              const std::vector<int32_t>& curve_map, size_t ncurves_in_view) {
  Csr<int32_t> rows;
  rows.offsets.assign(ncurves_in_view + 1, 0);
  auto each = [&](auto&& fn) {
    for (size_t o = 0; o < owner_curves.rows(); ++o)
      if (owner_map[o] >= 0)
        for (int32_t k : owner_curves[o])
          if (curve_map[static_cast<size_t>(k)] >= 0) fn(curve_map[static_cast<size_t>(k)], owner_map[o]);
  };
  each([&](int32_t i, int32_t) { ++rows.offsets[static_cast<size_t>(i) + 1]; });
  for (size_t i = 0; i < ncurves_in_view; ++i) rows.offsets[i + 1] += rows.offsets[i];
  rows.items.resize(static_cast<size_t>(rows.offsets.back()));
  std::vector<int32_t> fill(rows.offsets.begin(), rows.offsets.end() - 1);
  each([&](int32_t i, int32_t x) { rows.items[static_cast<size_t>(fill[static_cast<size_t>(i)]++)] = x; });
  return rows;
}

// Per corner in the view (vmap >= 0): the region components with a cell there. A cell at a
// vertex has a face there; components are visited one by one, so a stamp per vertex (the last
// component that counted it) counts each component once without sorting (vertex, component) pairs.
void count_corner_components(const Mesh& m, const BaseComplex& bc, const std::vector<uint8_t>& component_in,
                             const std::vector<int32_t>& vmap, std::vector<int32_t>& count) {
  std::vector<int32_t> stamp(m.num_vertices(), -1);
  for (size_t k = 0; k < component_in.size(); ++k) {
    if (!component_in[k]) continue;
    for (int32_t c : bc.component_cells[k])
      for (int32_t f : m.cell_faces[static_cast<size_t>(c)])
        for (int32_t v : m.face_verts[static_cast<size_t>(f)]) {
          const int32_t x = vmap[static_cast<size_t>(v)];
          if (x < 0 || stamp[static_cast<size_t>(v)] == static_cast<int32_t>(k)) continue;
          stamp[static_cast<size_t>(v)] = static_cast<int32_t>(k);
          ++count[static_cast<size_t>(x)];
        }
  }
}

// Which curves are in the view, their valence and boundary flag. A curve is in the view when a
// region cell lies at its first mesh edge (every mesh edge has a cell, so with the whole region
// every curve is). The valence is that of the curve's first mesh edge: every face around a curve
// separates, so each mesh cell there is a corner of a different coarse cell.
void curve_facts(const Mesh& m, const BaseComplex& bc, const std::vector<uint8_t>& in_cell, const RegionBoundary& rb,
                 bool whole, BaseViewFacts& f) {
  const size_t ncurve = bc.num_curves();
  f.curve_in.assign(ncurve, whole ? 1 : 0);
  f.curve_valence.assign(ncurve, 0);
  f.curve_boundary.assign(ncurve, 0);
  EdgeFan fan;
  for (size_t k = 0; k < ncurve; ++k) {
    const auto es = bc.curve_edges[k];
    if (whole) {
      f.curve_valence[k] = m.edge_valence(static_cast<size_t>(es[0]));
    } else {
      edge_fan(m, es[0], fan);
      f.curve_valence[k] = static_cast<int32_t>(std::count_if(fan.cells.begin(), fan.cells.end(), [&](int32_t c) { return in_cell[c] != 0; }));
      f.curve_in[k] = f.curve_valence[k] > 0;
    }
    if (!f.curve_in[k]) continue;
    for (int32_t e : es) f.curve_boundary[k] = f.curve_boundary[k] || rb.edge_boundary[e];
  }
}

// The view's vertices (the ends of its open curves) and, per vertex, its boundary flag, the
// region components there and whether every region patch there is a quad.
void corner_facts(const Mesh& m, const BaseComplex& bc, const RegionBoundary& rb, BaseViewFacts& f) {
  std::vector<uint8_t> corner_in(m.num_vertices(), 0);
  for (size_t k = 0; k < f.curve_in.size(); ++k) {
    if (!f.curve_in[k] || bc.curve_closed[k]) continue;
    const auto vs = bc.curve_verts[k];
    corner_in[vs.front()] = corner_in[vs.back()] = 1;
  }
  const std::vector<int32_t> vmap = compact(corner_in, f.corners);
  const size_t n = f.corners.size();
  f.corner_boundary.resize(n);
  for (size_t i = 0; i < n; ++i) f.corner_boundary[i] = rb.vert_boundary[f.corners[i]];
  f.corner_cells.assign(n, 0);
  count_corner_components(m, bc, f.component_in, vmap, f.corner_cells);
  // Non-quad patches at each corner, from the faces' side.
  f.corner_all_quad.assign(n, 1);
  for (size_t x = 0; x < m.num_faces(); ++x)
    if (rb.face_in[x] && bc.face_patch[x] >= 0 && !f.patch_quad[bc.face_patch[x]])
      for (int32_t v : m.face_verts[x])
        if (corner_in[static_cast<size_t>(v)]) f.corner_all_quad[static_cast<size_t>(vmap[v])] = 0;
}

// The view's edges (curves): end vertices, mesh polylines, valence, boundary flag, cells and
// faces around, non-hex and all-quad flags.
void curve_edges_of_view(const BaseComplex& bc, const BaseViewFacts& f, const std::vector<int32_t>& kmap,
                         const std::vector<int32_t>& pmap, const std::vector<int32_t>& emap,
                         const std::vector<int32_t>& vmap, CellComplex& cx) {
  const size_t nx = cx.edge_source.size();  // edge_verts is not sized yet
  cx.edge_verts.resize(nx);
  cx.edge_valence.resize(nx);
  cx.edge_boundary.resize(nx);
  cx.edge_non_hex.assign(nx, 0);
  cx.edge_all_quad.assign(nx, 1);
  // Components and patches around a curve: a cell at a curve's mesh edge has its two faces there
  // among the separation faces (every face at a complex edge separates), so the curve is one of
  // its component's curves, and conversely; likewise a patch holds the curve exactly when one of
  // its faces lies at it. Hence the transposes of component_curves / patch_curves, filtered to
  // the region, hold what the fans around the curve's mesh edges hold, sorted and distinct.
  cx.edge_cells = curve_owner_rows(bc.component_curves, kmap, emap, nx);
  cx.edge_faces = curve_owner_rows(bc.patch_curves, pmap, emap, nx);
  cx.edge_points.reserve(nx, bc.curve_verts.items.size() + nx);
  for (size_t i = 0; i < nx; ++i) {
    const int32_t k = cx.edge_source[i];
    const auto vs = bc.curve_verts[k];
    if (bc.curve_closed[k]) {
      cx.edge_verts[i] = {-1, -1};
      cx.edge_points.push_row(vs.begin(), vs.end());
      cx.edge_points.items.push_back(vs.front());
      cx.edge_points.offsets.back() += 1;
    } else {
      cx.edge_verts[i] = {vmap[vs.front()], vmap[vs.back()]};
      cx.edge_points.push_row(vs.begin(), vs.end());
    }
    cx.edge_valence[i] = f.curve_valence[k];
    cx.edge_boundary[i] = f.curve_boundary[k];
    for (int32_t x : cx.edge_cells[i]) cx.edge_non_hex[i] = cx.edge_non_hex[i] || cx.cell_non_hex[x];
    for (int32_t p : cx.edge_faces[i]) cx.edge_all_quad[i] = cx.edge_all_quad[i] && cx.face_quad[p];
  }
}

// Everything of the view but the whole-mesh adjacency of a proper region, from `bc` and the facts
// alone (no mesh).
CellComplex view_from_facts(const BaseComplex& bc, const BaseViewFacts& f) {
  CellComplex cx;
  cx.level = Level::Complex;
  const std::vector<int32_t> kmap = compact(f.component_in, cx.cell_source);
  cx.cell_non_hex.resize(cx.num_cells());
  for (size_t i = 0; i < cx.num_cells(); ++i)
    cx.cell_non_hex[i] = bc.component_kind[cx.cell_source[i]] == ComponentKind::NonHex;
  const std::vector<int32_t> pmap = compact(f.patch_in, cx.face_source);
  const std::vector<int32_t> emap = compact(f.curve_in, cx.edge_source);
  cx.vert_mesh = f.corners;
  std::vector<int32_t> vmap(f.num_mesh_vertices, -1);
  for (size_t i = 0; i < f.corners.size(); ++i) vmap[static_cast<size_t>(f.corners[i])] = static_cast<int32_t>(i);

  // A patch's edges are the curves on it (patch_curves), those off the view as -1.
  std::vector<int32_t> buf;
  cx.face_quad.resize(cx.num_faces());
  cx.face_edges.reserve(cx.num_faces(), 4 * cx.num_faces());
  for (size_t i = 0; i < cx.num_faces(); ++i) {
    const int32_t p = cx.face_source[i];
    buf.clear();
    for (int32_t k : bc.patch_curves[p]) buf.push_back(emap[k]);
    sort_unique_row(buf, cx.face_edges);
    cx.face_quad[i] = f.patch_quad[p];
  }
  cx.face_cells = region_face_cells(cx.face_source, bc.patch_components, kmap);
  curve_edges_of_view(bc, f, kmap, pmap, emap, vmap, cx);
  cx.vert_boundary = f.corner_boundary;
  cx.vert_cell_count = f.corner_cells;
  cx.vert_all_quad = f.corner_all_quad;
  build_vert_edges(cx);
  return cx;
}

}  // namespace

BaseViewFacts base_view_facts(const Mesh& m, const BaseComplex& bc, std::span<const int32_t> region_components) {
  BaseViewFacts f;
  f.num_mesh_vertices = m.num_vertices();
  f.component_in = flags_of(region_components, bc.num_components(), "component");
  std::vector<uint8_t> in_cell(m.num_cells());
  for (size_t c = 0; c < in_cell.size(); ++c) in_cell[c] = f.component_in[bc.cell_component[c]];
  const RegionBoundary rb = region_boundary(m, in_cell);
  const size_t npatch = bc.num_patches();
  // A patch is in the region when its faces are; all its faces have the same two components.
  f.patch_in.resize(npatch);
  f.patch_quad.resize(npatch);
  for (size_t p = 0; p < npatch; ++p) {
    f.patch_in[p] = rb.face_in[bc.patch_faces[p][0]];
    f.patch_quad[p] = bc.patch_curves.count(p) == 4 && bc.patch_corners.count(p) == 4;
  }
  curve_facts(m, bc, in_cell, rb, f.whole(), f);
  corner_facts(m, bc, rb, f);
  return f;
}

CellComplex complex_from_base(const BaseComplex& bc, const BaseViewFacts& facts) {
  if (!facts.whole()) throw std::invalid_argument("complex_from_base without the mesh: the facts are of a proper region");
  return view_from_facts(bc, facts);
}

CellComplex complex_from_base(const Mesh& m, const BaseComplex& bc,
                              std::span<const int32_t> region_components) {
  CellComplex cx = view_from_facts(bc, base_view_facts(m, bc, region_components));
  if (cx.num_cells() < bc.num_components())
    fill_whole_mesh_adjacency(
        m, cx, [&](size_t i) { return bc.curve_edges[cx.edge_source[i]]; },
        [&](int32_t f) { return bc.face_patch[f]; }, [&](int32_t c) { return bc.cell_component[c]; },
        bc.patch_components);
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
