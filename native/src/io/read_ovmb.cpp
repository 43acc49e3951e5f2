// OpenVolumeMesh binary (.ovmb), all numbers little-endian:
//   file header (48 bytes): magic "OVMB\n\r\n\xff", u8 file_version (1), u8 header_version (1),
//     u8 vertex_dim (3), u8 topo_type (0 polyhedral, 1 tetrahedral, 2 hexahedral), 4 reserved,
//     u64 n_verts, n_edges, n_faces, n_cells
//   chunks: fourcc type, u8 version (0), u8 padding, u8 compression (0), u8 flags (1 = mandatory),
//     u64 length (payload + padding), then the payload and the padding
//   VERT payload: u64 first, u32 count, u8 encoding (1 float, 2 double), 3 reserved, count*dim reals
//   TOPO payload: u64 first, u32 count, u8 entity (1 edge, 2 face, 3 cell), u8 valence (0 =
//     variable), u8 valence encoding, u8 handle encoding (1/2/4 byte unsigned), u64 handle offset
//     added to every handle; for a variable valence count valences come first; then the handles:
//     vertex pairs (edges), half-edges 2*e+rev (faces) or half-faces 2*f+side (cells)
//   DIRP / PROP carry properties and are read past; "EOF " ends the file.
// Chunks of one kind must continue where the previous one stopped (span.first), as in OVM's own
// reader. Every error names the byte offset of the offending field.
#include <array>
#include <bit>
#include <cstring>
#include <limits>

#include "hbc/io.hpp"

namespace hbc {
namespace {

constexpr uint32_t fourcc(const char (&s)[5]) {
  return static_cast<uint32_t>(static_cast<uint8_t>(s[0])) |
         static_cast<uint32_t>(static_cast<uint8_t>(s[1])) << 8 |
         static_cast<uint32_t>(static_cast<uint8_t>(s[2])) << 16 |
         static_cast<uint32_t>(static_cast<uint8_t>(s[3])) << 24;
}

// Bounds-checked little-endian reads over [pos, end).
class Bytes {
 public:
  Bytes(std::string_view b, const std::string& source) : b_(b), source_(source), end_(b.size()) {}

  size_t pos() const { return pos_; }
  size_t left() const { return end_ - pos_; }
  void seek(size_t p) { pos_ = p; }
  // Restricts reads to [pos, pos + n) (a chunk payload); returns the previous end.
  size_t limit(size_t n) {
    const size_t old = end_;
    end_ = pos_ + n;
    return old;
  }
  void unlimit(size_t old_end) { end_ = old_end; }

  [[noreturn]] void fail_at(size_t offset, const std::string& expected) const {
    throw InputError(source_, SourceLoc::at_byte(static_cast<int64_t>(offset)), "expected " + expected);
  }
  void need(size_t n, const std::string& what) const {
    if (left() < n)
      fail_at(pos_, what + " (" + std::to_string(n) + " bytes), found only " + std::to_string(left()) +
                        (end_ == b_.size() ? " before the end of the file" : " left in the chunk"));
  }
  uint64_t uint(size_t size, const std::string& what) {
    need(size, what);
    const uint64_t v = peek(pos_, size);
    pos_ += size;
    return v;
  }
  // A value already known to lie inside the buffer (bounds checked by the caller).
  uint64_t peek(size_t at, size_t size) const {
    uint64_t v = 0;
    for (size_t k = 0; k < size; ++k) v |= static_cast<uint64_t>(static_cast<uint8_t>(b_[at + k])) << (8 * k);
    return v;
  }
  uint8_t u8(const std::string& what) { return static_cast<uint8_t>(uint(1, what)); }
  uint32_t u32(const std::string& what) { return static_cast<uint32_t>(uint(4, what)); }
  uint64_t u64(const std::string& what) { return uint(8, what); }
  double real(size_t size, const std::string& what) {
    const uint64_t bits = uint(size, what);
    if (size == 4) return static_cast<double>(std::bit_cast<float>(static_cast<uint32_t>(bits)));
    return std::bit_cast<double>(bits);
  }
  std::string_view raw(size_t n, const std::string& what) {
    need(n, what);
    std::string_view r = b_.substr(pos_, n);
    pos_ += n;
    return r;
  }

