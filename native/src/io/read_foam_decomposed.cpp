// OpenFOAM cases decomposed by decomposePar into processor0/ .. processorN-1/, read as the mesh
// they were cut from, without reconstructPar. Each processor is a polyMesh of its own plus three
// labelLists beside it that give every local point, face and cell its id in the undecomposed mesh
// (faceProcAddressing: id + 1, negated where the processor sees the face reversed). A face between
// two processors is on a processor patch of both: once as written (+, the side of its owner cell)
// and once reversed (-, the side of its neighbour); joined, it is one internal face again. So the
// join is a relabelling, not a geometric match: no tolerance, and the numbering of decomposePar's
// input comes back (reconstructParMesh merges by geometry and numbers otherwise).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <limits>

#include "hbc/io.hpp"
#include "io/detail/foam_files.hpp"
#include "parallel/parallel.hpp"
#include "platform/worker_pool.hpp"

namespace hbc {
namespace {

namespace fs = std::filesystem;

constexpr int64_t kMaxId = std::numeric_limits<int32_t>::max();
enum Addressing { kPoint = 0, kFace = 1, kCell = 2 };
constexpr const char* kAddressingFile[3] = {"pointProcAddressing", "faceProcAddressing", "cellProcAddressing"};
constexpr const char* kWhat[3] = {"point", "face", "cell"};

// A processor patch of a processor's `boundary` file: its faces [start, start + n), the processor
// on their other side, and the line of its entry.
struct ProcPatch {
  int64_t start = 0, n = 0, neighbour = -1, line = 0;
  std::string name;
};

// The words and brackets of a dictionary file, with their lines; comments skipped.
class DictTokens {
 public:
  DictTokens(std::string_view t, const std::string& source) : t_(t), source_(source) {}
  bool next(std::string_view& tok) {
    for (;;) {
      while (pos_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[pos_]))) line_ += t_[pos_++] == '\n';
      if (t_.substr(pos_, 2) == "//") pos_ = std::min(t_.find('\n', pos_), t_.size());
      else if (t_.substr(pos_, 2) == "/*") {
        const size_t e = std::min(t_.find("*/", pos_ + 2), t_.size());
        line_ += std::count(t_.begin() + static_cast<ptrdiff_t>(pos_), t_.begin() + static_cast<ptrdiff_t>(e), '\n');
        pos_ = std::min(e + 2, t_.size());
      } else break;
    }
    if (pos_ >= t_.size()) return false;
    const size_t b = pos_;
    if (std::string_view("{}();").find(t_[pos_]) != std::string_view::npos) ++pos_;
    else if (t_[pos_] == '"') pos_ = std::min(t_.find('"', pos_ + 1), t_.size() - 1) + 1;
    else
      while (pos_ < t_.size() && !std::isspace(static_cast<unsigned char>(t_[pos_])) && std::string_view("{}();").find(t_[pos_]) == std::string_view::npos) ++pos_;
    tok = t_.substr(b, pos_ - b);
    return true;
  }
  std::string_view need(const char* what) {
    std::string_view tok;
    if (!next(tok)) fail(std::string(what) + ", found the end of the file");
    return tok;
  }
  int64_t number(const char* what) {
    const std::string_view tok = need(what);
    int64_t v = 0;
    const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (r.ec != std::errc() || r.ptr != tok.data() + tok.size()) fail(std::string(what) + " (an integer), found '" + std::string(tok) + "'");
    return v;
  }
  [[noreturn]] void fail(const std::string& expected) const { throw InputError(source_, SourceLoc::at_line(line_), "expected " + expected); }
  int64_t line() const { return line_; }

 private:
  std::string_view t_;
  const std::string& source_;
  size_t pos_ = 0;
  int64_t line_ = 1;
};

