#pragma once
// The nodes of the book of creep-force tables: the axes of a group, what maps its normalised
// creepages onto physical ones, the patch and creepages a node is solved with, and the threads
// that solve them.

#include <hdf5.h>

#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::generators {

/// The axes of one group (one nu): a/b, psi, theta, beta, r; values [g][psi][theta][beta][r].
struct Axes {
  std::vector<double> gs, psis, thetas, betas, rs;
};

/// Every node is solved at this load and shear modulus: the normalised forces do not depend on
/// them (the similarity of the exact theory).
inline const tangential::ContactLoad kNodeLoad{1e4, 0.3};
inline constexpr double kNodeShear = 80e9;

/// What maps a group's normalised creepages onto physical ones: Kalker's C11, C22, C23 at each
/// of its a/b nodes and its spin scale.
struct Normalisation {
  std::vector<double> c11, c22, c23;
  double spin_scale = 1.0;
};

/// The patch of node (ig, ip) (a = 5 mm) and the creepages of the normalised creepage
/// (r, theta, beta) on it.
struct NodeProblem {
  contactgeom::Sdec patch;
  tangential::Creepages creepages;
};

NodeProblem node_problem(const Axes& axes, const Normalisation& k, std::size_t ig, std::size_t ip,
                         double r, double theta, double beta);

/// The axes of a table's group (a_over_b, psi, theta, beta, r), each empty where it is missing.
Axes read_axes(hid_t group);

/// Calls body(i) for i = 0 ... total - 1 on `threads` threads, each taking the next index; the
/// first exception a call throws stops the others' taking and is rethrown after the join.
template <class Body>
void parallel_for(std::size_t total, unsigned threads, const Body& body) {
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(threads);
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      try {
        for (std::size_t i = next++; i < total; i = next++) body(i);
      } catch (...) {
        failed[t] = std::current_exception();
        next = total;
      }
    });
  }
  for (auto& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace wheelwear::generators
