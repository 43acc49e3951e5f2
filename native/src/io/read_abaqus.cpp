// Abaqus .inp (Abaqus Keywords Reference): lines of "*KEYWORD, PARAM=VALUE, ..." each followed by
// its data lines of comma-separated fields; "**" starts a comment line; keywords and parameter
// names are case-insensitive. The model is read up to the first *STEP: *NODE and *ELEMENT at the
// top level or inside *PART ... *END PART, each part placed by its *INSTANCEs (a translation line,
// then a rotation line: two points of the axis and an angle in degrees, applied after the
// translation) with the labels of each instance apart from the others'. An element record longer
// than a line goes on over the next ones (a line ending in a comma says so; volume elements are
// read until all their nodes are there). Files named by *INCLUDE, INPUT= (and *NODE/*ELEMENT,
// INPUT=) are read in place.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "hbc/io.hpp"
#include "io/detail/labelled_mesh.hpp"

namespace hbc {
namespace {

using detail::DeckLoc;
using detail::LabelledMesh;

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

// A keyword line: the keyword in upper case with single spaces ("END PART"), its parameters.
struct Keyword {
  std::string name;
  std::vector<std::pair<std::string, std::string>> params;  // NAME (upper case), value as written
  std::string param(const char* key) const {
    for (const auto& [k, v] : params)
      if (k == key) return v;
    return {};
  }
};

Keyword parse_keyword(std::string_view line) {
  std::vector<std::string_view> f;
  detail::split_commas(line.substr(1), f);
  Keyword k;
  for (char c : f[0]) {
    if (c == ' ' || c == '\t') {
      if (!k.name.empty() && k.name.back() != ' ') k.name += ' ';
    } else {
      k.name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  if (!k.name.empty() && k.name.back() == ' ') k.name.pop_back();
  for (size_t i = 1; i < f.size(); ++i) {
    const size_t eq = f[i].find('=');
    std::string_view v = eq == std::string_view::npos ? std::string_view() : detail::trim(f[i].substr(eq + 1));
    if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
    k.params.emplace_back(upper(detail::trim(f[i].substr(0, eq))), std::string(v));
  }
  return k;
}

// C3D<n><letters> with a prefix ending in C (C3D8R, DC3D20, AC3D10): a volume element of n nodes.
// Else the dimension the element is skipped as: 0 masses, 1 beams, trusses and connectors, 2 the
// rest (shells, membranes, continuum shells, rigid and plane elements, cohesive layers).
struct ElementType {
  CellShape shape = CellShape::Faces;  // Faces: not a volume element
  int nodes = 0, dim = 2;
};

ElementType element_type(const std::string& t) {
  ElementType r;
  const size_t p = t.find("3D");
  if (p != std::string::npos && p > 0 && t[p - 1] == 'C' &&
      std::all_of(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(p), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); })) {
    int64_t n = 0;
    size_t q = p + 2;
    while (q < t.size() && std::isdigit(static_cast<unsigned char>(t[q])) && n < 1000) n = 10 * n + (t[q++] - '0');
    const std::pair<int, CellShape> kinds[] = {{4, CellShape::Tet},     {10, CellShape::Tet},   {5, CellShape::Pyramid},
                                               {13, CellShape::Pyramid}, {6, CellShape::Prism}, {15, CellShape::Prism},
                                               {8, CellShape::Hex},     {20, CellShape::Hex},   {27, CellShape::Hex}};
    for (const auto& [k, s] : kinds)
      if (n == k) return {s, k, 3};
  }
  for (const char* pre : {"MASS", "ROTARYI"})
    if (t.rfind(pre, 0) == 0) r.dim = 0;
  for (const char* pre : {"T2D", "T3D", "B2", "B3", "PIPE", "ELBOW", "FRAME", "SPRING", "DASHPOT", "CONN", "JOINT", "GAP", "ITS"})
    if (t.rfind(pre, 0) == 0) r.dim = 1;
  return r;
}

class AbaqusReader {
 public:
  AbaqusReader(const std::string& source, const IncludeReader& include) : files_(source), include_(include) {}
  MeshInput read(std::string_view text) {
    lines(text, 0, 0);
    end_record();
    return top_.finish(files_, "*NODE", "*ELEMENT of type C3D4, C3D5, C3D6, C3D8, C3D10, C3D15, C3D20 or C3D27", end_);
  }

