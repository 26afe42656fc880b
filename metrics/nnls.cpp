#include "metrics/nnls.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace st::metrics {
namespace {

std::size_t columnsOf(const Matrix& a, const std::vector<double>& b) {
    if (a.size() != b.size()) throw std::invalid_argument("least squares: rows and right-hand side differ in length");
    const std::size_t n = a.empty() ? 0 : a.front().size();
    for (const auto& row : a)
        if (row.size() != n) throw std::invalid_argument("least squares: rows of different lengths");
    return n;
}

// Least squares on the columns listed in `cols` only; the others get 0.
std::vector<double> solveOn(const Matrix& a, const std::vector<double>& b, const std::vector<std::size_t>& cols,
                            std::size_t n) {
    const std::size_t m = a.size(), k = cols.size();
    std::vector<std::vector<double>> q(k, std::vector<double>(m));  // column-major copy of the subset
    for (std::size_t j = 0; j < k; ++j)
        for (std::size_t i = 0; i < m; ++i) q[j][i] = a[i][cols[j]];
    std::vector<double> rhs = b;
    std::vector<double> diag(k, 0.0);
    std::vector<bool> usable(k, false);
    std::vector<std::size_t> pivotRow(k, 0);  // the row of R that column j's pivot sits on
    // Householder QR: R's diagonal in diag, R's upper part in q[j][r] for r < j.
    for (std::size_t j = 0, r = 0; j < k && r < m; ++j) {
        double norm = 0.0;
        for (std::size_t i = r; i < m; ++i) norm += q[j][i] * q[j][i];
        norm = std::sqrt(norm);
        double scale = 0.0;
        for (std::size_t i = 0; i < m; ++i) scale = std::max(scale, std::abs(q[j][i]));
        if (norm <= 1e-12 * std::max(scale, 1e-300)) continue;  // dependent on earlier columns
        const double alpha = q[j][r] > 0 ? -norm : norm;
        std::vector<double> v(q[j].begin() + std::ptrdiff_t(r), q[j].end());
        v[0] -= alpha;
        double vv = 0.0;
        for (double x : v) vv += x * x;
        auto reflect = [&](std::vector<double>& col) {
            double dot = 0.0;
            for (std::size_t i = r; i < m; ++i) dot += v[i - r] * col[i];
            const double f = 2.0 * dot / vv;
            for (std::size_t i = r; i < m; ++i) col[i] -= f * v[i - r];
        };
        for (std::size_t jj = j; jj < k; ++jj) reflect(q[jj]);
        reflect(rhs);
        diag[j] = q[j][r];
        usable[j] = true;
        pivotRow[j] = r++;
    }
    std::vector<double> x(n, 0.0);
    std::vector<double> sol(k, 0.0);
    for (std::size_t jj = k; jj-- > 0;) {
        if (!usable[jj]) continue;
        const std::size_t r = pivotRow[jj];
        double s = rhs[r];
        for (std::size_t l = jj + 1; l < k; ++l)
            if (usable[l]) s -= q[l][r] * sol[l];
        sol[jj] = s / diag[jj];
    }
    for (std::size_t j = 0; j < k; ++j) x[cols[j]] = sol[j];
    return x;
}

std::vector<double> residual(const Matrix& a, const std::vector<double>& b, const std::vector<double>& x) {
    std::vector<double> r = b;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j) r[i] -= a[i][j] * x[j];
    return r;
}

}  // namespace

std::vector<double> leastSquares(const Matrix& a, const std::vector<double>& b) {
    const std::size_t n = columnsOf(a, b);
    std::vector<std::size_t> all(n);
    for (std::size_t j = 0; j < n; ++j) all[j] = j;
    return solveOn(a, b, all, n);
}

std::vector<double> nnls(const Matrix& raw, const std::vector<double>& b) {
    const std::size_t n = columnsOf(raw, b), m = raw.size();
    std::vector<double> scale(n, 0.0);
    for (const auto& row : raw)
        for (std::size_t j = 0; j < n; ++j) scale[j] += row[j] * row[j];
    Matrix a = raw;
    for (std::size_t j = 0; j < n; ++j) {
        scale[j] = std::sqrt(scale[j]);
        for (std::size_t i = 0; i < m; ++i) a[i][j] = scale[j] > 0 ? a[i][j] / scale[j] : 0.0;
    }
    double bNorm = 0.0;
    for (double v : b) bNorm = std::max(bNorm, std::abs(v));
    const double tol = 1e-12 * std::max(1.0, bNorm) * double(std::max<std::size_t>(m, 1));
    std::vector<double> x(n, 0.0);
    std::vector<bool> passive(n, false);
    auto gradient = [&] {
        const std::vector<double> r = residual(a, b, x);
        std::vector<double> w(n, 0.0);
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = 0; j < n; ++j) w[j] += a[i][j] * r[i];
        return w;
    };
    for (std::size_t outer = 0; outer < 3 * n + 3; ++outer) {
        const std::vector<double> w = gradient();
        std::size_t t = n;
        double best = tol;
        for (std::size_t j = 0; j < n; ++j)
            if (!passive[j] && scale[j] > 0 && w[j] > best) best = w[j], t = j;
        if (t == n) break;  // Kuhn-Tucker conditions hold
        passive[t] = true;
        for (std::size_t inner = 0; inner < 3 * n + 3; ++inner) {
            std::vector<std::size_t> cols;
            for (std::size_t j = 0; j < n; ++j)
                if (passive[j]) cols.push_back(j);
            const std::vector<double> s = solveOn(a, b, cols, n);
            double alpha = std::numeric_limits<double>::infinity();
            for (std::size_t j : cols)
                if (s[j] <= 0) alpha = std::min(alpha, x[j] / (x[j] - s[j]));
            if (!std::isfinite(alpha)) {
                x = s;
                break;
            }
            for (std::size_t j = 0; j < n; ++j) x[j] += alpha * (s[j] - x[j]);
            for (std::size_t j : cols)
                if (x[j] <= 1e-15) passive[j] = false, x[j] = 0.0;
        }
    }
    for (std::size_t j = 0; j < n; ++j) x[j] = scale[j] > 0 ? std::max(0.0, x[j]) / scale[j] : 0.0;
    return x;
}

double rSquared(const std::vector<double>& measured, const std::vector<double>& predicted) {
    if (measured.size() != predicted.size()) throw std::invalid_argument("R²: lengths differ");
    if (measured.empty()) return 0.0;
    double mean = 0.0;
    for (double v : measured) mean += v;
    mean /= double(measured.size());
    double ssRes = 0.0, ssTot = 0.0;
    for (std::size_t i = 0; i < measured.size(); ++i) {
        ssRes += (measured[i] - predicted[i]) * (measured[i] - predicted[i]);
        ssTot += (measured[i] - mean) * (measured[i] - mean);
    }
    if (ssTot == 0.0) return ssRes == 0.0 ? 1.0 : 0.0;
    return 1.0 - ssRes / ssTot;
}

}  // namespace st::metrics
