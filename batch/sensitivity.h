// Sensitivity of a design's outputs to its parameters (docs/theory/coupling.md
// section 13): standardised regression coefficients (Eq. 13.5: least squares of
// the standardised output on the standardised parameters) and Spearman rank
// correlations (Eq. 13.6: Pearson's correlation of the ranks, ties given their
// average rank).
#pragma once

#include <optional>
#include <vector>

namespace framedyn::batch {

// x[run][parameter], y[run]. The coefficients, one per parameter; none when the
// runs cannot determine them (fewer runs than parameters + 2, or an output or a
// parameter that does not vary). A parameter that does not vary gets 0.
std::optional<std::vector<double>> standardised_regression_coefficients(const std::vector<std::vector<double>>& x, const std::vector<double>& y);

// Ranks 1..n, ties given the average of the ranks they share.
std::vector<double> average_ranks(const std::vector<double>& v);
// Spearman's rho of a and b; none with fewer than 3 values or a constant series.
std::optional<double> spearman(const std::vector<double>& a, const std::vector<double>& b);

// Parameter indices by decreasing |coefficient|; coefficients within 1e-6
// (relative to the largest) of each other keep their parameter order, so that
// the ranking does not depend on round-off (the lowest index first).
std::vector<std::size_t> ranking(const std::vector<double>& coefficients);

}  // namespace framedyn::batch
