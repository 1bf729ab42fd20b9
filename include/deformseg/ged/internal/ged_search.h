// The machinery that the GED lower bound and the exact search share: a pair of graphs flattened
// into cost tables and adjacency bit rows, a partial node mapping kept as bit rows, and the
// admissible bound on what completing a partial mapping costs (an assignment problem over the
// nodes not yet mapped, as in Riesen's and Blumenthal's branch lower bounds).
#pragma once

#include <deformseg/exceptions.h>
#include <deformseg/ged/cost_model.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace deformseg::ged::internal {

// Rows of bits in one flat array: row r holds bits [0, columns).
class Bit_rows {
public:
  Bit_rows() = default;
  Bit_rows(std::size_t rows, std::size_t columns)
      : words_((columns + 63) / 64), bits_(rows * words_, 0) {}
  std::size_t words() const { return words_; }
  const std::uint64_t* row(std::size_t r) const { return bits_.data() + r * words_; }
  std::uint64_t* row(std::size_t r) { return bits_.data() + r * words_; }
  bool test(std::size_t r, std::size_t c) const { return (row(r)[c / 64] >> (c % 64)) & 1u; }
  void set(std::size_t r, std::size_t c) { row(r)[c / 64] |= std::uint64_t{1} << (c % 64); }
  void reset(std::size_t r, std::size_t c) { row(r)[c / 64] &= ~(std::uint64_t{1} << (c % 64)); }

private:
  std::size_t words_ = 0;
  std::vector<std::uint64_t> bits_;
};

inline std::size_t count_common(const std::uint64_t* x, const std::uint64_t* y, std::size_t words) {
  std::size_t total = 0;
  for (std::size_t w = 0; w < words; ++w) total += static_cast<std::size_t>(std::popcount(x[w] & y[w]));
  return total;
}

inline std::size_t count_bits(const std::uint64_t* x, std::size_t words) {
  std::size_t total = 0;
  for (std::size_t w = 0; w < words; ++w) total += static_cast<std::size_t>(std::popcount(x[w]));
  return total;
}

struct Edge_costs {
  double insertion = 1, deletion = 1, substitution = 0;

  // What a pair of nodes of A and its image pair in B cost, given which of them are edges.
  double pair(bool in_a, bool in_b) const {
    if (in_a) return in_b ? substitution : deletion;
    return in_b ? insertion : 0.0;
  }
  // The least cost of the edges at a node with `da` incident edges mapped onto one with `db`:
  // keeping an edge costs substitution, or deleting and inserting it when that is cheaper.
  // Half of it, summed over both ends of every edge, bounds the cost of the edges from below.
  double local(std::size_t da, std::size_t db) const {
    const std::size_t kept = std::min(da, db);
    return static_cast<double>(kept) * std::min(substitution, deletion + insertion) +
           static_cast<double>(da - kept) * deletion + static_cast<double>(db - kept) * insertion;
  }
};

// A pair of graphs A (n nodes) and B (m nodes) as flat tables, the cost model evaluated once.
struct Ged_instance {
  std::size_t n = 0, m = 0;
  Bit_rows adjacency_a, adjacency_b;  // n x n and m x m
  std::vector<double> substitution;   // n x m, row-major
  std::vector<double> deletion;       // n
  std::vector<double> insertion;      // m
  Edge_costs edge;

  double substitute(std::size_t i, std::size_t j) const { return substitution[i * m + j]; }
};

inline double checked_cost(double cost, const char* what, const char* caller) {
  if (!std::isfinite(cost) || cost < 0)
    throw invalid_input(std::string(caller) + ": the cost model gives " + what + " = " + std::to_string(cost) +
                        ", costs must be finite and non-negative");
  return cost;
}

template <class G>
Bit_rows adjacency_of(const G& g) {
  const std::size_t n = boost::num_vertices(g);
  Bit_rows rows(n, n);
  for (std::size_t u = 0; u < n; ++u)
    for (std::size_t v = u + 1; v < n; ++v)
      if (boost::edge(u, v, g).second) rows.set(u, v), rows.set(v, u);
  return rows;
}

