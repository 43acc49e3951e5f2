// OpenMesh's property containers push default-constructed colours (left uninitialised by design)
// and GCC 12 reports that from inside OpenMesh once inlined here; the warning is not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "hbc/surface.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace hbc {

std::array<uint8_t, 3> palette_color(int32_t id) {
  // Qualitative colours that stay apart on screen and in print (after ColorBrewer's Set3/Paired
  // spirit, picked by hand); hue order interleaved so consecutive ids differ strongly.
  static constexpr std::array<std::array<uint8_t, 3>, 12> kPalette{{{31, 119, 180},
                                                                     {255, 127, 14},
                                                                     {44, 160, 44},
                                                                     {214, 39, 40},
                                                                     {148, 103, 189},
                                                                     {140, 86, 75},
                                                                     {227, 119, 194},
                                                                     {188, 189, 34},
                                                                     {23, 190, 207},
                                                                     {174, 199, 232},
                                                                     {255, 187, 120},
                                                                     {152, 223, 138}}};
  if (id < 0) return {128, 128, 128};
  return kPalette[static_cast<size_t>(id) % kPalette.size()];
}

SurfaceMesh build_surface(const Mesh& mesh, const FaceSelection& sel, SurfaceStats* stats) {
  const size_t n = sel.faces.size();
  if (sel.reversed.size() != n || sel.ids.size() != n)
    throw std::invalid_argument("face selection: faces, reversed and ids differ in length");
  SurfaceMesh s;
  s.request_face_colors();
  OpenMesh::FPropHandleT<int> id_prop, face_prop;
  s.add_property(id_prop, kSurfaceIdProperty);
  s.add_property(face_prop, kSurfaceFaceProperty);

  // Mesh vertex -> surface vertex, created on first use so the surface holds only what it shows.
  std::vector<int32_t> vmap(mesh.num_vertices(), -1);
  // With separate ids, a mesh vertex mapped while an earlier id was current is mapped anew.
  std::vector<int32_t> vmap_owner(sel.separate_ids ? mesh.num_vertices() : 0, 0);
  size_t owner = 0;
  auto point = [&](int32_t v) {
    const double* p = &mesh.points[3 * static_cast<size_t>(v)];
    return SurfaceMesh::Point(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  };
  std::vector<SurfaceMesh::VertexHandle> loop;
  SurfaceStats st;
  // OpenMesh logs every face it refuses; those are counted in the stats instead.
  struct QuietOmerr {
    QuietOmerr() { omerr().disable(); }
    ~QuietOmerr() { omerr().enable(); }
  } quiet;
  for (size_t i = 0; i < n; ++i) {
    const int32_t f = sel.faces[i];
    if (f < 0 || static_cast<size_t>(f) >= mesh.num_faces())
      throw std::invalid_argument("face selection: face id " + std::to_string(f) + " out of range");
    auto verts = mesh.face_verts[static_cast<size_t>(f)];
    if (sel.separate_ids && (i == 0 || sel.ids[i] != sel.ids[i - 1])) ++owner;
    loop.clear();
    for (int32_t v : verts) {
      int32_t& sv = vmap[static_cast<size_t>(v)];
      if (sel.separate_ids && vmap_owner[static_cast<size_t>(v)] != static_cast<int32_t>(owner)) {
        vmap_owner[static_cast<size_t>(v)] = static_cast<int32_t>(owner);
        sv = -1;
      }
      if (sv < 0) sv = s.add_vertex(point(v)).idx();
      loop.push_back(SurfaceMesh::VertexHandle(sv));
    }
    if (sel.reversed[i]) std::reverse(loop.begin(), loop.end());
    auto fh = s.add_face(loop);
    if (!fh.is_valid()) {
      // OpenMesh keeps surfaces manifold; a face that would break that gets its own corners.
      for (size_t k = 0; k < loop.size(); ++k) loop[k] = s.add_vertex(s.point(loop[k]));
      fh = s.add_face(loop);
      ++st.unwelded_faces;
    }
    const auto rgb = palette_color(sel.ids[i]);
    s.set_color(fh, SurfaceMesh::Color(rgb[0], rgb[1], rgb[2]));
    s.property(id_prop, fh) = sel.ids[i];
    s.property(face_prop, fh) = f;
    ++st.faces;
  }
  if (stats) *stats = st;
  return s;
}

void write_surface(const SurfaceMesh& surface, const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext != "obj" && ext != "ply" && ext != "off")
    throw std::invalid_argument("surface output must end in .obj, .ply or .off: " + path);
  OpenMesh::IO::Options opt = OpenMesh::IO::Options::FaceColor;
  if (!OpenMesh::IO::write_mesh(surface, path, opt))
    throw std::runtime_error("OpenMesh could not write " + path);
}

}  // namespace hbc