 private:
  enum class Mode { Other, Node, Element, Instance };
  void lines(std::string_view text, int32_t file, int depth);
  void keyword(const Keyword& k, const DeckLoc& at, int depth);
  void node(const std::vector<std::string_view>& f, const DeckLoc& at);
  void element(const std::vector<std::string_view>& f, bool continued, const DeckLoc& at);
  void placement(const std::vector<std::string_view>& f, const DeckLoc& at);
  void end_record();
  void end_instance();
  void include(const std::string& path, const DeckLoc& at, int depth) {
    int32_t file = 0;
    const std::string_view bytes = files_.include(include_, at, path, depth, file);
    lines(bytes, file, depth + 1);
  }
  LabelledMesh& target() { return part_ < 0 ? top_ : parts_[static_cast<size_t>(part_)].second; }
  double number(std::string_view f, const DeckLoc& at, const char* what) const {
    double v = 0;
    if (!f.empty() && !detail::parse_real(f, v)) files_.fail(at, std::string(what) + " (a number), found " + detail::shown_field(f));
    return v;
  }
  int64_t label(std::string_view f, const DeckLoc& at, const char* what) const {
    int64_t v = 0;
    if (!detail::parse_int(f, v) || v < 1 || v > 0xffffffffLL)
      files_.fail(at, std::string(what) + " (an integer label from 1 to 2^32 - 1), found " + detail::shown_field(f));
    return v;
  }