template <class G, class C>
Ged_instance make_instance(const G& a, const G& b, const C& costs, const char* caller) {
  Ged_instance in;
  in.n = boost::num_vertices(a);
  in.m = boost::num_vertices(b);
  in.adjacency_a = adjacency_of(a);
  in.adjacency_b = adjacency_of(b);
  in.substitution.resize(in.n * in.m);
  in.deletion.resize(in.n);
  in.insertion.resize(in.m);
  for (std::size_t i = 0; i < in.n; ++i) {
    in.deletion[i] = checked_cost(costs.node_deletion(a[i]), "a node deletion", caller);
    for (std::size_t j = 0; j < in.m; ++j)
      in.substitution[i * in.m + j] = checked_cost(costs.node_substitution(a[i], b[j]), "a node substitution", caller);
  }
  for (std::size_t j = 0; j < in.m; ++j)
    in.insertion[j] = checked_cost(costs.node_insertion(b[j]), "a node insertion", caller);
  in.edge = {.insertion = checked_cost(costs.edge_insertion(), "edge_insertion()", caller),
             .deletion = checked_cost(costs.edge_deletion(), "edge_deletion()", caller),
             .substitution = checked_cost(costs.edge_substitution(), "edge_substitution()", caller)};
  return in;
}

// The same problem seen from B: turning B into A costs what turning A into B does, with
// insertions and deletions exchanged and substitutions read the other way.
inline Ged_instance reversed(const Ged_instance& in) {
  Ged_instance r;
  r.n = in.m;
  r.m = in.n;
  r.adjacency_a = in.adjacency_b;
  r.adjacency_b = in.adjacency_a;
  r.substitution.resize(in.n * in.m);
  for (std::size_t i = 0; i < in.n; ++i)
    for (std::size_t j = 0; j < in.m; ++j) r.substitution[j * in.n + i] = in.substitution[i * in.m + j];
  r.deletion = in.insertion;
  r.insertion = in.deletion;
  r.edge = {.insertion = in.edge.deletion, .deletion = in.edge.insertion, .substitution = in.edge.substitution};
  return r;
}

// A node mapping of A (n nodes) into B turned into one of B (m nodes) into A.
inline std::vector<int> inverted(const std::vector<int>& mapping, std::size_t m) {
  std::vector<int> inverse(m, -1);
  for (std::size_t i = 0; i < mapping.size(); ++i)
    if (mapping[i] >= 0) inverse[static_cast<std::size_t>(mapping[i])] = static_cast<int>(i);
  return inverse;
}

// The least total of an assignment of every row to a distinct column (rows <= columns) of a
// row-major matrix, by shortest augmenting paths with potentials; the buffers are reused so that
// the search allocates nothing per bound.
class Lsap_workspace {
public:
  double solve(const double* cost, std::size_t rows, std::size_t columns) {
    const double infinity = std::numeric_limits<double>::infinity();
    u_.assign(rows + 1, 0.0);
    v_.assign(columns + 1, 0.0);
    owner_.assign(columns + 1, 0);
    from_.resize(columns + 1);
    distance_.resize(columns + 1);
    done_.resize(columns + 1);
    for (std::size_t row = 1; row <= rows; ++row) {
      owner_[0] = row;
      std::size_t col = 0;
      std::fill(distance_.begin(), distance_.end(), infinity);
      std::fill(done_.begin(), done_.end(), char{0});
      do {
        done_[col] = 1;
        const std::size_t r = owner_[col];
        const double* cost_row = cost + (r - 1) * columns;
        double step = infinity;
        std::size_t next = 0;
        for (std::size_t j = 1; j <= columns; ++j) {
          if (done_[j]) continue;
          const double reduced = cost_row[j - 1] - u_[r] - v_[j];
          if (reduced < distance_[j]) distance_[j] = reduced, from_[j] = col;
          if (distance_[j] < step) step = distance_[j], next = j;
        }
        for (std::size_t j = 0; j <= columns; ++j) {
          if (done_[j]) {
            u_[owner_[j]] += step;
            v_[j] -= step;
          } else {
            distance_[j] -= step;
          }
        }
        col = next;
      } while (owner_[col] != 0);
      do {
        const std::size_t previous = from_[col];
        owner_[col] = owner_[previous];
        col = previous;
      } while (col != 0);
    }
    double total = 0;
    for (std::size_t j = 1; j <= columns; ++j)
      if (owner_[j] != 0) total += cost[(owner_[j] - 1) * columns + (j - 1)];
    return total;
  }

private:
  std::vector<double> u_, v_, distance_;
  std::vector<std::size_t> owner_, from_;
  std::vector<char> done_;
};

