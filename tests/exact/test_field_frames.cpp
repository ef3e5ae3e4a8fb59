// `newtop field` reports γ, ∂V/∂γ, L and F both in the principal axes and in the frame the user
// gave --gamma in (the mass model's), each labelled (issue: the input frame was missing).

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "newtop/analysis/field_scan.hpp"
#include "newtop/io/json.hpp"
#include "support/cli.hpp"

namespace newtop {
namespace test_field_frames {
namespace {

namespace fs = std::filesystem;

Vec3 vec(const io::Json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

/// Point masses whose principal axes are turned away from the file's frame.
fs::path tilted_scenario() {
  const fs::path p = newtop::test::scratch_path("newtop_field_frames", "tilted.toml");
  std::ofstream(p) << "[mass_model]\nkind = \"points\"\n"
                      "points = [[1.0, 1.0, 0.5, 0.0], [2.0, -0.5, 0.3, 0.2], [1.5, 0.1, -0.7, "
                      "0.4], [0.5, 0.2, 0.1, -0.9]]\n"
                      "[field]\nkind = \"exact\"\nmu = 1.0\nR = 10.0\n"
                      "[initial]\nomega = [0.0, 0.0, 0.0]\ngamma = [0.0, 0.0, 1.0]\n";
  return p;
}

// Tolerance of the frame check: P is orthonormal to a few ulps, so P (P^T v) returns v within
// ~1e-15 relative; 1e-13 of the vectors' size leaves a wide margin.
constexpr double kFrameTol = 1e-13;

TEST(FieldFrames, JsonHasTheInputFrameBesideThePrincipalAxes) {
  const fs::path sc = tilted_scenario();
  const test::CliResult r = test::run_newtop("field " + sc.string() + " --gamma 0.6,0,0.8 --json",
                                             test::Stderr::separate);
  fs::remove(sc);
  ASSERT_EQ(r.code, 0) << r.err;
  const io::Json j = io::Json::parse(r.out);
  ASSERT_TRUE(j.contains("frame") && j.contains("input_frame")) << r.out;
  EXPECT_EQ(j["frame"], "principal");
  const io::Json& in = j["input_frame"];
  EXPECT_EQ(in["frame"], "input");
  // γ in the input frame is the --gamma given (normalised).
  EXPECT_LT((vec(in["gamma"]) - Vec3(0.6, 0, 0.8)).norm(), kFrameTol);
  // The axes are turned: the principal γ differs from the input γ.
  EXPECT_GT((vec(j["gamma"]) - vec(in["gamma"])).norm(), 1e-3);
  // Vectors of the same size, scalars the same: a rotation.
  for (const char* part : {"exact", "approx"}) {
    for (const char* key : {"grad_gamma", "moment", "force"}) {
      EXPECT_NEAR(vec(in[part][key]).norm(), vec(j[part][key]).norm(),
                  kFrameTol * vec(j[part][key]).norm())
          << part << " " << key;
    }
    EXPECT_EQ(in[part]["potential"], j[part]["potential"]);
  }
  // The moment L = γ × ∂V/∂γ holds in the input frame as in the principal axes.
  const Vec3 g = vec(in["gamma"]), dV = vec(in["exact"]["grad_gamma"]);
  EXPECT_LT((g.cross(dV) - vec(in["exact"]["moment"])).norm(), 1e-12 * dV.norm());
}

TEST(FieldFrames, SummaryNamesBothFrames) {
  const fs::path sc = tilted_scenario();
  const test::CliResult r = test::run_newtop("field " + sc.string() + " --gamma 0.6,0,0.8");
  fs::remove(sc);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("gamma (input frame) = [0.6"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in the principal axes: gamma = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in the input frame (the mass model's): gamma = "), std::string::npos);
}

}  // namespace
}  // namespace test_field_frames
}  // namespace newtop
