// A corpus of malformed files for every reader: each must raise InputError naming the file, the
// line (byte offset for .ovmb) and what was expected. Text cases are a valid one-tetrahedron file
// with one line changed; binary cases corrupt the bytes of a real .ovmb or of a small file
// encoded here field by field.
#include <sys/wait.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <unistd.h>

#include "format_samples.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

namespace hbc {
namespace {

// ---------------------------------------------------------------------------------------------
// Text helpers: valid files and single-line edits.

const char* kOvmTet =
    "OVM ASCII\n"          // 1
    "Vertices\n"           // 2
    "4\n"                  // 3
    "0 0 0\n"              // 4
    "1 0 0\n"              // 5
    "0 1 0\n"              // 6
    "0 0 1\n"              // 7
    "Edges\n"              // 8
    "6\n"                  // 9
    "0 1\n"                // 10  edge 0
    "1 2\n"                // 11  edge 1
    "2 0\n"                // 12  edge 2
    "0 3\n"                // 13  edge 3
    "1 3\n"                // 14  edge 4
    "2 3\n"                // 15  edge 5
    "Faces\n"              // 16
    "4\n"                  // 17
    "3 0 2 4\n"            // 18  0 1 2
    "3 0 8 7\n"            // 19  0 1 3
    "3 2 10 9\n"           // 20  1 2 3
    "3 4 6 11\n"           // 21  2 0 3
    "Polyhedra\n"          // 22
    "1\n"                  // 23
    "4 1 2 4 6\n"          // 24
    "VProp double \"w\"\n"  // 25
    "0.5\n"                // 26
    "1.5\n"                // 27
    "2.5\n"                // 28
    "3.5\n";               // 29

const char* kMeditTet =
    "MeshVersionFormatted 1\n"  // 1
    "Dimension 3\n"             // 2
    "Vertices\n"                // 3
    "4\n"                       // 4
    "0 0 0 0\n"                 // 5
    "1 0 0 0\n"                 // 6
    "0 1 0 0\n"                 // 7
    "0 0 1 0\n"                 // 8
    "Tetrahedra\n"              // 9
    "1\n"                       // 10
    "1 2 3 4 0\n"               // 11
    "End\n";                    // 12

const char* kHybridTet =
    "4 4 3\n"     // 1
    "0 0 0\n"     // 2
    "1 0 0\n"     // 3
    "0 1 0\n"     // 4
    "0 0 1\n"     // 5
    "3 0 1 2\n"   // 6
    "3 0 1 3\n"   // 7
    "3 1 2 3\n"   // 8
    "3 2 0 3\n"   // 9
    "4 0 1 2 3\n" // 10 faces of the cell
    "4 1 0 0 0\n" // 11 their orientation flags
    "0\n";        // 12 cell orientation flag

const char* kHedraTet =
    "4 4 1\n"        // 1
    "0 0 0\n"        // 2
    "1 0 0\n"        // 3
    "0 1 0\n"        // 4
    "0 0 1\n"        // 5
    "3 1 2 3\n"      // 6
    "3 1 2 4\n"      // 7
    "3 2 3 4\n"      // 8
    "3 3 1 4\n"      // 9
    "4 -1 2 3 4\n";  // 10

// The text with its 1-based line `n` replaced by `by` (which may hold several lines).
std::string with_line(const std::string& text, int n, const std::string& by) {
  size_t start = 0;
  for (int i = 1; i < n; ++i) start = text.find('\n', start) + 1;
  const size_t end = text.find('\n', start);
  return text.substr(0, start) + by + text.substr(end);
}

// The first n lines of the text.
std::string first_lines(const std::string& text, int n) {
  size_t end = 0;
  for (int i = 0; i < n; ++i) end = text.find('\n', end) + 1;
  return text.substr(0, end);
}

MeshInput read_as(Format f, std::string_view bytes, const std::string& name) {
  switch (f) {
    case Format::Ovm: return read_ovm(bytes, name);
    case Format::Ovmb: return read_ovmb(bytes, name);
    case Format::Medit: return read_medit(bytes, name);
    case Format::Hybrid: return read_hybrid(bytes, name);
    case Format::Hedra: return read_hedra(bytes, name);
    case Format::Msh: return read_msh(bytes, name);
    case Format::Vtk: return read_vtk(bytes, name);
    case Format::Vtu: return read_vtu(bytes, name);
    case Format::Su2: return read_su2(bytes, name);
    case Format::Ugrid: return read_ugrid(bytes, name, ugrid_encoding_of(name));
    case Format::Fluent: return read_fluent(bytes, name);
    case Format::Abaqus: return read_abaqus(bytes, name);
    case Format::Nastran: return read_nastran(bytes, name);
    case Format::LsDyna: return read_lsdyna(bytes, name);
    case Format::Foam:  // four files: see the Foam cases below
    case Format::Auto: break;
  }
  throw std::logic_error("no reader");
}

struct Case {
  std::string name;
  std::string bytes;
  int64_t where;        // line, or byte offset for .ovmb
  std::string keyword;  // a piece of the expected-what text
  bool binary = false;  // `where` is a byte offset (binary .msh / .vtk)
};

// Reads and builds each case; each must fail at the stated place with the stated reason.
void expect_all_rejected(Format f, const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const bool binary = f == Format::Ovmb || f == Format::Vtu || c.binary;
    const std::string file = "bad_" + c.name + "." + format_name(f);
    SCOPED_TRACE(file);
    try {
      build_mesh(read_as(f, c.bytes, file));
      ADD_FAILURE() << "accepted a malformed file";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.file(), file);
      if (binary) {
        EXPECT_EQ(e.loc().byte_offset, c.where) << what;
        EXPECT_EQ(e.loc().line, -1) << what;
        EXPECT_EQ(what.rfind(file + ": byte " + std::to_string(c.where) + ": ", 0), 0u) << what;
      } else {
        EXPECT_EQ(e.loc().line, c.where) << what;
        EXPECT_EQ(what.rfind(file + ":" + std::to_string(c.where) + ": ", 0), 0u) << what;
      }
      EXPECT_NE(e.detail().find(c.keyword), std::string::npos) << "'" << c.keyword << "' not in: " << what;
    }
  }
}

// The base files are valid: the cases below differ from them only in what they break.
TEST(Malformed, BaseFilesAreValidTetrahedra) {
  for (auto [f, text] : {std::pair{Format::Ovm, kOvmTet}, std::pair{Format::Medit, kMeditTet},
                         std::pair{Format::Hybrid, kHybridTet}, std::pair{Format::Hedra, kHedraTet}}) {
    SCOPED_TRACE(format_name(f));
    const Mesh m = build_mesh(read_as(f, text, "tet"));
    ASSERT_EQ(m.num_cells(), 1u);
    EXPECT_EQ(m.cell_type[0], CellType::Tet);
    EXPECT_EQ(m.num_faces(), 4u);
    EXPECT_EQ(m.num_edges(), 6u);
  }
}

