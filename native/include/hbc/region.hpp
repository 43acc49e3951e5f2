#pragma once
// The region of a sheet (paper §6): the sheet's cells plus the non-hex cells adjacent to it, on
// which the viewer and `hbc wireframe --sheet` compute a sheet's own VSG wireframe. Part of the
// analysis: a region is a function of an Analysis and a sheet (or subsheet) id.
#include <cstdint>
#include <optional>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/level.hpp"
#include "hbc/vsg_wireframe.hpp"

namespace hbc {

// The sheet stage of the analysis, checked to hold sheet `sheet`; throws std::invalid_argument when
// the analysis has no sheets or the id is out of range.
const SheetStage& require_sheet(const Analysis& analysis, int32_t sheet);
// The subsheets of `sheet`; throws std::invalid_argument as require_sheet, when the analysis has
// no subsheets, or when the sheet is not self-intersecting.
const Subsheets& require_subsheets(const Analysis& analysis, int32_t sheet);

// The mesh cells of a region, sorted: the whole mesh's cells without a sheet; else the cells of
// that sheet (without a subsheet) or of that subsheet of the sheet, plus the non-hex cells
// adjacent to it (touching one of its curves). Throws std::invalid_argument for ids out of range,
// a subsheet without its sheet, or a subsheet of a sheet without a decomposition.
std::vector<int32_t> region_cells(const Mesh& mesh, const Analysis& analysis, std::optional<int32_t> sheet,
                                  std::optional<int32_t> subsheet = std::nullopt);

// The VSG wireframe of that region (the whole mesh without a sheet) at `level`, with the view it
// was computed on (which wireframe_style reads).
WireframeStage region_wireframe_stage(const Mesh& mesh, const Analysis& analysis, Level level,
                                      const WireframeOptions& options, std::optional<int32_t> sheet,
                                      std::optional<int32_t> subsheet = std::nullopt);
// The same without the view.
VsgWireframe region_wireframe(const Mesh& mesh, const Analysis& analysis, Level level, const WireframeOptions& options,
                              std::optional<int32_t> sheet, std::optional<int32_t> subsheet = std::nullopt);

}  // namespace hbc
