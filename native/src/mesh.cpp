#include "hbc/mesh.hpp"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "hbc/mesh_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

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

namespace mesh_steps {

std::string loop_text(std::span<const int32_t> loop) {
  std::ostringstream s;
  s << "(";
  for (size_t i = 0; i < loop.size(); ++i) s << (i ? " " : "") << loop[i];
  s << ")";
  return s.str();
}

// Checks what a reader handed over: counts, index ranges, finite coordinates, proper polygons.
void validate_input(const MeshInput& in) {
  const std::string& file = in.source;
  if (in.points.size() % 3 != 0) throw InputError(file, {}, "3 coordinates per vertex");
  const size_t nv = in.points.size() / 3;
  if (nv > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.faces.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
      in.cells.items.size() > static_cast<size_t>(std::numeric_limits<int32_t>::max()))
    throw InputError(file, {}, "fewer than 2^31 vertices, face corners and cell faces");
  for (size_t i = 0; i < in.points.size(); ++i)
    if (!std::isfinite(in.points[i]))
      throw InputError(file, in.loc_of(in.vertex_loc, i / 3),
                       "a finite coordinate for vertex " + std::to_string(i / 3));
  std::vector<int32_t> stamp(nv, -1);
  for (size_t f = 0; f < in.faces.rows(); ++f) {
    auto loop = in.faces[f];
    if (loop.size() < 3)
      throw InputError(file, in.loc_of(in.face_loc, f),
                       "a face with at least 3 vertices, face " + std::to_string(f) + " has " +
                           std::to_string(loop.size()));
    for (int32_t v : loop) {
      if (v < 0 || static_cast<size_t>(v) >= nv)
        throw InputError(file, in.loc_of(in.face_loc, f),
                         "vertex index in [0, " + std::to_string(nv) + ") in face " +
                             std::to_string(f) + ", found " + std::to_string(v));
      if (stamp[v] == static_cast<int32_t>(f))
        throw InputError(file, in.loc_of(in.face_loc, f),
                         "distinct vertices in face " + std::to_string(f) + ", vertex " +
                             std::to_string(v) + " repeats in " + loop_text(loop));
      stamp[v] = static_cast<int32_t>(f);
    }
  }
  const size_t nf = in.faces.rows();
  for (size_t c = 0; c < in.cells.rows(); ++c) {
    if (in.cells.count(c) < 2)
      throw InputError(file, in.loc_of(in.cell_loc, c),
                       "a cell with at least 2 faces, cell " + std::to_string(c) + " has " +
                           std::to_string(in.cells.count(c)));
    for (int32_t r : in.cells[c]) {
      int32_t f = r >> 1;
      if (r < 0 || static_cast<size_t>(f) >= nf)
        throw InputError(file, in.loc_of(in.cell_loc, c),
                         "face index in [0, " + std::to_string(nf) + ") in cell " +
                             std::to_string(c) + ", found " + std::to_string(r < 0 ? r : f));
    }
  }
}

}  // namespace mesh_steps

int resolve_threads(const LoadOptions& options) {
  if (options.threads > 0) return options.threads;
  if (const char* env = std::getenv("HBC_THREADS")) {
    int n = 0;
    const char* end = env + std::strlen(env);
    if (std::from_chars(env, end, n).ptr == end && n > 0) return n;
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

LoadOptions resolved(const LoadOptions& options) {
  LoadOptions r = options;
  r.threads = resolve_threads(options);
  r.grain = std::max(1, options.grain);
  return r;
}

Mesh build_mesh(MeshInput in, const LoadOptions& options) {
  using namespace mesh_steps;
  const LoadOptions par = resolved(options);
  validate_input(in);
  std::vector<int64_t>().swap(in.vertex_loc);  // only validate_input names vertices
  Mesh m;
  m.source = in.source;
  m.points = std::move(in.points);
  m.warnings = std::move(in.warnings);  // what the reader skipped (lower-dimensional elements, ...)
  merge_faces(in, m, par);
  {
    // The slot tables are the largest temporaries: gone before the vertex incidences are built.
    const std::vector<int32_t> slot_face = slot_faces(m, par);
    build_edges(m, slot_face, par);
    const std::vector<int32_t> partner = cell_incidences(m, in, par);
    orient_cells(m, partner, slot_face, par);
    mark_boundary(m);
    edge_fans(m, partner, slot_face, par);
  }
  vertex_incidences(m, in, par);
  cell_types(m, par);
  non_manifold_vertices(m, par);
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
