#pragma once
// Fill-reducing orderings of the graph of a symmetric matrix's blocks
// (sparse_cholesky.cpp finds the ordering on that graph and expands it to
// the unknowns), each postordered and with the flop count of a Cholesky
// factorization in that order (CHOLMOD's `fl`: the graph's own flops).
#include <functional>
#include <vector>

// CHOLMOD's cholmod_sparse (cholmod.h stays out of the installed headers).
struct cholmod_sparse_struct;

namespace akvf {

// CHOLMOD's ordering `method` (CHOLMOD_AMD, CHOLMOD_METIS) of the symmetric
// pattern A (upper triangle, stype 1). Its own cholmod_common: two may run
// at the same time.
std::vector<int> block_ordering(cholmod_sparse_struct* A, int method, double* flops);

// METIS's nested dissection on two cores. METIS orders a graph by finding a
// vertex separator, numbering it last, and ordering the two halves it
// leaves the same way; the halves are independent, but METIS works on them
// one after the other. Here the top separator is found once
// (cholmod_bisect: METIS's vertex separator) and the two halves are ordered
// by METIS at the same time. `also` (AMD's ordering of the whole graph),
// if given, runs on the second core while the first finds the separator. The same scheme as METIS's own,
// with its top level made explicit: the fill is about the same (tested
// against METIS's), the time about half on large meshes
// (docs/performance.md).
std::vector<int> nested_dissection_two_cores(cholmod_sparse_struct* A, double* flops,
                                             const std::function<void()>& also = nullptr);

}  // namespace akvf
