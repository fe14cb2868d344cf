#pragma once
// Fill-reducing orderings of the graph of a symmetric matrix's blocks (the
// D unknowns of a vertex are one block), found by CHOLMOD: AMD's, and METIS's
// nested dissection as well where it can pay, whichever needs fewer flops,
// postordered (the elimination tree's subtrees contiguous: the same fill, and
// the supernodes CHOLMOD's analysis finds). SparseCholesky::analyze computes
// one for every pattern it is given; a mesh's vertex graph can instead be
// ordered once and the ordering handed to the analyses of the matrices on it
// (akvf/parameterization.cpp: the Tutte system, restricted to its interior
// vertices, and the preconditioners' matrices). On large meshes the ordering
// costs more than a factorization: horse_b subdivided to 1.27 M vertices
// takes about 7 s of METIS against 2 s for a factorization of K.
#include <string>
#include <vector>

#include "framework/mesh/vertex_graph.h"

namespace akvf {

struct BlockOrdering {
  std::vector<int> permutation;  // the a-th block eliminated is block permutation[a]
  std::string method;            // "amd" or "metis"
  // Postordered for the graph it was computed on (fill_reducing_ordering,
  // postordered): SparseCholesky::analyze then takes it as it is, so give it
  // only for a matrix on that graph. False: analyze postorders it first.
  bool postordered = false;
  // The sums over the columns of the graph's Cholesky factor in this order
  // of their entry counts and of their squares (CHOLMOD's nonzeros and
  // flops), as CHOLMOD's analysis of the graph found them; 0: not known.
  double factor_nonzeros = 0, factor_flops = 0;
};

// The ordering SparseCholesky::analyze computes for a matrix whose blocks of
// block_size unknowns have the upper graph `graph` (METIS is tried where
// AMD's flops for the expanded matrix say it can pay; always_try_metis: at
// any size, for tests).
BlockOrdering fill_reducing_ordering(const UpperVertexGraph& graph, int block_size, bool always_try_metis = false);

// `order` (any permutation of the blocks of `graph`) postordered by CHOLMOD:
// the same fill, subtrees contiguous. An ordering fill_reducing_ordering
// found for this graph comes back unchanged (tested).
BlockOrdering postordered(const UpperVertexGraph& graph, const BlockOrdering& order);

// CHOLMOD's flops per factor entry (its supernodal switch compares them
// with 40) for a matrix on the ordering's graph whose blocks of block_size
// unknowns are all full, from the blocks' factor; 0 where that is not known.
double expanded_flops_per_entry(const BlockOrdering& ordering, int block_size);

// The order in which `ordering` eliminates the blocks listed in `subset`
// (distinct blocks of its graph): result[i] is the index into `subset` of
// the i-th of them eliminated. For the graph induced by the subset this
// order fills no more than the whole graph's ordering does (a fill edge of
// the subgraph is a path through earlier vertices, which the whole graph
// has as well), so the restriction of a good ordering is a good ordering.
std::vector<int> restricted_order(const BlockOrdering& ordering, const std::vector<int>& subset);

}  // namespace akvf