// One patch entry "name { key value; ... }" (nested lists and dictionaries skipped).
ProcPatch read_patch(DictTokens& d, std::string_view name, bool& processor) {
  ProcPatch p;
  p.name = std::string(name);
  p.line = d.line();
  if (d.need("'{' opening the patch entry") != "{") d.fail("'{' after the patch name " + p.name);
  processor = false;
  for (int depth = 1; depth > 0;) {
    const std::string_view tok = d.need("'}' closing a patch entry");
    if (tok == "{" || tok == "(") ++depth;
    else if (tok == "}" || tok == ")") --depth;
    else if (depth == 1 && tok == "type") processor = d.need("the patch type") == "processor";
    else if (depth == 1 && tok == "nFaces") p.n = d.number("the patch's nFaces");
    else if (depth == 1 && tok == "startFace") p.start = d.number("the patch's startFace");
    else if (depth == 1 && tok == "neighbProcNo") p.neighbour = d.number("the patch's neighbProcNo");
  }
  return p;
}

// The processor patches of a `boundary` file (polyBoundaryMesh: a FoamFile header, then a list of
// patch entries); always text, whatever the mesh's format.
std::vector<ProcPatch> processor_patches(std::string_view text, const std::string& source) {
  DictTokens d(text, source);
  std::string_view tok = d.need("the FoamFile header or the number of patches");
  if (tok == "FoamFile") {
    if (d.need("'{' opening the FoamFile header") != "{") d.fail("'{' opening the FoamFile header");
    for (int depth = 1; depth > 0;) {
      tok = d.need("'}' closing the FoamFile header");
      depth += tok == "{" ? 1 : tok == "}" ? -1 : 0;
    }
    tok = d.need("the number of patches");
  }
  if (d.need("'(' opening the list of patches") != "(") d.fail("'(' opening the list of patches");
  std::vector<ProcPatch> out;
  while ((tok = d.need("a patch name or ')'")) != ")") {
    bool processor = false;
    ProcPatch p = read_patch(d, tok, processor);
    if (processor) out.push_back(std::move(p));
  }
  return out;
}

// One processor as read: its local mesh, its three addressing lists, and the lists' bytes and
// names, kept to locate a label that the join finds wrong.
struct Part {
  MeshInput mesh;
  std::vector<int64_t> ids[3];
  std::string_view bytes[3];
  std::string names[3];
  std::vector<ProcPatch> patches;       // none when the boundary file was not given
  std::string boundary_name;
  std::vector<detail::FileText> files;  // the bytes above, when read from a case folder
};

size_t local_count(const Part& p, int a) {
  return a == kPoint ? p.mesh.points.size() / 3 : a == kFace ? p.mesh.faces.rows() : p.mesh.cells.rows();
}

// Label i of list `a` is wrong: the error names its file and line (byte offset when binary),
// found by reading the list again, which only this path pays for.
[[noreturn]] void fail_label(const Part& p, int a, size_t i, const std::string& expected) {
  std::vector<int64_t> locs;
  bool binary = false;
  detail::read_foam_labels(p.bytes[a], p.names[a], &locs, &binary);
  const SourceLoc at = i < locs.size() ? (binary ? SourceLoc::at_byte(locs[i]) : SourceLoc::at_line(locs[i])) : SourceLoc{};
  throw InputError(p.names[a], at, "expected " + expected);
}

