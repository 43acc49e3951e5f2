// Property tests: hundreds of generated meshes (grids, grids with random cells split into
// pyramids / prisms / tets, sectors, cylinders), each analyzed as generated and randomly
// renumbered. Every structural invariant is checked on both, and the renumbered analysis must equal the
// original one up to the renumbering. Seeded std::mt19937 throughout: every run sees the same
// meshes, and a failure names the case so it can be rebuilt alone.
#include <algorithm>
#include <numeric>
#include <random>
#include <sstream>

#include "hbc/analysis.hpp"
#include "hbc/generate.hpp"
#include "hbc/wireframe_style.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

struct Case {
  std::string name;
  MeshInput input;
};

int uniform(std::mt19937& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

Case random_split(std::mt19937& rng) {
  const int n = uniform(rng, 1, 6), m = uniform(rng, 1, 6), k = uniform(rng, 1, 6);
  const auto kind = static_cast<SplitKind>(uniform(rng, 0, 2));
  const int axis = uniform(rng, 0, 2);
  const int count = uniform(rng, 1, std::min(8, n * m * k));
  const auto seed = static_cast<uint32_t>(rng());
  const auto cells = random_cells(n, m, k, count, seed);
  std::ostringstream name;
  name << "split " << n << "x" << m << "x" << k << " kind " << static_cast<int>(kind) << " axis " << axis
       << " random " << count << " seed " << seed;
  return {name.str(), generate_split(n, m, k, kind, cells, axis)};
}

// ve = vertex_edges(m).
bool is_mesh_edge(const Mesh& m, const Csr<int32_t>& ve, int32_t a, int32_t b) {
  for (int32_t e : ve[static_cast<size_t>(a)])
    if (m.other_vertex(e, a) == b) return true;
  return false;
}

// The structural invariants (docs/concepts.md) on one analyzed mesh.
void expect_invariants(const Mesh& m, const Analysis& a, const AnalysisOptions& opt) {
  const SingularityGraph& g = a.graph;
  const BaseComplex& bc = a.complex;
  const size_t nc = m.num_cells();

  // Every cell in exactly one component; non-hex cells alone in theirs, hex cells never in a
  // non-hex one.
  ASSERT_EQ(bc.cell_component.size(), nc);
  std::vector<int32_t> seen(nc, 0);
  for (size_t k = 0; k < bc.num_components(); ++k)
    for (int32_t c : bc.component_cells[k]) {
      ++seen[c];
      EXPECT_EQ(bc.cell_component[c], static_cast<int32_t>(k));
      EXPECT_EQ(m.is_hex(c), bc.component_kind[k] != ComponentKind::NonHex) << "cell " << c;
    }
  for (size_t c = 0; c < nc; ++c) {
    EXPECT_EQ(seen[c], 1) << "cell " << c;
    if (!m.is_hex(c)) {
      EXPECT_EQ(bc.component_cells.count(bc.cell_component[c]), 1) << "non-hex cell " << c;
      for (int32_t f : m.cell_faces[c]) EXPECT_TRUE(bc.face_separation[f]) << "face " << f << " of non-hex cell " << c;
    }
  }
  // Boundary faces separate; a non-separation face joins one component; an interior separation
  // face with one component on both sides is reported, never hidden.
  size_t self_adjacent = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const auto [c0, c1] = m.face_cells[f];
    if (c1 < 0) {
      EXPECT_TRUE(bc.face_separation[f]) << "boundary face " << f;
      continue;
    }
    const bool same = bc.cell_component[c0] == bc.cell_component[c1];
    if (!bc.face_separation[f]) {
      EXPECT_TRUE(same) << "face " << f;
    } else if (same) {
      ++self_adjacent;
    }
  }
  EXPECT_EQ(self_adjacent, bc.self_adjacent_faces.size());

  // Edge classes: singular = irregular and all-hex; pseudo-singular = touching a non-hex cell.
  size_t singular = 0;
  for (size_t e = 0; e < m.num_edges(); ++e) {
    bool all_hex = true;
    for (int32_t c : test::fan_of(m, e).cells) all_hex = all_hex && m.is_hex(c);
    const EdgeClass k = g.edge_class[e];
    if (k == EdgeClass::Singular) {
      ++singular;
      EXPECT_TRUE(g.edge_irregular[e] && all_hex) << "singular edge " << e;
      EXPECT_GE(g.edge_chain[e], 0) << "singular edge " << e;
    }
    EXPECT_EQ(k == EdgeClass::PseudoSingular, !all_hex) << "edge " << e;
    if (all_hex && g.edge_irregular[e]) {
      EXPECT_EQ(k, EdgeClass::Singular) << "edge " << e;
    }
  }
  EXPECT_EQ(singular, g.num_singular_edges());

  // Sheets: a perfect sheet shares no curve end and leaves no vertex unmatched; no subsheet is
  // self-intersecting.
  ASSERT_TRUE(a.sheet_stage.has_value());
  for (size_t s = 0; s < a.sheet_stage->sheets.size(); ++s) {
    const SheetClass& k = a.sheet_stage->sheets.classes[s];
    if (k.type == SheetType::Perfect) {
      EXPECT_TRUE(k.shared_vertices.empty()) << "perfect sheet " << s;
      EXPECT_TRUE(k.unmatched_vertices.empty()) << "perfect sheet " << s;
    } else {
      EXPECT_FALSE(k.shared_vertices.empty()) << "imperfect sheet " << s;
    }
  }
  for (const Subsheets& sub : *a.sheet_stage->subsheets)
    for (size_t i = 0; i < sub.size(); ++i)
      EXPECT_NE(sub.classes[i].type, SheetType::Type3) << "subsheet " << i << " of sheet " << sub.sheet;

  // Wireframe: polylines follow mesh edges, opacities in [floor, 1].
  ASSERT_TRUE(a.wireframe_stage.has_value());
  const VsgWireframe& w = a.wireframe_stage->wireframe;
  const Csr<int32_t> ve = vertex_edges(m);
  for (size_t i = 0; i < w.size(); ++i) {
    const auto p = w.polylines[i];
    EXPECT_GE(p.size(), 2u) << "wire edge " << i;
    for (size_t j = 1; j < p.size(); ++j)
      EXPECT_TRUE(is_mesh_edge(m, ve, p[j - 1], p[j])) << "wire edge " << i << " step " << j;
  }
  const WireframeStyle style = wireframe_style(a.wireframe_stage->view, w);
  ASSERT_EQ(style.point_opacity.size(), w.polylines.items.size());
  const float floor = static_cast<float>(WireframeStyleOptions{}.opacity_floor);
  for (float o : style.point_opacity) {
    EXPECT_GE(o, floor - 1e-6f);
    EXPECT_LE(o, 1.0f + 1e-6f);
  }
}

