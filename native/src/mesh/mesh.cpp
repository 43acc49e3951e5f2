#include "hbc/mesh.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "mesh/mesh_steps.hpp"
#include "platform/worker_pool.hpp"

namespace hbc {

const char* cell_type_name(CellType t) {
  switch (t) {
    case CellType::Hex: return "hex";
    case CellType::Tet: return "tet";
    case CellType::Prism: return "prism";
    case CellType::Pyramid: return "pyramid";
    case CellType::Polyhedron: return "polyhedron";
  }
  return "?";
}

size_t Mesh::num_hex_cells() const {
  return static_cast<size_t>(std::count(cell_type.begin(), cell_type.end(), CellType::Hex));
}


void release_unanalyzed(Mesh& m) {
  m.released_vertices = m.num_vertices();
  std::vector<double>().swap(m.points);
  std::vector<uint8_t>().swap(m.cell_face_flip);
  std::vector<uint8_t>().swap(m.vert_boundary);
}

Mesh build_mesh(MeshInput in, const Threads& threads) {
  using namespace mesh_steps;
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  validate_input(in, par);
  std::vector<int64_t>().swap(in.vertex_loc);  // only validate_input names vertices
  Mesh m;
  m.source = in.source;
  m.points = std::move(in.points);
  m.warnings = std::move(in.warnings);  // what the reader skipped (lower-dimensional elements, ...)
  EdgeFaceCounts counts = build_edges(m, merge_faces(in, m, par), par);
  CellCheck cells = check_cells(m, in, par);
  orient_groups(m, cells.volume, par);
  std::vector<double>().swap(cells.volume);
  mark_boundary(m, par);
  edge_fans(m, counts, cells, par);
  counts = {};
  non_manifold_vertices(m, cells, par);
  drop_declared_edges(m, in);
  return m;
}

MeshInput to_input(const Mesh& mesh) {
  MeshInput in;
  in.source = mesh.source;
  in.points = mesh.points;
  in.faces = mesh.face_verts;
  in.cells.offsets = mesh.cell_faces.offsets;
  in.cells.items.resize(mesh.cell_faces.items.size());
  for (size_t i = 0; i < mesh.cell_faces.items.size(); ++i)
    in.cells.items[i] = 2 * mesh.cell_faces.items[i] + mesh.cell_face_flip[i];
  return in;
}

MeshInput renumbered(const Mesh& mesh, const std::vector<int32_t>& vperm,
                     const std::vector<int32_t>& cperm) {
  MeshInput in;
  in.source = mesh.source;
  const size_t nv = mesh.num_vertices(), nc = mesh.num_cells();
  in.points.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) in.points[3 * vperm[v] + k] = mesh.points[3 * v + k];
  in.faces.offsets = mesh.face_verts.offsets;
  in.faces.items.resize(mesh.face_verts.items.size());
  for (size_t i = 0; i < mesh.face_verts.items.size(); ++i)
    in.faces.items[i] = vperm[mesh.face_verts.items[i]];
  std::vector<int32_t> inv(nc);
  for (size_t c = 0; c < nc; ++c) inv[cperm[c]] = static_cast<int32_t>(c);
  for (size_t nc_i = 0; nc_i < nc; ++nc_i) {
    const size_t c = static_cast<size_t>(inv[nc_i]);
    for (int32_t i = mesh.cell_faces.offsets[c]; i < mesh.cell_faces.offsets[c + 1]; ++i)
      in.cells.items.push_back(2 * mesh.cell_faces.items[i] + mesh.cell_face_flip[i]);
    in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
  }
  return in;
}

}  // namespace hbc