Part read_part(const FoamProcessorFiles& f) {
  Part p;
  p.mesh = read_foam(f.mesh);
  p.bytes[kPoint] = f.point_addressing, p.bytes[kFace] = f.face_addressing, p.bytes[kCell] = f.cell_addressing;
  p.names[kPoint] = f.point_addressing_name, p.names[kFace] = f.face_addressing_name;
  p.names[kCell] = f.cell_addressing_name;
  if (!f.boundary.empty()) {
    p.boundary_name = f.boundary_name;
    p.patches = processor_patches(f.boundary, f.boundary_name);
    for (const ProcPatch& q : p.patches)
      if (q.start < 0 || q.n < 0 || q.n > static_cast<int64_t>(p.mesh.faces.rows()) ||
          q.start > static_cast<int64_t>(p.mesh.faces.rows()) - q.n)
        throw InputError(f.boundary_name, SourceLoc::at_line(q.line), "expected patch " + q.name + "'s faces among the processor's " +
                                                                          std::to_string(p.mesh.faces.rows()) + " faces");
  }
  for (int a = 0; a < 3; ++a) {
    p.ids[a] = detail::read_foam_labels(p.bytes[a], p.names[a]);
    if (p.ids[a].size() != local_count(p, a))
      throw InputError(p.names[a], {}, "expected " + std::to_string(local_count(p, a)) + " labels, one for each " + kWhat[a] +
                                           " of the processor's mesh, found " + std::to_string(p.ids[a].size()));
  }
  return p;
}

// read(i) for every processor, in parallel; the lowest processor's error wins, whatever the
// thread count (parallel_ranges keeps ranges in order and each range stops at its first).
template <class Read>
std::vector<Part> read_parts(size_t n, const Threads& threads, Read&& read) {
  const Threads par = detail::with_grain(resolved(threads), 1);
  std::vector<Part> parts(n);
  detail::parallel_ranges(n, par, [&](size_t b, size_t e, int) {
    for (size_t i = b; i < e; ++i) parts[i] = read(i);
  });
  return parts;
}

// The undecomposed count of `a`'s ids: one above the highest, each id checked against the most
// there can be (the processors' local counts summed; faceProcAddressing's signed and 1-based).
int32_t global_count(const std::vector<Part>& parts, int a) {
  int64_t room = 0;
  for (const Part& p : parts) room += static_cast<int64_t>(local_count(p, a));
  room = std::min(room, kMaxId);
  int64_t n = 0;
  for (const Part& p : parts)
    for (size_t i = 0; i < p.ids[a].size(); ++i) {
      const int64_t v = p.ids[a][i];
      if (a == kFace ? v == 0 || v < -room || v > room : v < 0 || v >= room) {
        const std::string range = a == kFace ? "[-" + std::to_string(room) + ", -1] or [1, " + std::to_string(room) + "]"
                                             : "[0, " + std::to_string(room - 1) + "]";
        fail_label(p, a, i, std::string("a ") + kWhat[a] + " id in " + range + " (at most the processors' " + kWhat[a] +
                                "s together), found " + std::to_string(v));
      }
      n = std::max(n, a == kFace ? (v < 0 ? -v : v) : v + 1);
    }
  return static_cast<int32_t>(n);
}

// Where each undecomposed face is: the processor and local face of the copy that sees it as
// written (+), and of its twin that sees it reversed (-, processor faces only).
struct FaceCopies {
  std::vector<int32_t> part[2], face[2];  // [0]: the + copy, [1]: the - copy; -1 for none
};

FaceCopies face_copies(const std::vector<Part>& parts, int32_t nf) {
  FaceCopies c;
  for (int s = 0; s < 2; ++s) c.part[s].assign(static_cast<size_t>(nf), -1), c.face[s].assign(static_cast<size_t>(nf), -1);
  for (size_t p = 0; p < parts.size(); ++p)
    for (size_t lf = 0; lf < parts[p].ids[kFace].size(); ++lf) {
      const int64_t v = parts[p].ids[kFace][lf];
      const size_t g = static_cast<size_t>((v < 0 ? -v : v) - 1);
      const int s = v < 0 ? 1 : 0;
      if (c.part[s][g] >= 0)
        fail_label(parts[p], kFace, lf, "each face once on each side, found face " + std::to_string(g) +
                                            (s ? " reversed" : " as written") + " in processor " +
                                            std::to_string(c.part[s][g]) + " too");
      c.part[s][g] = static_cast<int32_t>(p), c.face[s][g] = static_cast<int32_t>(lf);
    }
  return c;
}