TEST(Malformed, Ovm) {
  const std::string t = kOvmTet;
  const std::string three_cells = with_line(with_line(t, 23, "3"), 24, "4 1 2 4 6\n4 1 2 4 6\n4 1 2 4 6");
  expect_all_rejected(Format::Ovm, {
      {"empty", "", 1, "header line 'OVM ASCII', found the end of the file"},
      {"header", with_line(t, 1, "OFF"), 1, "header line 'OVM ASCII'"},
      {"binary_header", with_line(t, 1, "OVM BINARY"), 1, "ASCII"},
      // Cut short: a count the rest cannot hold, a cut inside a line, a cut between lines.
      {"truncated", first_lines(t, 5), 3, "number of vertices that the rest of the file can hold"},
      {"truncated_line", first_lines(t, 6) + "0 0", 7, "coordinates of vertex 3"},
      {"truncated_cells", first_lines(t, 23), 23, "polyhedron 0 of 1, found the end of the file"},
      {"count_edges", with_line(t, 9, "7"), 16, "two vertices of edge 6"},
      {"count_faces", with_line(t, 17, "3"), 21, "section keyword Polyhedra"},
      {"count_words", with_line(t, 3, "four"), 3, "number of vertices (an integer)"},
      {"range_vertex", with_line(t, 15, "2 4"), 15, "vertex index in [0, 3], found 4"},
      {"range_half_edge", with_line(t, 20, "3 2 10 12"), 20, "half-edge index in [0, 11], found 12"},
      {"range_half_face", with_line(t, 24, "4 1 2 4 8"), 24, "half-face index in [0, 7], found 8"},
      {"negative_vertex", with_line(t, 13, "0 -3"), 13, "found -3"},
      {"negative_half_edge", with_line(t, 19, "3 0 -8 7"), 19, "half-edge index in [0, 11], found -8"},
      {"negative_count", with_line(t, 17, "-4"), 17, "count >= 0"},
      {"non_numeric", with_line(t, 6, "0 one 0"), 6, "(a number), found 'one'"},
      {"non_numeric_index", with_line(t, 21, "3 4 six 11"), 21, "(an integer), found 'six'"},
      {"nan", with_line(t, 7, "0 nan 1"), 7, "finite"},
      {"inf", with_line(t, 5, "inf 0 0"), 5, "finite"},
      {"overflow", with_line(t, 5, "1e999 0 0"), 5, "finite"},
      {"two_half_edges", with_line(t, 18, "2 0 1"), 18, "half-edges of face 0 in [3,"},
      {"repeated_vertex", with_line(t, 18, "4 0 1 0 1"), 18, "distinct vertices in face 0"},
      {"broken_chain", with_line(t, 19, "3 0 10 7"), 19, "chain end to start"},
      {"open_loop", with_line(t, 19, "3 0 8 9"), 19, "closed loop of half-edges"},
      {"extra_token", with_line(t, 19, "3 0 8 7 5"), 19, "half-edges of face 1"},
      {"cell_not_closed", with_line(t, 24, "3 1 2 4"), 24, "closed cell"},
      {"face_in_three_cells", three_cells, 26, "at most 2 cells"},
      {"face_twice_in_cell", with_line(t, 24, "4 1 1 4 6"), 24, "each face once per cell"},
      {"huge_count", "OVM ASCII\nVertices\n2000000000\n0 0 0\n", 3, "rest of the file can hold"},
      {"huge_faces", with_line(t, 17, "99999999999"), 17, "rest of the file can hold"},
      {"prop_too_few", first_lines(t, 28), 28, "4 values of property \"w\", found 3 before the end"},
      {"prop_too_few_next", with_line(t, 29, "EProp int \"e\""), 29, "found 3 before the next property block"},
      {"prop_too_many", t + "4.5\n", 30, "after the 4 values of property \"w\""},
      {"prop_bad_value", with_line(t, 27, "x"), 27, "double value of property \"w\""},
      {"prop_bad_kind", t + "ZProp int \"z\"\n", 30, "property block header"},
      {"prop_no_name", t + "EProp int e\n", 30, "quoted property name"},
  });
}

TEST(Malformed, Medit) {
  const std::string t = kMeditTet;
  const std::string three = with_line(with_line(t, 10, "3"), 11, "1 2 3 4 0\n1 2 3 4 0\n1 2 3 4 0");
  expect_all_rejected(Format::Medit, {
      {"empty", "", 1, "a Vertices section"},
      {"truncated", first_lines(t, 6), 4, "number of vertices that the rest of the file can hold"},
      {"truncated_vertex", first_lines(t, 7) + "0 0", 8, "vertex coordinate, found the end of the file"},
      {"truncated_cells", first_lines(t, 10), 10, "vertex index, found the end"},
      {"count_cells", with_line(t, 10, "2"), 12, "vertex index (an integer), found 'End'"},
      {"count_vertices", with_line(t, 4, "5"), 9, "found 'Tetrahedra'"},
      {"range", with_line(t, 11, "1 2 3 5 0"), 11, "vertex index in [1, 4], found 5"},
      {"negative", with_line(t, 11, "1 2 -3 4 0"), 11, "found -3"},
      {"non_numeric", with_line(t, 7, "0 1 zero 0"), 7, "(a number), found 'zero'"},
      {"nan", with_line(t, 8, "0 0 NaN 0"), 8, "finite"},
      {"inf", with_line(t, 6, "inf 0 0 0"), 6, "finite"},
      {"degenerate", with_line(t, 11, "1 1 2 3 0"), 11, "at least 2 faces"},
      {"cell_not_closed", with_line(with_line(t, 9, "Hexahedra"), 11, "1 1 1 1 2 3 2 4 0"), 11, "closed cell"},
      {"face_in_three_cells", three, 13, "at most 2 cells"},
      {"huge_count", with_line(t, 4, "99999999"), 4, "rest of the file can hold"},
      {"dimension", with_line(t, 2, "Dimension 2"), 2, "dimension 3"},
  });
}

TEST(Malformed, Hybrid) {
  const std::string t = kHybridTet;
  // Three copies of the cell: lines 10/11, 12/13, 14/15, then three cell flags.
  const std::string three = with_line(first_lines(t, 9), 1, "4 4 9") +
                            "4 0 1 2 3\n4 1 0 0 0\n4 0 1 2 3\n4 1 0 0 0\n4 0 1 2 3\n4 1 0 0 0\n0\n0\n0\n";
  expect_all_rejected(Format::Hybrid, {
      {"empty", "", 1, "number of vertices, found the end of the file"},
      {"truncated", first_lines(t, 8), 8, "vertices of a face, found the end"},
      {"truncated_flags", first_lines(t, 11), 11, "cell orientation flag"},
      {"count_not_3", with_line(t, 1, "4 4 4"), 1, "multiple of 3"},
      {"count_flags", with_line(t, 11, "3 1 0 0"), 11, "as many face orientation flags as faces (4), found 3"},
      {"range_face", with_line(t, 10, "4 0 1 2 4"), 10, "face index (0-based) in [0, 3], found 4"},
      {"range_vertex", with_line(t, 8, "3 1 2 4"), 8, "vertex index (0-based) in [0, 3], found 4"},
      {"negative", with_line(t, 7, "3 0 -1 3"), 7, "found -1"},
      {"non_numeric", with_line(t, 3, "1 0 O"), 3, "(a number), found 'O'"},
      {"nan", with_line(t, 4, "nan 1 0"), 4, "finite"},
      {"two_vertices", with_line(t, 9, "2 0 1"), 9, "a face with at least 3 vertices"},
      {"repeated_vertex", with_line(t, 9, "3 2 2 3"), 9, "distinct vertices in face 3"},
      {"cell_not_closed", with_line(with_line(t, 10, "3 0 1 2"), 11, "3 1 0 0"), 10, "closed cell"},
      {"face_in_three_cells", three, 14, "at most 2 cells"},
      {"flag_value", with_line(t, 12, "2"), 12, "cell orientation flag (0 or 1)"},
      {"trailing", t + "7\n", 13, "end of the file"},
      {"huge_count", with_line(t, 1, "99999999 4 3"), 1, "rest of the file can hold"},
  });
}

