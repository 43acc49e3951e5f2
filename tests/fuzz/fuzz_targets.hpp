#pragma once
// The code paths the fuzzers drive, shared with tests/cpp/test_fuzz_regressions.cpp so that every
// kept crash input is replayed through exactly what crashed. Each function accepts any bytes; the
// only exception caught is hbc::InputError (the readers' verdict on bad input). Anything else
// escapes: under libFuzzer an uncaught exception, a crash, UB or a leak stops the run and keeps the
// input; the regression test reports it as a failure naming the file.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "hbc/analysis.hpp"
#include "hbc/io.hpp"
#include "hbc/mesh.hpp"

namespace hbc::fuzz {

// The OpenFOAM harness's input: points, faces, owner and neighbour one after the other, each ended
// by the line "#-#-#" (what is missing is empty).
inline FoamFiles foam_files(std::string_view bytes) {
  std::string_view part[4];
  for (auto& p : part) {
    const size_t end = bytes.find("\n#-#-#\n");
    p = bytes.substr(0, end);
    bytes = end == std::string_view::npos ? std::string_view() : bytes.substr(end + 7);
  }
  return {part[0], part[1], part[2], part[3], "points", "faces", "owner", "neighbour"};
}

// The decomposed-case harness's input: the files of each processor (points, faces, owner,
// neighbour, point-, face- and cellProcAddressing, boundary), all ended by "#-#-#" lines as above,
// processor after processor; at most 4 processors (8 files each, the last one's missing files empty).
inline std::vector<FoamProcessorFiles> foam_processors(std::string_view bytes) {
  std::vector<FoamProcessorFiles> out;
  while (!bytes.empty() && out.size() < 4) {
    std::string_view part[8];
    for (auto& p : part) {
      const size_t end = bytes.find("\n#-#-#\n");
      p = bytes.substr(0, end);
      bytes = end == std::string_view::npos ? std::string_view() : bytes.substr(end + 7);
    }
    const std::string d = "processor" + std::to_string(out.size()) + "/";
    out.push_back({{part[0], part[1], part[2], part[3], d + "points", d + "faces", d + "owner", d + "neighbour"},
                   part[4], part[5], part[6], d + "pointProcAddressing", d + "faceProcAddressing",
                   d + "cellProcAddressing", part[7], d + "boundary"});
  }
  return out;
}

// CGNS's library opens files only: the bytes go to a file of this process's own first.
inline MeshInput read_cgns_bytes(std::string_view bytes) {
  const std::string path = (std::filesystem::temp_directory_path() / ("hbc_fuzz_" + std::to_string(::getpid()) + ".cgns")).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return read_cgns(path);
}

// What the deck harnesses' includes read: one small fixed file, so that an input including itself
// many times cannot multiply its own size.
inline std::string fuzz_include(const std::string&, const std::string&, std::string& name) {
  name = "included";
  return "1, 0, 0, 0\n2, 1, 0, 0\n";
}

inline MeshInput read_as(Format f, std::string_view bytes) {
  switch (f) {
    case Format::Ovm: return read_ovm(bytes, "fuzz");
    case Format::Ovmb: return read_ovmb(bytes, "fuzz");
    case Format::Medit: return read_medit(bytes, "fuzz");
    case Format::Hybrid: return read_hybrid(bytes, "fuzz");
    case Format::Hedra: return read_hedra(bytes, "fuzz");
    case Format::Msh: return read_msh(bytes, "fuzz");
    case Format::Vtk: return read_vtk(bytes, "fuzz");
    case Format::Vtu: return read_vtu(bytes, "fuzz");
    case Format::Foam: return read_foam(foam_files(bytes));
    case Format::Su2: return read_su2(bytes, "fuzz");
    // The first byte picks the encoding, so one corpus holds all five.
    case Format::Ugrid:
      if (bytes.empty()) return read_ugrid(bytes, "fuzz", UgridEncoding::Ascii);
      return read_ugrid(bytes.substr(1), "fuzz", static_cast<UgridEncoding>(static_cast<uint8_t>(bytes[0]) % 5));
    case Format::Fluent: return read_fluent(bytes, "fuzz");
    case Format::Exodus: return read_exodus(bytes, "fuzz");
    case Format::Cgns: return read_cgns_bytes(bytes);
    case Format::Abaqus: return read_abaqus(bytes, "fuzz", fuzz_include);
    case Format::Nastran: return read_nastran(bytes, "fuzz", fuzz_include);
    case Format::LsDyna: return read_lsdyna(bytes, "fuzz", fuzz_include);
    case Format::Med: return read_med(bytes, "fuzz");
    case Format::Xdmf: return read_xdmf(bytes, "fuzz");
    case Format::Auto: break;
  }
  std::abort();
}

// The analyze harness's first byte picks the reader, so one corpus mixes all eight formats.
inline Format format_of_selector(uint8_t b) {
  constexpr Format kFormats[8] = {Format::Ovm, Format::Ovmb, Format::Medit, Format::Hybrid,
                                  Format::Hedra, Format::Msh, Format::Vtk, Format::Vtu};
  return kFormats[b % 8];
}

// A failed invariant on a mesh that was accepted. Not an InputError, so it escapes the harness.
inline void check(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("invariant broken: ") + what);
}