// Cells each local face is in (1 on a patch, 2 inside the processor).
std::vector<std::vector<uint8_t>> local_face_cells(const std::vector<Part>& parts, const Threads& par) {
  std::vector<std::vector<uint8_t>> out(parts.size());
  detail::parallel_ranges(parts.size(), detail::with_grain(par, 1), [&](size_t b, size_t e, int) {
    for (size_t p = b; p < e; ++p) {
      out[p].assign(parts[p].mesh.faces.rows(), 0);
      for (int32_t item : parts[p].mesh.cells.items) ++out[p][static_cast<size_t>(item >> 1)];
    }
  });
  return out;
}

// Each face of a processor patch has its twin on the processor the patch names: a missing
// processor folder, or addressing that lost a face, leaves a hole in the mesh that nothing else
// would show.
void check_patch_neighbours(const std::vector<Part>& parts) {
  for (const Part& p : parts)
    for (const ProcPatch& q : p.patches)
      if (q.neighbour < 0 || q.neighbour >= static_cast<int64_t>(parts.size()))
        throw InputError(p.boundary_name, SourceLoc::at_line(q.line),
                         "expected the folder processor" + std::to_string(q.neighbour) + " that patch " + q.name +
                             " faces, found processor0 .. processor" + std::to_string(parts.size() - 1) + " only");
}

void check_processor_patches(const std::vector<Part>& parts, const FaceCopies& c) {
  for (const Part& p : parts)
    for (const ProcPatch& q : p.patches) {
      const SourceLoc at = SourceLoc::at_line(q.line);
      for (int64_t lf = q.start; lf < q.start + q.n; ++lf) {
        const int64_t v = p.ids[kFace][static_cast<size_t>(lf)];
        const size_t g = static_cast<size_t>((v < 0 ? -v : v) - 1);
        const int32_t twin = c.part[v < 0 ? 0 : 1][g];
        if (twin != q.neighbour)
          throw InputError(p.boundary_name, at, "expected face " + std::to_string(g) + " of patch " + q.name + " (local face " +
                                                    std::to_string(lf) + ") on processor" + std::to_string(q.neighbour) + " too, found it " +
                                                    (twin < 0 ? "on no other processor" : "on processor" + std::to_string(twin)));
      }
    }
}

// Every face has its + copy; a - copy pairs two processor-patch faces; and the faces in two cells
// come first, as OpenFOAM numbers internal faces, so that a processor face whose twin is missing
// (a face in one cell before faces in two) is found, not read as a hole in the mesh.
void check_faces(const std::vector<Part>& parts, const FaceCopies& c, const std::vector<std::vector<uint8_t>>& in_cells,
                 const std::string& source) {
  const size_t nf = c.part[0].size();
  size_t first_single = nf;  // the first face in one cell
  for (size_t g = 0; g < nf; ++g) {
    if (c.part[0][g] < 0) {
      if (c.part[1][g] < 0) throw InputError(source, {}, "expected face " + std::to_string(g) + " (below the highest face id) on a processor, found it on none");
      const Part& p = parts[static_cast<size_t>(c.part[1][g])];
      fail_label(p, kFace, static_cast<size_t>(c.face[1][g]),
                 "the twin of this processor face (face " + std::to_string(g + 1) + " as written) on another processor, found none");
    }
    int cells = in_cells[static_cast<size_t>(c.part[0][g])][static_cast<size_t>(c.face[0][g])];
    if (c.part[1][g] >= 0) {
      const int twin = in_cells[static_cast<size_t>(c.part[1][g])][static_cast<size_t>(c.face[1][g])];
      if (cells != 1 || twin != 1)
        fail_label(parts[static_cast<size_t>(c.part[1][g])], kFace, static_cast<size_t>(c.face[1][g]),
                   "a reversed face only on a processor patch, with its twin on one, found face " + std::to_string(g) + " in " +
                       std::to_string(cells + twin) + " cells");
      cells = 2;
    }
    if (cells == 1 && first_single == nf) first_single = g;
    if (cells == 2 && first_single < g)
      throw InputError(source, {}, "expected the faces between two cells numbered first, found face " + std::to_string(first_single) +
                                       " in one cell before face " + std::to_string(g) +
                                       " in two: a processor face whose twin is missing from faceProcAddressing");
  }
}

