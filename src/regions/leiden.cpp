#include "ussnav/regions/leiden.hpp"

#include <mutex>
#include <igraph/igraph.h>

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace ussnav {

namespace {

// igraph is C: every object gets an owner that destroys it, so no path leaks.
void check(igraph_error_t rc, const char* what) {
  if (rc != IGRAPH_SUCCESS)
    throw std::runtime_error(std::string("igraph: ") + what + ": " + igraph_strerror(rc));
}

struct IntVector {
  igraph_vector_int_t v;
  explicit IntVector(igraph_integer_t n) { check(igraph_vector_int_init(&v, n), "vector"); }
  ~IntVector() { igraph_vector_int_destroy(&v); }
  IntVector(const IntVector&) = delete;
  IntVector& operator=(const IntVector&) = delete;
};

struct RealVector {
  igraph_vector_t v;
  explicit RealVector(igraph_integer_t n) { check(igraph_vector_init(&v, n), "vector"); }
  ~RealVector() { igraph_vector_destroy(&v); }
  RealVector(const RealVector&) = delete;
  RealVector& operator=(const RealVector&) = delete;
};

struct Graph {
  igraph_t g;
  Graph(const IntVector& edges, igraph_integer_t n) {
    check(igraph_create(&g, &edges.v, n, IGRAPH_UNDIRECTED), "create graph");
  }
  ~Graph() { igraph_destroy(&g); }
  Graph(const Graph&) = delete;
  Graph& operator=(const Graph&) = delete;
};

// igraph's default handler aborts the process; inside our calls errors come back as codes
// (the ignore handler still frees igraph's temporaries) and we throw.
class ScopedErrorHandler {
 public:
  ScopedErrorHandler() : prev_(igraph_set_error_handler(igraph_error_handler_ignore)) {}
  ~ScopedErrorHandler() { igraph_set_error_handler(prev_); }
  ScopedErrorHandler(const ScopedErrorHandler&) = delete;
  ScopedErrorHandler& operator=(const ScopedErrorHandler&) = delete;

 private:
  igraph_error_handler_t* prev_;
};

// Labels renumbered by first appearance, so equal partitions compare equal.
std::vector<int> canonical(const igraph_vector_int_t& m) {
  std::vector<int> out(igraph_vector_int_size(&m));
  std::vector<int> remap(out.size(), -1);
  int next = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    const auto l = static_cast<size_t>(VECTOR(m)[i]);
    if (l >= remap.size()) remap.resize(l + 1, -1);
    if (remap[l] < 0) remap[l] = next++;
    out[i] = remap[l];
  }
  return out;
}

}  // namespace

LeidenResult leiden(int n, const std::vector<IndexedEdge>& edges, const LeidenParams& params,
                    const std::vector<int>* initial) {
  if (n < 0) throw std::invalid_argument("leiden: negative node count");
  if (params.iterations == 0) throw std::invalid_argument("leiden: iterations must not be 0");
  if (initial && static_cast<int>(initial->size()) != n)
    throw std::invalid_argument("leiden: initial membership size differs from node count");
  LeidenResult out;
  if (n == 0) return out;
  for (const auto& e : edges)
    if (e.u < 0 || e.v < 0 || e.u >= n || e.v >= n || e.u == e.v || !(e.w >= 0.0))
      throw std::invalid_argument("leiden: edge out of range, self-loop or negative weight");

  // Debian's igraph keeps its error "finally" stack, error handler and default RNG in globals
  // (not thread-local): one Leiden run at a time per process, so episodes may run in threads.
  static std::mutex igraph_mutex;
  const std::lock_guard<std::mutex> lock(igraph_mutex);
  ScopedErrorHandler handler;
  IntVector ev(2 * static_cast<igraph_integer_t>(edges.size()));
  RealVector wv(static_cast<igraph_integer_t>(edges.size()));
  for (size_t k = 0; k < edges.size(); ++k) {
    VECTOR(ev.v)[2 * k] = edges[k].u;
    VECTOR(ev.v)[2 * k + 1] = edges[k].v;
    VECTOR(wv.v)[k] = edges[k].w;
  }
  Graph graph(ev, n);
  IntVector membership(n);
  if (initial) {
    // igraph wants labels below n: renumber by first appearance.
    std::unordered_map<int, int> remap;
    for (int i = 0; i < n; ++i) {
      if ((*initial)[i] < 0) throw std::invalid_argument("leiden: negative initial label");
      auto [it, fresh] = remap.emplace((*initial)[i], static_cast<int>(remap.size()));
      VECTOR(membership.v)[i] = it->second;
    }
  }
  check(igraph_rng_seed(igraph_rng_default(), params.seed), "seed rng");
  igraph_integer_t clusters = 0;
  igraph_real_t quality = 0.0;
  // igraph 0.10.x (Debian bookworm ships 0.10.2) runs a negative n_iterations "until an
  // iteration changes something", i.e. forever on an already stable warm start (igraph issue
  // #2798). So we iterate one step at a time ourselves and stop when the partition holds.
  const int max_steps = params.iterations < 0 ? kMaxLeidenIterations : params.iterations;
  std::vector<int> before = canonical(membership.v);
  for (int step = 0; step < max_steps; ++step) {
    // node_weights = NULL: every node weighs 1, i.e. the Constant Potts Model.
    check(igraph_community_leiden(&graph.g, &wv.v, nullptr, params.resolution, params.beta,
                                  initial != nullptr || step > 0, 1, &membership.v, &clusters,
                                  &quality),
          "community_leiden");
    std::vector<int> after = canonical(membership.v);
    const bool stable = after == before;
    before = std::move(after);
    if (params.iterations < 0 && stable) break;
  }
  out.membership.resize(n);
  for (int i = 0; i < n; ++i) out.membership[i] = static_cast<int>(VECTOR(membership.v)[i]);
  out.communities = static_cast<int>(clusters);
  out.quality = quality;
  return out;
}

}  // namespace ussnav
