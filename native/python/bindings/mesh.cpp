// hbc.Mesh: read-only numpy views of the flat topology arrays of a built mesh.
// Every array property is a view into the C++ mesh (no copy) whose numpy base is the Mesh object,
// so the arrays stay valid after the Mesh goes out of scope in Python. Exceptions (copies):
// `points` (float32 conversion, made once and cached) and `edge_valence` (derived).
#include <algorithm>
#include <array>
#include <string>

#include "bindings.hpp"
#include "hbc/report.hpp"

namespace hbc::python {

namespace {

// Rows sharing another CSR's offsets (def_csr reads .offsets and .items).
struct RowsOf {
  const std::vector<int32_t>& offsets;
  const std::vector<int32_t>& items;
};

static_assert(sizeof(CellType) == 1, "cell_types is exposed as uint8");
static_assert(sizeof(std::array<int32_t, 2>) == 2 * sizeof(int32_t), "pairs are exposed as (n, 2)");

using Cls = py::class_<PyMesh, PyMeshPtr>;

py::array points32(py::object self) {
  PyMesh& pm = self.cast<PyMesh&>();
  if (pm.points32.size() != pm.mesh.points.size())
    pm.points32.assign(pm.mesh.points.begin(), pm.mesh.points.end());
  return view(pm.points32.data(), {ssize(pm.mesh.num_vertices()), 3}, self);
}

// A property returning a view of get(mesh), a vector of one-byte values (0/1 flags, enums) as the
// table's dtype: uint8 or bool.
template <class Get>
void byte_view(Cls& cls, const char* name, Get get) {
  const ExportedArray& e = exported(cls, name);
  const py::dtype dtype(e.dtype == Dtype::Bool ? "bool" : "uint8");
  cls.def_property_readonly(
      name,
      [get, dtype](py::object self) {
        const auto& v = get(self.cast<const PyMesh&>().mesh);
        return view(reinterpret_cast<const uint8_t*>(v.data()), {ssize(v.size())}, self, dtype);
      },
      array_doc(e).c_str());
}

// A property returning a view of get(mesh), a vector of id pairs, as int32 (n, 2).
template <class Get>
void pair_view(Cls& cls, const char* name, Get get) {
  const std::string doc = array_doc(exported(cls, name));
  cls.def_property_readonly(
      name,
      [get](py::object self) {
        const auto& v = get(self.cast<const PyMesh&>().mesh);
        return view(reinterpret_cast<const int32_t*>(v.data()), {ssize(v.size()), 2}, self);
      },
      doc.c_str());
}

// `hbc info --json`'s object without "file", read back from the library's one writer of it (so
// the keys, their order and every value are the CLI's and the WebAssembly binding's).
py::dict info(const Mesh& m) {
  py::dict d = py::module_::import("json").attr("loads")(json_text(mesh_info_json(m, "")));
  d.attr("pop")("file");
  return d;
}

std::string repr(const Mesh& m) {
  return "<hbc.Mesh '" + m.source + "': " + std::to_string(m.num_vertices()) + " vertices, " +
         std::to_string(m.num_cells()) + " cells (" + std::to_string(m.num_hex_cells()) + " hex)>";
}

}  // namespace

void bind_mesh(py::module_& mod) {
  Cls cls(mod, "Mesh",
          "A conforming polyhedral volume mesh (vertices, edges, faces, cells) with its topology. "
          "Array properties are read-only numpy views sharing memory with the mesh. "
          "Create with hbc.load() or Mesh.from_arrays().");

  cls.def_property_readonly("dropped", &dropped_dict,
                            "What hbc.load(skip_invalid=True) dropped, as `hbc analyze --skip-invalid --json` "
                            "says it: {count, by_reason: {key: n}, cells: [{id, reason, line|byte}]}; None "
                            "for a mesh loaded without skip_invalid.");
  cls.def_property_readonly("source", [](const PyMesh& p) { return p.mesh.source; },
                            "The file (or '<arrays>') the mesh was built from.");
  cls.def_property_readonly("warnings", [](const PyMesh& p) {
                              py::list out;
                              for (const std::string& w : p.mesh.warnings) out.append(w);
                              return out;
                            },
                            "list[str]: what was repaired while building (dropped faces/edges).");
  cls.def_property_readonly("num_vertices", [](const PyMesh& p) { return p.mesh.num_vertices(); });
  cls.def_property_readonly("num_edges", [](const PyMesh& p) { return p.mesh.num_edges(); });
  cls.def_property_readonly("num_faces", [](const PyMesh& p) { return p.mesh.num_faces(); });
  cls.def_property_readonly("num_cells", [](const PyMesh& p) { return p.mesh.num_cells(); });

  cls.def_property_readonly("points", &points32, array_doc(exported(cls, "points")).c_str());
  cls.def_property_readonly(
      "points64",
      [](py::object self) {
        const Mesh& m = self.cast<const PyMesh&>().mesh;
        return view(m.points.data(), {ssize(m.num_vertices()), 3}, self);
      },
      array_doc(exported(cls, "points64")).c_str());
  pair_view(cls, "edges", [](const Mesh& m) -> auto& { return m.edge_verts; });

  def_csr(cls, "face_vertices", [](const PyMesh& p) -> auto& { return p.mesh.face_verts; });
  // Stored as items aligned with face_vertices_items; the offsets are those of face_vertices.
  def_csr(cls, "face_edges", [](const PyMesh& p) { return RowsOf{p.mesh.face_verts.offsets, p.mesh.face_edge_ids}; });
  pair_view(cls, "face_cells", [](const Mesh& m) -> auto& { return m.face_cells; });
  def_csr(cls, "cell_faces", [](const PyMesh& p) -> auto& { return p.mesh.cell_faces; });
  byte_view(cls, "cell_face_flip", [](const Mesh& m) -> auto& { return m.cell_face_flip; });
  byte_view(cls, "cell_types", [](const Mesh& m) -> auto& { return m.cell_type; });
  byte_view(cls, "face_boundary", [](const Mesh& m) -> auto& { return m.face_boundary; });
  byte_view(cls, "edge_boundary", [](const Mesh& m) -> auto& { return m.edge_boundary; });
  byte_view(cls, "vertex_boundary", [](const Mesh& m) -> auto& { return m.vert_boundary; });
  byte_view(cls, "vertex_non_manifold", [](const Mesh& m) -> auto& { return m.vert_non_manifold; });

  cls.def_property_readonly(
      "edge_valence",
      [](const PyMesh& p) {
        const Mesh& m = p.mesh;
        py::array_t<int32_t> a(ssize(m.num_edges()));
        int32_t* out = a.mutable_data();
        for (size_t e = 0; e < m.num_edges(); ++e) out[e] = m.edge_valence(e);
        return a;
      },
      array_doc(exported(cls, "edge_valence")).c_str());

  cls.def("info", [](const PyMesh& p) { return info(p.mesh); },
          "The summary `hbc info --json` prints, as a dict (without 'file').");
  cls.def("__repr__", [](const PyMesh& p) { return repr(p.mesh); });

  bind_from_arrays(cls);
}

}  // namespace hbc::python
