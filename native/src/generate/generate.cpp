// Synthetic meshes. Prism-like meshes (grid, sector, cylinder) are a planar polygon mesh extruded
// in layers with direct indexing, which keeps a 10^6-cell grid well under a second; split grids
// go through a face soup merged by sorting, simpler and fast enough for their sizes.
#include "hbc/generate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace hbc {
namespace {

constexpr int64_t kMaxIndex = std::numeric_limits<int32_t>::max();

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// Planar mesh: counterclockwise polygons (3 or 4 corners) over 2D points.
struct Planar {
  std::vector<double> xy;  // 2 * nv
  Csr<int32_t> polys;
  size_t num_vertices() const { return xy.size() / 2; }
};

// Each polygon becomes a column of `layers` cells (quads -> hexes, triangles -> prisms).
// Vertex (v, l) = l*nv + v; horizontal face (p, l) = l*np + p with the polygon's loop (normal +z);
// vertical face of 2D edge e in layer l = (layers+1)*np + l*ne + e, loop (lo, hi, hi', lo') which
// is outward for a polygon walking the edge from lo to hi.
MeshInput extrude(const Planar& pl, int layers, double height, const std::string& source) {
  require(layers >= 1, source + ": at least 1 layer");
  const int64_t nv = static_cast<int64_t>(pl.num_vertices());
  const int64_t np = static_cast<int64_t>(pl.polys.rows());
  const int64_t corners = static_cast<int64_t>(pl.polys.items.size());

  // 2D edges by sorting (lo, hi, slot): ids in key order, independent of hashing.
  std::vector<std::array<int32_t, 3>> slots(static_cast<size_t>(corners));
  for (int64_t p = 0; p < np; ++p) {
    auto loop = pl.polys[static_cast<size_t>(p)];
    for (size_t i = 0; i < loop.size(); ++i) {
      const int32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      slots[static_cast<size_t>(pl.polys.offsets[p]) + i] = {std::min(a, b), std::max(a, b),
                                                             pl.polys.offsets[p] + static_cast<int32_t>(i)};
    }
  }
  std::sort(slots.begin(), slots.end());
  std::vector<int32_t> slot_edge(static_cast<size_t>(corners));
  std::vector<std::array<int32_t, 2>> edges;
  for (const auto& s : slots) {
    if (edges.empty() || edges.back() != std::array<int32_t, 2>{s[0], s[1]}) edges.push_back({s[0], s[1]});
    slot_edge[static_cast<size_t>(s[2])] = static_cast<int32_t>(edges.size() - 1);
  }
  const int64_t ne = static_cast<int64_t>(edges.size());

  const int64_t L = layers;
  const int64_t total_v = nv * (L + 1), total_c = np * L;
  const int64_t face_items = corners * (L + 1) + 4 * ne * L;
  const int64_t cell_items = (2 * np + corners) * L;
  require(total_v <= kMaxIndex && face_items <= kMaxIndex && cell_items <= kMaxIndex &&
              np * (L + 1) + ne * L <= kMaxIndex,
          source + ": too large for 32-bit ids");

  MeshInput in;
  in.source = source;
  in.points.resize(static_cast<size_t>(3 * total_v));
  for (int64_t l = 0; l <= L; ++l)
    for (int64_t v = 0; v < nv; ++v) {
      double* p = &in.points[static_cast<size_t>(3 * (l * nv + v))];
      p[0] = pl.xy[static_cast<size_t>(2 * v)];
      p[1] = pl.xy[static_cast<size_t>(2 * v + 1)];
      p[2] = static_cast<double>(l) * height;
    }

  in.faces.offsets.reserve(static_cast<size_t>(np * (L + 1) + ne * L + 1));
  in.faces.items.reserve(static_cast<size_t>(face_items));
  for (int64_t l = 0; l <= L; ++l)
    for (int64_t p = 0; p < np; ++p) {
      for (int32_t v : pl.polys[static_cast<size_t>(p)]) in.faces.items.push_back(static_cast<int32_t>(l * nv + v));
      in.faces.offsets.push_back(static_cast<int32_t>(in.faces.items.size()));
    }
  for (int64_t l = 0; l < L; ++l)
    for (const auto& e : edges) {
      const int32_t lo = static_cast<int32_t>(l * nv + e[0]), hi = static_cast<int32_t>(l * nv + e[1]);
      const int32_t up = static_cast<int32_t>(nv);
      for (int32_t v : {lo, hi, hi + up, lo + up}) in.faces.items.push_back(v);
      in.faces.offsets.push_back(static_cast<int32_t>(in.faces.items.size()));
    }

  in.cells.offsets.reserve(static_cast<size_t>(total_c + 1));
  in.cells.items.reserve(static_cast<size_t>(cell_items));
  const int64_t vbase = np * (L + 1);
  for (int64_t l = 0; l < L; ++l)
    for (int64_t p = 0; p < np; ++p) {
      in.cells.items.push_back(static_cast<int32_t>(2 * (l * np + p) + 1));  // bottom, seen from above
      in.cells.items.push_back(static_cast<int32_t>(2 * ((l + 1) * np + p)));
      auto loop = pl.polys[static_cast<size_t>(p)];
      for (size_t i = 0; i < loop.size(); ++i) {
        const int32_t k = pl.polys.offsets[p] + static_cast<int32_t>(i);
        const int32_t e = slot_edge[static_cast<size_t>(k)];
        const int flip = loop[i] == edges[static_cast<size_t>(e)][0] ? 0 : 1;
        in.cells.items.push_back(static_cast<int32_t>(2 * (vbase + l * ne + e) + flip));
      }
      in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
    }
  return in;
}

Planar planar_grid(int n, int m, double spacing) {
  Planar pl;
  pl.xy.reserve(static_cast<size_t>(2 * (n + 1) * (m + 1)));
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      pl.xy.push_back(i * spacing);
      pl.xy.push_back(j * spacing);
    }
  auto id = [&](int i, int j) { return static_cast<int32_t>(i + (n + 1) * j); };
  pl.polys.offsets.reserve(static_cast<size_t>(n) * m + 1);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      pl.polys.push_row(q, q + 4);
    }
  return pl;
}

