// Unit tests of core/functional_map.h: the Laplace–Beltrami spectrum of a sphere against
// the analytic one (l(l+1) / r^2, multiplicity 2l + 1), the basis' mass-orthonormality seen
// through the constant function, and ZoomOut refining a noisy map of spot onto spot refined
// (other vertices) back to the true correspondence.
#include "core/closest.h"
#include "core/functional_map.h"
#include "tests/support/meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace eulermap {
namespace {

using namespace eulermap::testing;

TEST(LaplaceBasis, SphereSpectrumIsAnalytic) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1.0, 4);
  const LaplaceBasis basis = ComputeLaplaceBasis(sphere, 16);
  ASSERT_EQ(basis.phi.cols(), 16);
  ASSERT_EQ(basis.phi.rows(), Eigen::Index(sphere.vert.size()));
  // Unit area: r^2 = 1 / (4 pi), lambda_l = 4 pi l (l + 1).
  EXPECT_NEAR(basis.lambda[0], 0, 1e-6);
  int index = 1;
  for (int l = 1; l <= 3; ++l)
    for (int copy = 0; copy < 2 * l + 1; ++copy, ++index)
      EXPECT_NEAR(basis.lambda[index] / (4 * M_PI * l * (l + 1)), 1, 0.01) << "l = " << l << ", copy " << copy;
  for (int n = 1; n < 16; ++n) EXPECT_LE(basis.lambda[n - 1], basis.lambda[n] + 1e-9);
  // phi_0 is constant, 1 / sqrt(area) = 1 with unit area (M-orthonormal).
  EXPECT_NEAR(std::abs(basis.phi.col(0).mean()), 1, 1e-6);
  EXPECT_LT((basis.phi.col(0).array() - basis.phi.col(0).mean()).abs().maxCoeff(), 1e-6);
}

// Cancel (interrupt.h): the basis asks before each Lanczos step, so a host's progress bar
// moves at least once a step (more than k of them) and Cancel stops it at the next one, with
// no call after that and no basis.
TEST(LaplaceBasis, AsksTheInterruptEachStepAndStopsWhenCancelled) {
  Mesh sphere;
  MakeSphere(sphere, Point3(0, 0, 0), 1.0, 4);
  int polls = 0;
  const LaplaceBasis whole = ComputeLaplaceBasis(sphere, 16, Interrupt([&] { return ++polls > 0; }));
  EXPECT_EQ(whole.phi.cols(), 16);
  EXPECT_GT(polls, 16);
  int cancelledAt = 0;
  const Interrupt cancel([&] { return ++cancelledAt < 5; });
  const LaplaceBasis cut = ComputeLaplaceBasis(sphere, 16, cancel);
  EXPECT_TRUE(cancel.Cancelled());
  EXPECT_EQ(cut.phi.cols(), 0);
  EXPECT_EQ(cancelledAt, 5);
  const Interrupt stopNow([] { return false; });
  EXPECT_TRUE(ZoomOut(whole, whole, {0, 1}, Eigen::VectorXd::Ones(2), {0, 1}, {0, 1}, 4, 16, 4, {0}, stopNow).empty());
}

TEST(ZoomOut, RefinesANoisyMapBetweenTwoMeshingsOfOneShape) {
  Mesh source, target;
  LoadMesh(SampleFile("spot.ply"), source);
  LoadMesh(SampleFile("spot.ply"), target);
  RefineMidpoint(target, 1);
  const ClosestPoint targetIndex(target);
  auto nearestVertex = [&](const Point3 &p) {
    const ClosestHit hit = targetIndex.Query(p);
    int corner = 0;
    for (int c = 1; c < 3; ++c)
      if (hit.barycentric[c] > hit.barycentric[corner]) corner = c;
    return std::size_t(vcg::tri::Index(target, hit.face->cV(corner)));
  };
  const double diag = source.bbox.Diag();
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0, 0.04 * diag);
  std::vector<std::size_t> samples, start, query;
  double startError = 0;
  for (std::size_t v = 0; v < source.vert.size(); v += 2) {
    samples.push_back(v);
    const Point3 off(noise(random), noise(random), noise(random));
    start.push_back(nearestVertex(source.vert[v].cP() + off));
    startError += vcg::Distance(target.vert[start.back()].cP(), source.vert[v].cP());
  }
  startError /= samples.size();
  for (std::size_t v = 0; v < source.vert.size(); v += 17) query.push_back(v);
  std::vector<std::size_t> candidates;  // every third target vertex
  for (std::size_t v = 0; v < target.vert.size(); v += 3) candidates.push_back(v);
  const LaplaceBasis a = ComputeLaplaceBasis(source, 60), b = ComputeLaplaceBasis(target, 60);
  const std::vector<std::size_t> refined = ZoomOut(a, b, samples, Eigen::VectorXd::Ones(Eigen::Index(samples.size())), candidates, start, 10, 60, 5, query);
  ASSERT_EQ(refined.size(), query.size());
  double error = 0, worst = 0;
  for (std::size_t n = 0; n < query.size(); ++n) {
    const double d = vcg::Distance(target.vert[refined[n]].cP(), source.vert[query[n]].cP());
    error += d, worst = std::max(worst, d);
  }
  error /= query.size();
  EXPECT_GT(startError, 0.04 * diag);
  EXPECT_LT(error, 0.01 * diag) << "start " << startError / diag << " of the diagonal";
  EXPECT_LT(worst, 0.1 * diag);
}

}  // namespace
}  // namespace eulermap