// The points in undecomposed order, each from the lowest processor that has it.
std::vector<double> join_points(const std::vector<Part>& parts, int32_t np, const std::string& source) {
  std::vector<double> xyz(3 * static_cast<size_t>(np));
  std::vector<uint8_t> set(static_cast<size_t>(np), 0);
  for (const Part& p : parts)
    for (size_t i = 0; i < p.ids[kPoint].size(); ++i) {
      const auto g = static_cast<size_t>(p.ids[kPoint][i]);
      if (set[g]) continue;
      set[g] = 1;
      std::copy_n(p.mesh.points.begin() + static_cast<ptrdiff_t>(3 * i), 3, xyz.begin() + static_cast<ptrdiff_t>(3 * g));
    }
  const auto missing = std::find(set.begin(), set.end(), 0);
  if (missing != set.end())
    throw InputError(source, {}, "expected point " + std::to_string(missing - set.begin()) +
                                     " (below the highest point id) on a processor, found it on none (pointProcAddressing)");
  return xyz;
}

// Face g's loop in undecomposed point ids, from its + copy (written as the undecomposed face).
Csr<int32_t> join_faces(const std::vector<Part>& parts, const FaceCopies& c, const Threads& par) {
  const size_t nf = c.part[0].size();
  Csr<int32_t> faces;
  faces.offsets.resize(nf + 1);
  for (size_t g = 0; g < nf; ++g) {
    const int64_t n = parts[static_cast<size_t>(c.part[0][g])].mesh.faces.count(static_cast<size_t>(c.face[0][g]));
    if (faces.offsets[g] + n > kMaxId) throw InputError(parts[0].names[kFace], {}, "fewer than 2^31 face corners in all");
    faces.offsets[g + 1] = static_cast<int32_t>(faces.offsets[g] + n);
  }
  faces.items.resize(static_cast<size_t>(faces.offsets.back()));
  detail::parallel_ranges(nf, par, [&](size_t b, size_t e, int) {
    for (size_t g = b; g < e; ++g) {
      const Part& p = parts[static_cast<size_t>(c.part[0][g])];
      int32_t* out = faces.items.data() + faces.offsets[g];
      for (int32_t v : p.mesh.faces[static_cast<size_t>(c.face[0][g])]) *out++ = static_cast<int32_t>(p.ids[kPoint][static_cast<size_t>(v)]);
    }
  });
  return faces;
}

// A processor face and its twin must be the same polygon: the twin's points, mapped, are the
// face's. (decomposePar writes the twin reversed with its first point kept.)
void check_twins(const std::vector<Part>& parts, const FaceCopies& c, const Csr<int32_t>& faces) {
  std::vector<int32_t> a, b;
  for (size_t g = 0; g < faces.rows(); ++g) {
    if (c.part[1][g] < 0) continue;
    const Part& p = parts[static_cast<size_t>(c.part[1][g])];
    a.assign(faces[g].begin(), faces[g].end());
    b.clear();
    for (int32_t v : p.mesh.faces[static_cast<size_t>(c.face[1][g])]) b.push_back(static_cast<int32_t>(p.ids[kPoint][static_cast<size_t>(v)]));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b)
      fail_label(p, kFace, static_cast<size_t>(c.face[1][g]),
                 "the same points as the twin of this processor face (face " + std::to_string(g) + "), found others");
  }
}