  detail::DeckFiles files_;
  const IncludeReader& include_;
  LabelledMesh top_;
  std::vector<std::pair<std::string, LabelledMesh>> parts_;
  int part_ = -1;  // the *PART being read, or -1
  Mode mode_ = Mode::Other;
  bool stop_ = false;  // past the model data (*STEP)
  DeckLoc end_;
  std::vector<std::string_view> fields_;
  // The *ELEMENT being read: its type, the open record's node labels and where it started.
  ElementType type_;
  std::string type_name_;
  std::vector<int64_t> record_;
  DeckLoc record_at_;
  bool open_ = false;
  // The *INSTANCE being read.
  int instance_part_ = -1, placement_lines_ = 0;
  double move_[3] = {0, 0, 0}, axis_[7] = {0, 0, 0, 0, 0, 0, 0};
  int64_t instances_ = 0;
};

void AbaqusReader::lines(std::string_view text, int32_t file, int depth) {
  detail::LineCursor c(text);
  std::string_view line;
  while (!stop_ && c.next(line)) {
    const DeckLoc at{file, c.line()};
    if (file == 0) end_ = at;
    const std::string_view t = detail::trim(line);
    if (t.empty() || t.rfind("**", 0) == 0) continue;
    if (t[0] == '*') {
      const Keyword k = parse_keyword(t);
      if (k.name != "INCLUDE") end_record();
      keyword(k, at, depth);
      continue;
    }
    detail::split_commas(t, fields_);
    const bool continues = fields_.size() > 1 && fields_.back().empty();
    if (continues) fields_.pop_back();
    if (mode_ == Mode::Node) node(fields_, at);
    else if (mode_ == Mode::Element) element(fields_, continues, at);
    else if (mode_ == Mode::Instance) placement(fields_, at);
  }
  if (file == 0 && !stop_) end_.line = std::max<int64_t>(1, c.line());
}

void AbaqusReader::keyword(const Keyword& k, const DeckLoc& at, int depth) {
  const std::string& n = k.name;
  if (n == "INCLUDE") {  // its lines go on with the keyword before it (*NODE, then the nodes' file)
    const std::string path = k.param("INPUT");
    if (path.empty()) files_.fail(at, "*INCLUDE, INPUT=<file>");
    return include(path, at, depth);
  }
  mode_ = Mode::Other;
  if (n == "STEP") {
    stop_ = true;
    return;
  }
  if (n == "NODE") {
    const std::string sys = upper(k.param("SYSTEM"));
    if (!sys.empty() && sys != "R")
      files_.fail(at, "*NODE in rectangular coordinates (SYSTEM=R), found SYSTEM=" + sys + ", which hbc does not convert");
    mode_ = Mode::Node;
  } else if (n == "ELEMENT") {
    type_name_ = upper(k.param("TYPE"));
    if (type_name_.empty()) files_.fail(at, "*ELEMENT with TYPE=<element type>");
    type_ = element_type(type_name_);
    mode_ = Mode::Element;
  } else if (n == "PART") {
    parts_.emplace_back(upper(k.param("NAME")), LabelledMesh());
    part_ = static_cast<int>(parts_.size() - 1);
  } else if (n == "END PART") {
    part_ = -1;
  } else if (n == "INSTANCE") {
    const std::string want = upper(k.param("PART"));
    instance_part_ = -1;
    for (size_t i = 0; i < parts_.size(); ++i)
      if (parts_[i].first == want) instance_part_ = static_cast<int>(i);
    if (instance_part_ < 0) files_.fail(at, "*INSTANCE of a *PART defined before it, found PART=" + (want.empty() ? "nothing" : want));
    placement_lines_ = 0;
    std::fill(std::begin(move_), std::end(move_), 0.0);
    std::fill(std::begin(axis_), std::end(axis_), 0.0);
    mode_ = Mode::Instance;
  } else if (n == "END INSTANCE") {
    end_instance();
  }
  if ((mode_ == Mode::Node || mode_ == Mode::Element) && !k.param("INPUT").empty()) include(k.param("INPUT"), at, depth);
}

void AbaqusReader::node(const std::vector<std::string_view>& f, const DeckLoc& at) {
  const int64_t id = label(f[0], at, "a node label");
  double p[3] = {0, 0, 0};
  for (size_t k = 0; k < 3 && k + 1 < f.size(); ++k) p[k] = number(f[k + 1], at, "a node coordinate");
  target().node(id, p, at);
}

void AbaqusReader::element(const std::vector<std::string_view>& f, bool continued, const DeckLoc& at) {
  if (type_.shape == CellShape::Faces) {
    // Skipped elements: one per record, a record going on while its lines end in a comma.
    if (!open_) target().skip(type_.dim);
    open_ = continued;
    return;
  }
  size_t k = 0;
  if (!open_) {
    label(f[0], at, "an element label");
    record_.clear();
    record_at_ = at;
    open_ = true;
    k = 1;
  }
  for (; k < f.size(); ++k) {
    if (f[k].empty() && k + 1 == f.size()) break;
    if (record_.size() == static_cast<size_t>(type_.nodes))
      files_.fail(at, std::to_string(type_.nodes) + " node labels for an element of type " + type_name_ + ", found more");
    record_.push_back(label(f[k], at, "a node label"));
  }
  if (record_.size() == static_cast<size_t>(type_.nodes)) {
    target().element(type_.shape, record_.data(), type_.nodes, record_at_);
    open_ = false;
  }
}

void AbaqusReader::end_record() {
  if (open_ && type_.shape != CellShape::Faces)
    files_.fail(record_at_, std::to_string(type_.nodes) + " node labels for an element of type " + type_name_ + ", found " +
                                std::to_string(record_.size()));
  open_ = false;
}

void AbaqusReader::placement(const std::vector<std::string_view>& f, const DeckLoc& at) {
  if (placement_lines_ == 2) files_.fail(at, "at most two data lines after *INSTANCE (translation, rotation), found a third");
  double* out = placement_lines_ == 0 ? move_ : axis_;
  const size_t n = placement_lines_ == 0 ? 3 : 7;
  for (size_t k = 0; k < n && k < f.size(); ++k) out[k] = number(f[k], at, placement_lines_ == 0 ? "a translation" : "a rotation axis point or angle");
  ++placement_lines_;
}

void AbaqusReader::end_instance() {
  if (instance_part_ < 0) return;
  // Rodrigues' rotation about the axis from a to b by the angle, after the translation.
  const double a[3] = {axis_[0], axis_[1], axis_[2]};
  double u[3] = {axis_[3] - a[0], axis_[4] - a[1], axis_[5] - a[2]};
  const double len = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const bool rotate = len > 0 && axis_[6] != 0;
  if (rotate)
    for (double& x : u) x /= len;
  const double th = axis_[6] * 3.14159265358979323846 / 180, c = std::cos(th), s = std::sin(th);
  const double* t = move_;
  top_.add_instance(parts_[static_cast<size_t>(instance_part_)].second, ++instances_, [&](double* p) {
    for (int k = 0; k < 3; ++k) p[k] += t[k];
    if (!rotate) return;
    const double v[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int k = 0; k < 3; ++k) p[k] = a[k] + v[k] * c + x[k] * s + u[k] * d * (1 - c);
  });
  instance_part_ = -1;
}

}  // namespace

MeshInput read_abaqus(std::string_view text, const std::string& source, const IncludeReader& include) {
  return AbaqusReader(source, include).read(text);
}

}  // namespace hbc