// A partial mapping of A into B: the nodes of A done so far (each mapped or deleted) and the
// nodes of B used. For every node i of A, `images` row i holds the images of i's done neighbours
// and `deleted_neighbours[i]` counts its deleted ones, so that what mapping i to j costs on the
// pairs with done nodes takes a few popcounts: no undo can drift, all of it is integer.
class Partial_mapping {
public:
  explicit Partial_mapping(const Ged_instance& in)
      : in_(&in), images_(in.n, in.m), deleted_neighbours_(in.n, 0), open_a_(1, in.n), open_b_(1, in.m) {
    for (std::size_t i = 0; i < in.n; ++i) open_a_.set(0, i);
    for (std::size_t j = 0; j < in.m; ++j) open_b_.set(0, j);
    open_a_list_.reserve(in.n);
    open_b_list_.reserve(in.m);
  }

  // Cost of the pairs (i, done node) when i maps onto j (j open), node costs left out.
  double anchored_substitution(std::size_t i, std::size_t j) const {
    const Ged_instance& in = *in_;
    const std::size_t words = in.adjacency_b.words();
    const std::uint64_t* images = images_.row(i);
    const std::uint64_t* neighbours_b = in.adjacency_b.row(j);
    const std::size_t kept = count_common(images, neighbours_b, words);
    const std::size_t a_only = count_bits(images, words) - kept + deleted_neighbours_[i];
    const std::size_t b_only = used_neighbours(j) - kept;
    return static_cast<double>(kept) * in.edge.substitution + static_cast<double>(a_only) * in.edge.deletion +
           static_cast<double>(b_only) * in.edge.insertion;
  }
  // Cost of the pairs (i, done node) when i is deleted.
  double anchored_deletion(std::size_t i) const {
    return static_cast<double>(count_bits(images_.row(i), images_.words()) + deleted_neighbours_[i]) *
           in_->edge.deletion;
  }
  // Cost of the pairs (j, used node) when j is inserted.
  double anchored_insertion(std::size_t j) const {
    return static_cast<double>(used_neighbours(j)) * in_->edge.insertion;
  }
  // What doing node v of A costs: mapping it onto w (w < 0: deleting it).
  double step_cost(std::size_t v, int w) const {
    const Ged_instance& in = *in_;
    if (w < 0) return in.deletion[v] + anchored_deletion(v);
    const auto j = static_cast<std::size_t>(w);
    return in.substitute(v, j) + anchored_substitution(v, j);
  }

  bool is_open_in_b(std::size_t j) const { return open_b_.test(0, j); }

  void map(std::size_t v, int w) { update(v, w, true); }
  void unmap(std::size_t v, int w) { update(v, w, false); }

