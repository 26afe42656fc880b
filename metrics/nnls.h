#pragma once
// Non-negative least squares and the goodness of a fit: what the cost model's calibration
// (metrics/cost_model.h) fits its coefficients with. Plain numerics, no GL.
#include <vector>

namespace st::metrics {

// Row-major design matrix: rows[i] holds sample i's features; every row the same length.
using Matrix = std::vector<std::vector<double>>;

// x >= 0 minimising |A x - b|^2, by the active-set method of Lawson and Hanson ("Solving Least
// Squares Problems", Prentice-Hall 1974, chapter 23, algorithm NNLS). Columns are scaled to unit
// norm before solving (features range from 1 per pass to 1e8 fragments) and the result scaled
// back. An all-zero column gets 0. Throws std::invalid_argument for ragged rows or a size mismatch.
std::vector<double> nnls(const Matrix& a, const std::vector<double>& b);

// The unconstrained least-squares solution (Householder QR) of the columns `a` holds; a
// rank-deficient column gets 0. What nnls solves on its passive set, exposed for the tests.
std::vector<double> leastSquares(const Matrix& a, const std::vector<double>& b);

// Coefficient of determination of `predicted` against `measured`: 1 - SSres / SStot. 1 for a
// perfect fit; 0 when measured has no spread and the fit misses it; can be negative.
double rSquared(const std::vector<double>& measured, const std::vector<double>& predicted);

}  // namespace st::metrics
