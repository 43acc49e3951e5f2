// Render-ready geometry for viewers: hbc.Wireframe (a VSG wireframe's arrays as views),
// hbc.block_soup() and hbc.polylines(). The geometry is made in C++ (render_geometry.hpp) with the
// GIL released and handed to numpy without a copy (the vectors move into capsules).
#include <string>
#include <type_traits>

#include "bindings.hpp"

namespace hbc::python {

namespace {

static_assert(sizeof(WireKind) == 1 && sizeof(TraceStop) == 1, "enums are exposed as uint8");

using IntArray = py::array_t<int32_t, py::array::c_style | py::array::forcecast>;

// A read-only view of a vector of the style (Get takes the WireframeStyle); the Wireframe object
// is the numpy base.
template <class Get>
void style_prop(py::class_<PyWireframe>& cls, const char* name, Get get) {
  cls.def_property_readonly(
      name, [get](py::object self) -> py::array {
        const auto& v = get(*self.cast<const PyWireframe&>().style);
        return view(v.data(), {ssize(v.size())}, self);
      }, array_doc(exported(cls, name)).c_str());
}

// A read-only view of a wireframe vector, one-byte ones as the table's dtype (uint8 or bool); the
// Wireframe object is the numpy base.
template <class Get>
void wire_prop(py::class_<PyWireframe>& cls, const char* name, Get get) {
  const ExportedArray& e = exported(cls, name);
  const bool as_bool = e.dtype == Dtype::Bool;
  cls.def_property_readonly(
      name,
      [get, as_bool](py::object self) -> py::array {
        const auto& v = get(*self.cast<const PyWireframe&>().w);
        using T = typename std::decay_t<decltype(v)>::value_type;
        if constexpr (sizeof(T) == 1) {
          const auto* d = reinterpret_cast<const uint8_t*>(v.data());
          return view(d, {ssize(v.size())}, self, as_bool ? py::dtype::of<bool>() : py::dtype::of<uint8_t>());
        } else {
          return view(v.data(), {ssize(v.size())}, self);
        }
      },
      array_doc(e).c_str());
}

void bind_wireframe(py::module_& m) {
  py::class_<PyWireframe> c(m, "Wireframe",
                            "A VSG wireframe (paper §5): the complete wireframe's polylines of mesh vertices with per-point "
                            "opacity and per-polyline kind, simplification flags and colours, and the simplified "
                            "wireframe's polylines. Arrays are views.");
  c.def_property_readonly("count", [](const PyWireframe& p) { return p.w->size(); }, "Number of polylines.");
  def_csr(c, "polylines", [](const PyWireframe& p) -> auto& { return p.w->polylines; });
  style_prop(c, "point_opacity", [](const WireframeStyle& s) -> auto& { return s.point_opacity; });
  wire_prop(c, "kind", [](const VsgWireframe& w) -> auto& { return w.kind; });
  wire_prop(c, "valence", [](const VsgWireframe& w) -> auto& { return w.valence; });
  wire_prop(c, "stop", [](const VsgWireframe& w) -> auto& { return w.stop; });
  wire_prop(c, "shown", [](const VsgWireframe& w) -> auto& { return w.shown; });
  wire_prop(c, "non_important", [](const VsgWireframe& w) -> auto& { return w.non_important; });
  wire_prop(c, "reactivated", [](const VsgWireframe& w) -> auto& { return w.reactivated; });
  def_csr(c, "simplified_polylines", [](const PyWireframe& p) -> auto& { return p.w->simplified_polylines; });
  style_prop(c, "color", [](const WireframeStyle& s) -> auto& { return s.color; });
  style_prop(c, "color_class", [](const WireframeStyle& s) -> auto& { return s.color_class; });
  def_csr(c, "non_hex", [](const PyWireframe& p) -> auto& { return p.w->non_hex; });
  def_csr(c, "simplified_non_hex", [](const PyWireframe& p) -> auto& { return p.w->simplified_non_hex; });
  c.def_property_readonly("rho", [](const PyWireframe& p) { return p.rho; },
                          "The ρ of this wireframe's colour classes (point_opacity, color, color_class).");
  c.def(
      "restyled",
      [](const PyWireframe& p, double rho) {
        return PyWireframe{p.w, p.view, style_of(*p.view, *p.w, rho), rho};
      },
      py::arg("rho"),
      "The same wireframe (shared, not computed again) styled at another rho: new point_opacity, "
      "color and color_class (GIL released; no analysis runs).");
  c.def_property_readonly(
      "counts",
      [](const PyWireframe& p) { return wireframe_counts(*p.w); },
      "dict: vsg_edges, wireframe_edges (complete wireframe polylines), wireframe_edges_simplified, vsg_chains, "
      "singular_vertices (of the wireframe, not the graph's), vsg_mesh_edges, wireframe_mesh_edges, "
      "wireframe_mesh_edges_simplified (distinct mesh edges covered), wireframe_components and "
      "wireframe_components_simplified (connected pieces of the complete and of the simplified wireframe; "
      "reference_components and shown_components, their deprecated keys, beside them).");
}

// block_soup's dict; each key is the table's (a BlockSoup entry of hbc/exports.hpp).
py::dict soup_dict(BlockSoup&& s) {
  const py::ssize_t np = ssize(s.num_points()), nf = ssize(s.num_faces());
  const py::ssize_t nfv = ssize(s.face_vertices.items.size());
  py::dict d;
  const auto key = [](const char* name) {
    exported("BlockSoup", name);
    return py::str(name);
  };
  d[key("positions")] = adopt(std::move(s.positions), {np, 3});
  d[key("face_vertices_offsets")] = adopt(std::move(s.face_vertices.offsets), {nf + 1});
  d[key("face_vertices_items")] = adopt(std::move(s.face_vertices.items), {nfv});
  d[key("face_owner")] = adopt(std::move(s.face_owner), {nf});
  d[key("face_source")] = adopt(std::move(s.face_source), {nf});
  d[key("face_cell")] = adopt(std::move(s.face_cell), {nf});
  d[key("point_vertex")] = adopt(std::move(s.point_vertex), {np});
  return d;
}

using MaskArray = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;

py::dict kept_surface(const PyMeshPtr& mesh, const MaskArray& kept, double shrink) {
  if (kept.ndim() != 1) throw std::invalid_argument("kept_surface_soup: kept must be 1-D");
  BlockSoup s;
  {
    py::gil_scoped_release unlocked;
    s = kept_surface_soup(mesh->mesh, {kept.data(), static_cast<size_t>(kept.size())}, shrink);
  }
  return soup_dict(std::move(s));
}

py::dict block_soup(const PyMeshPtr& mesh, const PyAnalysisPtr& analysis, const std::string& what,
                    const py::object& sheet_arg, double shrink) {
  const std::optional<int32_t> sheet = optional_id(sheet_arg, "sheet");
  const SoupKind kind = soup_kind_from_name(what);
  if (!analysis && soup_kind_needs_analysis(kind))
    throw std::invalid_argument("block_soup: '" + what + "' needs an analysis (only 'cells', 'non_hex', 'hex' and "
                                "'boundary' take analysis=None)");
  if (analysis && analysis->mesh.get() != mesh.get())
    throw std::invalid_argument("block_soup: the analysis was computed on another mesh");
  BlockSoup s;
  {
    py::gil_scoped_release unlocked;
    // The mesh-only kinds never read the analysis: an empty one stands in for None.
    s = analysis ? hbc::block_soup(mesh->mesh, analysis->analysis, kind, sheet, shrink)
                 : hbc::block_soup(mesh->mesh, Analysis{}, kind, sheet, shrink);
  }
  return soup_dict(std::move(s));
}

py::array polylines(const PyMeshPtr& mesh, const IntArray& offsets, const IntArray& items) {
  if (offsets.ndim() != 1 || items.ndim() != 1) throw std::invalid_argument("polylines: offsets and items must be 1-D");
  std::vector<float> pos;
  {
    py::gil_scoped_release unlocked;
    pos = polyline_positions(mesh->mesh, {offsets.data(), static_cast<size_t>(offsets.size())},
                             {items.data(), static_cast<size_t>(items.size())});
  }
  const py::ssize_t n = ssize(pos.size() / 3);
  return adopt(std::move(pos), {n, 3});
}

// The distinct undirected edges of a polygon set and the edge of every corner (corner k to the
// next corner of its face), which is what Blender keeps for a mesh with faces: handed over ready-made,
// the add-on skips Blender's own edge search (1.8 s of the 4 M faces of a 10^6-cell mesh's Blocks
// layer in Blender 3.4). Edges are grouped by their lower point, each row in order of first use, so
// the result depends on the input only. O(corners): a counting sort by lower point, then each
// point's few edges deduplicated by a scan of its row.
py::dict polygon_edges(const IntArray& offsets, const IntArray& items, int64_t num_points) {
  if (offsets.ndim() != 1 || items.ndim() != 1) throw std::invalid_argument("polygon_edges: offsets and items must be 1-D");
  const size_t nf = offsets.size() > 0 ? static_cast<size_t>(offsets.size()) - 1 : 0, nl = static_cast<size_t>(items.size());
  const int32_t* off = offsets.data();
  const int32_t* it = items.data();
  if (num_points < 0 || (offsets.size() > 0 && (off[0] != 0 || static_cast<size_t>(off[nf]) != nl)))
    throw std::invalid_argument("polygon_edges: offsets must start at 0 and end at len(items)");
  std::vector<int32_t> edges, corner_edge(nl);
  {
    py::gil_scoped_release unlocked;
    const size_t np = static_cast<size_t>(num_points);
    std::vector<int32_t> row(np + 1, 0), other(nl), corner(nl);
    auto ends = [&](size_t f, size_t k) {  // (lower, higher) point of the edge from corner k of face f
      const size_t next = k + 1 < static_cast<size_t>(off[f + 1]) ? k + 1 : static_cast<size_t>(off[f]);
      const int32_t a = it[k], b = it[next];
      if (a < 0 || b < 0 || static_cast<size_t>(a) >= np || static_cast<size_t>(b) >= np || off[f + 1] < off[f])
        throw std::invalid_argument("polygon_edges: point id out of range or offsets decreasing");
      return std::pair{std::min(a, b), std::max(a, b)};
    };
    for (size_t f = 0; f < nf; ++f)
      for (size_t k = static_cast<size_t>(off[f]); k < static_cast<size_t>(off[f + 1]); ++k) ++row[static_cast<size_t>(ends(f, k).first) + 1];
    for (size_t p = 0; p < np; ++p) row[p + 1] += row[p];
    std::vector<int32_t> fill(row.begin(), row.end() - 1);
    for (size_t f = 0; f < nf; ++f)
      for (size_t k = static_cast<size_t>(off[f]); k < static_cast<size_t>(off[f + 1]); ++k) {
        const auto [lo, hi] = ends(f, k);
        const auto slot = static_cast<size_t>(fill[static_cast<size_t>(lo)]++);
        other[slot] = hi;
        corner[slot] = static_cast<int32_t>(k);
      }
    edges.reserve(nl);  // at most one edge per corner; a closed quad surface has half as many
    for (size_t p = 0; p < np; ++p) {
      const size_t first_edge = edges.size() / 2;
      for (auto j = static_cast<size_t>(row[p]); j < static_cast<size_t>(row[p + 1]); ++j) {
        size_t e = first_edge;
        while (e < edges.size() / 2 && edges[2 * e + 1] != other[j]) ++e;
        if (e == edges.size() / 2) {
          edges.push_back(static_cast<int32_t>(p));
          edges.push_back(other[j]);
        }
        corner_edge[static_cast<size_t>(corner[j])] = static_cast<int32_t>(e);
      }
    }
    edges.shrink_to_fit();
  }
  py::dict d;
  const py::ssize_t ne = ssize(edges.size() / 2);
  d["edges"] = adopt(std::move(edges), {ne, 2});
  d["corner_edge"] = adopt(std::move(corner_edge), {ssize(nl)});
  return d;
}

py::array cell_centroid_array(const PyMeshPtr& mesh) {
  std::vector<double> c;
  {
    py::gil_scoped_release unlocked;
    c = cell_centroids(mesh->mesh);
  }
  const py::ssize_t nc = ssize(c.size() / 3);
  return adopt(std::move(c), {nc, 3});
}

}  // namespace

void bind_geometry(py::module_& m) {
  bind_wireframe(m);
  m.def("block_soup", &block_soup, py::arg("mesh"), py::arg("analysis").none(true), py::arg("what"), py::arg("sheet") = py::none(),
        py::arg("shrink") = 0.0,
        "Faces of a set of owners (cells, components, sheets, ...) as a polygon soup, each owner with its own vertex copies, "
        "shrunk toward its vertex centroid by `shrink` in [0, 1). what: 'cells', 'components', "
        "'sheets', 'subsheets' (needs sheet), 'sheet' (needs sheet; owner = component), "
        "'sheet_non_hex' (needs sheet), 'non_hex', 'boundary' (owner = cell type), 'hex' (the hex region's surface, owner 0). Returns a dict: "
        "positions float32 (np, 3), point_vertex int32 (np,), face_vertices_offsets int32 (nf + 1,) "
        "and face_vertices_items int32 (face_vertices_offsets[-1],) the CSR of each face's point loop, "
        "face_owner int32 (nf,), face_source int32 (nf,) mesh face ids. "
        "face_cell int32 (nf,) the mesh cell on the owner's side (the face points out of it). "
        "Loops are outward; faces grouped by increasing owner. analysis may be None for 'cells', "
        "'non_hex', 'hex' and 'boundary'.");
  m.def("kept_surface_soup", &kept_surface, py::arg("mesh"), py::arg("kept"), py::arg("shrink") = 0.0,
        "The surface of a set of cells as block_soup's dict (owner = cell): every face of a kept cell "
        "(kept: (num_cells,) bool/uint8) whose other side is not kept or is the boundary, pointing out "
        "of the kept cell.");
  m.def("polygon_edges", &polygon_edges, py::arg("offsets"), py::arg("items"), py::arg("num_points"),
        "The distinct undirected edges of polygons given as a CSR of point ids (e.g. block_soup's "
        "face_vertices_offsets and face_vertices_items; num_points: the point count). Returns a dict: edges int32 "
        "(ne, 2), lower point first, grouped by lower point; corner_edge int32 (len(items),) the edge from "
        "each corner to the next corner of its polygon.");
  m.def("cell_centroids", &cell_centroid_array, py::arg("mesh"),
        "float64 (num_cells, 3): the mean of each cell's distinct vertices.");
  m.def("polylines", &polylines, py::arg("mesh"), py::arg("offsets"), py::arg("items"),
        "float32 (len(items), 3): the positions of the polyline points given as a CSR of mesh "
        "vertex ids (offsets start at 0 and end at len(items)), e.g. a Wireframe's "
        "polylines_offsets and polylines_items.");
}

}  // namespace hbc::python