int64_t unmatched_total(const Analysis& a) {
  int64_t n = 0;
  for (const SheetClass& k : a.sheet_stage->sheets.classes) n += static_cast<int64_t>(k.unmatched_vertices.size());
  return n;
}

// Checks one case: invariants on the mesh and on a random renumbering of it, and that both
// analyses agree. Returns false after the first failing case so the log stays readable.
bool check_case(const Case& cs, std::mt19937& rng, const AnalysisOptions& opt) {
  SCOPED_TRACE(cs.name);
  const Mesh m = build_mesh(cs.input);
  const Analysis a = analyze(m, opt);
  expect_invariants(m, a, opt);

  const test::Renumbering rn = test::random_renumbering(m, rng);
  const Mesh& r = rn.mesh;
  const std::vector<int32_t>& cperm = rn.cell;
  const Analysis b = analyze(r, opt);
  {
    SCOPED_TRACE("renumbered");
    expect_invariants(r, b, opt);
  }
  test::expect_same_counts(compute_stats(m, a), compute_stats(r, b));
  EXPECT_EQ(unmatched_total(a), unmatched_total(b)) << "a maximum matching has one size";
  test::expect_same_partition(a.complex, b.complex, cperm);
  // The same sheets: each sheet's cells, mapped through cperm, are the cells of one sheet of r.
  auto sheet_sets = [](const Sheets& sh, const std::vector<int32_t>* perm) {
    std::vector<std::vector<int32_t>> sets;
    for (size_t s = 0; s < sh.size(); ++s) {
      std::vector<int32_t> cells;
      for (int32_t c : sh.sheet_cells[s]) cells.push_back(perm ? (*perm)[c] : c);
      std::sort(cells.begin(), cells.end());
      sets.push_back(std::move(cells));
    }
    std::sort(sets.begin(), sets.end());
    return sets;
  };
  EXPECT_TRUE(sheet_sets(a.sheet_stage->sheets, &cperm) == sheet_sets(b.sheet_stage->sheets, nullptr)) << "sheets differ";
  return !::testing::Test::HasFailure();
}

