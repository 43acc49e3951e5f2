// The fewest parts of a sheet's curves (fewest_parts.hpp): a lower bound from the conflicts, a
// first split from greedy growth, then an exact branch and bound within a step budget.
#include "structure/fewest_parts.hpp"

#include <algorithm>
#include <numeric>

namespace hbc::detail {
namespace {

using Graph = Csr<int32_t>;

// The largest set of pairwise conflicting curves: each must open a part of its own. Conflicts are
// few per curve (the curves at one corner of a block), so a plain search over each curve's later
// neighbours is quick; `budget` caps it all the same.
void grow_clique(const Graph& g, std::vector<int32_t>& cand, int32_t size, int32_t& best, int64_t& budget) {
  if (size > best) best = size;
  while (!cand.empty() && budget-- > 0) {
    if (size + static_cast<int32_t>(cand.size()) <= best) return;
    const int32_t v = cand.back();
    cand.pop_back();
    std::vector<int32_t> next;
    const auto nb = g[v];
    for (int32_t w : cand)
      if (std::binary_search(nb.begin(), nb.end(), w)) next.push_back(w);
    grow_clique(g, next, size + 1, best, budget);
  }
}

int32_t largest_conflicting_set(const Graph& conflicts, int64_t& budget) {
  const size_t n = conflicts.rows();
  int32_t best = n == 0 ? 0 : conflicts.items.empty() ? 1 : 2;
  for (size_t v = 0; v < n; ++v) {
    std::vector<int32_t> cand;
    for (int32_t w : conflicts[v])
      if (w > static_cast<int32_t>(v)) cand.push_back(w);
    grow_clique(conflicts, cand, 1, best, budget);
  }
  return best;
}

bool conflicts_with_part(const Graph& conflicts, const std::vector<int32_t>& part, int32_t c, int32_t k) {
  const auto cs = conflicts[c];
  return std::any_of(cs.begin(), cs.end(), [&](int32_t x) { return part[x] == k; });
}

// Parts grown one at a time from the first unassigned curve of `order`, breadth-first over
// parallels, taking every curve that conflicts with none already in the part (and, with `within`,
// only curves of the seed's group there).
std::vector<int32_t> grow_parts(const Graph& par, const Graph& conf, const std::vector<int32_t>& order,
                                const std::vector<int32_t>* within = nullptr) {
  std::vector<int32_t> part(par.rows(), -1), queue;
  int32_t k = 0;
  for (int32_t s : order) {
    if (part[s] >= 0) continue;
    part[s] = k;
    queue.assign(1, s);
    for (size_t q = 0; q < queue.size(); ++q)
      for (int32_t p : par[queue[q]])
        if (part[p] < 0 && (!within || (*within)[p] == (*within)[s]) && !conflicts_with_part(conf, part, p, k)) {
          part[p] = k;
          queue.push_back(p);
        }
    ++k;
  }
  return part;
}

// Parts renumbered by their lowest curve, each split into its connected pieces: every piece is a
// subsheet. Returns the number of pieces.
int32_t normalise(const Graph& par, std::vector<int32_t>& part) {
  const size_t n = part.size();
  std::vector<int32_t> out(n, -1), queue;
  int32_t k = 0;
  for (size_t s = 0; s < n; ++s) {
    if (out[s] >= 0) continue;
    out[s] = k;
    queue.assign(1, static_cast<int32_t>(s));
    for (size_t q = 0; q < queue.size(); ++q)
      for (int32_t p : par[queue[q]])
        if (out[p] < 0 && part[p] == part[s]) {
          out[p] = k;
          queue.push_back(p);
        }
    ++k;
  }
  part = std::move(out);
  return k;
}

// Merges two adjacent parts whenever their union has no conflict, until no pair can merge.
void merge_parts(const Graph& par, const Graph& conf, std::vector<int32_t>& part) {
  for (bool merged = true; merged;) {
    merged = false;
    const int32_t k = normalise(par, part);
    for (int32_t a = 0; a < k && !merged; ++a)
      for (int32_t b = a + 1; b < k && !merged; ++b) {
        bool adjacent = false, clash = false;
        for (size_t c = 0; c < part.size() && !clash; ++c) {
          if (part[c] != b) continue;
          for (int32_t p : par[c]) adjacent |= part[p] == a;
          clash = conflicts_with_part(conf, part, static_cast<int32_t>(c), a);
        }
        if (!adjacent || clash) continue;
        std::replace(part.begin(), part.end(), b, a);
        merged = true;
      }
  }
}

// Seed orders for the greedy growth: by id starting at each of up to 256 curves spread over the
// sheet (wrapping around), and the most conflicting curves first. Each growth is linear in the
// sheet, so many starts cost little and often save a part.
std::vector<std::vector<int32_t>> seed_orders(const Graph& conf) {
  const size_t n = conf.rows();
  std::vector<std::vector<int32_t>> orders;
  const size_t step = std::max<size_t>(1, n / 256);
  for (size_t s = 0; s < n; s += step) {
    std::vector<int32_t> o(n);
    for (size_t i = 0; i < n; ++i) o[i] = static_cast<int32_t>((s + i) % n);
    orders.push_back(std::move(o));
  }
  std::vector<int32_t> busy(n);
  std::iota(busy.begin(), busy.end(), 0);
  std::stable_sort(busy.begin(), busy.end(), [&](int32_t a, int32_t b) { return conf.count(a) > conf.count(b); });
  orders.push_back(std::move(busy));
  return orders;
}

// Exact search: curves in a fixed order (conflicting curves first, the most conflicting first,
// then the others breadth-first), each put in an existing part it does not conflict with or in a
// new one; a full assignment counts the connected pieces of its parts. Parts only grow, so the
// parts opened bound the pieces from below: a branch that opens as many as the best split found
// is cut. Curves without conflicts open a part last (a part of such curves alone could always
// join a neighbouring part).
struct Search {
  const Graph &par, &conf;
  std::vector<int32_t> order, part, best;
  int32_t best_count = 0;
  int64_t budget = 0, nodes = 0;
  bool aborted = false;

