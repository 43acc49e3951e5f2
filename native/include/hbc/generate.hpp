#pragma once
// Synthetic meshes with structure known by construction, for tests, benchmarks and figures.
// Every generator returns a MeshInput (faces listed once, each cell's loops outward by the right-hand
// rule once its flip is applied, as MEDIT's templates are) that build_mesh accepts, and is
// deterministic: the same arguments give identical arrays on every platform.
// Invalid arguments (sizes < 1, too many elements for 32-bit ids, ...) throw std::invalid_argument.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hbc/mesh.hpp"

namespace hbc {

// n×m×k unit hexes (edge length `spacing`) filling [0,n]×[0,m]×[0,k]·spacing.
// Vertex (i,j,l) has id i + (n+1)(j + (m+1) l); cell (i,j,l) has id i + n(j + m l).
// Counts: V = (n+1)(m+1)(k+1), C = nmk, F = (n+1)mk + n(m+1)k + nm(k+1),
// E = n(m+1)(k+1) + (n+1)m(k+1) + (n+1)(m+1)k, boundary faces 2(mk + nk + nm).
MeshInput generate_grid(int n, int m, int k, double spacing = 1.0);

enum class SplitKind {
  Pyramids,  // the hex becomes 6 pyramids around an added centre vertex; its quads stay
  Prisms,    // the whole column of cells along `axis` through the chosen cell becomes prism pairs
  Tets,      // the hex becomes 6 tets (Kuhn split along its min-max diagonal); each hex across one
             // of its quads sees two triangles there and becomes a polyhedron (7 faces for one)
};

// A grid as generate_grid whose chosen cells (grid coordinates, each in range; repeats are ignored)
// are split into non-hex cells, keeping the mesh conforming. Prism columns run along `axis`
// (0 = x, 1 = y, 2 = z); the diagonal plane of every prism pair goes through the cell's corner of
// lowest coordinates and the opposite edge along `axis`. Tets and the triangles of their
// neighbours split each quad along the diagonal through its lowest vertex id, so that adjacent
// split cells agree. Cells are numbered in grid order, each cell's pieces consecutively.
MeshInput generate_split(int n, int m, int k, SplitKind kind,
                         std::span<const std::array<int32_t, 3>> cells, int axis = 2,
                         double spacing = 1.0);

// `count` distinct grid cells of an n×m×k grid chosen with std::mt19937(seed): a partial
// Fisher–Yates shuffle of the cell ids 0..nmk-1 where step t swaps slot t with slot
// t + (draw mod (nmk - t)), draw being the generator's raw 32-bit output (fully specified by the
// standard, unlike std::uniform_int_distribution). Returned in the order drawn.
std::vector<std::array<int32_t, 3>> random_cells(int n, int m, int k, int count, uint32_t seed);

// One interior singular edge chain of valence `valence` (>= 3) along the z axis: the cross-section
// is `valence` parallelograms around the origin (sector s spanned by the unit vectors at angles
// 2πs/valence and 2π(s+1)/valence), each cut into rings×rings quads, extruded `layers` layers of
// height 1/rings. valence 4 gives a (2 rings)×(2 rings)×layers grid.
// Counts (N = valence, R = rings, L = layers), cross-section V2 = 1 + NR + NR², Q2 = NR²,
// E2 = NR + 2NR²: V = V2(L+1), C = Q2 L, E = E2(L+1) + V2 L, F = Q2(L+1) + E2 L,
// boundary faces 2Q2 + 2NRL. The L edges along the axis have valence N.
MeshInput generate_sector(int valence, int rings, int layers);

// A cylinder of radius about `radius_cells` cells and height `layers` (unit cells), hex-dominant:
// the disk cross-section is an O-grid, a 2a×2a quad core (a = ceil(radius_cells / 2)) surrounded
// by rings = radius_cells - a rings that step evenly, along every direction, from the core's
// square (half-size a) to the circle of radius a + rings. A ring with more vertices than the one
// inside it is stitched with evenly spaced triangles, which extrude to columns of triangular
// prisms. Ring r (1-based, t = r / rings) has max(previous, 4·round(P / 4)) vertices at equal
// angles from angle 0, P = (1 - t)·8a + t·2π(a + rings) being the blended perimeter.
// Example radius_cells 2: core 2×2 (9 vertices, boundary 8), one circular ring of radius 2 with
// 12 vertices: 12 quads + 4 triangles per layer.
MeshInput generate_cylinder(int radius_cells, int layers);

// A ring of `sections` layers (>= 3) round the z axis whose square cross-section, `section` ×
// `section` unit cells, turns by quarter_turns × 90° (0..3) on the way round, so the ring closes
// on itself turned: sheets along the ring come back as other layers of the section, which makes
// them self-parallel (a half turn brings layer i back as layer section-1-i) or self-intersecting
// (a quarter turn brings a layer of one direction back as one of the other). With `prisms` quads
// of the section become fans of 4 triangles, columns of prisms round the ring that the sheets
// through them cross: the middle quad (odd `section`, unless `spread`), else the quad at (1, 1)
// and the quads it turns into on the way round (so the ring still closes on itself).
MeshInput generate_twisted_ring(int section, int sections, int quarter_turns, bool prisms, bool spread = false);

// Two concentric twisted rings of one `section` × `section` section (even, >= 2) in `sections`
// layers each, the inner one where generate_twisted_ring puts a ring, the outer one round it (its
// circle 2 sections further out). In each ring one hex of the first layer, the boundary quad left of the section's
// middle line, is split into 6 pyramids around its centre (its quads stay). Its faces start
// separation surfaces that run round the ring turning with the section: the base complex is cut
// into that layer and the rest of the ring, and across the section along the lines of the split
// quad and the lines they turn into. The outer ring turns a quarter turn: each sheet through the
// section comes back as one of the other direction and crosses itself (self-intersecting), and
// those through the split quad's row and column have its edges for parallel curves, so their
// regions hold the pyramids, at which their VSG chains round the ring end. The inner ring turns a
// half turn: the column of blocks left of the middle line comes back as the column right of it, so
// that sheet's parallel curves meet end to end across the line (self-parallel) and never cross.
// Section 4: 2 self-intersecting sheets, 1 self-parallel sheet and 7 perfect ones
// (tests/cpp/test_generate.cpp derives them).
MeshInput generate_twisted_pair(int section, int sections);

}  // namespace hbc