void check_grid_size(int n, int m, int k, double spacing, const char* what) {
  require(n >= 1 && m >= 1 && k >= 1, std::string(what) + ": sizes must be at least 1");
  require(std::isfinite(spacing) && spacing > 0, std::string(what) + ": spacing must be positive");
  // Faces of a grid hold about 12 vertex ids per cell; keep them within 32-bit offsets.
  require(static_cast<int64_t>(n + 1) * (m + 1) * (k + 1) * 13 < kMaxIndex,
          std::string(what) + ": too large for 32-bit ids");
}

// ---- face soup for split grids -----------------------------------------------------------

// Cells given as outward loops of at most 4 vertices; finish() merges loops with the same vertex
// set into one face (first appearance keeps its loop) and records each cell's view as a flip.
class Soup {
 public:
  std::vector<double> points;

  void face(std::initializer_list<int32_t> loop) { loops_.push_row(loop.begin(), loop.end()); }
  void end_cell() { cell_end_.push_back(static_cast<int32_t>(loops_.rows())); }

  MeshInput finish(const std::string& source) const {
    const size_t nl = loops_.rows();
    std::vector<std::array<int32_t, 4>> key(nl);
    for (size_t i = 0; i < nl; ++i) {
      auto loop = loops_[i];
      if (loop.size() > 4) throw std::logic_error("soup faces have at most 4 vertices");
      key[i].fill(std::numeric_limits<int32_t>::max());
      std::copy(loop.begin(), loop.end(), key[i].begin());
      std::sort(key[i].begin(), key[i].end());
    }
    std::vector<int32_t> order(nl);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
      return key[a] != key[b] ? key[a] < key[b] : a < b;
    });
    std::vector<int32_t> rep(nl);
    for (size_t s = 0; s < nl;) {
      size_t t = s;
      while (t < nl && key[order[t]] == key[order[s]]) rep[order[t++]] = order[s];
      if (t - s > 2) throw std::logic_error("soup face shared by more than 2 cells");
      s = t;
    }
    MeshInput in;
    in.source = source;
    in.points = points;
    std::vector<int32_t> id(nl, -1);
    for (size_t i = 0; i < nl; ++i) {
      if (rep[i] != static_cast<int32_t>(i)) continue;
      id[i] = static_cast<int32_t>(in.faces.rows());
      in.faces.push_row(loops_[i]);
    }
    size_t c = 0;
    for (size_t i = 0; i < nl; ++i) {
      const int32_t r = rep[i];
      int flip = 0;
      if (r != static_cast<int32_t>(i)) {
        auto a = loops_[static_cast<size_t>(r)], b = loops_[i];
        const size_t p = static_cast<size_t>(std::find(a.begin(), a.end(), b[0]) - a.begin());
        flip = a[(p + 1) % a.size()] == b[1] ? 0 : 1;
      }
      in.cells.items.push_back(2 * id[static_cast<size_t>(r)] + flip);
      if (static_cast<int32_t>(i + 1) == cell_end_[c]) {
        in.cells.offsets.push_back(static_cast<int32_t>(in.cells.items.size()));
        ++c;
      }
    }
    return in;
  }

 private:
  Csr<int32_t> loops_;
  std::vector<int32_t> cell_end_;  // loop count after each cell
};