  void run(size_t i, int32_t open) {
    if (aborted) return;
    if (++nodes > budget) {
      aborted = true;
      return;
    }
    if (i == order.size()) {
      std::vector<int32_t> p = part;
      const int32_t k = normalise(par, p);
      if (k < best_count) {
        best_count = k;
        best = std::move(p);
      }
      return;
    }
    const int32_t c = order[i];
    for (int32_t k : candidate_parts(c, open)) {
      part[c] = k;
      run(i + 1, std::max(open, k + 1));
      part[c] = -1;
      if (aborted) return;
    }
  }

  // Existing parts without a conflict, those holding a parallel of c first; then a new part
  // when it can still beat the best.
  std::vector<int32_t> candidate_parts(int32_t c, int32_t open) const {
    std::vector<int32_t> near, far;
    for (int32_t k = 0; k < open; ++k) {
      if (conflicts_with_part(conf, part, c, k)) continue;
      const auto ps = par[c];
      (std::any_of(ps.begin(), ps.end(), [&](int32_t p) { return part[p] == k; }) ? near : far).push_back(k);
    }
    near.insert(near.end(), far.begin(), far.end());
    if (open + 1 < best_count) near.push_back(open);
    return near;
  }
};

std::vector<int32_t> search_order(const Graph& par, const Graph& conf) {
  const size_t n = par.rows();
  std::vector<int32_t> order;  // also the breadth-first queue
  std::vector<uint8_t> seen(n, 0);
  for (size_t c = 0; c < n; ++c)
    if (conf.count(c) > 0) order.push_back(static_cast<int32_t>(c));
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return conf.count(a) > conf.count(b); });
  for (int32_t c : order) seen[c] = 1;
  auto spread = [&](size_t from) {
    for (size_t q = from; q < order.size(); ++q)
      for (int32_t p : par[order[q]])
        if (!seen[p]) {
          seen[p] = 1;
          order.push_back(p);
        }
  };
  spread(0);
  for (size_t s = 0; s < n; ++s)  // curves no conflicting curve reaches over parallels
    if (!seen[s]) {
      seen[s] = 1;
      order.push_back(static_cast<int32_t>(s));
      spread(order.size() - 1);
    }
  return order;
}

}  // namespace

FewestParts fewest_parts(const Graph& par, const Graph& conf, int64_t node_budget, const std::vector<int32_t>& hint) {
  FewestParts r;
  const size_t n = par.rows();
  if (n == 0) return r;
  // Its own budget: the bound must not vanish when the caller allows no search.
  int64_t clique_budget = 1'000'000;
  r.lower_bound = largest_conflicting_set(conf, clique_budget);
  auto orders = seed_orders(conf);
  if (hint.size() == n) {  // the hint's groups first, each grown into conflict-free pieces
    std::vector<int32_t> o(n);
    std::iota(o.begin(), o.end(), 0);
    std::stable_sort(o.begin(), o.end(), [&](int32_t a, int32_t b) { return hint[a] < hint[b]; });
    orders.insert(orders.begin(), std::move(o));
  }
  for (size_t i = 0; i < orders.size(); ++i) {
    std::vector<int32_t> p = grow_parts(par, conf, orders[i], i == 0 && hint.size() == n ? &hint : nullptr);
    merge_parts(par, conf, p);
    const int32_t k = normalise(par, p);
    if (r.count == 0 || k < r.count) {
      r.count = k;
      r.part = std::move(p);
    }
  }
  if (r.count > r.lower_bound) {
    Search s{par, conf, search_order(par, conf), std::vector<int32_t>(n, -1), r.part, r.count, node_budget};
    s.run(0, 0);
    r.nodes = s.nodes;
    r.count = s.best_count;
    r.part = std::move(s.best);
    if (!s.aborted) r.lower_bound = r.count;  // every split with fewer parts was ruled out
  }
  r.proven = r.count == r.lower_bound;
  return r;
}

}  // namespace hbc::detail