TEST(Malformed, Hedra) {
  const std::string t = kHedraTet;
  const std::string three = with_line(with_line(t, 1, "4 4 3"), 10, "4 -1 2 3 4\n4 -1 2 3 4\n4 -1 2 3 4");
  expect_all_rejected(Format::Hedra, {
      {"empty", "", 1, "number of vertices, found the end of the file"},
      {"truncated", first_lines(t, 9), 9, "faces of a cell, found the end"},
      {"count_cells", with_line(t, 1, "4 4 2"), 10, "faces of a cell, found the end"},
      {"count_faces", with_line(t, 1, "4 5 1"), 10, "vertex index (1-based) in [1, 4], found -1"},
      {"range", with_line(t, 10, "4 -1 2 3 5"), 10, "face index (1-based) in [-4, 4], found 5"},
      {"negative_vertex", with_line(t, 7, "3 1 -2 4"), 7, "found -2"},
      {"zero_face", with_line(t, 10, "4 -1 0 3 4"), 10, "never 0"},
      {"non_numeric", with_line(t, 2, "0 0 z"), 2, "(a number), found 'z'"},
      {"nan", with_line(t, 5, "0 0 nan"), 5, "finite"},
      {"repeated_vertex", with_line(t, 8, "3 2 2 4"), 8, "distinct vertices in face 2"},
      {"cell_not_closed", with_line(t, 10, "3 -1 2 3"), 10, "closed cell"},
      {"face_in_three_cells", three, 12, "at most 2 cells"},
      {"huge_count", with_line(t, 1, "4 4 99999999"), 1, "rest of the file can hold"},
  });
}

// ---------------------------------------------------------------------------------------------
// OVMB: a small encoder (independent of the reader) and byte-level corruption.

class OvmbEncoder {
 public:
  std::string bytes;
  std::vector<size_t> cell_at;  // where each cell's half-faces start

  void u8(uint64_t v) { bytes.push_back(static_cast<char>(v & 0xff)); }
  void u32(uint64_t v) {
    for (int k = 0; k < 4; ++k) u8(v >> (8 * k));
  }
  void u64(uint64_t v) {
    for (int k = 0; k < 8; ++k) u8(v >> (8 * k));
  }
  // Chunk header, payload written by `body`, padding to 8 bytes.
  void chunk(const char* type, const std::function<void()>& body) {
    bytes.append(type, 4);
    const size_t head = bytes.size();
    for (int k = 0; k < 12; ++k) u8(0);
    const size_t start = bytes.size();
    body();
    const size_t len = bytes.size() - start, pad = (8 - len % 8) % 8;
    bytes.append(pad, '\0');
    bytes[head + 1] = static_cast<char>(pad);  // version 0, padding, compression 0, flags 1
    bytes[head + 3] = 1;
    for (int k = 0; k < 8; ++k) bytes[head + 4 + k] = static_cast<char>(((len + pad) >> (8 * k)) & 0xff);
  }

  // A polyhedral mesh: u32 handles, u8 valences for faces and cells.
  OvmbEncoder(const std::vector<double>& pts, const std::vector<uint32_t>& edges,
              const std::vector<std::vector<uint32_t>>& faces, const std::vector<std::vector<uint32_t>>& cells) {
    bytes.append("OVMB\n\r\n\xff", 8);
    u8(1), u8(1), u8(3), u8(0), u32(0);
    u64(pts.size() / 3), u64(edges.size() / 2), u64(faces.size()), u64(cells.size());
    chunk("VERT", [&] {
      u64(0), u32(pts.size() / 3), u8(2), u8(0), u8(0), u8(0);
      for (double x : pts) u64(std::bit_cast<uint64_t>(x));
    });
    auto topo = [&](uint8_t entity, uint8_t valence, uint64_t count) {
      u64(0), u32(count), u8(entity), u8(valence), u8(valence ? 0 : 1), u8(4), u64(0);
    };
    chunk("TOPO", [&] {
      topo(1, 2, edges.size() / 2);
      for (uint32_t v : edges) u32(v);
    });
    for (const auto* list : {&faces, &cells}) {
      chunk("TOPO", [&] {
        topo(list == &faces ? 2 : 3, 0, list->size());
        for (const auto& row : *list) u8(row.size());
        for (const auto& row : *list) {
          if (list == &cells) cell_at.push_back(bytes.size());
          for (uint32_t h : row) u32(h);
        }
      });
    }
    chunk("EOF ", [] {});
  }
};

const std::vector<double> kTetPoints{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const std::vector<uint32_t> kTetEdges{0, 1, 1, 2, 2, 0, 0, 3, 1, 3, 2, 3};
const std::vector<std::vector<uint32_t>> kTetFaces{{0, 2, 4}, {0, 8, 7}, {2, 10, 9}, {4, 6, 11}};

TEST(Malformed, OvmbEncoderMatchesTheTextFile) {
  const OvmbEncoder enc(kTetPoints, kTetEdges, kTetFaces, {{1, 2, 4, 6}});
  const Mesh a = build_mesh(read_ovmb(enc.bytes, "tet.ovmb"));
  const Mesh b = build_mesh(read_ovm(kOvmTet, "tet.ovm"));
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.face_verts.items, b.face_verts.items);
  EXPECT_EQ(a.cell_face_flip, b.cell_face_flip);
  EXPECT_EQ(a.cell_type[0], CellType::Tet);
}

std::string real_ovmb(const char* name) {
  return read_file_bytes(test::data_path(std::string("openvolumemesh/") + name));
}

std::string patched(std::string b, size_t at, std::initializer_list<uint8_t> v) {
  for (uint8_t x : v) b.at(at++) = static_cast<char>(x);
  return b;
}

std::string patched_u64(std::string b, size_t at, uint64_t v) {
  for (int k = 0; k < 8; ++k) b.at(at + k) = static_cast<char>((v >> (8 * k)) & 0xff);
  return b;
}