  // An admissible bound on the cost of completing this mapping: every open node of A is mapped
  // onto an open node of B or deleted, every open node of B left is inserted; each choice costs
  // its node cost, its pairs with done nodes exactly, and half the local cost of its edges among
  // open nodes. The optimal assignment of those costs (with deletions and insertions) is the
  // bound; with no open node on one side it is the exact completion cost.
  double completion_bound(Lsap_workspace& lsap, std::vector<double>& matrix) {
    const Ged_instance& in = *in_;
    collect_open();
    double total = 0;
    delete_cost_.resize(open_a_list_.size());
    insert_cost_.resize(open_b_list_.size());
    for (std::size_t k = 0; k < open_a_list_.size(); ++k) {
      const std::size_t i = open_a_list_[k];
      delete_cost_[k] = in.deletion[i] + anchored_deletion(i) + 0.5 * in.edge.local(open_degree_a_[k], 0);
      total += delete_cost_[k];
    }
    for (std::size_t k = 0; k < open_b_list_.size(); ++k) {
      const std::size_t j = open_b_list_[k];
      insert_cost_[k] = in.insertion[j] + anchored_insertion(j) + 0.5 * in.edge.local(0, open_degree_b_[k]);
      total += insert_cost_[k];
    }
    if (open_a_list_.empty() || open_b_list_.empty()) return total;
    // Mapping i onto j instead of deleting i and inserting j changes the total by the reduced
    // cost; clamped at 0, since a pair may always be left as a deletion and an insertion.
    const bool a_rows = open_a_list_.size() <= open_b_list_.size();
    const std::size_t rows = a_rows ? open_a_list_.size() : open_b_list_.size();
    const std::size_t columns = a_rows ? open_b_list_.size() : open_a_list_.size();
    matrix.resize(rows * columns);
    for (std::size_t ka = 0; ka < open_a_list_.size(); ++ka)
      for (std::size_t kb = 0; kb < open_b_list_.size(); ++kb) {
        const std::size_t i = open_a_list_[ka], j = open_b_list_[kb];
        const double substitute = in.substitute(i, j) + anchored_substitution(i, j) +
                                  0.5 * in.edge.local(open_degree_a_[ka], open_degree_b_[kb]);
        const double reduced = std::min(substitute - delete_cost_[ka] - insert_cost_[kb], 0.0);
        matrix[a_rows ? ka * columns + kb : kb * columns + ka] = reduced;
      }
    return std::max(0.0, total + lsap.solve(matrix.data(), rows, columns));
  }

private:
  std::size_t used_neighbours(std::size_t j) const {
    const Ged_instance& in = *in_;
    const std::size_t words = in.adjacency_b.words();
    const std::uint64_t* neighbours = in.adjacency_b.row(j);
    const std::uint64_t* open = open_b_.row(0);
    std::size_t total = 0;
    for (std::size_t w = 0; w < words; ++w) total += static_cast<std::size_t>(std::popcount(neighbours[w] & ~open[w]));
    return total;
  }

  void update(std::size_t v, int w, bool doing) {
    const Ged_instance& in = *in_;
    if (doing) open_a_.reset(0, v); else open_a_.set(0, v);
    if (w >= 0) {
      if (doing) open_b_.reset(0, static_cast<std::size_t>(w)); else open_b_.set(0, static_cast<std::size_t>(w));
    }
    for (std::size_t i = 0; i < in.n; ++i) {
      if (!in.adjacency_a.test(v, i)) continue;
      if (w < 0) {
        deleted_neighbours_[i] = doing ? deleted_neighbours_[i] + 1 : deleted_neighbours_[i] - 1;
      } else if (doing) {
        images_.set(i, static_cast<std::size_t>(w));
      } else {
        images_.reset(i, static_cast<std::size_t>(w));
      }
    }
  }

  void collect_open() {
    const Ged_instance& in = *in_;
    open_a_list_.clear();
    open_b_list_.clear();
    open_degree_a_.clear();
    open_degree_b_.clear();
    for (std::size_t i = 0; i < in.n; ++i)
      if (open_a_.test(0, i)) {
        open_a_list_.push_back(i);
        open_degree_a_.push_back(count_common(in.adjacency_a.row(i), open_a_.row(0), open_a_.words()));
      }
    for (std::size_t j = 0; j < in.m; ++j)
      if (open_b_.test(0, j)) {
        open_b_list_.push_back(j);
        open_degree_b_.push_back(count_common(in.adjacency_b.row(j), open_b_.row(0), open_b_.words()));
      }
  }

  const Ged_instance* in_;
  Bit_rows images_;                              // n x m
  std::vector<std::size_t> deleted_neighbours_;  // n
  Bit_rows open_a_, open_b_;                     // one row each
  std::vector<std::size_t> open_a_list_, open_b_list_, open_degree_a_, open_degree_b_;
  std::vector<double> delete_cost_, insert_cost_;
};

}  // namespace deformseg::ged::internal
