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

#include "base/error.hpp"
#include "io/folder_lock.hpp"
#include "io/frame_files.hpp"
#include "io/frame_sums.hpp"
#include "io/png.hpp"
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
  tumble::run::Outcome render(Recorder& l, const std::string& frames = "", bool resume = false) {
    const tumble::scene::Scene s =
        tumble::scene::load_scene(fs::path(TUMBLE_SOURCE_DIR) / "tests/app/data/tiny_render.toml");
    return tumble::run::render_scene({s, dir_, frames, resume, false, false, tumble::render::GlBackend::osmesa, "tiny.toml"},
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

namespace {

/// Tries, while the render draws its first frame, to take the folder as a
/// shard of the very same render would (same scene and settings key).
struct ShardProbe : Recorder {
  fs::path dir;
  int tries = 0;
  std::string refused;  ///< the refusal's message, empty when the shard got in
  void advance(long) override {
    if (tries++ > 0) return;
    const auto man = tumble::io::read_json_file(dir / "manifest.json");
    ASSERT_TRUE(man);
    const std::string key = man->value("scene_hash", std::string()) + " " + man->value("settings_hash", std::string());
    try {
      tumble::io::FolderLock shard(dir, tumble::io::FolderLock::Mode::shared, "tumble render tiny.toml --frames 0:1", key);
    } catch (const tumble::InputError& e) {
      refused = e.what();
    }
  }
};

}  // namespace

// A whole render holds its folder alone: not even a shard of the same scene
// and settings may start in it meanwhile (it would race the whole render's
// manifest and its removal of stale frames). Decided in-process, mid-render,
// so no timing is involved.
TEST_F(RenderFolder, AShardOfTheSameRenderCannotStartWhileTheWholeRenderHoldsTheFolder) {
  ShardProbe l;
  l.dir = dir_;
  EXPECT_EQ(render(l).kind, tumble::run::Outcome::done);
  EXPECT_GT(l.tries, 0);
  EXPECT_NE(l.refused.find("is in use by"), std::string::npos) << "the shard got into the folder";
  ShardProbe s;  // and a shard holds it shared: a sibling shard of the same render gets in
  s.dir = dir_;
  EXPECT_EQ(render(s, "0:3").kind, tumble::run::Outcome::done);
  EXPECT_EQ(s.refused, "");
}

// A resumed render keeps a frame only when it is the frame the settings ask
// for: one of the right width but the wrong height (recorded as written, so
// only its size betrays it) is drawn again.
TEST_F(RenderFolder, AResumedRenderRedrawsAFrameOfTheRightWidthButTheWrongHeight) {
  Recorder first;
  ASSERT_EQ(render(first).kind, tumble::run::Outcome::done);
  const fs::path f = tumble::io::frame_path(dir_, 3);
  tumble::io::Image tall = tumble::io::read_png(f, tumble::ReadRole::own_output);
  ASSERT_EQ(tall.width, 96);
  tall.height += 2;
  tall.rgb.resize(static_cast<std::size_t>(tall.width) * tall.height * 3, 0);
  tumble::io::write_png_atomic(f, tall);
  tumble::io::record_frame(f);  // as if this render had written it
  Recorder again;
  ASSERT_EQ(render(again, "", true).kind, tumble::run::Outcome::done);
  const tumble::io::Image redrawn = tumble::io::read_png(f, tumble::ReadRole::own_output);
  EXPECT_EQ(redrawn.width, 96);
  EXPECT_EQ(redrawn.height, 72) << "the frame of the wrong height was kept";
  const bool said = std::any_of(again.notes.begin(), again.notes.end(), [](const std::string& n) {
    return n.rfind("1 frame(s) on disk failed their check", 0) == 0;
  });
  EXPECT_TRUE(said) << "expected exactly the one frame to be rejected";
}

// Assemble makes the folder one render of frames 0 … count - 1: an earlier,
// longer render's frames from count on go, the first of them (numbered
// exactly count) included.
TEST_F(RenderFolder, AssembleRemovesEveryFrameFromTheFrameCountOn) {
  Recorder l;
  ASSERT_EQ(render(l, "0:3").kind, tumble::run::Outcome::done);
  ASSERT_EQ(render(l, "4:6").kind, tumble::run::Outcome::done);
  for (long k : {7L, 8L}) fs::copy_file(tumble::io::frame_path(dir_, 6), tumble::io::frame_path(dir_, k));
  ASSERT_EQ(tumble::run::assemble(dir_, std::nullopt, l).kind, tumble::run::Outcome::done);
  EXPECT_TRUE(fs::exists(tumble::io::frame_path(dir_, 6)));
  EXPECT_FALSE(fs::exists(tumble::io::frame_path(dir_, 7))) << "the stale frame numbered the frame count was kept";
  EXPECT_FALSE(fs::exists(tumble::io::frame_path(dir_, 8)));
}