AnalysisOptions level_options(bool mesh_level) {
  AnalysisOptions o;
  if (mesh_level) {
    o.sheet_level = Level::Mesh;
    o.wireframe_level = Level::Mesh;
  }
  return o;
}

TEST(Properties, Grids) {
  std::mt19937 rng(20240501);
  int checked = 0;
  for (int i = 0; i < 100; ++i) {
    const int n = uniform(rng, 1, 6), m = uniform(rng, 1, 6), k = uniform(rng, 1, 6);
    Case cs{"grid " + std::to_string(n) + "x" + std::to_string(m) + "x" + std::to_string(k),
            generate_grid(n, m, k)};
    // A structured grid is one cube-like component whose three sheets are perfect.
    const Mesh mesh = build_mesh(cs.input);
    const Stats s = compute_stats(mesh, analyze(mesh));
    EXPECT_EQ(s.components, 1) << cs.name;
    EXPECT_EQ(s.hex_components, 1) << cs.name;
    EXPECT_EQ(s.sheets, 3) << cs.name;
    EXPECT_EQ(s.sheets_perfect, 3) << cs.name;
    if (!check_case(cs, rng, level_options(i % 4 == 3))) break;
    ++checked;
  }
  EXPECT_EQ(checked, 100);
}

TEST(Properties, SplitGrids) {
  std::mt19937 rng(7);
  int checked = 0;
  for (int i = 0; i < 500; ++i) {
    const Case cs = random_split(rng);
    if (!check_case(cs, rng, level_options(i % 4 == 3))) break;
    ++checked;
  }
  EXPECT_EQ(checked, 500);
}

TEST(Properties, Sectors) {
  std::mt19937 rng(11);
  int checked = 0;
  for (int valence = 3; valence <= 6; ++valence)
    for (int rings = 1; rings <= 3; ++rings)
      for (int layers = 1; layers <= 4; ++layers) {
        Case cs{"sector valence " + std::to_string(valence) + " rings " + std::to_string(rings) +
                    " layers " + std::to_string(layers),
                generate_sector(valence, rings, layers)};
        if (!check_case(cs, rng, level_options((rings + layers) % 2 == 0))) return;
        ++checked;
      }
  EXPECT_EQ(checked, 48);
}

TEST(Properties, Cylinders) {
  std::mt19937 rng(13);
  int checked = 0;
  for (int radius = 1; radius <= 6; ++radius)
    for (int layers = 1; layers <= 4; ++layers) {
      Case cs{"cylinder radius " + std::to_string(radius) + " layers " + std::to_string(layers),
              generate_cylinder(radius, layers)};
      if (!check_case(cs, rng, level_options(layers % 2 == 0))) return;
      ++checked;
    }
  EXPECT_EQ(checked, 24);
}

}  // namespace
}  // namespace hbc