TEST(Malformed, Ovmb) {
  HBC_REQUIRE_DATA("openvolumemesh/Cube_with_props.ovmb");
  HBC_REQUIRE_DATA("openvolumemesh/NonManifold.ovmb");
  // Cube_with_props.ovmb (880 bytes): header 0..48 (counts at 16, 24, 32, 40); DIRP at 0x30;
  // VERT at 0xc0 (length at 0xc8, payload 0xd0: encoding at 0xdc, coordinates from 0xe0);
  // TOPO edges at 0x1a0 (payload 0x1b0: entity 0x1bc, handle offset 0x1c0, handles 0x1c8);
  // TOPO faces at 0x1e0 (handles 0x208); TOPO cells at 0x220 (handles 0x248); PROP chunks;
  // EOF at 0x360.
  const std::string cube = real_ovmb("Cube_with_props.ovmb");
  ASSERT_EQ(cube.size(), 880u);
  // NonManifold.ovmb: cells chunk payload at 0x230, valences 6 5 at 0x248, half-faces from
  // 0x24a: 1 2 5 6 8 11 (hex) | 15 17 19 21 7 (pyramid). Face 6 is the dangling quad.
  const std::string nm = real_ovmb("NonManifold.ovmb");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const OvmbEncoder three(kTetPoints, kTetEdges, kTetFaces, {{1, 2, 4, 6}, {1, 2, 4, 6}, {1, 2, 4, 6}});
  ASSERT_EQ(three.cell_at.size(), 3u);

  expect_all_rejected(Format::Ovmb, {
      {"empty", "", 0, "magic"},
      {"magic", patched(cube, 0, {'X'}), 0, "magic"},
      {"version", patched(cube, 8, {7}), 8, "file version 1"},
      {"truncated_header", cube.substr(0, 20), 16, "number of vertices (8 bytes), found only 4 before the end"},
      {"truncated_chunk", cube.substr(0, 300), 0xc8, "chunk length within"},
      {"truncated_chunk_header", cube.substr(0, 0xc4), 0xc4, "chunk version (1 bytes), found only 0"},
      {"truncated_before_eof", cube.substr(0, 0x360), 0x360, "EOF chunk"},
      {"count_cells", patched_u64(cube, 40, 2), 880, "2 cells as the header declares, found 1"},
      {"count_vertices", patched_u64(cube, 16, 7), 0xd0 + 8, "at most 7 more vertices"},
      {"range_vertex", patched(cube, 0x1c8, {8}), 0x1c8, "vertex index below 8, found 8"},
      {"range_half_edge", patched(cube, 0x209, {24}), 0x209, "half-edge index below 24, found 24"},
      {"range_half_face", patched(cube, 0x24a, {12}), 0x24a, "half-face index below 12, found 12"},
      {"negative_offset", patched_u64(cube, 0x1c0, ~uint64_t{0}), 0x1c8, "+ offset 18446744073709551615"},
      {"vertex_encoding", patched(cube, 0xdc, {7}), 0xdc, "vertex encoding 1 (float) or 2 (double), found 7"},
      {"topo_entity", patched(cube, 0x1bc, {9}), 0x1bc, "topology entity"},
      {"handle_encoding", patched(cube, 0x1bf, {3}), 0x1bf, "handle encoding 1, 2 or 4, found 3"},
      {"hex_valence", patched(cube, 0x1fd, {5}), 0x1fd, "valence 4 in a hexahedral file, found 5"},
      {"nan", patched_u64(cube, 0xe0 + 3 * 24 + 8, std::bit_cast<uint64_t>(nan)), 0xe0 + 3 * 24,
       "finite coordinate for vertex 3"},
      {"inf", patched_u64(cube, 0xe0, std::bit_cast<uint64_t>(-inf)), 0xe0, "finite coordinate for vertex 0"},
      {"repeated_vertex", patched(cube, 0x208, {0, 1, 0, 1}), 0x208, "distinct vertices in face 0"},
      {"broken_chain", patched(cube, 0x208, {0, 2, 4, 8}), 0x20b, "chain end to start"},
      {"cell_not_closed", patched(nm, 0x24f, {12}), 0x24a, "closed cell"},
      {"face_in_three_cells", three.bytes, static_cast<int64_t>(three.cell_at[2]), "at most 2 cells"},
      {"huge_vertices", patched_u64(cube, 16, uint64_t{1} << 40), 16, "that the file can hold"},
      {"huge_faces", patched_u64(cube, 32, uint64_t{1} << 31), 32, "that the file can hold"},
      {"huge_chunk", patched_u64(cube, 0xc8, uint64_t{1} << 62), 0xc8, "chunk length within"},
      {"unknown_chunk", patched(cube, 0x30, {'A', 'B', 'C', 'D'}), 0x30, "known chunk type"},
      {"after_eof", cube + std::string(16, '\0'), 880, "after the EOF chunk"},
  });
}

// ---------------------------------------------------------------------------------------------