// MEDIT hex loops over local corners 0-3 (bottom, counterclockwise from above) and 4-7 above them,
// outward, with the neighbour offset across each (in the frame of the corners).
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
constexpr int kHexAcross[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
constexpr int kCornerOffset[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

}  // namespace

MeshInput generate_grid(int n, int m, int k, double spacing) {
  check_grid_size(n, m, k, spacing, "grid");
  return extrude(planar_grid(n, m, spacing), k, spacing,
                 "grid " + std::to_string(n) + "x" + std::to_string(m) + "x" + std::to_string(k));
}

std::vector<std::array<int32_t, 3>> random_cells(int n, int m, int k, int count, uint32_t seed) {
  check_grid_size(n, m, k, 1.0, "random cells");
  const int64_t nc = static_cast<int64_t>(n) * m * k;
  require(count >= 0 && count <= nc, "random cells: count must be in [0, " + std::to_string(nc) + "]");
  std::vector<int32_t> ids(static_cast<size_t>(nc));
  std::iota(ids.begin(), ids.end(), 0);
  std::mt19937 gen(seed);
  std::vector<std::array<int32_t, 3>> out;
  out.reserve(static_cast<size_t>(count));
  for (int64_t t = 0; t < count; ++t) {
    const int64_t r = t + static_cast<int64_t>(gen() % static_cast<uint64_t>(nc - t));
    std::swap(ids[static_cast<size_t>(t)], ids[static_cast<size_t>(r)]);
    const int32_t c = ids[static_cast<size_t>(t)];
    out.push_back({c % n, (c / n) % m, c / (n * m)});
  }
  return out;
}

MeshInput generate_split(int n, int m, int k, SplitKind kind,
                         std::span<const std::array<int32_t, 3>> cells, int axis, double spacing) {
  check_grid_size(n, m, k, spacing, "split");
  require(axis >= 0 && axis <= 2, "split: axis must be x, y or z");
  const int dims[3] = {n, m, k};
  auto cell_id = [&](const int c[3]) { return c[0] + n * (c[1] + m * c[2]); };
  auto vert_id = [&](const int c[3]) { return static_cast<int32_t>(c[0] + (n + 1) * (c[1] + (m + 1) * c[2])); };

  std::vector<uint8_t> split(static_cast<size_t>(n) * m * k, 0);
  for (const auto& c : cells) {
    for (int d = 0; d < 3; ++d)
      require(c[d] >= 0 && c[d] < dims[d], "split: cell (" + std::to_string(c[0]) + "," + std::to_string(c[1]) +
                                               "," + std::to_string(c[2]) + ") outside the grid");
    int q[3] = {c[0], c[1], c[2]};
    if (kind != SplitKind::Prisms) {
      split[static_cast<size_t>(cell_id(q))] = 1;
      continue;
    }
    for (q[axis] = 0; q[axis] < dims[axis]; ++q[axis]) split[static_cast<size_t>(cell_id(q))] = 1;
  }

  Soup soup;
  soup.points.reserve(static_cast<size_t>(3 * (n + 1) * (m + 1) * (k + 1)));
  for (int z = 0; z <= k; ++z)
    for (int y = 0; y <= m; ++y)
      for (int x = 0; x <= n; ++x)
        for (double t : {x * spacing, y * spacing, z * spacing}) soup.points.push_back(t);
  // Prisms use a frame whose third axis is `axis` (a cyclic permutation keeps it right-handed);
  // the other kinds use the grid's own frame.
  const int w = kind == SplitKind::Prisms ? axis : 2, u = (w + 1) % 3, v = (w + 2) % 3;

  int c[3];
  for (c[2] = 0; c[2] < k; ++c[2])
    for (c[1] = 0; c[1] < m; ++c[1])
      for (c[0] = 0; c[0] < n; ++c[0]) {
        int32_t h[8];
        for (int i = 0; i < 8; ++i) {
          int p[3] = {c[0], c[1], c[2]};
          p[u] += kCornerOffset[i][0];
          p[v] += kCornerOffset[i][1];
          p[w] += kCornerOffset[i][2];
          h[i] = vert_id(p);
        }
        const bool is_split = split[static_cast<size_t>(cell_id(c))] != 0;
        if (!is_split) {
          for (int f = 0; f < 6; ++f) {
            const int32_t q0 = h[kHexFaces[f][0]], q1 = h[kHexFaces[f][1]], q2 = h[kHexFaces[f][2]],
                          q3 = h[kHexFaces[f][3]];
            int o[3] = {c[0], c[1], c[2]};
            for (int d = 0; d < 3; ++d) o[d] += kHexAcross[f][d];  // only read for tets: grid frame
            const bool inside = o[0] >= 0 && o[0] < n && o[1] >= 0 && o[1] < m && o[2] >= 0 && o[2] < k;
            if (kind == SplitKind::Tets && inside && split[static_cast<size_t>(cell_id(o))]) {
              // Two triangles along the diagonal through the lowest id, as the tets across have.
              const int32_t lo = std::min({q0, q1, q2, q3});
              if (lo == q0 || lo == q2) {
                soup.face({q0, q1, q2});
                soup.face({q0, q2, q3});
              } else {
                soup.face({q1, q2, q3});
                soup.face({q1, q3, q0});
              }
            } else {
              soup.face({q0, q1, q2, q3});
            }
          }
          soup.end_cell();
          continue;
        }
        switch (kind) {
          case SplitKind::Pyramids: {
            const int32_t apex = static_cast<int32_t>(soup.points.size() / 3);
            for (int d = 0; d < 3; ++d) soup.points.push_back((c[d] + 0.5) * spacing);
            for (const auto& f : kHexFaces) {
              soup.face({h[f[0]], h[f[1]], h[f[2]], h[f[3]]});
              for (int i = 0; i < 4; ++i) soup.face({h[f[(i + 1) % 4]], h[f[i]], apex});
              soup.end_cell();
            }
            break;
          }
          case SplitKind::Prisms: {
            // MEDIT prism loops over (a b c) below and (a' b' c') above, counterclockwise.
            for (const auto& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
              const int32_t a = h[t[0]], b = h[t[1]], cc = h[t[2]];
              const int32_t a2 = h[t[0] + 4], b2 = h[t[1] + 4], c2 = h[t[2] + 4];
              soup.face({a, cc, b});
              soup.face({a2, b2, c2});
              soup.face({a, b, b2, a2});
              soup.face({b, cc, c2, b2});
              soup.face({cc, a, a2, c2});
              soup.end_cell();
            }
            break;
          }
          case SplitKind::Tets: {
            // Kuhn: one tet per axis order, along the path 000 -> e_p0 -> e_p0 + e_p1 -> 111.
            int perm[3] = {0, 1, 2};
            do {
              int p1[3] = {0, 0, 0};
              p1[perm[0]] = 1;
              int p2[3] = {p1[0], p1[1], p1[2]};
              p2[perm[1]] = 1;
              auto corner = [&](const int* off) {
                int g[3] = {c[0] + off[0], c[1] + off[1], c[2] + off[2]};
                return vert_id(g);
              };
              const int zero[3] = {0, 0, 0}, one[3] = {1, 1, 1};
              int32_t t0 = corner(zero), t1 = corner(p1), t2 = corner(p2), t3 = corner(one);
              // det(e_p0, e_p1, e_p2) is the permutation's sign; MEDIT's tet loops need it positive.
              const bool odd = (perm[0] == 0 && perm[1] == 2) || (perm[0] == 1 && perm[1] == 0) ||
                               (perm[0] == 2 && perm[1] == 1);
              if (odd) std::swap(t1, t2);
              soup.face({t0, t2, t1});
              soup.face({t0, t1, t3});
              soup.face({t1, t2, t3});
              soup.face({t0, t3, t2});
              soup.end_cell();
            } while (std::next_permutation(perm, perm + 3));
            break;
          }
        }
      }
  const char* names[3] = {"pyramids", "prisms", "tets"};
  return soup.finish("split " + std::string(names[static_cast<int>(kind)]) + " " + std::to_string(n) + "x" +
                     std::to_string(m) + "x" + std::to_string(k));
}

// The cross-section of generate_sector: `valence` parallelograms round the origin, each cut into
// rings×rings quads, of radius 1. Turning it by 2π/valence maps it onto itself.
Planar planar_sector(int valence, int rings) {
  const int N = valence, R = rings;
  Planar pl;
  pl.xy.assign(static_cast<size_t>(2 * (1 + N * R + N * R * R)), 0.0);
  auto dir = [&](int s, int d) {  // unit vector of ray s, component d
    const double a = 2.0 * std::numbers::pi * (s % N) / N;
    return d == 0 ? std::cos(a) : std::sin(a);
  };
  // Vertex (a, b) of sector s sits at (a A_s + b A_{s+1}) / R; its rays are shared with the
  // neighbouring sectors, so ray points get their own ids.
  auto id = [&](int s, int a, int b) -> int32_t {
    if (a == 0 && b == 0) return 0;
    if (b == 0) return 1 + s * R + (a - 1);
    if (a == 0) return 1 + ((s + 1) % N) * R + (b - 1);
    return 1 + N * R + s * R * R + (a - 1) * R + (b - 1);
  };
  for (int s = 0; s < N; ++s)
    for (int a = 0; a <= R; ++a)
      for (int b = 0; b <= R; ++b) {
        const int32_t v = id(s, a, b);
        for (int d = 0; d < 2; ++d)
          pl.xy[static_cast<size_t>(2 * v + d)] = (a * dir(s, d) + b * dir(s + 1, d)) / R;
      }
  for (int s = 0; s < N; ++s)
    for (int a = 0; a < R; ++a)
      for (int b = 0; b < R; ++b) {
        // Counterclockwise: the sector's frame (A_s, A_{s+1}) has positive determinant sin(2π/N).
        const int32_t q[4] = {id(s, a, b), id(s, a + 1, b), id(s, a + 1, b + 1), id(s, a, b + 1)};
        pl.polys.push_row(q, q + 4);
      }
  return pl;
}

MeshInput generate_sector(int valence, int rings, int layers) {
  require(valence >= 3, "sector: valence must be at least 3");
  require(rings >= 1 && layers >= 1, "sector: rings and layers must be at least 1");
  require(static_cast<int64_t>(valence) * (rings + 1) * (rings + 1) * (layers + 1) * 13 < kMaxIndex,
          "sector: too large for 32-bit ids");
  const int N = valence, R = rings;
  const Planar pl = planar_sector(N, R);
  return extrude(pl, layers, 1.0 / R,
                 "sector valence " + std::to_string(N) + " rings " + std::to_string(R) + " layers " +
                     std::to_string(layers));
}

MeshInput generate_cylinder(int radius_cells, int layers) {
  require(radius_cells >= 1 && layers >= 1, "cylinder: radius cells and layers must be at least 1");
  require(radius_cells <= 4096 && static_cast<int64_t>(radius_cells) * radius_cells * (layers + 1) * 100 < kMaxIndex,
          "cylinder: too large for 32-bit ids");
  const int a = (radius_cells + 1) / 2, c = 2 * a, rings = radius_cells - a;
  Planar pl;
  for (int j = 0; j <= c; ++j)
    for (int i = 0; i <= c; ++i) {
      pl.xy.push_back(i - a);
      pl.xy.push_back(j - a);
    }
  auto core = [&](int i, int j) { return static_cast<int32_t>(i + (c + 1) * j); };
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < c; ++i) {
      const int32_t q[4] = {core(i, j), core(i + 1, j), core(i + 1, j + 1), core(i, j + 1)};
      pl.polys.push_row(q, q + 4);
    }
  // The core's boundary counterclockwise from (a, 0), the midpoint of its right side.
  std::vector<int32_t> inner;
  {
    int i = c, j = a;
    const int step[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};
    int d = 0;
    for (int t = 0; t < 4 * c; ++t) {
      inner.push_back(core(i, j));
      if ((d == 0 && j == c) || (d == 1 && i == 0) || (d == 2 && j == 0) || (d == 3 && i == c)) d = (d + 1) % 4;
      i += step[d][0];
      j += step[d][1];
    }
  }
  const double outer_radius = a + rings;
  for (int r = 1; r <= rings; ++r) {
    // Along each direction the rings step evenly from the core's square to the outer circle.
    const double t = static_cast<double>(r) / rings;
    const double perimeter = (1.0 - t) * 8.0 * a + t * 2.0 * std::numbers::pi * outer_radius;
    const int n_in = static_cast<int>(inner.size());
    const int n_out = std::max(n_in, 4 * static_cast<int>(std::lround(perimeter / 4.0)));
    const int d = n_out - n_in;
    std::vector<int32_t> outer(static_cast<size_t>(n_out));
    for (int o = 0; o < n_out; ++o) {
      const double th = 2.0 * std::numbers::pi * o / n_out;
      const double cs = std::cos(th), sn = std::sin(th);
      const double radius = (1.0 - t) * a / std::max(std::abs(cs), std::abs(sn)) + t * outer_radius;
      outer[static_cast<size_t>(o)] = static_cast<int32_t>(pl.num_vertices());
      pl.xy.push_back(radius * cs);
      pl.xy.push_back(radius * sn);
    }
    // Slot o is a triangle when it holds the middle of one of d equal arcs of the ring: the
    // quads of an arc then lean at most half a cell either way.
    auto arc_mid = [&](int64_t o) { return (2 * o * d + n_out) / (2 * static_cast<int64_t>(n_out)); };
    int i = 0;
    for (int o = 0; o < n_out; ++o) {
      const int32_t o0 = outer[static_cast<size_t>(o)], o1 = outer[static_cast<size_t>((o + 1) % n_out)];
      const int32_t i0 = inner[static_cast<size_t>(i % n_in)];
      if (arc_mid(o + 1) > arc_mid(o)) {
        const int32_t t[3] = {i0, o0, o1};
        pl.polys.push_row(t, t + 3);
      } else {
        const int32_t q[4] = {i0, o0, o1, inner[static_cast<size_t>((i + 1) % n_in)]};
        pl.polys.push_row(q, q + 4);
        ++i;
      }
    }
    inner = std::move(outer);
  }
  return extrude(pl, layers, 1.0,
                 "cylinder radius " + std::to_string(radius_cells) + " layers " + std::to_string(layers));
}

}  // namespace hbc