 private:
  std::string_view b_;
  const std::string& source_;
  size_t pos_ = 0;
  size_t end_;
};

struct Header {
  uint8_t topo_type = 0;
  uint64_t n[4] = {0, 0, 0, 0};  // vertices, edges, faces, cells
};

const char* const kEntity[4] = {"vertices", "edges", "faces", "cells"};

size_t int_size(uint8_t enc) { return enc == 1 || enc == 2 || enc == 4 ? enc : 0; }

class OvmbReader {
 public:
  OvmbReader(std::string_view bytes, const std::string& source) : in_(bytes, source) {
    out_.source = source;
    out_.binary = true;
  }

  MeshInput read() {
    read_header();
    bool seen_eof = false;
    while (in_.left() > 0) {
      if (seen_eof) in_.fail_at(in_.pos(), "the end of the file after the EOF chunk");
      seen_eof = read_chunk();
    }
    if (!seen_eof) in_.fail_at(in_.pos(), "an EOF chunk at the end of the file");
    for (int k = 0; k < 4; ++k)
      if (done_[k] != h_.n[k])
        in_.fail_at(in_.pos(), std::to_string(h_.n[k]) + " " + kEntity[k] + " as the header declares, found " +
                                   std::to_string(done_[k]));
    return std::move(out_);
  }

 private:
  void read_header() {
    static constexpr char kMagic[8] = {'O', 'V', 'M', 'B', '\n', '\r', '\n', '\xff'};
    if (in_.left() < 8 || std::memcmp(in_.raw(8, "the OVMB magic").data(), kMagic, 8) != 0)
      in_.fail_at(0, "the OVMB magic bytes 'OVMB\\n\\r\\n\\xff'");
    const uint8_t file_version = in_.u8("the file version");
    const uint8_t header_version = in_.u8("the header version");
    if (file_version != 1 || header_version != 1)
      in_.fail_at(8, "OVMB file version 1 with header version 1, found " + std::to_string(file_version) +
                         " and " + std::to_string(header_version));
    const uint8_t dim = in_.u8("the vertex dimension");
    if (dim != 3) in_.fail_at(10, "vertex dimension 3, found " + std::to_string(dim));
    h_.topo_type = in_.u8("the topology type");
    if (h_.topo_type > 2) in_.fail_at(11, "topology type 0, 1 or 2, found " + std::to_string(h_.topo_type));
    in_.raw(4, "4 reserved header bytes");
    for (int k = 0; k < 4; ++k) h_.n[k] = in_.u64(std::string("the number of ") + kEntity[k]);
    // Smallest encodings: a float vertex is 12 bytes, an edge 2, a face 3 and a cell 2 handles
    // of one byte. Counts the rest of the file cannot hold are rejected before any allocation.
    const uint64_t min_bytes[4] = {12, 2, 3, 2};
    const uint64_t left = in_.left();
    constexpr uint64_t kMax = std::numeric_limits<int32_t>::max() / 2;
    uint64_t total = 0;
    for (int k = 0; k < 4; ++k) {
      const uint64_t room = std::min(left / min_bytes[k], kMax);
      if (h_.n[k] > room)
        in_.fail_at(16 + 8 * k, std::string("a number of ") + kEntity[k] + " that the file can hold (at most " +
                                    std::to_string(room) + "), found " + std::to_string(h_.n[k]));
      total += h_.n[k] * min_bytes[k];
    }
    if (total > left)
      in_.fail_at(16, "entity counts that fit in the " + std::to_string(left) +
                          " bytes after the header, found counts needing " + std::to_string(total));
  }

  // Reads one chunk; true for the EOF chunk.
  bool read_chunk() {
    const size_t at = in_.pos();
    const uint32_t type = in_.u32("a chunk type");
    const uint8_t version = in_.u8("the chunk version");
    const uint8_t padding = in_.u8("the chunk padding");
    const uint8_t compression = in_.u8("the chunk compression");
    const uint8_t flags = in_.u8("the chunk flags");
    const uint64_t length = in_.u64("the chunk length");
    if (length > in_.left())
      in_.fail_at(at + 8, "a chunk length within the " + std::to_string(in_.left()) +
                              " bytes left in the file, found " + std::to_string(length));
    if (padding > length)
      in_.fail_at(at + 5, "chunk padding at most the chunk length " + std::to_string(length) +
                              ", found " + std::to_string(padding));
    if (compression != 0) in_.fail_at(at + 6, "an uncompressed chunk, found compression " + std::to_string(compression));
    const size_t payload = in_.pos();
    const size_t next = payload + static_cast<size_t>(length);
    const bool mandatory = (flags & 1) != 0;
    const bool known = type == fourcc("VERT") || type == fourcc("TOPO") || type == fourcc("DIRP") ||
                       type == fourcc("PROP") || type == fourcc("EOF ");
    if (version != 0 || !known) {
      if (mandatory)
        in_.fail_at(at, version != 0 ? "chunk version 0, found " + std::to_string(version)
                                     : "a known chunk type (VERT, TOPO, DIRP, PROP or EOF)");
      in_.seek(next);  // optional chunks we do not know may be skipped
      return false;
    }
    const size_t old_end = in_.limit(static_cast<size_t>(length) - padding);
    bool eof = false;
    if (type == fourcc("EOF ")) {
      if (length != 0) in_.fail_at(at + 8, "an empty EOF chunk, found length " + std::to_string(length));
      eof = true;
    } else if (type == fourcc("VERT")) {
      read_vertices();
    } else if (type == fourcc("TOPO")) {
      read_topo();
    } else {
      in_.seek(in_.pos() + in_.left());  // properties carry no topology
    }
    if (in_.left() != 0)
      in_.fail_at(in_.pos(), "the end of the chunk payload, found " + std::to_string(in_.left()) + " more bytes");
    in_.unlimit(old_end);
    in_.seek(next);
    return eof;
  }

