// VTK XML UnstructuredGrid (.vtu). The XML is parsed by pugixml; the data arrays are ours: ascii
// text, inline "binary" (base64 of a size header and the bytes, optionally zlib-compressed in
// blocks with a block header) or appended after the XML (raw bytes or base64) at each array's
// offset. Header words are UInt32 or UInt64 (header_type), numbers in the file's byte_order.
// Locations in messages are byte offsets into the file.
#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/base64.hpp"
#include "io/detail/byte_cursor.hpp"
#include "io/detail/vtk_cells.hpp"
#include "platform/charconv.hpp"

namespace hbc {
namespace {

// zlib cannot expand data by more than about 1032:1; a header that declares more lies.
constexpr uint64_t kMaxZlibRatio = 1032;

class VtuReader {
 public:
  VtuReader(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}
  MeshInput read();

 private:
  [[noreturn]] void fail(int64_t at, const std::string& expected) const {
    throw InputError(source_, SourceLoc::at_byte(at), "expected " + expected);
  }
  void split_appended();
  // The values of a DataArray as int64 or double, `count` of them (checked).
  template <class T>
  std::vector<T> array(const pugi::xml_node& a, int64_t count);
  std::string decode_block(std::string_view b, int64_t at) const;
  std::string base64(std::string_view s, int64_t at) const;
  template <class T>
  void convert(const std::string& raw, const std::string& type, std::vector<T>& out, int64_t at) const;
  int value_size(const std::string& type, bool integral, int64_t at) const;
  pugi::xml_node cell_array(const pugi::xml_node& cells, const char* name, bool required) const;