namespace hbc {
namespace {

// The cross-section of a twisted ring: an a×a grid of unit quads centred on the origin. With
// `prisms`, `fan` quads are each a fan of 4 triangles around an added centre vertex: the middle
// quad (odd a), or the quad at (1, 1) and those it turns into under the ring's turn (even a or
// `spread`), so that turning the section maps it onto itself, vertices to vertices.
Planar ring_section(int a, bool prisms, int quarter_turns, bool spread) {
  Planar pl = planar_grid(a, a, 1.0);
  for (double& c : pl.xy) c -= 0.5 * a;
  if (!prisms) return pl;
  std::vector<uint8_t> fan(static_cast<size_t>(a) * a, 0);
  if (!spread && a % 2 == 1) {
    fan[static_cast<size_t>(a / 2) * a + a / 2] = 1;
  } else {
    int i = 1, j = 1;
    const int turns = quarter_turns == 0 ? 1 : 4 / std::gcd(quarter_turns, 4);
    for (int t = 0; t < turns; ++t) {
      fan[static_cast<size_t>(j) * a + i] = 1;
      for (int r = 0; r < quarter_turns; ++r) std::tie(i, j) = std::make_pair(a - 1 - j, i);
    }
  }
  Planar out;
  out.xy = pl.xy;
  for (size_t p = 0; p < pl.polys.rows(); ++p) {
    auto q = pl.polys[p];
    if (!fan[p]) {
      out.polys.push_row(q.begin(), q.end());
      continue;
    }
    const int32_t centre = static_cast<int32_t>(out.xy.size() / 2);
    double cx = 0, cy = 0;
    for (int32_t v : q) cx += 0.25 * pl.xy[2 * static_cast<size_t>(v)], cy += 0.25 * pl.xy[2 * static_cast<size_t>(v) + 1];
    out.xy.push_back(cx);
    out.xy.push_back(cy);
    for (size_t k = 0; k < 4; ++k) {
      const int32_t tri[3] = {q[k], q[(k + 1) % 4], centre};
      out.polys.push_row(tri, tri + 3);
    }
  }
  return out;
}

// The section vertex that vertex v of `pl` lands on when the section turns by `angle` about the
// origin (the section must map onto itself). Vertices sorted by x: each turned point looks only at
// those within the tolerance in x, so large sections take n log n, not n².
std::vector<int32_t> turn_map(const Planar& pl, double angle) {
  constexpr double tol = 1e-9;
  const size_t nv = pl.num_vertices();
  std::vector<int32_t> by_x(nv);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int32_t a, int32_t b) { return pl.xy[2 * static_cast<size_t>(a)] < pl.xy[2 * static_cast<size_t>(b)]; });
  std::vector<int32_t> to(nv, -1);
  const double c = std::cos(angle), sn = std::sin(angle);
  for (size_t v = 0; v < nv; ++v) {
    const double x = c * pl.xy[2 * v] - sn * pl.xy[2 * v + 1], y = sn * pl.xy[2 * v] + c * pl.xy[2 * v + 1];
    auto w = std::lower_bound(by_x.begin(), by_x.end(), x - tol,
                              [&](int32_t a, double t) { return pl.xy[2 * static_cast<size_t>(a)] < t; });
    for (; w != by_x.end() && pl.xy[2 * static_cast<size_t>(*w)] < x + tol; ++w)
      if (std::abs(pl.xy[2 * static_cast<size_t>(*w) + 1] - y) < tol) to[v] = *w;
    require(to[v] >= 0, "twisted ring: the section does not map onto itself");
  }
  return to;
}

