#include "hbc/region.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "hbc/cell_complex.hpp"

namespace hbc {

const SheetStage& require_sheet(const Analysis& a, int32_t sheet) {
  if (!a.sheet_stage) throw std::invalid_argument("the analysis was run without sheets");
  const size_t n = a.sheet_stage->sheets.size();
  if (sheet < 0 || static_cast<size_t>(sheet) >= n)
    throw std::invalid_argument("sheet " + std::to_string(sheet) + " out of range: the mesh has " + std::to_string(n) +
                                " sheets");
  return *a.sheet_stage;
}

const Subsheets& require_subsheets(const Analysis& a, int32_t sheet) {
  const SheetStage& st = require_sheet(a, sheet);
  if (!st.subsheets) throw std::invalid_argument("the analysis was run without subsheets");
  const Subsheets* sub = st.subsheets_of(sheet);
  if (!sub) throw std::invalid_argument("sheet " + std::to_string(sheet) + " is not self-intersecting");
  return *sub;
}

std::vector<int32_t> region_cells(const Mesh& m, const Analysis& a, std::optional<int32_t> sheet,
                                  std::optional<int32_t> subsheet) {
  std::vector<int32_t> cells;
  if (!sheet) {
    if (subsheet) throw std::invalid_argument("a subsheet needs its sheet");
    cells.resize(m.num_cells());
    for (size_t c = 0; c < cells.size(); ++c) cells[c] = static_cast<int32_t>(c);
    return cells;
  }
  const SheetStage& st = require_sheet(a, *sheet);
  const size_t s = static_cast<size_t>(*sheet);
  if (!subsheet) {
    for (auto row : {st.sheets.sheet_cells[s], st.sheets.sheet_non_hex_cells[s]}) cells.insert(cells.end(), row.begin(), row.end());
  } else {
    const Subsheets& sub = require_subsheets(a, *sheet);
    if (*subsheet < 0 || static_cast<size_t>(*subsheet) >= sub.size())
      throw std::invalid_argument("subsheet " + std::to_string(*subsheet) + " out of range: sheet " +
                                  std::to_string(*sheet) + " has " + std::to_string(sub.size()) + " subsheets");
    const auto own = sub.cells[static_cast<size_t>(*subsheet)];
    cells.assign(own.begin(), own.end());
    // A sheet's adjacent non-hex cells are those touching its curves; the same rule for a subsheet.
    for (int32_t k : sub.curves[static_cast<size_t>(*subsheet)]) {
      const auto nh = st.domain.curve_non_hex_cells[static_cast<size_t>(k)];
      cells.insert(cells.end(), nh.begin(), nh.end());
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

namespace {

// The sheet's (or subsheet's) parallel edges as complex edge ids of `cx`: the authors remove, last,
// the simplified chains made of them only, so the wireframe of a sheet shows what crosses it.
std::vector<int32_t> region_parallel_edges(const Analysis& a, const CellComplex& cx, int32_t sheet,
                                           std::optional<int32_t> subsheet) {
  const SheetStage& st = require_sheet(a, sheet);
  std::vector<int32_t> mesh_edges;
  if (!subsheet) {
    const auto row = st.sheets.sheet_edges[static_cast<size_t>(sheet)];
    mesh_edges.assign(row.begin(), row.end());
  } else {
    for (int32_t k : require_subsheets(a, sheet).curves[static_cast<size_t>(*subsheet)])
      for (int32_t e : st.domain.curve_edges[static_cast<size_t>(k)]) mesh_edges.push_back(e);
  }
  return complex_edges_of(cx, a.complex, mesh_edges);
}

}  // namespace

WireframeStage region_wireframe_stage(const Mesh& m, const Analysis& a, Level level, const WireframeOptions& options,
                                      std::optional<int32_t> sheet, std::optional<int32_t> subsheet) {
  WireframeStage st;
  if (!sheet && !subsheet) {
    st.view = level == Level::Complex ? complex_from_base(m, a.complex) : complex_from_mesh(m);
    st.wireframe = vsg_wireframe(st.view, options);
    return st;
  }
  const std::vector<int32_t> cells = region_cells(m, a, sheet, subsheet);  // checks the ids
  st.view = level == Level::Complex ? complex_from_base(m, a.complex, components_of_cells(a.complex, cells))
                                    : complex_from_mesh(m, cells);
  WireframeOptions opt = options;
  opt.parallel_edges = region_parallel_edges(a, st.view, *sheet, subsheet);
  st.wireframe = vsg_wireframe(st.view, opt);
  return st;
}

VsgWireframe region_wireframe(const Mesh& m, const Analysis& a, Level level, const WireframeOptions& options,
                              std::optional<int32_t> sheet, std::optional<int32_t> subsheet) {
  return region_wireframe_stage(m, a, level, options, sheet, subsheet).wireframe;
}

}  // namespace hbc