// read_X + build_mesh. Returns true when the bytes were accepted.
inline bool read_and_build(Format f, std::string_view bytes) {
  try {
    Mesh m = build_mesh(read_as(f, bytes));
    // What build_mesh promises about an accepted mesh, cheap enough to check on every input.
    check(m.face_cells.size() == m.num_faces() && m.cell_type.size() == m.num_cells(), "array sizes");
    for (const auto& fc : m.face_cells)
      check(fc[0] >= 0 && static_cast<size_t>(fc[0]) < m.num_cells() && fc[1] < static_cast<int32_t>(m.num_cells()),
            "face cells in range");
    for (const auto& e : m.edge_verts)
      check(e[0] >= 0 && e[0] < e[1] && static_cast<size_t>(e[1]) < m.num_vertices(), "edge ends in range");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// join_foam_processors (one thread and two: the same result) + build_mesh.
inline bool join_and_build(std::string_view bytes) {
  try {
    const std::vector<FoamProcessorFiles> procs = foam_processors(bytes);
    MeshInput one = join_foam_processors(procs, "case", {1, 1});
    const MeshInput two = join_foam_processors(procs, "case", {2, 1});
    check(one.points == two.points && one.faces == two.faces && one.cells == two.cells, "same join for any thread count");
    const Mesh m = build_mesh(std::move(one));
    check(m.face_cells.size() == m.num_faces(), "array sizes");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// Selector byte, then a file; the whole pipeline on whatever parses, plus the base complex's
// invariants that hold for every mesh (every cell in exactly one component, non-hex cells alone).
inline bool load_and_analyze(std::string_view data) {
  if (data.empty()) return false;
  const Format f = format_of_selector(static_cast<uint8_t>(data[0]));
  Mesh m;
  try {
    m = build_mesh(read_as(f, data.substr(1)));
  } catch (const InputError&) {
    return false;
  }
  const Analysis a = analyze(m);
  const BaseComplex& bc = a.complex;
  const size_t nc = m.num_cells();
  check(bc.cell_component.size() == nc, "one component per cell");
  size_t listed = 0;
  for (size_t k = 0; k < bc.num_components(); ++k) {
    for (int32_t c : bc.component_cells[k]) {
      check(c >= 0 && static_cast<size_t>(c) < nc && bc.cell_component[c] == static_cast<int32_t>(k),
            "component lists agree with cell_component");
      check(m.is_hex(c) == (bc.component_kind[k] != ComponentKind::NonHex), "hex cells in hex components");
      ++listed;
    }
    if (bc.component_kind[k] == ComponentKind::NonHex)
      check(bc.component_cells.count(k) == 1, "non-hex cells alone in their component");
  }
  check(listed == nc, "every cell in exactly one component");
  const Stats s = compute_stats(m, a);
  check(s.cells == static_cast<int64_t>(nc) && s.components == static_cast<int64_t>(bc.num_components()),
        "stats agree with the analysis");
  return true;
}

}  // namespace hbc::fuzz