// Radius of a twisted ring of an a×a section: its hole is 2a + 4 across.
double ring_radius(int a) { return 1.5 * a + 2.0; }

// The section swept round the z axis in `sections` layers, turning by `angle` on the way round,
// the last layer closed on the first one turned (build_mesh merges the faces that then repeat
// layer 0's). `radius`: of the circle the section's centre follows.
MeshInput ring_of(const Planar& pl, int sections, double angle, double radius, const std::string& source) {
  MeshInput in = extrude(pl, sections, 1.0, source);
  const size_t nv = pl.num_vertices();
  const double pi = std::acos(-1.0);
  for (int l = 0; l < sections; ++l) {
    const double phi = 2 * pi * l / sections, alpha = angle * l / sections;
    for (size_t v = 0; v < nv; ++v) {
      double* p = &in.points[3 * (static_cast<size_t>(l) * nv + v)];
      const double x = p[0] * std::cos(alpha) - p[1] * std::sin(alpha);
      const double y = p[0] * std::sin(alpha) + p[1] * std::cos(alpha);
      p[0] = (radius + x) * std::cos(phi);
      p[1] = (radius + x) * std::sin(phi);
      p[2] = y;
    }
  }
  const std::vector<int32_t> to = turn_map(pl, angle);
  const int32_t last = static_cast<int32_t>(sections * nv);
  for (int32_t& v : in.faces.items)
    if (v >= last) v = to[static_cast<size_t>(v - last)];
  in.points.resize(3 * static_cast<size_t>(last));
  in.source = source;
  return in;
}

