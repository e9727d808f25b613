// The corpus of broken scenes: each file lists the errors it must produce as
// `# expect: <text>` lines; every diagnostic must also start with the file path.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "expectations.hpp"

#include "scene/scene.hpp"

namespace fs = std::filesystem;
using tumble::scene::SceneError;

namespace {

const fs::path kBrokenDir = fs::path(TUMBLE_SOURCE_DIR) / "tests/scene/broken";

std::vector<std::string> broken_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kBrokenDir))
    if (e.path().extension() == ".toml") out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

class BrokenScene : public testing::TestWithParam<std::string> {};

TEST_P(BrokenScene, ReportsItsDocumentedErrors) {
  const fs::path path = kBrokenDir / GetParam();
  const auto expected = expectations(path);
  ASSERT_FALSE(expected.empty()) << "no '# expect:' line in " << path;
  try {
    tumble::scene::load_scene(path);
    FAIL() << path << " loaded without error";
  } catch (const SceneError& e) {
    const std::string all = e.what();
    for (const std::string& x : expected) EXPECT_NE(all.find(x), std::string::npos) << "missing: " << x << "\ngot:\n" << all;
    for (const auto& d : e.diagnostics()) {
      EXPECT_EQ(d.file, path.string());
      EXPECT_EQ(d.str().rfind(path.string() + ":", 0), 0u) << d.str();
      EXPECT_GT(d.line, 0);
      EXPECT_GT(d.column, 0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BrokenScene, testing::ValuesIn(broken_files()),
                         [](const testing::TestParamInfo<std::string>& i) {
                           return fs::path(i.param).stem().string();
                         });

TEST(BrokenScene, SeveralErrorsAreReportedTogether) {
  try {
    tumble::scene::load_scene(kBrokenDir / "several_errors.toml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diagnostics().size(), 3u) << e.what();
  }
}

TEST(BrokenScene, MissingFileIsAnInputError) {
  EXPECT_THROW(tumble::scene::load_scene(kBrokenDir / "does_not_exist.toml"), tumble::InputError);
}

TEST(BrokenScene, StringSourcesNameTheGivenSource) {
  try {
    tumble::scene::load_scene_from_string("[simulation]\ndt = -1\n", "inline.toml");
    FAIL();
  } catch (const SceneError& e) {
    const std::string what = e.what();  // sorted by position: the missing [[bodies]] (1:1) comes first
    EXPECT_EQ(what.rfind("inline.toml:1:1: error: bodies: missing", 0), 0u) << what;
    EXPECT_NE(what.find("\ninline.toml:2:6: error: simulation.dt:"), std::string::npos) << what;
  }
}

TEST(BrokenScene, ErrorCountIsCapped) {
  std::string text = "[[bodies]]\nparticles = [";
  for (int i = 0; i < 200; ++i) text += "[0, 0, 0, -1], ";
  text += "]\n";
  try {
    tumble::scene::load_scene_from_string(text, "many.toml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_LE(e.diagnostics().size(), 51u);
    EXPECT_NE(std::string(e.what()).find("too many errors"), std::string::npos);
  }
}

}  // namespace
