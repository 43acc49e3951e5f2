#pragma once
// The hybrid base complex G_B (paper §3.3; docs/concepts.md): separation faces traced from the hybrid
// singularity graph, the components they cut the volume into, and the patches, curves and
// corners that bound the components.
#include <array>
#include <cstdint>
#include <vector>

#include "hbc/csr.hpp"
#include "hbc/mesh.hpp"
#include "hbc/singularity_graph.hpp"

namespace hbc {

enum class ComponentKind : uint8_t {
  Cube = 0,    // hex cells; 6 quad patches, 12 curves, 8 corners (counted in H_B)
  Ring = 1,    // hex cells; cut by a separation face with itself on both sides, or torus-like
               // (boundary surface of Euler characteristic 0)
  Other = 2,   // hex cells; any other shape
  NonHex = 3,  // a single non-hex cell
};
const char* component_kind_name(ComponentKind k);

struct BaseComplex {
  std::vector<uint8_t> face_separation;  // nf
  std::vector<uint8_t> edge_complex;     // ne: every incident face is a separation face
  std::vector<uint8_t> vert_corner;      // nv: every incident edge is complex

  // Components C_B: numbered by their lowest cell.
  std::vector<int32_t> cell_component;   // nc
  Csr<int32_t> component_cells;          // ncomp rows, sorted cell ids
  std::vector<ComponentKind> component_kind;
  Csr<int32_t> component_adjacency;      // ncomp rows: components sharing a separation face, sorted

  // Patches F_B: separation faces joined across non-complex edges; numbered by their lowest face.
  std::vector<int32_t> face_patch;       // nf: patch of a separation face, else -1
  Csr<int32_t> patch_faces;              // npatch rows, sorted face ids
  std::vector<std::array<int32_t, 2>> patch_components;  // components on its two sides (-1: boundary)
  Csr<int32_t> patch_corners;            // npatch rows: corners on the patch, sorted
  Csr<int32_t> patch_curves;             // npatch rows: curves bounding the patch, sorted

  // Curves E_B: complex edges chained through vertices that are not corners.
  std::vector<int32_t> edge_curve;       // ne: curve of a complex edge, else -1
  Csr<int32_t> curve_verts;              // ncurve rows, ordered (a closed curve does not repeat)
  Csr<int32_t> curve_edges;              // ncurve rows, ordered
  std::vector<uint8_t> curve_closed;
  std::vector<int32_t> corners;          // V_B: sorted vertex ids

  // Per component: its patches, curves and corners (sorted ids).
  Csr<int32_t> component_patches, component_curves, component_corners;

  // Interior separation faces with the same component on both sides (a ring cut or a dangling
  // surface): counted and reported, never hidden.
  std::vector<int32_t> self_adjacent_faces;

  size_t num_components() const { return component_kind.size(); }
  size_t num_hex_components() const;   // Cube components: |H_B|
  size_t num_non_hex_components() const;
  size_t num_patches() const { return patch_faces.rows(); }
  size_t num_curves() const { return curve_edges.rows(); }

  // Every member compared, so that a member added later cannot escape the thread-count tests.
  bool operator==(const BaseComplex&) const = default;
};

// `threads`: see threads.hpp; the result is the same for any thread count.
BaseComplex base_complex(const Mesh& mesh, const SingularityGraph& graph, const Threads& threads = {});

// The straight continuation of face f across edge e: the face around e sharing no cell with f,
// defined when e's fan is manifold, all-hex and regular (4 faces inside, 3 on the boundary).
// Returns -1 otherwise. `scratch` holds the fan where it has to be walked.
int32_t straight_face(const Mesh& mesh, int32_t e, int32_t f, EdgeFan& scratch);

}  // namespace hbc