// Hex `cell` of `in` becomes 6 pyramids, one per face, around an added vertex at the centroid of
// its corners (generate_split's Pyramids on any hex): its quads stay, so its neighbours stay hexes.
// The 12 triangles (a hex edge and the centre) are each shared by the pyramids of the two faces at
// that edge. The pieces take the cell's place in the numbering, consecutively.
void split_into_pyramids(MeshInput& in, size_t cell) {
  const auto row = in.cells[cell];
  const std::vector<int32_t> faces(row.begin(), row.end());
  if (faces.size() != 6) throw std::logic_error("split_into_pyramids: not a hex");
  std::vector<int32_t> corners;
  for (int32_t half : faces)
    for (int32_t v : in.faces[static_cast<size_t>(half / 2)]) corners.push_back(v);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  const int32_t apex = static_cast<int32_t>(in.points.size() / 3);
  for (int d = 0; d < 3; ++d) {
    double c = 0;
    for (int32_t v : corners) c += in.points[3 * static_cast<size_t>(v) + d];
    in.points.push_back(c / static_cast<double>(corners.size()));
  }
  std::vector<std::array<int32_t, 3>> triangles;  // (lo, hi, face) of each hex edge's triangle
  Csr<int32_t> pieces;
  for (int32_t half : faces) {
    auto l = in.faces[static_cast<size_t>(half / 2)];
    std::vector<int32_t> loop(l.begin(), l.end());  // as the cell sees it: outward
    if (half % 2) std::reverse(loop.begin(), loop.end());
    std::vector<int32_t> piece{half};
    for (size_t i = 0; i < loop.size(); ++i) {
      // (b, a, apex) walks the base edge a -> b backwards: outward for this pyramid.
      const int32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      const std::array<int32_t, 2> key{std::min(a, b), std::max(a, b)};
      auto it = std::find_if(triangles.begin(), triangles.end(),
                             [&](const auto& t) { return t[0] == key[0] && t[1] == key[1]; });
      if (it == triangles.end()) {
        const int32_t f = static_cast<int32_t>(in.faces.rows());
        const int32_t tri[3] = {b, a, apex};
        in.faces.push_row(tri, tri + 3);
        triangles.push_back({key[0], key[1], f});
        piece.push_back(2 * f);
      } else {  // the neighbouring pyramid made it walking the edge the other way
        piece.push_back(2 * (*it)[2] + (in.faces[static_cast<size_t>((*it)[2])][0] == b ? 0 : 1));
      }
    }
    pieces.push_row(piece.begin(), piece.end());
  }
  Csr<int32_t> cells;
  for (size_t c = 0; c < in.cells.rows(); ++c) {
    if (c != cell) {
      cells.push_row(in.cells[c]);
      continue;
    }
    for (size_t p = 0; p < pieces.rows(); ++p) cells.push_row(pieces[p]);
  }
  in.cells = std::move(cells);
}