  // Checks that a span continues where the previous chunk of its kind stopped.
  void check_span(size_t at, int kind, uint64_t first, uint64_t count) {
    if (first != done_[kind])
      in_.fail_at(at, std::string("the next chunk of ") + kEntity[kind] + " to start at " +
                          std::to_string(done_[kind]) + ", found " + std::to_string(first));
    if (count > h_.n[kind] - done_[kind])
      in_.fail_at(at + 8, std::string("at most ") + std::to_string(h_.n[kind] - done_[kind]) + " more " +
                              kEntity[kind] + " (the header declares " + std::to_string(h_.n[kind]) +
                              "), found " + std::to_string(count));
  }

  void read_vertices() {
    const size_t at = in_.pos();
    const uint64_t first = in_.u64("the first vertex of the chunk");
    const uint32_t count = in_.u32("the number of vertices in the chunk");
    const uint8_t enc = in_.u8("the vertex encoding");
    in_.raw(3, "3 reserved bytes");
    check_span(at, 0, first, count);
    if (enc != 1 && enc != 2) in_.fail_at(at + 12, "vertex encoding 1 (float) or 2 (double), found " + std::to_string(enc));
    const size_t size = enc == 1 ? 4 : 8;
    if (in_.left() != 3 * size * count)
      in_.fail_at(in_.pos(), std::to_string(3 * size * count) + " bytes of coordinates for " +
                                 std::to_string(count) + " vertices, found " + std::to_string(in_.left()));
    for (uint32_t i = 0; i < count; ++i) {
      out_.vertex_loc.push_back(static_cast<int64_t>(in_.pos()));
      for (int k = 0; k < 3; ++k) out_.points.push_back(in_.real(size, "a vertex coordinate"));
    }
    done_[0] += count;
  }

