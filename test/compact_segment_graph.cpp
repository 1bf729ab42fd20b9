// Tests of compact_segment_graph.h: detached rigid nodes merged into one with their sums, the other
// nodes and edges kept in order, and graphs with at most one detached rigid node unchanged.
#include "test_support.h"

#include <deformseg/spatiotemporal/compact_segment_graph.h>

using namespace deformseg;

namespace {

spatiotemporal::Segment_node rigid(std::size_t triangles, double area) {
  return {spatiotemporal::Segment_kind::rigid, -1, triangles, area};
}
spatiotemporal::Segment_node deformed(std::int32_t id, std::size_t triangles, double area) {
  return {spatiotemporal::Segment_kind::deformed, id, triangles, area};
}

}  // namespace

TEST_CASE("compact_segment_graph: detached rigid pieces become one node", "[compact_segment_graph]") {
  // D0 - R(a) - D1, and three rigid pieces touching nothing (R(b), R(c), R(d)).
  spatiotemporal::Segment_graph g;
  const auto d0 = boost::add_vertex(deformed(0, 10, 0.1), g);
  const auto b = boost::add_vertex(rigid(5, 0.05), g);
  const auto a = boost::add_vertex(rigid(40, 0.4), g);
  const auto d1 = boost::add_vertex(deformed(1, 20, 0.2), g);
  const auto c = boost::add_vertex(rigid(7, 0.07), g);
  boost::add_vertex(rigid(18, 0.18), g);
  boost::add_edge(d0, a, g);
  boost::add_edge(a, d1, g);
  (void)b, (void)c;
  const spatiotemporal::Segment_graph out = spatiotemporal::compact_segment_graph(g);
  REQUIRE(boost::num_vertices(out) == 4);
  CHECK(out[0] == g[d0]);
  CHECK(out[1] == g[a]);
  CHECK(out[2] == g[d1]);
  CHECK(out[3].kind == spatiotemporal::Segment_kind::rigid);
  CHECK(out[3].segment == -1);
  CHECK(out[3].triangles == 5 + 7 + 18);
  CHECK(out[3].area == Approx(0.05 + 0.07 + 0.18));
  REQUIRE(boost::num_edges(out) == 2);
  CHECK(boost::edge(0, 1, out).second);
  CHECK(boost::edge(1, 2, out).second);
  CHECK(boost::out_degree(3, out) == 0);
}

TEST_CASE("compact_segment_graph: one detached rigid node or none leaves the graph as it is",
          "[compact_segment_graph]") {
  spatiotemporal::Segment_graph still;
  boost::add_vertex(rigid(100, 1.0), still);
  const spatiotemporal::Segment_graph same = spatiotemporal::compact_segment_graph(still);
  REQUIRE(boost::num_vertices(same) == 1);
  CHECK(same[0] == still[0]);
  // A detached deformed node is kept apart: only rigid pieces merge.
  spatiotemporal::Segment_graph g;
  boost::add_vertex(deformed(3, 4, 0.3), g);
  boost::add_vertex(rigid(6, 0.7), g);
  const spatiotemporal::Segment_graph kept = spatiotemporal::compact_segment_graph(g);
  REQUIRE(boost::num_vertices(kept) == 2);
  CHECK(kept[0] == g[0]);
  CHECK(kept[1] == g[1]);
}