// `from` appended to `to`: a second, disjoint part of the same mesh.
void append_part(MeshInput& to, const MeshInput& from) {
  const int32_t nv = static_cast<int32_t>(to.points.size() / 3), nf = static_cast<int32_t>(to.faces.rows());
  to.points.insert(to.points.end(), from.points.begin(), from.points.end());
  std::vector<int32_t> row;
  for (size_t f = 0; f < from.faces.rows(); ++f) {
    row.clear();
    for (int32_t v : from.faces[f]) row.push_back(v + nv);
    to.faces.push_row(row.begin(), row.end());
  }
  for (size_t c = 0; c < from.cells.rows(); ++c) {
    row.clear();
    for (int32_t half : from.cells[c]) row.push_back(half + 2 * nf);
    to.cells.push_row(row.begin(), row.end());
  }
}

// A twisted ring of an a×a section (a even) round a circle of `radius`, whose first layer has the
// cell at quad (a/2 - 1, 0), the boundary quad just left of the middle line, split into pyramids.
MeshInput pyramid_ring(int a, int sections, int quarter_turns, double radius) {
  MeshInput in = ring_of(ring_section(a, false, quarter_turns, false), sections, quarter_turns * 0.5 * std::acos(-1.0),
                         radius, "twisted_pair");
  // Quad (i, j) of the section is polygon i + a j, and layer 0's cells are the polygons in order.
  split_into_pyramids(in, static_cast<size_t>(a / 2 - 1));
  return in;
}

}  // namespace

