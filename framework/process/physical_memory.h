#pragma once
// The machine's physical memory, which sizes the memory budgets of the
// linear solvers (factored_preconditioner.cpp: CHOLMOD or multigrid;
// sparse_cholesky.cpp: how much a factor may store beyond its nonzeros).
namespace akvf {

// Bytes of physical memory (sysconf).
double physical_memory_bytes();

}  // namespace akvf
