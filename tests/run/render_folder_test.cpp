// run::render_scene in-process: how a render ended comes back as a value
// (run::Outcome), never as an exit code, and every note goes through the Listener.
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/json.hpp"
#include "run/render_folder.hpp"
#include "scene/scene.hpp"

namespace {

namespace fs = std::filesystem;

/// Records notes; answers stop() with `stop_signal` once armed.
struct Recorder : tumble::run::Listener {
  int stop_signal = 0;
  bool armed = false;
  std::vector<std::string> notes;
  void note(const std::string& line) override { notes.push_back(line); }
  void begin(long, const std::string&) override {}
  void advance(long) override {}
  void end() override {}
  void arm_stop() override { armed = true; }
  int stop() const override { return armed ? stop_signal : 0; }
};

class RenderFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tumble_render_folder_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  tumble::run::Outcome render(Recorder& l) {
    const tumble::scene::Scene s =
        tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "tests/app/data/tiny_render.toml");
    return tumble::run::render_scene({s, dir_, "", false, false, false, tumble::render::GlBackend::osmesa, "tiny.toml"}, l);
  }
  fs::path dir_;
};

TEST_F(RenderFolder, ACompleteRenderIsDoneWithItsSummary) {
  Recorder l;
  const tumble::run::Outcome o = render(l);
  EXPECT_EQ(o.kind, tumble::run::Outcome::done);
  EXPECT_EQ(o.summary, "rendered frames 0..6 of 7 into " + dir_.string());
  const auto man = tumble::io::read_json_file(dir_ / "manifest.json");
  ASSERT_TRUE(man);
  EXPECT_EQ(man->value("complete", false), true);
  EXPECT_EQ(man->value("aa", std::string()), "msaa");
  EXPECT_EQ(man->value("video_format", std::string()), "none");
  EXPECT_EQ(man->value("crf", 0), 18);
}

TEST_F(RenderFolder, AStopRequestIsAnInterruptedOutcomeNamingHowToResume) {
  Recorder l;
  l.stop_signal = SIGTERM;
  const tumble::run::Outcome o = render(l);
  EXPECT_EQ(o.kind, tumble::run::Outcome::interrupted);
  EXPECT_EQ(o.signal, SIGTERM);
  ASSERT_EQ(l.notes.size(), 2u);
  EXPECT_EQ(l.notes[0], "interrupted (SIGTERM): kept 0 of 7 frames in " + dir_.string());
  EXPECT_EQ(l.notes[1], "continue with: tumble render tiny.toml -o " + dir_.string() + " --resume");
  const auto man = tumble::io::read_json_file(dir_ / "manifest.json");
  ASSERT_TRUE(man);
  EXPECT_EQ(man->value("complete", true), false);
}

}  // namespace