MeshInput generate_twisted_pair(int section, int sections) {
  require(section >= 2 && section % 2 == 0 && sections >= 3,
          "twisted pair: an even section of at least 2 cells and at least 3 sections");
  require(static_cast<int64_t>(section + 1) * (section + 1) * sections * 13 < kMaxIndex,
          "twisted pair: too large for 32-bit ids");
  // The half-turned ring where a single twisted ring lies, the quarter-turned one round it. A
  // section turned by 45° reaches section/√2 from its centre: 2 sections between the circles leave
  // at least 0.59 of a section between the rings.
  const double inner = ring_radius(section), outer = inner + 2.0 * section;
  MeshInput pair = pyramid_ring(section, sections, 1, outer);
  append_part(pair, pyramid_ring(section, sections, 2, inner));
  pair.source = "twisted_pair";
  return pair;
}

MeshInput generate_twisted_ring(int section, int sections, int quarter_turns, bool prisms, bool spread) {
  require(section >= 1 && sections >= 3, "twisted ring: a section of at least 1 cell and at least 3 sections");
  require(quarter_turns >= 0 && quarter_turns <= 3, "twisted ring: 0 to 3 quarter turns");
  require(!prisms || section >= 3 || (section % 2 == 1 && !spread),
          "twisted ring: prisms need an odd section or one of at least 3 cells");
  const Planar pl = ring_section(section, prisms, quarter_turns, spread || section % 2 == 0);
  return ring_of(pl, sections, quarter_turns * 0.5 * std::acos(-1.0), ring_radius(section), "twisted_ring");
}

}  // namespace hbc