TEST(Malformed, CliExitsWithStatus2AndTheMessageOnStderr) {
  ASSERT_TRUE(std::filesystem::exists(HBC_CLI)) << "build the hbc_cli target: " << HBC_CLI;
  const auto dir = std::filesystem::temp_directory_path() / ("hbc_bad_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto bad = dir / "bad.ovm";
  {
    std::ofstream f(bad, std::ios::binary);
    f << with_line(kOvmTet, 19, "3 0 10 7");
  }
  const test::CliRun r = test::run_cli("info '" + bad.string() + "'");
  EXPECT_EQ(r.status, 2);
  const std::string& msg = r.err;
  EXPECT_NE(msg.find(bad.string() + ":19: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("chain"), std::string::npos) << msg;
  std::filesystem::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Element-list formats: the one-prism files of tests/data/formats with one thing broken.

std::string sample(const std::string& name) { return read_file_bytes(std::string(HBC_FORMATS_DIR) + "/" + name); }

// The bytes with a little-endian number written over those at `at`.
template <class T>
std::string patched(std::string b, size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof(T));
  return b;
}

TEST(Malformed, MshAscii) {
  // prism_gmsh.msh: nodes on lines 6-11, the prism on line 15.
  const std::string t = sample("prism_gmsh.msh");
  expect_all_rejected(Format::Msh, {
      {"empty", "", 1, "$MeshFormat at the start"},
      {"version", with_line(t, 2, "3.0 0 8"), 2, "version 2.2 or 4.1, found '3.0'"},
      {"truncated_nodes", first_lines(t, 8), 5, "number of nodes that the rest of the file can hold"},
      {"truncated_elements", first_lines(t, 14), 14, "element tag, found the end of the file"},
      {"count_elements", with_line(t, 14, "2"), 16, "an element tag (an integer), found '$EndElements'"},
      {"count_nodes", with_line(t, 5, "5"), 11, "$EndNodes, found '6'"},
      {"unknown_type", with_line(t, 15, "1 99 2 0 1 1 2 3 4 5 6"), 15, "found type 99"},
      {"node_out_of_range", with_line(t, 15, "1 6 2 0 1 1 2 3 4 5 7"), 15, "node tag defined in $Nodes, found 7"},
      {"duplicate_tag", with_line(t, 11, "5 0 1 1"), 11, "distinct node tags, found tag 5 twice"},
      {"section_end", with_line(t, 12, "$EndNodez"), 12, "$EndNodes, found '$EndNodez'"},
      {"unclosed_section", t + "$Comments\nno end\n", 18, "$EndComments to close $Comments"},
      {"no_volume", with_line(t, 15, "1 3 2 0 1 1 2 3 4"), 16, "at least one volume element"},
      {"non_numeric", with_line(t, 8, "3 0 one 0"), 8, "node coordinate (a finite number), found 'one'"},
      {"nan", with_line(t, 8, "3 0 nan 0"), 8, "finite"},
      {"elements_first", with_line(with_line(t, 4, "$Elements"), 12, "$EndElements"), 4, "a $Nodes section before $Elements"},
  });
}

TEST(Malformed, MshBinary) {
  // Offsets: see prism_msh41_binary.
  const std::string t = test::prism_msh41_binary(false);
  ASSERT_NO_THROW(build_mesh(read_msh(t, "ok.msh")));
  expect_all_rejected(Format::Msh, {
      {"check_value", patched<int32_t>(t, 20, 2), 24, "byte-order check value 1, found 2", true},
      {"huge_node_count", patched<uint64_t>(t, 55, 1000000000000), 63, "number of nodes that the rest of the file can hold", true},
      // The total node count is checked against the rest of the file before any block.
      {"truncated_nodes", t.substr(0, 200), 63, "number of nodes that the rest of the file can hold (0 to 5), found 6", true},
      {"truncated_coordinate", t.substr(0, 290), 283, "node coordinate (8 bytes), found the end of the file after 7", true},
      {"unknown_type", patched<int32_t>(t, 352, 99), 344, "found type 99", true},
      {"node_out_of_range", patched<uint64_t>(t, 412, 7), 364, "node tag defined in $Nodes, found 7", true},
      {"count_elements", patched<uint64_t>(t, 320, 2), 420, "2 elements as the $Elements header says, found 1", true},
  });
}

TEST(Malformed, VtkAscii) {
  // prism_vtk.vtk: points on lines 6-11, the wedge on line 13, its type on line 15.
  const std::string t = sample("prism_vtk.vtk");
  // A tetrahedron-like polyhedron whose fourth face leaves for vertex 4: not closed.
  const std::string open_poly = with_line(with_line(with_line(t, 12, "CELLS 1 18"), 13, "17 4 3 0 2 1 3 0 1 3 3 1 2 3 3 0 3 4"), 15, "42");
  expect_all_rejected(Format::Vtk, {
      {"empty", "", 1, "'# vtk DataFile Version x.y'"},
      {"header", with_line(t, 1, "# not vtk"), 1, "'# vtk DataFile Version x.y'"},
      {"version", with_line(t, 1, "# vtk DataFile Version 9.0"), 1, "version 2.0 to 5.1, found '9.0'"},
      {"encoding", with_line(t, 3, "EBCDIC"), 3, "ASCII or BINARY, found 'ebcdic'"},
      {"dataset", with_line(t, 4, "DATASET POLYDATA"), 4, "DATASET UNSTRUCTURED_GRID, found DATASET polydata"},
      {"truncated_points", first_lines(t, 8), 5, "number of values that the rest of the file can hold"},
      {"truncated_cells", first_lines(t, 12), 12, "number of values that the rest of the file can hold"},
      {"cell_size", with_line(t, 13, "9 0 2 1 3 5 4"), 13, "cell size that fits in the CELLS entries, found 9"},
      {"count_types", with_line(with_line(t, 14, "CELL_TYPES 2"), 15, "13 13"), 14, "1 cell types, one per cell, found 2"},
      {"unknown_type", with_line(t, 15, "15"), 13, "found type 15"},
      {"point_out_of_range", with_line(t, 13, "6 0 2 1 3 5 6"), 13, "point id in [0, 5], found 6"},
      {"poly_not_closed", open_poly, 13, "closed cell"},
      {"poly_stream", with_line(with_line(with_line(t, 12, "CELLS 1 9"), 13, "8 4 3 0 2 1 3 0 1"), 15, "42"), 13, "face 1 of the polyhedron"},
      {"float_type", with_line(t, 5, "POINTS 6 quaternion"), 5, "numeric data type"},
      {"no_cell_types", first_lines(t, 13), 13, "a CELL_TYPES section"},
      {"unknown_section", with_line(t, 14, "LINES 1 3"), 14, "POINTS, CELLS, CELL_TYPES"},
  });
}

TEST(Malformed, VtkBinary) {
  // meshio's binary 5.1 file of the real slab: big-endian OFFSETS and CONNECTIVITY (vtktypeint64).
  const std::string t = sample("real/slab_51_bin.vtk");
  const size_t points_line_end = t.find('\n', t.find("POINTS"));
  const size_t conn = t.find('\n', t.find("CONNECTIVITY")) + 1;
  std::string bad_id = t;
  for (int k = 0; k < 8; ++k) bad_id[conn + k] = k == 6 ? '\x27' : k == 7 ? '\x0f' : '\0';  // 9999
  expect_all_rejected(Format::Vtk, {
      {"truncated", t.substr(0, points_line_end + 200), static_cast<int64_t>(points_line_end), "number of values that the rest of the file can hold", true},
      {"point_out_of_range", bad_id, static_cast<int64_t>(conn), "found 9999", true},
  });
}

TEST(Malformed, Vtu) {
  const std::string t = sample("poly.vtu");
  // Byte offsets name the element (pugixml gives the position of its name, after '<').
  auto at = [&](const std::string& s, const std::string& needle) { return static_cast<int64_t>(s.find(needle)) + 1; };
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string r = t;
    r.replace(r.find(from), from.size(), to);
    return r;
  };
  const std::string offsets_tag = "<DataArray type=\"Int64\" Name=\"offsets\"";
  // A binary points array whose base64 holds '!' and one whose size header promises 1000 bytes.
  const std::string points_ascii = t.substr(t.find("<DataArray type=\"Float64\""), t.find("</DataArray>") + 12 - t.find("<DataArray type=\"Float64\""));
  std::string b64 = t, huge = t, zbad = t;
  b64.replace(b64.find(points_ascii), points_ascii.size(), "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">AAAA!AAA</DataArray>");
  huge.replace(huge.find(points_ascii), points_ascii.size(), "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">6AMAAAAAAAA=</DataArray>");
  // Compressed: 1 block of 288 bytes claimed to be in 4 zlib bytes that are not zlib.
  zbad.replace(zbad.find("header_type=\"UInt32\""), 20, "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"");
  zbad.replace(zbad.find(points_ascii), points_ascii.size(), "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">AQAAACABAAAgAQAABAAAAA==AAAAAA==</DataArray>");
  const int64_t b64_text = static_cast<int64_t>(b64.find(">AAAA!AAA")) + 1;
  expect_all_rejected(Format::Vtu, {
      {"empty", "", 0, "well-formed XML (No document element found)"},
      {"no_vtkfile", "<VTK/>", 0, "<VTKFile type=\"UnstructuredGrid\">"},
      // Cut inside a tag: pugixml points at the tag's last character.
      {"not_xml", t.substr(0, t.find("<Cells>") + 3), static_cast<int64_t>(t.find("<Cells>") + 2), "well-formed XML"},
      {"poly_data", replaced("type=\"UnstructuredGrid\"", "type=\"PolyData\""), 0, "UnstructuredGrid"},
      {"count_points", replaced("NumberOfPoints=\"12\"", "NumberOfPoints=\"13\""), at(t, "<DataArray type=\"Float64\""), "39 values in DataArray '', found 36"},
      {"huge_count", replaced("NumberOfCells=\"2\"", "NumberOfCells=\"2000000\""), at(t, "<Piece"), "NumberOfCells in [0,"},
      {"unknown_type", replaced(">12 42<", ">99 42<"), at(t, offsets_tag), "found type 99"},
      // "12" is one digit more than "7": the offsets array moves one byte on.
      {"point_out_of_range", replaced("0 1 2 3 4 5 6 7 4", "0 1 2 3 4 5 6 12 4"), at(t, offsets_tag) + 1, "point id in [0, 11], found 12"},
      {"poly_not_closed", replaced("4 7 4 8 11", "4 7 4 8 0"), at(t, offsets_tag), "closed cell"},
      {"faceoffsets", replaced(">-1 31<", ">-1 40<"), at(t, offsets_tag), "faces and faceoffsets"},
      {"non_numeric", replaced("0 0 0 1 0 0 1 1 0", "0 0 0 1 x 0 1 1 0"), at(t, "<DataArray type=\"Float64\""), "a number in the ascii DataArray, found 'x"},
      {"bad_base64", b64, b64_text + 4, "base64 data, found the character code 33"},
      // Errors inside base64 text name the offset of the text.
      {"declared_size", huge, at(huge, ">6AMA"), "the 1000 bytes the data header declares, found 4"},
      {"corrupt_zlib", zbad, at(zbad, ">AQAAA"), "zlib data of block 0 inflating to 288 bytes (zlib: data error)"},
      {"missing_offsets", replaced("Name=\"offsets\"", "Name=\"offs\""), at(t, "<Cells"), "a DataArray named 'offsets'"},
      {"appended_offset", replaced("Name=\"types\" format=\"ascii\"", "Name=\"types\" format=\"appended\" offset=\"0\""), at(t, "<DataArray type=\"UInt8\""), "an AppendedData element"},
  });
}

// ---------------------------------------------------------------------------------------------
// OpenFOAM polyMesh: the two-hexahedra case of tests/data/formats/foam with one file changed; the
// error names that file and its line (byte offset once a binary file's header is read).

struct FoamCase {
  std::string name;
  std::string file;     // which of the four is broken
  std::string bytes;    // its new bytes
  int64_t where;        // line, or byte offset when `binary`
  std::string keyword;
  bool binary = false;
  std::string reported = {};  // the file the error names, when not `file`
};

void expect_foam_rejected(const std::string& dir, const std::vector<FoamCase>& cases) {
  const std::string base = std::string(HBC_FORMATS_DIR) + "/foam/" + dir + "/constant/polyMesh/";
  for (const FoamCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::map<std::string, std::string> bytes;
    for (const char* f : {"points", "faces", "owner", "neighbour"}) bytes[f] = f == c.file ? c.bytes : read_file_bytes(base + f);
    try {
      build_mesh(read_foam({bytes["points"], bytes["faces"], bytes["owner"], bytes["neighbour"], "points", "faces", "owner", "neighbour"}));
      ADD_FAILURE() << "accepted a malformed case";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), c.reported.empty() ? c.file : c.reported) << e.what();
      EXPECT_EQ(c.binary ? e.loc().byte_offset : e.loc().line, c.where) << e.what();
      EXPECT_NE(e.detail().find(c.keyword), std::string::npos) << "'" << c.keyword << "' not in: " << e.what();
    }
  }
}

std::string foam_file(const std::string& dir, const std::string& name) {
  return read_file_bytes(std::string(HBC_FORMATS_DIR) + "/foam/" + dir + "/constant/polyMesh/" + name);
}

// Two unit cubes along x with a boundary marker (lines 1-21): NELEM first, then 12 points with
// their index column on lines 6-17, one marker quadrangle on line 21.
std::string su2_sample() {
  std::string s = "NDIME= 3\nNELEM= 2\n12 0 1 4 3 6 7 10 9 0\n12 1 2 5 4 7 8 11 10 1\nNPOIN= 12\n";
  for (int i = 0; i < 12; ++i)
    s += std::to_string(i % 3) + " " + std::to_string(i / 3 % 2) + " " + std::to_string(i / 6) + " " + std::to_string(i) + "\n";
  return s + "NMARK= 1\nMARKER_TAG= bottom\nMARKER_ELEMS= 1\n9 0 3 4 1\n";
}

TEST(Malformed, Su2) {
  const std::string t = su2_sample();
  ASSERT_NO_THROW(build_mesh(read_su2(t, "ok.su2")));
  expect_all_rejected(Format::Su2, {
      {"empty", "", 1, "NDIME= 3 in an SU2 file"},
      {"dimension", with_line(t, 1, "NDIME= 2"), 1, "NDIME= 3"},
      {"unknown_type", with_line(t, 3, "11 0 1 4 3 6 7 10 9 0"), 3, "found 11"},
      {"too_few_ids", with_line(t, 3, "12 0 1 4 3 6 7 10"), 3, "8 point ids (and an optional index) for type 12, found 7"},
      {"id_out_of_range", with_line(t, 4, "12 1 2 5 4 7 8 11 12 1"), 4, "a point id in [0, 11], found 12"},
      // 5 point lines of 8 bytes cannot hold 12 points.
      {"truncated_points", first_lines(t, 10), 5, "number of points that the rest of the file can hold"},
      {"truncated_elements", first_lines(t, 3), 3, "an element line (type ids [index]), found the end of the file"},
      {"no_points", first_lines(t, 4), 4, "an NPOIN= section in the zone"},
      {"keyword", with_line(t, 18, "NMARKS= 1"), 18, "an SU2 keyword"},
      {"columns", with_line(t, 7, "1 0"), 7, "a point line of 4 numbers (x y z [index]), found 2"},
      {"non_numeric", with_line(t, 6, "0 zero 0 0"), 6, "a point coordinate (a finite number)"},
      {"no_keyword", with_line(t, 18, "1 2 3"), 18, "a KEYWORD= line"},
  });
}

// One pyramid (lines 1-7): the counts, 5 nodes on lines 2-6, the pyramid on line 7.
const std::string kUgrid = "5 0 0 0 1 0 0\n1 0 0\n0 0 0\n0.5 0.5 1\n1 1 0\n0 1 0\n1 2 3 4 5\n";

TEST(Malformed, Ugrid) {
  ASSERT_NO_THROW(build_mesh(read_ugrid(kUgrid, "ok.ugrid", UgridEncoding::Ascii)));
  expect_all_rejected(Format::Ugrid, {
      {"empty", "", 1, "the number of nodes, found the end of the file"},
      {"huge_count", with_line(kUgrid, 1, "500 0 0 0 1 0 0"), 1, "the number of nodes that the rest of the file can hold"},
      {"truncated", first_lines(kUgrid, 6), 6, "a node id of a volume element, found the end of the file"},
      {"truncated_coordinate", first_lines(kUgrid, 5) + "0 1", 6, "a node coordinate, found the end of the file"},
      {"id_out_of_range", with_line(kUgrid, 7, "1 2 3 4 6"), 7, "a node id in [1, 5], found 6"},
      {"no_volume", with_line(kUgrid, 1, "5 0 0 0 0 0 0"), 6, "at least one volume element"},
      {"non_numeric", with_line(kUgrid, 3, "0 x 0"), 3, "a node coordinate (a finite number), found 'x'"},
  });
}

TEST(Malformed, UgridBinary) {
  // kUgrid little-endian (lb8): counts at bytes 0-27, coordinates 28-147, the pyramid 148-167.
  test::Bytes b;
  for (int32_t v : {5, 0, 0, 0, 1, 0, 0}) b.put<int32_t>(v);
  for (double x : {1., 0., 0., 0., 0., 0., 0.5, 0.5, 1., 1., 1., 0., 0., 1., 0.}) b.put<double>(x);
  for (int32_t v : {1, 2, 3, 4, 5}) b.put<int32_t>(v);
  const std::string t = b.s;
  ASSERT_NO_THROW(build_mesh(read_ugrid(t, "ok.lb8.ugrid", UgridEncoding::LittleEndian)));
  auto rejected = [](const std::string& bytes, UgridEncoding enc, int64_t at, const std::string& what) {
    try {
      read_ugrid(bytes, "bad.ugrid", enc);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InputError& e) {
      EXPECT_EQ(e.loc().byte_offset, at) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  rejected(t.substr(0, 160), UgridEncoding::LittleEndian, 160, "a node id of a volume element (4 bytes), found the end of the file");
  rejected(patched<int32_t>(t, 164, 6), UgridEncoding::LittleEndian, 164, "a node id in [1, 5], found 6");
  rejected(patched<double>(t, 36, std::nan("")), UgridEncoding::LittleEndian, 36, "a node coordinate (a finite number)");
  // Read as big-endian, the count 5 is 83886080: more nodes than 168 bytes hold.
  rejected(t, UgridEncoding::BigEndian, 4, "the number of nodes that the rest of the file can hold");
}

// Two unit cubes as Fluent writes them: nodes on lines 7-18, the interior face on line 22, the
// ten boundary faces on lines 25-34 (see test_cfd_formats.cpp for their sides).
std::string fluent_sample() {
  std::string s = "(0 \"two cubes\")\n(2 3)\n(10 (0 1 c 0 3))\n(12 (0 1 2 0 0))\n(13 (0 1 b 0 0))\n(10 (1 1 c 1 3)(\n";
  for (int i = 0; i < 12; ++i) s += std::to_string(i % 3) + " " + std::to_string(i / 3 % 2) + " " + std::to_string(i / 6) + "\n";
  s += "))\n(12 (2 1 2 1 4))\n(13 (3 1 1 2 0)(\n4 2 5 b 8 2 1\n))\n(13 (4 2 b 3 4)(\n";
  for (const char* f : {"1 4 a 7 1 0", "1 7 8 2 1 0", "4 5 b a 1 0", "1 2 5 4 1 0", "7 a b 8 1 0", "3 9 c 6 2 0", "2 8 9 3 2 0",
                        "5 6 c b 2 0", "2 3 6 5 2 0", "8 b c 9 2 0"})
    s += std::string(f) + "\n";
  return s + "))\n(45 (2 fluid fluid)())\n(39 (3 interior int)())\n";
}

TEST(Malformed, Fluent) {
  const std::string t = fluent_sample();
  ASSERT_NO_THROW(build_mesh(read_fluent(t, "ok.msh")));
  expect_all_rejected(Format::Fluent, {
      {"empty", "", 1, "a face section (13) in a Fluent mesh, found the end of the file"},
      {"dimension", with_line(t, 2, "(2 2)"), 2, "a 3D mesh"},
      {"node_out_of_range", with_line(t, 22, "4 2 5 b d 2 1"), 22, "a node id of a node section (1 to 12), found 13"},
      // 6 lines of faces cannot hold the 10 the zone header announces.
      {"truncated", first_lines(t, 30), 24, "a face zone that the rest of the file can hold"},
      {"truncated_face", first_lines(t, 33) + "8 b c", 34, "a node id of a face (a hexadecimal integer), found the end of the file"},
      {"cell_id", with_line(t, 25, "1 4 a 7 -1 0"), 25, "a cell id in [0, 2^31 - 1), found -1"},
      {"no_faces", first_lines(t, 19), 19, "a face section (13) in a Fluent mesh"},
      {"unclosed", t + "(45 (5 wall", 38, "')' closing section 45, found the end of the file"},
      {"node_twice", with_line(t, 20, "(10 (2 1 1 1 3)(0 0 0))"), 20, "each node once, found node 1 again"},
      {"bad_hex", with_line(t, 21, "(13 (3 1 1 2 z)("), 21, "the element type or dimension of the zone (a hexadecimal integer)"},
      {"cell_without_faces", with_line(t, 4, "(12 (0 1 3 0 0))"), 4, "every cell from 1 to 3 to have faces, cell 3 has none"},
      {"not_a_section", "hello", 1, "'(' opening a Fluent section, found 'hello'"},
  });
}

TEST(Malformed, FluentBinary) {
  // A node section of 3010 (doubles) cut short: byte offsets from the start of the file.
  test::Bytes b;
  b.text("(2 3)\n(3010 (1 1 2 1 3)(");  // the coordinates start at byte 24
  for (int i = 0; i < 5; ++i) b.put<double>(0.5);
  try {
    read_fluent(b.s + "End of Binary Section 3010)\n", "bad.msh");
    ADD_FAILURE() << "accepted a truncated binary node section";
  } catch (const InputError& e) {
    // The sixth coordinate (byte 64) would need the 8 bytes "End of B": read as a double it is
    // finite, so the reader then misses the ')' closing the binary data.
    EXPECT_EQ(e.loc().byte_offset, 72) << e.what();
    EXPECT_NE(std::string(e.what()).find("')' closing the binary data"), std::string::npos) << e.what();
  }
}

TEST(Malformed, FoamAscii) {
  // points: the count on line 14, point i on line 16 + i; faces: face i on line 16 + i; owner
  // (one header line more, its note): the count on line 15, face i's owner on line 17 + i.
  const std::string p = foam_file("hex2_ascii", "points"), f = foam_file("hex2_ascii", "faces"),
                    o = foam_file("hex2_ascii", "owner"), n = foam_file("hex2_ascii", "neighbour");
  expect_foam_rejected("hex2_ascii", {
      {"empty_points", "points", "", 1, "the number of points (an integer), found the end of the file"},
      {"format", "points", with_line(p, 7, "    format      ebcdic;"), 7, "format ascii or binary, found 'ebcdic'"},
      {"header_entry", "faces", with_line(f, 10, "    object      faces"), 11, "';' ending the header entry object, found '}'"},
      {"point_word", "points", with_line(p, 18, "(0 one 0)"), 18, "a point coordinate (a number), found 'one'"},
      {"point_nan", "points", with_line(p, 18, "(0 nan 0)"), 18, "finite"},
      {"point_open", "points", with_line(p, 18, "0 1 0)"), 18, "'(' opening point 2"},
      {"too_many_points", "points", with_line(p, 14, "4000"), 14, "number of points that the rest of the file can hold"},
      {"too_few_points", "points", with_line(p, 14, "11"), 27, "')' closing the list of 11, found '(2'"},
      {"too_many_lists", "points", p + "2(0 1)\n", 32, "the end of the file after the list of points, found '2(0'"},
      {"point_label", "faces", with_line(f, 17, "4(0 6 9 12)"), 17, "a point label in [0, 11], found 12"},
      {"negative_label", "faces", with_line(f, 17, "4(0 6 -9 3)"), 17, "found -9"},
      {"face_unclosed", "faces", with_line(f, 17, "4(0 6 9 3"), 18, "')' closing the list of 4"},
      {"face_class", "faces", with_line(f, 8, "    class       cellList;"), 1, "class faceList or faceCompactList"},
      {"two_corners", "faces", with_line(f, 17, "2(0 6)"), 17, "at least 3"},
      {"owner_count", "owner", with_line(o, 15, "10"), 15, "one owner cell for each of the 11 faces, found 10"},
      {"owner_negative", "owner", with_line(o, 19, "-1"), 19, "a cell label in [0, 2^31), found -1"},
      {"neighbour_count", "neighbour", with_line(n, 15, "12(1 1 1 1 1 1 1 1 1 1 1 1)"), 15, "at most one neighbour cell for each of the 11 faces"},
      // Face 0 owned and neighboured by cell 0: cell 0 lists it twice (found by build_mesh, which
      // names the faces file, the MeshInput's source).
      {"face_twice", "neighbour", with_line(n, 15, "1(0)"), -1, "each face once per cell", false, "faces"},
      // Face 10 owned by cell 5: cells 2 to 4 own and neighbour nothing.
      {"cell_gap", "owner", with_line(o, 27, "5"), -1, "cell 2 has none"},
  });
}

TEST(Malformed, FoamBinary) {
  // hex2_binary as foamFormatConvert wrote it: faces a faceCompactList of 12 offsets, then 44
  // labels, each 4 bytes after its '('.
  const std::string f = foam_file("hex2_binary", "faces"), o = foam_file("hex2_binary", "owner");
  const size_t offsets = f.find("12\n(") + 4, labels = f.find("44\n(") + 4;
  const size_t owner_at = o.find("11\n(") + 4;
  std::string bad_label = f, bad_offset = f, bad_owner = o;
  bad_label[labels + 4 * 5] = 12;            // face 1's second label: point 12 of 12
  bad_offset[offsets + 4 * 3] = 3;           // offsets 0 4 8 3: falling
  bad_owner[owner_at + 4 * 2 + 3] = '\x80';  // a negative owner
  expect_foam_rejected("hex2_binary", {
      {"point_label", "faces", bad_label, static_cast<int64_t>(labels + 4 * 5), "a point label in [0, 11], found 12", true},
      {"falling_offsets", "faces", bad_offset, static_cast<int64_t>(offsets + 4 * 3), "face offsets rising from 0, found 3 after 8", true},
      {"truncated", "faces", f.substr(0, labels + 10), static_cast<int64_t>(labels - 4), "number of face labels that the rest of the file can hold (at most 3), found 44", true},
      // Cut inside the labels, the count padded to pass: the spaces read as a label.
      {"cut_labels", "faces", f.substr(0, labels + 10) + std::string(170, ' '), static_cast<int64_t>(labels + 8), "a point label in [0, 11], found", true},
      {"label_count", "faces", f.substr(0, labels - 4) + "43" + f.substr(labels - 2), static_cast<int64_t>(labels - 4), "44 face labels as the last offset says, found 43", true},
      {"owner_negative", "owner", bad_owner, static_cast<int64_t>(owner_at + 8), "a cell label in [0, 2^31)", true},
      {"arch", "owner", with_line(o, 13, "    arch        \"LSB;label=16;scalar=64\";"), 13, "label=32 or 64 in the arch entry"},
  });
}

TEST(Malformed, FoamGzipAndCaseFolders) {
  // A .gz file that is no gzip data: the file and the offset where zlib gave up.
  const auto dir = std::filesystem::temp_directory_path() / ("hbc_bad_foam_" + std::to_string(::getpid()));
  const auto mesh = dir / "constant" / "polyMesh";
  std::filesystem::create_directories(mesh);
  std::filesystem::copy(std::string(HBC_FORMATS_DIR) + "/foam/hex2_gzip/constant/polyMesh", mesh);
  {
    std::ofstream(mesh / "points.gz", std::ios::binary) << std::string("\x1f\x8b\x08\x00garbage", 11);
  }
  try {
    load_mesh(dir.string());
    ADD_FAILURE() << "accepted a broken .gz";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (mesh / "points.gz").string());
    EXPECT_NE(e.detail().find("gzip data"), std::string::npos) << e.what();
  }
  std::filesystem::remove(mesh / "points.gz");
  try {
    load_mesh(dir.string());
    ADD_FAILURE() << "accepted a case without points";
  } catch (const InputError& e) {
    EXPECT_NE(e.detail().find("the polyMesh file points (or points.gz)"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace

// The finite-element decks: a valid base file each, then each case breaks one thing. Errors at
// the end of a truncated record name the line the record started on.
const char* const kAbaqusBase = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 0., 1., 0.
4, 0., 0., 1.
*ELEMENT, TYPE=C3D4
1, 1, 2, 3, 4
)";

TEST(Malformed, Abaqus) {
  const std::string t = kAbaqusBase;
  ASSERT_NO_THROW(build_mesh(read_abaqus(t, "base.inp")));
  expect_all_rejected(Format::Abaqus, {
      {"empty", "", 1, "at least one volume element"},
      {"no_elements", first_lines(t, 5), 5, "at least one volume element"},
      {"truncated_record", first_lines(t, 6) + "1, 1, 2,\n", 7, "4 node labels for an element of type C3D4, found 2"},
      {"too_many_nodes", with_line(t, 7, "1, 1, 2, 3, 4, 4"), 7, "found more"},
      {"bad_coordinate", with_line(t, 3, "2, 1.x, 0., 0."), 3, "a node coordinate (a number), found '1.x'"},
      {"bad_label", with_line(t, 3, "-2, 1., 0., 0."), 3, "a node label (an integer label"},
      {"unknown_node", with_line(t, 7, "1, 1, 2, 3, 9"), 7, "found 9 which no node has"},
      {"duplicate_node", with_line(t, 4, "2, 0., 1., 0."), 4, "one *NODE with label 2, found a second (the first at bad_duplicate_node.inp:3)"},
      {"no_type", with_line(t, 6, "*ELEMENT"), 6, "TYPE=<element type>"},
      {"cylindrical", with_line(t, 1, "*NODE, SYSTEM=C"), 1, "SYSTEM=R"},
      {"instance_of_nothing", t + "*INSTANCE, NAME=I, PART=NONE\n", 8, "*INSTANCE of a *PART defined before it, found PART=NONE"},
      {"include_without_files", with_line(t, 1, "*NODE\n*INCLUDE, INPUT=more.inp"), 2, "no include"},
      {"repeated_corner", with_line(t, 7, "1, 1, 2, 3, 3"), 7, "a cell with at least 2 faces"},
  });
}

const char* const kNastranBase = R"(BEGIN BULK
GRID    1               0.      0.      0.
GRID    2               1.      0.      0.
GRID    3               0.      1.      0.
GRID    4               0.      0.      1.
CTETRA  1       1       1       2       3       4
ENDDATA
)";

TEST(Malformed, Nastran) {
  const std::string t = kNastranBase;
  ASSERT_NO_THROW(build_mesh(read_nastran(t, "base.bdf")));
  expect_all_rejected(Format::Nastran, {
      {"empty", "", 1, "at least one volume element (CHEXA, CPENTA, CPYRAM or CTETRA)"},
      {"truncated", first_lines(t, 5), 5, "at least one volume element"},
      {"bad_real", with_line(t, 3, "GRID    2               1.e     0.      0."), 3, "a coordinate of GRID 2 (a real), found '1.e'"},
      {"cord", with_line(t, 3, "GRID    2       5       1.      0.      0."), 3, "basic coordinate system"},
      {"few_grids", with_line(t, 6, "CTETRA  1       1       1       2       3"), 6, "a CTETRA with 4 to 10 grid ids, found 3"},
      {"unknown_grid", with_line(t, 6, "CTETRA  1       1       1       2       3       7"), 6, "found 7 which no node has"},
      {"bad_grid_id", with_line(t, 6, "CTETRA  1       1       1       2       3       x"), 6, "a grid id of the element"},
      {"blank_corner", with_line(t, 6, "CTETRA  1       1       1               3       4"), 6, "a grid id of the element (an integer from 1 to 2^32 - 1), found an empty field"},
      {"too_many_grids", with_line(t, 6, "CTETRA,1,1,1,2,3,4,5,6,+\n+,7,8,9,10,11"), 6, "a CTETRA with 4 to 10 grid ids, found 11"},
      {"orphan_continuation", "BEGIN BULK\n+       1       2\n", 2, "a bulk data entry before its continuation line"},
      {"duplicate_grid", with_line(t, 3, "GRID    1               1.      0.      0."), 3, "one GRID with label 1, found a second"},
      {"include_without_files", with_line(t, 2, "INCLUDE 'grids.bdf'"), 2, "no include"},
  });
}

const char* const kLsDynaBase = R"(*KEYWORD
*NODE
       1             0.0             0.0             0.0
       2             1.0             0.0             0.0
       3             0.0             1.0             0.0
       4             0.0             0.0             1.0
*ELEMENT_SOLID
       1       1       1       2       3       4       4       4       4       4
*END
)";

TEST(Malformed, LsDyna) {
  const std::string t = kLsDynaBase;
  ASSERT_NO_THROW(build_mesh(read_lsdyna(t, "base.k")));
  expect_all_rejected(Format::LsDyna, {
      {"empty", "", 1, "at least one volume element (*ELEMENT_SOLID)"},
      {"truncated", first_lines(t, 6), 6, "at least one volume element"},
      {"pending_card", first_lines(t, 7) + "       1       1\n", 8, "the node card of the *ELEMENT_SOLID element above, found none"},
      {"pending_keyword", with_line(t, 8, "       1       1"), 8, "the node card of the *ELEMENT_SOLID element above, found '*END'"},
      {"bad_coordinate", with_line(t, 4, "       2             1.0           abc             0.0"), 4, "a coordinate of node 2 (a number), found 'abc'"},
      {"bad_node_id", with_line(t, 8, "       1       1       1       2       3       x       4       4       4       4"), 8, "a node id of the element"},
      {"blank_corner", with_line(t, 8, "       1       1       1       2       3"), 8, "a blank N4"},
      {"half_blank", with_line(t, 8, "       1       1       1       2       3       4       1       2"), 8, "all set, or all blank"},
      {"unknown_node", with_line(t, 8, "       1       1       1       2       3       9       9       9       9       9"), 8, "found 9 which no node has"},
      {"solid_variant", with_line(t, 7, "*ELEMENT_SOLID_H20"), 7, "found *ELEMENT_SOLID_H20"},
      {"include_without_files", with_line(t, 2, "*INCLUDE\nnodes.k\n*NODE"), 3, "no include"},
  });
}

}  // namespace hbc