// Cell rows in undecomposed ids: each local 2*face + flip as 2*g + (flip, reversed once more where
// this processor sees g reversed), sorted, which is face order as read_foam lists a cell's faces.
Csr<int32_t> join_cells(const std::vector<Part>& parts, int32_t nc, const Threads& par) {
  std::vector<int32_t> count(static_cast<size_t>(nc), -1);
  for (const Part& p : parts)
    for (size_t i = 0; i < p.ids[kCell].size(); ++i) {
      int32_t& n = count[static_cast<size_t>(p.ids[kCell][i])];
      if (n >= 0) fail_label(p, kCell, i, "each cell on one processor, found cell " + std::to_string(p.ids[kCell][i]) + " twice");
      n = p.mesh.cells.count(i);
    }
  // No cell is missing: the processors' cells, as many as their ids' room (global_count) and
  // each id once, fill it.
  Csr<int32_t> cells;
  cells.offsets.resize(static_cast<size_t>(nc) + 1);
  for (size_t c = 0; c < count.size(); ++c) cells.offsets[c + 1] = cells.offsets[c] + count[c];
  cells.items.resize(static_cast<size_t>(cells.offsets.back()));
  detail::parallel_ranges(parts.size(), detail::with_grain(par, 1), [&](size_t b, size_t e, int) {
    for (size_t q = b; q < e; ++q) {
      const Part& p = parts[q];
      for (size_t i = 0; i < p.ids[kCell].size(); ++i) {
        const auto row = cells.row(static_cast<size_t>(p.ids[kCell][i]));
        size_t k = 0;
        for (int32_t item : p.mesh.cells[i]) {
          const int64_t v = p.ids[kFace][static_cast<size_t>(item >> 1)];
          row[k++] = static_cast<int32_t>(2 * ((v < 0 ? -v : v) - 1) + ((item & 1) ^ (v < 0 ? 1 : 0)));
        }
        std::sort(row.begin(), row.end());
      }
    }
  });
  return cells;
}

MeshInput join_parts(const std::vector<Part>& parts, const std::string& source, const Threads& par) {
  if (parts.empty()) throw InputError(source, {}, "expected at least one processor folder (processor0)");
  check_patch_neighbours(parts);  // first: a missing processor explains the ids out of range
  const int32_t np = global_count(parts, kPoint), nf = global_count(parts, kFace), nc = global_count(parts, kCell);
  const FaceCopies copies = face_copies(parts, nf);
  check_processor_patches(parts, copies);
  check_faces(parts, copies, local_face_cells(parts, par), source);
  MeshInput in;
  in.source = source;
  in.cells = join_cells(parts, nc, par);
  in.points = join_points(parts, np, source);
  in.faces = join_faces(parts, copies, par);
  check_twins(parts, copies, in.faces);
  for (const Part& p : parts) in.warnings.insert(in.warnings.end(), p.mesh.warnings.begin(), p.mesh.warnings.end());
  return in;
}

