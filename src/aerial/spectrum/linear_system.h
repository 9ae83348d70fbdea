#pragma once
// Small dense linear systems (a least-squares fit's normal equations), solved in double precision.
#include <vector>

namespace aerial::spectrum {

// The solution x of A x = b for a square, invertible A (Gauss-Jordan elimination with partial
// pivoting).
std::vector<double> SolveLinearSystem(std::vector<std::vector<double>> a, std::vector<double> b);

}  // namespace aerial::spectrum