  std::string_view bytes_;
  std::string source_;
  std::string xml_;                // the XML part (with the appended data cut out)
  std::string_view appended_;      // after the '_' marker
  int64_t appended_at_ = 0;
  bool appended_base64_ = false, big_endian_ = false, zlib_ = false;
  int header_bytes_ = 4;
};

void VtuReader::split_appended() {
  const size_t tag = bytes_.find("<AppendedData");
  if (tag == std::string_view::npos) {
    xml_.assign(bytes_);
    return;
  }
  const size_t close = bytes_.find('>', tag);
  const size_t mark = close == std::string_view::npos ? close : bytes_.find('_', close);
  if (mark == std::string_view::npos) fail(static_cast<int64_t>(tag), "'_' starting the AppendedData");
  // Raw data may hold any byte: only the tag itself goes to the XML parser.
  xml_.assign(bytes_.substr(0, close + 1));
  xml_ += "</AppendedData></VTKFile>";
  appended_at_ = static_cast<int64_t>(mark + 1);
  appended_ = bytes_.substr(mark + 1);
  const size_t end = appended_.rfind("</AppendedData>");
  if (end != std::string_view::npos) appended_ = appended_.substr(0, end);
}

std::string VtuReader::base64(std::string_view s, int64_t at) const {
  std::string out, why;
  size_t bad = 0;
  if (!detail::base64_decode(s, out, bad, why)) fail(at + static_cast<int64_t>(bad), why);
  return out;
}

std::string VtuReader::decode_block(std::string_view b, int64_t at) const {
  size_t pos = 0;
  auto word = [&](const char* what) -> uint64_t {
    if (b.size() - pos < static_cast<size_t>(header_bytes_))
      fail(at, std::string(what) + " in the data header, found the end of the data");
    unsigned char w[8];
    std::memcpy(w, b.data() + pos, static_cast<size_t>(header_bytes_));
    pos += static_cast<size_t>(header_bytes_);
    uint64_t v = 0;
    for (int k = 0; k < header_bytes_; ++k) v |= static_cast<uint64_t>(w[big_endian_ ? header_bytes_ - 1 - k : k]) << (8 * k);
    return v;
  };
  if (!zlib_) {
    const uint64_t n = word("the byte count");
    if (n > b.size() - pos) fail(at, "the " + std::to_string(n) + " bytes the data header declares, found " + std::to_string(b.size() - pos));
    return std::string(b.substr(pos, static_cast<size_t>(n)));
  }
  const uint64_t nblocks = word("the number of blocks");
  const uint64_t block = word("the block size");
  const uint64_t last = word("the last block's size");
  if (nblocks > (b.size() - pos) / static_cast<size_t>(header_bytes_)) fail(at, "a compressed-block count that the data can hold, found " + std::to_string(nblocks));
  std::vector<uint64_t> csize(static_cast<size_t>(nblocks));
  uint64_t ctotal = 0;
  for (uint64_t& s : csize) ctotal += (s = word("a compressed block size"));
  if (ctotal > b.size() - pos) fail(at, "the " + std::to_string(ctotal) + " compressed bytes the header declares, found " + std::to_string(b.size() - pos));
  std::string out;
  for (size_t k = 0; k < csize.size(); ++k) {
    const uint64_t want = (k + 1 == csize.size() && last != 0) ? last : block;
    if (want > kMaxZlibRatio * csize[k] + 64) fail(at, "block sizes that zlib data of " + std::to_string(csize[k]) + " bytes can expand to, found " + std::to_string(want));
    const size_t o = out.size();
    out.resize(o + static_cast<size_t>(want));
    uLongf got = static_cast<uLongf>(want);
    const int rc = uncompress(reinterpret_cast<Bytef*>(out.data() + o), &got, reinterpret_cast<const Bytef*>(b.data() + pos), static_cast<uLong>(csize[k]));
    if (rc != Z_OK || got != want) fail(at, "zlib data of block " + std::to_string(k) + " inflating to " + std::to_string(want) + " bytes (zlib: " + (rc == Z_OK ? "short" : zError(rc)) + ")");
    pos += static_cast<size_t>(csize[k]);
  }
  return out;
}

int VtuReader::value_size(const std::string& type, bool integral, int64_t at) const {
  int sz = 0;
  if (type == "Int8" || type == "UInt8") sz = 1;
  else if (type == "Int16" || type == "UInt16") sz = 2;
  else if (type == "Int32" || type == "UInt32" || type == "Float32") sz = 4;
  else if (type == "Int64" || type == "UInt64" || type == "Float64") sz = 8;
  else fail(at, "a DataArray type Int8..Int64, UInt8..UInt64, Float32 or Float64, found '" + type.substr(0, 40) + "'");
  if (integral && type[0] == 'F') fail(at, "an integer DataArray type, found " + type);
  return sz;
}

template <class T>
void VtuReader::convert(const std::string& raw, const std::string& type, std::vector<T>& out, int64_t at) const {
  const int sz = value_size(type, std::is_integral_v<T>, at);
  if (raw.size() % static_cast<size_t>(sz) != 0) fail(at, "whole " + type + " values, found " + std::to_string(raw.size()) + " bytes");
  out.resize(raw.size() / static_cast<size_t>(sz));
  const bool swap = big_endian_ == detail::kLittleEndian;
  const bool uns = type[0] == 'U';
  unsigned char w[8];
  for (size_t i = 0; i < out.size(); ++i) {
    std::memcpy(w, raw.data() + i * static_cast<size_t>(sz), static_cast<size_t>(sz));
    if (swap) std::reverse(w, w + sz);
    double d = 0;
    int64_t v = 0;
    switch (sz) {
      case 1: v = uns ? int64_t{w[0]} : int64_t{static_cast<int8_t>(w[0])}; break;
      case 2: { uint16_t x; std::memcpy(&x, w, 2); v = uns ? int64_t{x} : int64_t{static_cast<int16_t>(x)}; break; }
      case 4: {
        uint32_t x; std::memcpy(&x, w, 4);
        if (type[0] == 'F') { float f; std::memcpy(&f, w, 4); d = f; }
        else v = uns ? int64_t{x} : int64_t{static_cast<int32_t>(x)};
        break;
      }
      default: {
        if (type[0] == 'F') std::memcpy(&d, w, 8);
        else std::memcpy(&v, w, 8);
      }
    }
    if constexpr (std::is_integral_v<T>) out[i] = v;
    else out[i] = type[0] == 'F' ? d : static_cast<double>(v);
  }
}

template <class T>
std::vector<T> VtuReader::array(const pugi::xml_node& a, int64_t count) {
  const int64_t at = static_cast<int64_t>(a.offset_debug());
  const std::string format = a.attribute("format").as_string("ascii");
  const std::string type = a.attribute("type").as_string("");
  std::vector<T> out;
  if (format == "ascii") {
    const std::string_view text = a.child_value();
    const char* p = text.data();
    const char* e = p + text.size();
    while (true) {
      while (p < e && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t')) ++p;
      if (p == e) break;
      T v{};
      const auto r = ::hbc::detail::from_chars(p, e, v);
      if (r.ec != std::errc() || (r.ptr < e && !std::isspace(static_cast<unsigned char>(*r.ptr))))
        fail(at, std::string(std::is_integral_v<T> ? "an integer" : "a number") + " in the ascii DataArray, found '" + std::string(p, std::min<size_t>(20, static_cast<size_t>(e - p))) + "'");
      out.push_back(v);
      p = r.ptr;
    }
    value_size(type, std::is_integral_v<T>, at);
  } else if (format == "binary") {
    const std::string_view text = a.child_value();
    const int64_t text_at = a.first_child() ? static_cast<int64_t>(a.first_child().offset_debug()) : at;
    convert(decode_block(base64(text, text_at), text_at), type, out, at);
  } else if (format == "appended") {
    if (appended_.data() == nullptr) fail(at, "an AppendedData element for the appended DataArray");
    const auto off = a.attribute("offset");
    if (!off || off.as_llong(-1) < 0 || static_cast<uint64_t>(off.as_llong()) > appended_.size())
      fail(at, "an offset within the " + std::to_string(appended_.size()) + " bytes of appended data, found '" + std::string(off.as_string("")) + "'");
    const int64_t o = off.as_llong();
    const std::string_view from = appended_.substr(static_cast<size_t>(o));
    const int64_t data_at = appended_at_ + o;
    const std::string decoded = appended_base64_ ? base64(from, data_at) : std::string();
    convert(decode_block(appended_base64_ ? std::string_view(decoded) : from, data_at), type, out, at);
  } else if (format != "ascii") {
    fail(at, "a DataArray format ascii, binary or appended, found '" + format.substr(0, 40) + "'");
  }
  if (count >= 0 && static_cast<int64_t>(out.size()) != count)
    fail(at, std::to_string(count) + " values in DataArray '" + std::string(a.attribute("Name").as_string("")) + "', found " + std::to_string(out.size()));
  return out;
}

pugi::xml_node VtuReader::cell_array(const pugi::xml_node& cells, const char* name, bool required) const {
  for (pugi::xml_node a : cells.children("DataArray"))
    if (std::string(a.attribute("Name").as_string()) == name) return a;
  if (required) fail(static_cast<int64_t>(cells.offset_debug()), std::string("a DataArray named '") + name + "' in Cells");
  return {};
}

MeshInput VtuReader::read() {
  split_appended();
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_buffer(xml_.data(), xml_.size());
  if (!r) fail(r.offset, std::string("well-formed XML (") + r.description() + ")");
  const pugi::xml_node root = doc.child("VTKFile");
  if (!root || std::string(root.attribute("type").as_string()) != "UnstructuredGrid")
    fail(0, "<VTKFile type=\"UnstructuredGrid\"> (a .vtu file)");
  big_endian_ = std::string(root.attribute("byte_order").as_string("LittleEndian")) == "BigEndian";
  const std::string header = root.attribute("header_type").as_string("UInt32");
  if (header != "UInt32" && header != "UInt64") fail(static_cast<int64_t>(root.offset_debug()), "header_type UInt32 or UInt64, found " + header);
  header_bytes_ = header == "UInt64" ? 8 : 4;
  const std::string compressor = root.attribute("compressor").as_string("");
  if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
    fail(static_cast<int64_t>(root.offset_debug()), "no compressor or vtkZLibDataCompressor, found " + compressor);
  zlib_ = !compressor.empty();
  if (const pugi::xml_node ad = root.child("AppendedData"))
    appended_base64_ = std::string(ad.attribute("encoding").as_string("raw")) == "base64";
  const pugi::xml_node grid = root.child("UnstructuredGrid");
  const pugi::xml_node piece = grid.child("Piece");
  if (!piece) fail(static_cast<int64_t>(grid.offset_debug()), "a Piece in the UnstructuredGrid");
  if (piece.next_sibling("Piece")) fail(static_cast<int64_t>(piece.next_sibling("Piece").offset_debug()), "one Piece, found a second");
  const int64_t piece_at = static_cast<int64_t>(piece.offset_debug());
  const int64_t nv = piece.attribute("NumberOfPoints").as_llong(-1);
  const int64_t nc = piece.attribute("NumberOfCells").as_llong(-1);
  // Each point and cell takes at least a byte: larger counts than the file are lies.
  const int64_t room = static_cast<int64_t>(bytes_.size());
  if (nv < 0 || nv > std::min<int64_t>(room, INT32_MAX)) fail(piece_at, "NumberOfPoints in [0, " + std::to_string(std::min<int64_t>(room, INT32_MAX)) + "]");
  if (nc < 0 || nc > room) fail(piece_at, "NumberOfCells in [0, " + std::to_string(room) + "]");
  const pugi::xml_node pts = piece.child("Points").child("DataArray");
  if (!pts) fail(piece_at, "a Points DataArray");
  if (pts.attribute("NumberOfComponents").as_int(1) != 3) fail(static_cast<int64_t>(pts.offset_debug()), "3 components per point");
  MeshInput in;
  in.source = source_;
  in.binary = true;
  in.points = array<double>(pts, 3 * nv);
  for (double x : in.points)
    if (!std::isfinite(x)) fail(static_cast<int64_t>(pts.offset_debug()), "finite point coordinates");
  const pugi::xml_node cells = piece.child("Cells");
  if (!cells) fail(piece_at, "a Cells element");
  const auto conn = array<int64_t>(cell_array(cells, "connectivity", true), -1);
  const auto offsets = array<int64_t>(cell_array(cells, "offsets", true), nc);
  const auto types = array<int64_t>(cell_array(cells, "types", true), nc);
  std::vector<int64_t> faces, faceoffsets;
  if (const pugi::xml_node fa = cell_array(cells, "faces", false)) faces = array<int64_t>(fa, -1);
  if (const pugi::xml_node fo = cell_array(cells, "faceoffsets", false)) faceoffsets = array<int64_t>(fo, nc);
  const int64_t conn_at = static_cast<int64_t>(cell_array(cells, "offsets", true).offset_debug());
  detail::VtkCells out(in, nv);
  int64_t begin = 0, face_begin = 0;
  for (int64_t c = 0; c < nc; ++c) {
    const int64_t end = offsets[c];
    if (end < begin || end > static_cast<int64_t>(conn.size()))
      fail(conn_at, "offsets rising within the " + std::to_string(conn.size()) + " connectivity entries, found " + std::to_string(end) + " for cell " + std::to_string(c));
    if (types[c] == 42) {
      // faceoffsets: the end of each polyhedron's face stream in `faces`, -1 for other cells.
      const int64_t fend = c < static_cast<int64_t>(faceoffsets.size()) ? faceoffsets[c] : -1;
      if (fend < face_begin || fend > static_cast<int64_t>(faces.size()))
        fail(conn_at, "faces and faceoffsets giving the face stream of polyhedron cell " + std::to_string(c));
      out.add(42, faces.data() + face_begin, static_cast<size_t>(fend - face_begin), conn_at);
      face_begin = fend;
    } else {
      out.add(types[c], conn.data() + begin, static_cast<size_t>(end - begin), conn_at);
    }
    begin = end;
  }
  out.finish(piece_at);
  return in;
}

}  // namespace

MeshInput read_vtu(std::string_view bytes, const std::string& source) { return VtuReader(bytes, source).read(); }

}  // namespace hbc
