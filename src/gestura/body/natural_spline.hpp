#pragma once
// A C2 curve through knots: the natural cubic spline (second derivative 0 at both ends), flat beyond
// the ends. The sculpted body parts interpolate their profiles with it because shading follows
// curvature: where a curve's curvature jumps (a Catmull-Rom or piecewise-linear profile), the
// shading of the surface shows a line.
#include <array>
#include <cstddef>
#include <vector>

namespace gestura {

class NaturalSpline {
 public:
  NaturalSpline() = default;
  // Knots (x, y) with x strictly ascending, at least 2.
  explicit NaturalSpline(std::vector<std::array<float, 2>> knots) : k_(std::move(knots)), m_(k_.size(), 0.0f) {
    const std::size_t n = k_.size();
    if (n < 3) return;
    // Tridiagonal system for the inner second derivatives (Thomas algorithm).
    std::vector<float> c(n, 0.0f), d(n, 0.0f);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const float h0 = k_[i][0] - k_[i - 1][0], h1 = k_[i + 1][0] - k_[i][0];
      const float r = 6.0f * ((k_[i + 1][1] - k_[i][1]) / h1 - (k_[i][1] - k_[i - 1][1]) / h0);
      const float denom = 2.0f * (h0 + h1) - h0 * c[i - 1];
      c[i] = h1 / denom;
      d[i] = (r - h0 * d[i - 1]) / denom;
    }
    for (std::size_t i = n - 2; i >= 1; --i) m_[i] = d[i] - c[i] * m_[i + 1];
  }

  float operator()(float x) const {
    const std::size_t n = k_.size();
    if (n == 0) return 0.0f;
    if (x <= k_[0][0]) return k_[0][1];
    if (x >= k_[n - 1][0]) return k_[n - 1][1];
    std::size_t i = 0;
    while (x > k_[i + 1][0]) ++i;
    const float h = k_[i + 1][0] - k_[i][0], a = (k_[i + 1][0] - x) / h, b = 1.0f - a;
    return a * k_[i][1] + b * k_[i + 1][1] + ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0f;
  }

 private:
  std::vector<std::array<float, 2>> k_;
  std::vector<float> m_;
};

}  // namespace gestura
