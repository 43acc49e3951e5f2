// The VSG wireframe (paper §5) step by step: the VSG (vsg_chains.cpp), the complete wireframe
// traced from it (vsg_trace.cpp), its simplification (vsg_simplification.cpp); and the counts.
#include "hbc/vsg_wireframe.hpp"

#include <algorithm>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"
#include "structure/vsg_chains.hpp"
#include "structure/vsg_simplification.hpp"
#include "structure/vsg_trace.hpp"

namespace hbc {

using namespace vsg;
using detail::set_flag;

int64_t covered_mesh_edges(const CellComplex& cx, const Csr<int32_t>& chains) {
  std::vector<uint8_t> on = edge_flags(cx, chains);
  int64_t n = 0;
  for (size_t e = 0; e < on.size(); ++e)
    if (on[e]) n += cx.edge_points.count(e) - 1;
  return n;
}

namespace {

// Connected components of the chains: their vertices are joined chain by chain, and each set of
// wireframe vertices is one component (its root, the lowest member, counted once); a chain of a
// closed curve alone has no vertex and is a component by itself.
// The sets do not depend on the order of the unions, so ranges of chains unite at once.
int64_t components(const CellComplex& cx, const Csr<int32_t>& chains, const Threads& par) {
  const size_t nv = cx.num_vertices();
  detail::ConcurrentUnionFind uf(nv, par);
  std::vector<uint8_t> on(nv, 0);
  std::vector<int64_t> closed(static_cast<size_t>(detail::range_count(chains.rows(), par)), 0);
  detail::parallel_ranges(chains.rows(), par, [&](size_t b, size_t e, int r) {
    int64_t alone = 0;  // local: the ranges' counts share a cache line
    for (size_t c = b; c < e; ++c) {
      int32_t first = -1;
      for (int32_t x : chains[c])
        for (int32_t v : cx.edge_verts[x]) {
          if (v < 0) continue;
          set_flag(on, v);
          if (first < 0) first = v;
          else uf.unite(first, v);
        }
      alone += first < 0;
    }
    closed[static_cast<size_t>(r)] = alone;
  });
  std::vector<int64_t> roots(static_cast<size_t>(detail::range_count(nv, par)), 0);
  detail::parallel_ranges(nv, par, [&](size_t b, size_t e, int r) {
    int64_t n = 0;
    for (size_t v = b; v < e; ++v) n += on[v] && uf.find(static_cast<int32_t>(v)) == static_cast<int32_t>(v);
    roots[static_cast<size_t>(r)] = n;
  });
  int64_t n = 0;
  for (int64_t k : closed) n += k;
  for (int64_t k : roots) n += k;
  return n;
}

}  // namespace

VsgWireframe vsg_wireframe(const CellComplex& cx, const WireframeOptions& opt, const Threads& threads) {
  const Threads par = resolved(threads);
  Region r{cx, {}};
  r.face_mask = face_masks(r, par);
  VsgWireframe w;
  const size_t ne = cx.num_edges(), nv = cx.num_vertices();
  w.edge_vsg.assign(ne, 0);
  detail::parallel_ranges(ne, par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) w.edge_vsg[e] = !r.regular(static_cast<int32_t>(e));
  });
  w.vsg_edges = std::count(w.edge_vsg.begin(), w.edge_vsg.end(), uint8_t{1});

  // VSG (§5.1, vsg_chains.cpp): chains of seeds, broken only where the continuation is not unique or changes valence.
  Chains vsg = valence_chains(r, w.edge_vsg, std::vector<uint8_t>(nv, 0), par);
  add_closed(cx, w.edge_vsg, vsg);
  w.vsg_chain_edges = vsg.edges;
  w.vsg_chains = static_cast<int64_t>(vsg.edges.rows());
  w.vert_vsg = chain_end_flags(cx, vsg, par, [](size_t) { return true; });

  // Complete wireframe (vsg_trace.cpp): flood from the VSG's edges and from every edge at a VSG vertex.
  std::vector<uint8_t> start = edge_flags(cx, vsg.edges);
  const auto any = [](int32_t) { return true; };
  flag_edges_at(cx, w.vert_vsg, start, par, any);
  const std::vector<uint8_t> flooded = flood_faces(r, start, par);
  w.vert_singular = patch_singular_vertices(r, flooded, par);
  w.singular_vertices = detail::ids_where(nv, par, [&](size_t v) { return w.vert_singular[v] != 0; });
  std::vector<uint8_t> seeds(ne, 0);
  flag_edges_at(cx, w.vert_singular, seeds, par, any);
  const Chains complete = valence_chains(r, seeds, w.vert_singular, par);
  fill_complete(r, complete, par, w);
  w.non_hex = chain_kinds(cx, complete, par);

  // Simplification (§5.2, vsg_simplification.cpp).
  std::vector<uint8_t> parallel(ne, 0);
  for (int32_t e : opt.parallel_edges)
    if (e >= 0 && static_cast<size_t>(e) < ne) parallel[e] = 1;
  const Cleaning cl = clean_chains(r, complete, w.vert_singular, parallel, par);
  w.vert_non_important.resize(nv);
  detail::parallel_ranges(nv, par, [&](size_t b, size_t end, int) {
    for (size_t v = b; v < end; ++v) w.vert_non_important[v] = !w.vert_singular[v] || cl.redundant_vert[v];
  });
  w.non_important = cl.non_important;
  w.reactivated = cl.reactivated;
  const Chains simple = final_chains(r, complete, cl.kept, par);
  w.simplified_edges = simple.edges;
  w.simplified_polylines = polylines(cx, simple, par);
  w.simplified_non_hex = chain_kinds(cx, simple, par);
  const std::vector<uint8_t> on = edge_flags(cx, simple.edges);
  w.shown.assign(w.size(), 0);
  detail::parallel_ranges(w.size(), par, [&](size_t b, size_t end, int) {
    for (size_t c = b; c < end; ++c) {
      bool all = true;
      for (int32_t e : w.edges[c]) all = all && on[e];
      w.shown[c] = all;
    }
  });
  w.vsg_mesh_edges = covered_mesh_edges(cx, w.vsg_chain_edges);
  w.wireframe_mesh_edges = covered_mesh_edges(cx, w.edges);
  w.simplified_mesh_edges = covered_mesh_edges(cx, w.simplified_edges);
  w.components = components(cx, w.edges, par);
  w.simplified_components = components(cx, w.simplified_edges, par);
  return w;
}

}  // namespace hbc
