// run::render_scene in-process: how a render ended comes back as a value
// (run::Outcome), never as an exit code, and every note goes through the Listener.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/folder_lock.hpp"
#include "io/json.hpp"
#include "run/assemble.hpp"
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
  tumble::run::Outcome render(Recorder& l, const std::string& frames = "") {
    const tumble::scene::Scene s =
        tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "tests/app/data/tiny_render.toml");
    return tumble::run::render_scene({s, dir_, frames, false, false, false, tumble::render::GlBackend::osmesa, "tiny.toml"},
                                     l);
  }
  std::vector<std::string> names() const {
    std::vector<std::string> v;
    for (const auto& e : fs::directory_iterator(dir_)) v.push_back(e.path().filename().string());
    std::sort(v.begin(), v.end());
    return v;
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

// A folder that render or assemble refuses gets nothing written into
// it, not even the lock file (.tumble.lock was left in such folders). No GL:
// the folder is refused before any drawing.
TEST_F(RenderFolder, ARefusedFolderGetsNoLockFile) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "manifest.json") << "{\"tool\": \"other\"}";  // not tumble's
  std::ofstream(dir_ / "notes.txt") << "mine";
  const std::vector<std::string> before = names();
  Recorder l;
  for (const std::string& frames : {std::string(), std::string("0:2")}) {
    SCOPED_TRACE("--frames '" + frames + "'");
    try {
      render(l, frames);
      ADD_FAILURE() << "a folder holding another tool's manifest.json was accepted";
    } catch (const tumble::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("holds a manifest.json that tumble did not write"), std::string::npos)
          << e.what();
    }
    EXPECT_EQ(names(), before);
  }
  EXPECT_THROW(tumble::run::assemble(dir_, std::nullopt, l), tumble::InputError);  // no manifest parts
  EXPECT_EQ(names(), before);
}

// A folder that looks foreign while its writer is mid-way is refused as in use,
// naming the holder, and still gets no lock file of ours.
TEST_F(RenderFolder, AFolderRefusedWhileHeldNamesItsHolder) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "frame_000000.png") << "x";  // a frame, no manifest yet
  const tumble::io::FolderLock held(dir_, tumble::io::FolderLock::Mode::exclusive, "tumble render other.toml", "k");
  Recorder l;
  for (int assemble = 0; assemble < 2; ++assemble) {
    try {
      if (assemble) tumble::run::assemble(dir_, std::nullopt, l); else render(l);
      ADD_FAILURE() << "a held folder was accepted";
    } catch (const tumble::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is in use by pid " + std::to_string(::getpid()) + ", tumble render other.toml"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
