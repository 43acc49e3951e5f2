// The complete VSG wireframe (paper §5): the flood of faces from the VSG, the wireframe's singular
// vertices where its separation surfaces meet, and the chains traced from them.
#include "structure/vsg_trace.hpp"

#include <algorithm>
#include <array>

#include "parallel/concurrent_union_find.hpp"
#include "parallel/parallel.hpp"

namespace hbc::vsg {

// Faces reachable from the faces at `start` edges, across edges that do not stop the flood, into
// the faces at the crossed edge sharing no cell with the current face. The authors' mesh marks an
// edge singular (a stop) when irregular, at a non-hex cell (mesh level); their base-complex mesh
// marks none, so there only the boundary stops.
// Crossing is symmetric (it depends on the edge and on the two faces alone), so the reachable
// faces are the classes, under "crossed into each other", of the start faces: classes are joined
// edge by edge, which reads the complex in memory order instead of hopping from face to face.
// Which faces a class holds does not depend on the order of the unions, so ranges of edges
// unite at once.
std::vector<uint8_t> flood_faces(const Region& r, const std::vector<uint8_t>& start, const Threads& par) {
  const CellComplex& cx = r.cx;
  const bool mesh_level = cx.level == Level::Mesh;
  detail::ConcurrentUnionFind uf(cx.num_faces(), par);
  detail::parallel_ranges(cx.num_edges(), par, [&](size_t begin, size_t end, int) {
    std::vector<int32_t> rest, next, queue;
    for (size_t g = begin; g < end; ++g) {
      const int32_t e = static_cast<int32_t>(g);
      if (cx.edge_faces.count(g) < 2 || r.mesh_boundary(e) || (mesh_level && r.mesh_singular(e))) continue;
      // Classes of the faces around g under "share no cell": a search in the complement of the
      // share-a-cell relation, each test either settling a face or charged to a sharing pair, so a
      // fan of thousands of faces costs about as many tests as it has faces.
      const auto fs = cx.edge_faces[g];
      rest.assign(fs.begin() + 1, fs.end());
      queue.assign(1, fs[0]);
      for (size_t q = 0;; ++q) {
        if (q == queue.size()) {
          if (rest.empty()) break;
          queue.push_back(rest.back());
          rest.pop_back();
        }
        const int32_t f = queue[q];
        next.clear();
        for (int32_t h : rest) {
          if (r.faces_share_cell(f, h)) {
            next.push_back(h);
          } else {
            uf.unite(f, h);
            queue.push_back(h);
          }
        }
        rest.swap(next);
      }
    }
  });
  std::vector<uint8_t> root_seen(cx.num_faces(), 0);
  for (size_t e = 0; e < start.size(); ++e)
    if (start[e])
      for (int32_t f : cx.edge_faces[e]) root_seen[static_cast<size_t>(uf.find(f))] = 1;
  std::vector<uint8_t> seen(cx.num_faces(), 0);
  detail::parallel_ranges(seen.size(), par, [&](size_t begin, size_t end, int) {
    for (size_t f = begin; f < end; ++f) seen[f] = root_seen[static_cast<size_t>(uf.find(static_cast<int32_t>(f)))];
  });
  return seen;
}

// Singular vertices of the complete wireframe: ends of patch edges (all faces flooded or on the
// boundary) with a patch-edge count other than 0 and 2, or two patch edges sharing a face.
// Each element's flag depends on its neighbours' only: ranges in parallel.
std::vector<uint8_t> patch_singular_vertices(const Region& r, const std::vector<uint8_t>& flooded, const Threads& par) {
  const CellComplex& cx = r.cx;
  std::vector<uint8_t> patch_edge(cx.num_edges(), 0);
  detail::parallel_ranges(patch_edge.size(), par, [&](size_t b, size_t end, int) {
    for (size_t e = b; e < end; ++e) {
      bool all = !cx.edge_faces[e].empty();
      for (int32_t f : cx.edge_faces[e]) all = all && (flooded[f] || cx.face_cells[f][1] < 0);
      patch_edge[e] = all;
    }
  });
  std::vector<uint8_t> out(cx.num_vertices(), 0);
  detail::parallel_ranges(out.size(), par, [&](size_t b, size_t end, int) {
    int32_t at[2] = {-1, -1};
    for (size_t v = b; v < end; ++v) {
      size_t n = 0;
      for (int32_t e : cx.vert_edges[v])
        if (patch_edge[e] && n++ < 2) at[n - 1] = e;
      out[v] = (n != 0 && n != 2) || (n == 2 && r.share_region_face(at[0], at[1]));
    }
  });
  return out;
}

void fill_complete(const Region& r, const Chains& ch, const Threads& par, VsgWireframe& w) {
  const CellComplex& cx = r.cx;
  const size_t n = ch.edges.rows();
  w.edges = ch.edges;
  w.polylines = polylines(cx, ch, par);
  w.ends.resize(n);
  w.kind.resize(n);
  w.valence.resize(n);
  w.stop.resize(n);
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t c = b; c < e; ++c) {
      const auto es = ch.edges[c], vs = ch.verts[c];
      const bool closed = vs.front() == vs.back();
      w.ends[c] = closed ? std::array<int32_t, 2>{-1, -1} : std::array<int32_t, 2>{vs.front(), vs.back()};
      bool all_vsg = true;
      for (int32_t x : es) all_vsg = all_vsg && w.edge_vsg[x];
      w.kind[c] = all_vsg ? WireKind::Vsg : WireKind::Trace;
      w.valence[c] = r.valence(es[0]);
      const int32_t last = vs.back();
      w.stop[c] = closed ? TraceStop::None
                  : w.vert_singular[last] ? TraceStop::SingularVertex
                  : cx.vert_boundary[last] ? TraceStop::Boundary
                                           : TraceStop::NoContinuation;
    }
  });
}

}  // namespace hbc::vsg
