// Gmsh .msh, versions 2.2 and 4.1, ASCII and binary. Sections start with $Name and end with
// $EndName; $MeshFormat says the version, the file type and the size of size_t, and binary files
// follow it with the integer 1 so that the byte order can be detected. Nodes carry tags (4.1:
// in entity blocks, possibly with gaps); volume elements name nodes by tag. Higher-order elements
// list their corners first, in the order of the linear element, so only the corners are read.
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "io/detail/byte_cursor.hpp"
#include "mesh/cell_templates.hpp"
#include "io/detail/element_tally.hpp"
#include "hbc/io.hpp"

namespace hbc {
namespace {

using detail::Element;

struct ElementType {
  int type, dim, nodes;
  Element element;  // meaningful when dim == 3
};

// Gmsh's element types (gmsh.info, "MSH file format"): lines, triangles, quadrangles and points
// are read past; volume elements of order 1 to 4.
constexpr ElementType kTypes[] = {
    {1, 1, 2, Element::Tet},      {2, 2, 3, Element::Tet},       {3, 2, 4, Element::Tet},
    {4, 3, 4, Element::Tet},      {5, 3, 8, Element::Hex},       {6, 3, 6, Element::Prism},
    {7, 3, 5, Element::Pyramid},  {8, 1, 3, Element::Tet},       {9, 2, 6, Element::Tet},
    {10, 2, 9, Element::Tet},     {11, 3, 10, Element::Tet},     {12, 3, 27, Element::Hex},
    {13, 3, 18, Element::Prism},  {14, 3, 14, Element::Pyramid}, {15, 0, 1, Element::Tet},
    {16, 2, 8, Element::Tet},     {17, 3, 20, Element::Hex},     {18, 3, 15, Element::Prism},
    {19, 3, 13, Element::Pyramid}, {20, 2, 9, Element::Tet},     {21, 2, 10, Element::Tet},
    {22, 2, 12, Element::Tet},    {23, 2, 15, Element::Tet},     {24, 2, 15, Element::Tet},
    {25, 2, 21, Element::Tet},    {26, 1, 4, Element::Tet},      {27, 1, 5, Element::Tet},
    {28, 1, 6, Element::Tet},     {29, 3, 20, Element::Tet},     {30, 3, 35, Element::Tet},
    {31, 3, 56, Element::Tet},    {36, 2, 16, Element::Tet},     {37, 2, 25, Element::Tet},
    {92, 3, 64, Element::Hex},    {93, 3, 125, Element::Hex},
};

const ElementType* element_type(int64_t type) {
  for (const ElementType& t : kTypes)
    if (t.type == type) return &t;
  return nullptr;
}

class MshReader {
 public:
  MshReader(std::string_view bytes, const std::string& source) : c_(bytes, source), cells_(in_) {
    in_.source = source;
  }
  MeshInput read();

 private:
  void header();
  void nodes();
  void elements();
  void section_end(std::string_view name);
  // Numbers in the current encoding: a 4-byte int, a size_t of the header's size, a double.
  int64_t i32(const char* what) { return binary_ ? c_.bin<int32_t>(swap_, what) : c_.integer(what); }
  int64_t size(const char* what);
  double real(const char* what) { return binary_ ? c_.bin<double>(swap_, what) : c_.real(what); }
  int64_t count(int64_t item_bytes, const char* what) {
    return c_.checked_count(v4_ ? size(what) : i32(what), item_bytes, what);
  }
  void node(int64_t tag, int64_t loc);
  void element(int64_t type, const std::vector<int64_t>& tags, int64_t loc);
  int32_t index_of(int64_t tag, int64_t loc) const;

