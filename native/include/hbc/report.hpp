#pragma once
// What hbc writes about a mesh and its analysis as text, one writer each for every front end (the
// CLI, the Python binding, the WebAssembly binding): the mesh's counts (`hbc info --json`), the
// Table 1 statistics as JSON, CSV and a human-readable table from the schema (hbc/schema.hpp),
// what --skip-invalid dropped, and the CSV field rules the other tables (hbc metrics, hbc compare)
// share.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/check.hpp"
#include "hbc/json.hpp"
#include "hbc/mesh.hpp"

namespace hbc {

// The counts `hbc info` prints (keys in docs/concepts.md, "The mesh").
struct MeshCounts {
  std::array<int64_t, 5> cell_types{};  // by CellType: hex, tet, prism, pyramid, polyhedron
  int64_t boundary_faces = 0;
  int64_t non_manifold_vertices = 0;
  double hex_ratio = 0.0;  // hexahedra / cells; 0 without cells
};
MeshCounts mesh_counts(const Mesh& m);
// `hbc info --json`'s object: {"file", "vertices", "edges", "faces", "cells", "hex_cells",
// "hex_ratio", "cell_types": {name: n}, "boundary_faces", "non_manifold_vertices",
// "dropped_faces", "dropped_edges"}; `file` is the name the mesh was read from, as given.
Json mesh_info_json(const Mesh& m, const std::string& file);

// Adds the stats keys (and "timings") to a JSON object.
void add_stats_json(Json& j, const Stats& s);
// j["dropped"]: what --skip-invalid dropped, {"count", "by_reason": {key: n}, "cells": [{"id",
// "reason", "line" or "byte"}]} (docs/check.md); nothing when `skip` is false.
void add_dropped_json(Json& j, bool skip, const std::vector<DroppedCell>& dropped);
std::string stats_csv_header();
std::string stats_csv_row(const std::string& name, const Stats& s);
std::string stats_table(const std::string& name, const Stats& s);

// A metric's value as CSV and text print it: "%.10g"; empty when it is not finite (not measured).
std::string number_text(double v);
// A CSV field (RFC 4180): quoted, with its quotes doubled, when it holds a comma, a quote, CR or LF.
std::string csv_quoted(const std::string& s);

}  // namespace hbc