// processor0 .. processorN-1 of the case, in order; InputError for a gap or for the collated
// layout (processorsN/), whose files hold every processor at once.
std::vector<fs::path> processor_dirs(const fs::path& c) {
  std::vector<std::pair<int64_t, fs::path>> found;
  std::error_code ec;
  for (fs::directory_iterator it(c, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!it->is_directory(ec) || name.rfind("processor", 0) != 0) continue;
    const char* b = name.data() + 9;
    const char* e = name.data() + name.size();
    if (b < e && *b == 's')
      throw InputError(it->path().string(), {}, "expected processor0/ .. processorN-1/ (decomposePar's uncollated layout), found "
                                                "the collated processors folder, which hbc does not read: decompose with "
                                                "-fileHandler uncollated, or reconstructPar");
    int64_t k = 0;
    const auto r = std::from_chars(b, e, k);
    if (r.ec == std::errc() && r.ptr == e && b < e) found.emplace_back(k, it->path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (size_t i = 0; i < found.size(); ++i) {
    if (found[i].first != static_cast<int64_t>(i))
      throw InputError(c.string(), {}, "expected processor0 .. processorN-1 without a gap, found " +
                                           found[i].second.filename().string() + " but no processor" + std::to_string(i));
    out.push_back(found[i].second);
  }
  if (out.empty()) throw InputError(c.string(), {}, "expected a decomposed OpenFOAM case (processor0/ ...), found no processor folder");
  return out;
}

// One processor folder: its mesh where a case keeps one, and the addressing beside it.
Part read_processor(const fs::path& dir) {
  const fs::path mesh = detail::case_mesh(dir);
  if (mesh.empty())
    throw InputError(dir.string(), {}, "expected a processor's polyMesh (constant/polyMesh/owner or a time folder's), found none");
  Part p;
  std::vector<detail::FileText> files;
  files.reserve(8);
  for (const char* name : {"points", "faces", "owner", "neighbour", "boundary"}) files.push_back(detail::mesh_file(mesh, name));
  for (const char* name : kAddressingFile) {
    std::error_code ec;
    if (!fs::exists(mesh / name, ec) && !fs::exists(mesh / (std::string(name) + ".gz"), ec))
      throw InputError((mesh / name).string(), {}, std::string("expected decomposePar's addressing file ") + name +
                                                       " beside the processor's mesh, found none (a mesh split by another "
                                                       "tool, e.g. snappyHexMesh -parallel, may lack it: reconstructParMesh "
                                                       "joins such processors by geometry)");
    files.push_back(detail::mesh_file(mesh, name));
  }
  FoamProcessorFiles f{{files[0].view(), files[1].view(), files[2].view(), files[3].view(), files[0].name, files[1].name,
                        files[2].name, files[3].name},
                       files[5].view(), files[6].view(), files[7].view(), files[5].name, files[6].name, files[7].name,
                       files[4].view(), files[4].name};
  p = read_part(f);
  // Only the addressing is read again (fail_label): the mesh files' maps and inflated bytes go now,
  // in place. Moving the vector hands its buffer over, so the kept strings (and the views into
  // them, even of a short inflated file) stay where they are.
  for (size_t i = 0; i < 5; ++i) files[i].map.reset(), files[i].bytes = std::string();
  p.files = std::move(files);
  return p;
}

}  // namespace

MeshInput join_foam_processors(std::span<const FoamProcessorFiles> processors, const std::string& source, const Threads& threads) {
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  const std::vector<Part> parts = read_parts(processors.size(), par, [&](size_t i) { return read_part(processors[i]); });
  return join_parts(parts, source, par);
}

MeshInput read_foam_decomposed(const std::string& case_dir, const Threads& threads) {
  const detail::RunOptions run(threads);
  const Threads& par = run.get();
  const std::vector<fs::path> dirs = processor_dirs(case_dir);
  const std::vector<Part> parts = read_parts(dirs.size(), par, [&](size_t i) { return read_processor(dirs[i]); });
  MeshInput in = join_parts(parts, case_dir, par);
  in.warnings.insert(in.warnings.begin(), "decomposed case: " + std::to_string(dirs.size()) +
                                              " processor folders joined by decomposePar's addressing (not constant/polyMesh)");
  return in;
}

std::string foam_decomposed_case(const std::string& path) {
  std::error_code ec;
  const fs::path p(path);
  const fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (p.filename() == "processor*") return parent.string();
  fs::path c;
  if (fs::is_directory(p, ec)) c = p;
  else if (p.extension() == ".foam" && fs::exists(p, ec)) c = parent;
  else return {};
  if (!detail::case_mesh(c).empty() || fs::exists(c / "polyMesh" / "owner", ec) || fs::exists(c / "owner", ec)) return {};
  return fs::is_directory(c / "processor0", ec) ? c.string() : std::string();
}

}  // namespace hbc