  void read_topo() {
    const size_t at = in_.pos();
    const uint64_t first = in_.u64("the first entity of the chunk");
    const uint32_t count = in_.u32("the number of entities in the chunk");
    const uint8_t entity = in_.u8("the topology entity");
    const uint8_t valence = in_.u8("the valence");
    const uint8_t valence_enc = in_.u8("the valence encoding");
    const uint8_t handle_enc = in_.u8("the handle encoding");
    const uint64_t offset = in_.u64("the handle offset");
    if (entity < 1 || entity > 3)
      in_.fail_at(at + 12, "topology entity 1 (edges), 2 (faces) or 3 (cells), found " + std::to_string(entity));
    check_span(at, entity, first, count);
    if (count == 0) in_.fail_at(at + 8, "a TOPO chunk with at least one entity");
    const size_t hsize = int_size(handle_enc);
    if (hsize == 0) in_.fail_at(at + 15, "handle encoding 1, 2 or 4, found " + std::to_string(handle_enc));
    if (valence != 0 && valence_enc != 0)
      in_.fail_at(at + 14, "valence encoding 0 for a fixed valence, found " + std::to_string(valence_enc));
    if (entity == 1 && valence != 2) in_.fail_at(at + 13, "valence 2 for edges, found " + std::to_string(valence));
    const uint8_t fixed[3][2] = {{0, 0}, {3, 4}, {4, 6}};  // tetrahedral / hexahedral face, cell valence
    if (entity > 1 && h_.topo_type > 0 && valence != fixed[h_.topo_type][entity - 2])
      in_.fail_at(at + 13, "valence " + std::to_string(fixed[h_.topo_type][entity - 2]) + " in a " +
                               (h_.topo_type == 1 ? "tetrahedral" : "hexahedral") + " file, found " +
                               std::to_string(valence));

    // Valences first (variable case), checked against the bytes left before anything grows.
    const size_t vsize = int_size(valence_enc);
    if (valence == 0 && vsize == 0)
      in_.fail_at(at + 14, "valence encoding 1, 2 or 4 for a variable valence, found " + std::to_string(valence_enc));
    const size_t val_at = in_.pos();
    uint64_t total = static_cast<uint64_t>(valence) * count;
    if (valence == 0) {
      in_.need(static_cast<size_t>(count) * vsize, std::to_string(count) + " valences");
      total = 0;
      for (uint32_t i = 0; i < count; ++i) total += in_.uint(vsize, "a valence");
    }
    if (total > in_.left() / hsize || in_.left() != total * hsize)
      in_.fail_at(in_.pos(), std::to_string(total) + " handles of " + std::to_string(hsize) +
                                 " byte(s) filling the rest of the chunk, found " + std::to_string(in_.left()) + " bytes");

    // Handles index the entities of the level below, as far as the file has defined them.
    const uint64_t limit = entity == 1 ? h_.n[0] : 2 * done_[entity - 1];
    const char* what = entity == 1 ? "a vertex index" : entity == 2 ? "a half-edge index" : "a half-face index";
    auto handle = [&]() -> int64_t {
      const size_t p = in_.pos();
      const uint64_t raw = in_.uint(hsize, what);
      if (offset >= limit || raw >= limit - offset)
        in_.fail_at(p, std::string(what) + " below " + std::to_string(limit) + ", found " +
                           std::to_string(raw) + " + offset " + std::to_string(offset));
      return static_cast<int64_t>(raw + offset);
    };
    for (uint32_t i = 0; i < count; ++i) {
      const uint64_t n = valence != 0 ? valence : in_.peek(val_at + i * vsize, vsize);
      const size_t start = in_.pos();
      if (entity == 1) {
        const auto a = static_cast<int32_t>(handle());
        const auto b = static_cast<int32_t>(handle());
        out_.declared_edges.push_back({a, b});
      } else if (entity == 2) {
        read_face(start, n, handle);
      } else {
        for (uint64_t k = 0; k < n; ++k) out_.cells.items.push_back(static_cast<int32_t>(handle()));
        out_.cells.offsets.push_back(static_cast<int32_t>(out_.cells.items.size()));
        out_.cell_loc.push_back(static_cast<int64_t>(start));
      }
    }
    done_[entity] += count;
  }

  template <class Handle>
  void read_face(size_t start, uint64_t n, Handle&& handle) {
    const int64_t f = static_cast<int64_t>(out_.faces.rows());
    if (n < 3) in_.fail_at(start, "a face with at least 3 half-edges, face " + std::to_string(f) + " has " + std::to_string(n));
    std::array<int32_t, 2> first{}, prev{};
    for (uint64_t k = 0; k < n; ++k) {
      const size_t p = in_.pos();
      const int64_t h = handle();
      const auto& e = out_.declared_edges[static_cast<size_t>(h >> 1)];
      const std::array<int32_t, 2> cur = (h & 1) ? std::array<int32_t, 2>{e[1], e[0]} : e;
      if (k == 0) first = cur;
      else if (cur[0] != prev[1])
        in_.fail_at(p, "half-edges of face " + std::to_string(f) + " that chain end to start, half-edge " +
                           std::to_string(h) + " starts at vertex " + std::to_string(cur[0]) +
                           " but the previous one ends at " + std::to_string(prev[1]));
      out_.faces.items.push_back(cur[0]);
      prev = cur;
    }
    if (prev[1] != first[0])
      in_.fail_at(start, "a closed loop of half-edges in face " + std::to_string(f) + ", it ends at vertex " +
                             std::to_string(prev[1]) + " but starts at " + std::to_string(first[0]));
    out_.faces.offsets.push_back(static_cast<int32_t>(out_.faces.items.size()));
    out_.face_loc.push_back(static_cast<int64_t>(start));
  }

  Bytes in_;
  Header h_;
  uint64_t done_[4] = {0, 0, 0, 0};  // entities read so far, per kind
  MeshInput out_;
};

}  // namespace

MeshInput read_ovmb(std::string_view bytes, const std::string& source) {
  return OvmbReader(bytes, source).read();
}

}  // namespace hbc
