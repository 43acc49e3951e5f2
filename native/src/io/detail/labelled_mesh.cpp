#include "io/detail/labelled_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "platform/charconv.hpp"

namespace hbc::detail {

int32_t DeckFiles::add(std::string name, int64_t top_line) {
  names_.push_back(std::move(name));
  top_line_.push_back(top_line);
  return static_cast<int32_t>(names_.size() - 1);
}

void DeckFiles::fail(const DeckLoc& at, const std::string& expected) const {
  throw InputError(name(at.file), at.line > 0 ? SourceLoc::at_line(at.line) : SourceLoc{}, "expected " + expected);
}

std::string_view DeckFiles::include(const IncludeReader& fetch, const DeckLoc& at, const std::string& path, int depth,
                                    int32_t& file) {
  if (!fetch) fail(at, "no include (this deck is read from memory, without its folder), found one of '" + path + "'");
  if (depth >= 16) fail(at, "includes nested at most 16 deep (a file including itself?), found '" + path + "'");
  std::string called;
  std::string bytes = fetch(name(at.file), path, called);
  file = add(called.empty() ? path : called, top_line(at));
  bytes_.push_back(std::move(bytes));
  return bytes_.back();
}

void LabelledMesh::node(int64_t key, const double* xyz, const DeckLoc& at) {
  keys_.push_back(key);
  points_.insert(points_.end(), xyz, xyz + 3);
  node_at_.push_back(at);
}

void LabelledMesh::element(CellShape shape, const int64_t* keys, int n, const DeckLoc& at) {
  shape_.push_back(shape);
  el_keys_.insert(el_keys_.end(), keys, keys + n);
  start_.push_back(static_cast<int32_t>(el_keys_.size()));
  el_at_.push_back(at);
}

namespace {

// Key -> vertex id: a dense table when the keys fill a sixteenth of their range or more (the usual
// 1..n numbering, with gaps), else sorted pairs searched.
class KeyIndex {
 public:
  KeyIndex(const std::vector<int64_t>& keys, const std::vector<DeckLoc>& at, const DeckFiles& files, const char* what) {
    if (keys.empty()) return;
    const auto [lo, hi] = std::minmax_element(keys.begin(), keys.end());
    lo_ = *lo;
    const uint64_t range = static_cast<uint64_t>(*hi) - static_cast<uint64_t>(*lo);
    auto twice = [&](size_t first, size_t second) {
      const DeckLoc& a = at[first];
      files.fail(at[second], std::string("one ") + what + " with label " + std::to_string(keys[second] & 0xffffffff) +
                                 ", found a second (the first at " + files.name(a.file) + ":" + std::to_string(a.line) + ")");
    };
    if (range < 16 * keys.size() + 1024) {  // at most 64 bytes a node, less than a node takes
      dense_.assign(range + 1, -1);
      for (size_t i = 0; i < keys.size(); ++i) {
        int32_t& slot = dense_[static_cast<size_t>(keys[i] - lo_)];
        if (slot >= 0) twice(static_cast<size_t>(slot), i);
        slot = static_cast<int32_t>(i);
      }
      return;
    }
    sorted_.reserve(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) sorted_.emplace_back(keys[i], static_cast<int32_t>(i));
    std::sort(sorted_.begin(), sorted_.end());
    for (size_t i = 1; i < sorted_.size(); ++i)
      if (sorted_[i].first == sorted_[i - 1].first) {
        const auto [a, b] = std::minmax(sorted_[i - 1].second, sorted_[i].second);
        twice(static_cast<size_t>(a), static_cast<size_t>(b));
      }
  }
  int32_t find(int64_t key) const {
    if (!dense_.empty()) {
      const uint64_t off = static_cast<uint64_t>(key) - static_cast<uint64_t>(lo_);
      return off < dense_.size() ? dense_[off] : -1;
    }
    const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::pair<int64_t, int32_t>(key, INT32_MIN));
    return it != sorted_.end() && it->first == key ? it->second : -1;
  }

 private:
  int64_t lo_ = 0;
  std::vector<int32_t> dense_;
  std::vector<std::pair<int64_t, int32_t>> sorted_;
};

}  // namespace

MeshInput LabelledMesh::finish(const DeckFiles& files, const char* what, const char* volume, const DeckLoc& end) const {
  if (shape_.empty()) files.fail(end, std::string("at least one volume element (") + volume + ")");
  if (keys_.size() > static_cast<size_t>(INT32_MAX)) files.fail(end, "fewer than 2^31 nodes");
  const KeyIndex index(keys_, node_at_, files, what);
  MeshInput in;
  in.source = files.name(0);
  in.points = points_;
  in.vertex_loc.reserve(keys_.size());
  for (const DeckLoc& a : node_at_) in.vertex_loc.push_back(files.top_line(a));
  in.cells.reserve(shape_.size(), el_keys_.size());
  in.cell_shape.reserve(shape_.size());
  in.cell_loc.reserve(shape_.size());
  CellAppender cells(in);
  std::vector<int32_t> v(32);
  for (size_t e = 0; e < shape_.size(); ++e) {
    const int32_t b = start_[e], n = start_[e + 1] - b;
    v.resize(static_cast<size_t>(n));
    for (int32_t k = 0; k < n; ++k) {
      const int64_t key = el_keys_[static_cast<size_t>(b + k)];
      v[static_cast<size_t>(k)] = index.find(key);
      if (v[static_cast<size_t>(k)] < 0)
        files.fail(el_at_[e], std::string("the label of a node (") + what + "), found " + std::to_string(key & 0xffffffff) +
                                  " which no node has");
    }
    for (int32_t k = corner_count(shape_[e]); k < n; ++k) cells.midside(v[static_cast<size_t>(k)]);
    cells.element(shape_[e], v.data(), files.top_line(el_at_[e]));
  }
  tally_.report(in);
  cells.finish();
  return in;
}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  last_ = pos_;
  const size_t nl = text_.find('\n', pos_);
  const size_t end = nl == std::string_view::npos ? text_.size() : nl;
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
  ++line_;
  return true;
}

bool parse_int(std::string_view f, int64_t& v) {
  f = trim(f);
  if (!f.empty() && f[0] == '+') f.remove_prefix(1);
  if (f.empty()) return false;
  const auto r = from_chars(f.data(), f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size();
}

bool parse_real(std::string_view f, double& v) {
  f = trim(f);
  if (!f.empty() && f[0] == '+') f.remove_prefix(1);
  if (f.empty()) return false;
  const auto r = from_chars(f.data(), f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size() && std::isfinite(v);
}

std::string shown_field(std::string_view f) {
  f = trim(f);
  if (f.empty()) return "an empty field";
  // Appended, not "'" + ... + "'": GCC 12 warns (-Wrestrict) on that chain for no cause.
  std::string r(1, '\'');
  r.append(f.substr(0, 40));
  r += '\'';
  return r;
}

void split_commas(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  for (;;) {
    const size_t c = line.find(',');
    fields.push_back(trim(line.substr(0, c)));
    if (c == std::string_view::npos) return;
    line.remove_prefix(c + 1);
  }
}

}  // namespace hbc::detail
