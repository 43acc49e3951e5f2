// OpenVolumeMesh ASCII writer: the mesh's own vertex, edge, face and cell numbering, faces as
// half-edge loops and cells as half-faces carrying each cell's view of its faces, so that
// read_ovm + build_mesh give back exactly the same arrays.
#include <charconv>

#include "hbc/io.hpp"
#include "io/detail/text_writer.hpp"

namespace hbc {
namespace {

using detail::append_int;
using detail::append_real;

}  // namespace

std::string ovm_text(const Mesh& m) {
  std::string out;
  out.reserve(64 * m.num_vertices() + 16 * m.num_edges() + 8 * m.face_verts.items.size() +
              8 * m.cell_faces.items.size() + 64);
  out += "OVM ASCII\nVertices\n";
  append_int(out, static_cast<int64_t>(m.num_vertices()));
  out += '\n';
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) {
      if (k) out += ' ';
      append_real(out, m.points[3 * v + k]);
    }
    out += '\n';
  }
  out += "Edges\n";
  append_int(out, static_cast<int64_t>(m.num_edges()));
  out += '\n';
  for (const auto& e : m.edge_verts) {
    append_int(out, e[0]);
    out += ' ';
    append_int(out, e[1]);
    out += '\n';
  }
  out += "Faces\n";
  append_int(out, static_cast<int64_t>(m.num_faces()));
  out += '\n';
  for (size_t f = 0; f < m.num_faces(); ++f) {
    auto loop = m.face_verts[f];
    auto edges = m.face_edges(f);
    append_int(out, static_cast<int64_t>(loop.size()));
    // Edge i runs from loop[i] to loop[i+1]; the odd half-edge when that is against (lo, hi).
    for (size_t i = 0; i < loop.size(); ++i) {
      out += ' ';
      append_int(out, 2 * static_cast<int64_t>(edges[i]) + (m.edge_verts[edges[i]][0] == loop[i] ? 0 : 1));
    }
    out += '\n';
  }
  out += "Polyhedra\n";
  append_int(out, static_cast<int64_t>(m.num_cells()));
  out += '\n';
  for (size_t c = 0; c < m.num_cells(); ++c) {
    append_int(out, m.cell_faces.count(c));
    for (int32_t i = m.cell_faces.offsets[c]; i < m.cell_faces.offsets[c + 1]; ++i) {
      out += ' ';
      append_int(out, 2 * static_cast<int64_t>(m.cell_faces.items[i]) + m.cell_face_flip[i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace hbc
