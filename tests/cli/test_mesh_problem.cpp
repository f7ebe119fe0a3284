// The bridge between mesh tables and the engine: AE-unit tolerances, patches, constraints.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mesh_problem.h"
#include "ply_test_util.h"

using namespace qd;
using qd::io::test::error_of;

namespace {

// Unit square split along its diagonal: 5 edges, 4 of length 1 and one of √2.
io::MeshDocument square() {
  io::MeshDocument m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.patch = {4, 9};
  m.constrained = {0, 1, 0, 0};
  return m;
}

cli::ApproximateOptions options(std::vector<std::string> args) {
  return cli::parse_command_line(std::move(args)).approximate;
}

TEST(MeshProblem, TolerancesAreInUnitsOfTheAverageEdge) {
  cli::ApproximateOptions o = options({"a.ply", "b.ply", "--tolerance-ae", "0.5",
                                       "--patch-tolerance-ae", "9=2", "--max-iter", "4"});
  const approximate::Problem p = cli::make_problem(square(), o);
  const double ae = (4 + std::sqrt(2.0)) / 5;
  EXPECT_NEAR(p.params.tolerance, 0.5 * ae, 1e-15);
  ASSERT_EQ(p.params.patch_tolerance.size(), 1u);
  EXPECT_NEAR(p.params.patch_tolerance.at(9), 2 * ae, 1e-15);
  EXPECT_EQ(p.params.max_iter, 4);
  EXPECT_EQ(p.V.rows(), 4);
  EXPECT_EQ(p.F(1, 2), 3);
  EXPECT_EQ(p.patch, (std::vector<int>{4, 9}));
  EXPECT_EQ(p.constrained, (std::vector<char>{0, 1, 0, 0}));
  o.settings.tolerance_model = 0.25;  // model units replace AE
  EXPECT_EQ(cli::make_problem(square(), o).params.tolerance, 0.25);
  EXPECT_TRUE(
      cli::make_problem(square(), options({"a.ply", "b.ply", "--no-use-patches"})).patch.empty());
  o.settings.patch_tolerance_ae = {{5, 1.0}};
  EXPECT_NE(error_of([&] { cli::make_problem(square(), o); }).find("names patch 5"),
            std::string::npos);
}

TEST(MeshProblem, ConstraintFileAddsToTheSelection) {
  const auto path = std::filesystem::temp_directory_path() / "qd_cli_test_constraints.txt";
  std::ofstream(path) << "3\n";
  const cli::ApproximateOptions o =
      options({"a.ply", "b.ply", "--constraints-file", path.string()});
  EXPECT_EQ(cli::make_problem(square(), o).constrained, (std::vector<char>{0, 1, 0, 1}));
  std::filesystem::remove(path);
}

TEST(MeshProblem, DegenerateMeshIsRefused) {
  io::MeshDocument m = square();
  for (auto& p : m.positions) p = {1, 2, 3};
  const cli::ApproximateOptions o = options({"a.ply", "b.ply"});
  EXPECT_NE(error_of([&] { cli::make_problem(m, o); }).find("average edge length is 0"),
            std::string::npos);
}

}  // namespace