  detail::ByteCursor c_;
  MeshInput in_;
  detail::CellAppender cells_;
  detail::ElementTally tally_;
  bool binary_ = false, swap_ = false, v4_ = false;
  int size_bytes_ = 8;
  std::vector<std::pair<int64_t, int32_t>> tag_index_;  // (node tag, vertex id), sorted by tag
  bool have_nodes_ = false;
};

int64_t MshReader::size(const char* what) {
  if (!binary_) return c_.integer(what);
  if (size_bytes_ == 4) return c_.bin<uint32_t>(swap_, what);
  const uint64_t v = c_.bin<uint64_t>(swap_, what);
  if (v > static_cast<uint64_t>(INT64_MAX)) c_.fail(std::string(what) + " below 2^63, found " + std::to_string(v));
  return static_cast<int64_t>(v);
}

void MshReader::header() {
  if (c_.word("$MeshFormat at the start of a Gmsh file") != "$MeshFormat") c_.fail("$MeshFormat at the start of a Gmsh file");
  const std::string_view version = c_.word("the .msh version");
  if (version == "4.1") v4_ = true;
  else if (version != "2.2" && version != "2.1" && version != "2") c_.fail("a .msh version 2.2 or 4.1, found '" + std::string(version.substr(0, 20)) + "'");
  binary_ = c_.integer_in(0, 1, "the file type (0 ASCII, 1 binary)") == 1;
  size_bytes_ = static_cast<int>(c_.integer("the data size"));
  if (size_bytes_ != 8 && !(v4_ && size_bytes_ == 4)) c_.fail("a data size of 8 (or 4 for size_t in 4.1), found " + std::to_string(size_bytes_));
  if (binary_) {
    c_.end_line();
    c_.set_binary(true);
    in_.binary = true;
    const int32_t one = c_.bin<int32_t>(false, "the byte-order check value 1");
    if (one != 1) {
      if (one != 0x01000000) c_.fail("the byte-order check value 1, found " + std::to_string(one));
      swap_ = true;
    }
  }
  section_end("MeshFormat");
}

void MshReader::section_end(std::string_view name) {
  const std::string end = "$End" + std::string(name);
  std::string_view t;
  if (!c_.token(t) || t != end) c_.fail(end + (t.empty() ? std::string(", found the end of the file") : ", found '" + std::string(t.substr(0, 40)) + "'"));
}

void MshReader::node(int64_t tag, int64_t loc) {
  if (tag < 0) c_.fail_at(loc, "a node tag >= 0, found " + std::to_string(tag));
  tag_index_.emplace_back(tag, static_cast<int32_t>(in_.vertex_loc.size()));
  in_.vertex_loc.push_back(loc);
  for (int k = 0; k < 3; ++k) in_.points.push_back(real("a node coordinate"));
}

void MshReader::nodes() {
  if (have_nodes_) c_.fail("one $Nodes section, found a second");
  have_nodes_ = true;
  const int num_bytes = binary_ ? 24 + (v4_ ? size_bytes_ : 4) : 8;  // smallest node: tag and 3 doubles
  if (!v4_) {
    if (binary_) c_.set_binary(false);  // the count is a text line even in binary 2.2
    const int64_t n = c_.checked_count(c_.integer("the number of nodes"), num_bytes, "the number of nodes");
    if (binary_) c_.end_line(), c_.set_binary(true);
    for (int64_t i = 0; i < n; ++i) {
      const int64_t loc = c_.loc();
      node(i32("a node tag"), loc);
    }
  } else {
    const int64_t blocks = count(12, "the number of node entity blocks");
    const int64_t total = count(num_bytes, "the number of nodes");
    size("the smallest node tag");
    size("the largest node tag");
    std::vector<int64_t> tags;
    for (int64_t b = 0; b < blocks; ++b) {
      const int64_t dim = i32("the entity dimension of a node block");
      i32("the entity tag of a node block");
      const int64_t parametric = i32("the parametric flag of a node block");
      const int64_t n = count(num_bytes, "the number of nodes in the block");
      std::vector<int64_t> locs(static_cast<size_t>(n));
      tags.resize(static_cast<size_t>(n));
      for (int64_t i = 0; i < n; ++i) {
        locs[i] = c_.loc();
        tags[i] = size("a node tag");
      }
      for (int64_t i = 0; i < n; ++i) {
        node(tags[i], locs[i]);
        for (int64_t k = 0; parametric && k < dim; ++k) real("a parametric coordinate");
      }
    }
    if (static_cast<int64_t>(in_.vertex_loc.size()) != total)
      c_.fail(std::to_string(total) + " nodes as the $Nodes header says, found " + std::to_string(in_.vertex_loc.size()));
  }
  section_end("Nodes");
  std::sort(tag_index_.begin(), tag_index_.end());
  for (size_t i = 1; i < tag_index_.size(); ++i)
    if (tag_index_[i].first == tag_index_[i - 1].first)
      c_.fail_at(in_.vertex_loc[tag_index_[i].second], "distinct node tags, found tag " + std::to_string(tag_index_[i].first) + " twice");
}

int32_t MshReader::index_of(int64_t tag, int64_t loc) const {
  auto it = std::lower_bound(tag_index_.begin(), tag_index_.end(), std::make_pair(tag, INT32_MIN));
  if (it == tag_index_.end() || it->first != tag)
    c_.fail_at(loc, "a node tag defined in $Nodes, found " + std::to_string(tag));
  return it->second;
}

void MshReader::element(int64_t type, const std::vector<int64_t>& tags, int64_t loc) {
  const ElementType* t = element_type(type);
  if (t->dim < 3) {
    tally_.skip(t->dim);
    return;
  }
  std::array<int32_t, 8> v{};
  const int corners = detail::corner_count(t->element);
  for (size_t k = 0; k < tags.size(); ++k) {
    const int32_t id = index_of(tags[k], loc);  // every node must exist, corner or not
    if (static_cast<int>(k) < corners) v[k] = id;
    else cells_.midside(id);
  }
  cells_.element(t->element, v.data(), loc);
}

void MshReader::elements() {
  if (!have_nodes_) c_.fail("a $Nodes section before $Elements");
  auto type_of = [&](int64_t loc) {
    const int64_t type = i32("an element type");
    if (!element_type(type)) c_.fail_at(loc, "a Gmsh element type of a point, line, surface or volume element, found type " + std::to_string(type));
    return type;
  };
  std::vector<int64_t> tags;
  int64_t read = 0;
  if (!v4_) {
    if (binary_) c_.set_binary(false);
    const int64_t n = c_.checked_count(c_.integer("the number of elements"), binary_ ? 12 : 6, "the number of elements");
    if (binary_) c_.end_line(), c_.set_binary(true);
    while (read < n) {
      // ASCII: one element per line; binary: blocks of elements of one type with a shared header.
      const int64_t loc = c_.loc();
      if (!binary_) i32("an element tag");
      const int64_t type = type_of(loc);
      const int64_t in_block = binary_ ? c_.checked_count(i32("the number of elements in the block"), 12, "the number of elements in the block") : 1;
      const int64_t ntags = binary_ ? i32("the number of element tags") : c_.integer_in(0, 1000, "the number of element tags");
      if (ntags < 0 || ntags > 1000) c_.fail("a number of element tags in [0, 1000], found " + std::to_string(ntags));
      if (in_block > n - read) c_.fail_at(loc, std::to_string(n) + " elements as the $Elements header says, found more");
      tags.resize(static_cast<size_t>(element_type(type)->nodes));
      for (int64_t e = 0; e < in_block; ++e) {
        const int64_t eloc = binary_ ? c_.loc() : loc;
        if (binary_) i32("an element tag");
        for (int64_t k = 0; k < ntags; ++k) i32("an element tag value");
        for (int64_t& t : tags) t = i32("a node tag of an element");
        element(type, tags, eloc);
      }
      read += in_block;
    }
  } else {
    const int64_t blocks = count(12, "the number of element entity blocks");
    const int64_t n = count(binary_ ? 2 * size_bytes_ : 4, "the number of elements");
    size("the smallest element tag");
    size("the largest element tag");
    for (int64_t b = 0; b < blocks; ++b) {
      const int64_t loc = c_.loc();
      i32("the entity dimension of an element block");
      i32("the entity tag of an element block");
      const int64_t type = type_of(loc);
      const int64_t in_block = count(binary_ ? 2 * size_bytes_ : 4, "the number of elements in the block");
      if (in_block > n - read) c_.fail_at(loc, std::to_string(n) + " elements as the $Elements header says, found more");
      tags.resize(static_cast<size_t>(element_type(type)->nodes));
      for (int64_t e = 0; e < in_block; ++e) {
        const int64_t eloc = c_.loc();
        size("an element tag");
        for (int64_t& t : tags) t = size("a node tag of an element");
        element(type, tags, eloc);
      }
      read += in_block;
    }
    if (read != n) c_.fail(std::to_string(n) + " elements as the $Elements header says, found " + std::to_string(read));
  }
  section_end("Elements");
}

MeshInput MshReader::read() {
  header();
  bool have_elements = false;
  std::string_view t;
  while (true) {
    if (binary_) c_.set_binary(false);  // section names are text in binary files too
    const bool more = c_.token(t);
    if (binary_) {
      c_.end_line();
      c_.set_binary(true);
    }
    if (!more) break;
    if (t.empty() || t[0] != '$') c_.fail("a $Section name, found '" + std::string(t.substr(0, 40)) + "'");
    if (t == "$Nodes") nodes();
    else if (t == "$Elements") {
      if (have_elements) c_.fail("one $Elements section, found a second");
      elements();
      have_elements = true;
    } else {
      // $PhysicalNames, $Entities, $Periodic, $NodeData, ...: everything up to the matching end.
      const std::string end = "$End" + std::string(t.substr(1));
      if (!c_.skip_past(end)) c_.fail(end + " to close " + std::string(t) + ", found the end of the file");
    }
  }
  if (!have_elements) c_.fail("an $Elements section");
  if (in_.cells.rows() == 0) c_.fail("at least one volume element (tetrahedron, hexahedron, prism or pyramid)");
  tally_.report(in_);
  cells_.finish();
  return std::move(in_);
}

}  // namespace

MeshInput read_msh(std::string_view bytes, const std::string& source) { return MshReader(bytes, source).read(); }

}  // namespace hbc
