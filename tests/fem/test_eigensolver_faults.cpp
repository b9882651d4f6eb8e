// The frame eigensolver's failures are explanations (fem::lowest_eigenpairs):
// a Lanczos iteration stopped before convergence says how far it got and what
// to try; a mass matrix that is not positive definite names the equation (the
// node and DOF, when the caller names them) where the factorisation stopped.
// The problem is K = diag(1, 2, ..., 200), M = I: eigenvalues 1, 2, 3, ...
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "fem/modal_analysis.h"

namespace framedyn {
namespace {

using core::NumericalError;

fem::SparseMatrix diagonal(const Eigen::VectorXd& d) {
  fem::SparseMatrix a(d.size(), d.size());
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index i = 0; i < d.size(); ++i) t.emplace_back(static_cast<int>(i), static_cast<int>(i), d(i));
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

constexpr int kSize = 200;

TEST(EigensolverFaults, ConvergedWithTheDefaultsToTheExactEigenvalues) {
  const Eigen::VectorXd k = Eigen::VectorXd::LinSpaced(kSize, 1.0, kSize);
  fem::EigenOptions o;
  o.count = 10;
  const fem::EigenSolution s = fem::lowest_eigenpairs(diagonal(k), diagonal(Eigen::VectorXd::Ones(kSize)), o);
  ASSERT_EQ(s.eigenvalues.size(), 10);
  for (int i = 0; i < 10; ++i) EXPECT_NEAR(s.eigenvalues(i), i + 1.0, 1e-8 * (i + 1.0));
}

TEST(EigensolverFaults, AnIterationCutShortSaysHowFarItGotAndWhatToTry) {
  const Eigen::VectorXd k = Eigen::VectorXd::LinSpaced(kSize, 1.0, kSize);
  fem::EigenOptions o;
  o.count = 10;
  o.subspace = 12;       // a basis barely larger than the modes wanted
  o.max_iterations = 1;  // one restart
  o.tolerance = 1e-14;
  try {
    fem::lowest_eigenpairs(diagonal(k), diagonal(Eigen::VectorXd::Ones(kSize)), o);
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    std::printf("%s\n", m.c_str());
    expect_contains(m, "the eigensolver did not converge: ");
    expect_contains(m, " of 10 modes reached the tolerance 1e-14 within the limit of 1 restarts of the Lanczos iteration "
                       "(subspace of 12 vectors, 200 equations)");
    expect_contains(m, "Try: ask for a few more modes than you need");
    expect_contains(m, "framedyn modes --shift HZ; now 0.159155 Hz below zero");  // sigma = -1 rad^2/s^2
  }
}

TEST(EigensolverFaults, MassMatrixNotPositiveDefiniteNamesTheEquation) {
  const Eigen::VectorXd k = Eigen::VectorXd::LinSpaced(kSize, 1.0, kSize);
  Eigen::VectorXd m = Eigen::VectorXd::Ones(kSize);
  m(137) = -0.5;  // K - sigma M stays positive definite there: 138 - 0.5 > 0
  fem::EigenOptions o;
  o.count = 5;
  o.describe_equation = [](int i) { return "node " + std::to_string(i / 6 + 1) + ", DOF " + std::to_string(i % 6 + 1); };
  for (fem::Factorization f : {fem::Factorization::cholmod, fem::Factorization::eigen_simplicial_ldlt}) {
    o.factorization = f;
    try {
      fem::lowest_eigenpairs(diagonal(k), diagonal(m), o);
      ADD_FAILURE() << "no NumericalError";
    } catch (const NumericalError& e) {
      const std::string text = e.what();
      std::printf("%s\n", text.c_str());
      expect_contains(text, "the mass matrix is not positive definite");
      // CHOLMOD says where it stopped: equation 137 is node 23, DOF 6.
      if (f == fem::Factorization::cholmod) expect_contains(text, "the factorisation stopped at node 23, DOF 6");
    }
  }
}

}  // namespace
}  // namespace framedyn
