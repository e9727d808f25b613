// The edit-render loop. Rendering the same scene file again after an
// edit replaces its frames without --force: new frames are written whole
// (atomically), stale frames past the new range go once the new ones exist,
// and an interrupted replacement is never resumed from the old frames.
#include "render_fixture.hpp"

namespace {

class EditLoop : public RobustRender {
 protected:
  // tiny_render.toml with `from` replaced by `to`, written to DIR/edit.toml.
  std::string edited(const std::string& from, const std::string& to) const {
    std::string text = slurp(kSource / "tests/app/data/tiny_render.toml");
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(dir_ / "edit.toml") << text;
    return (dir_ / "edit.toml").string();
  }
  Result render(const std::string& scene, const fs::path& out, const std::string& extra = "") const {
    return run("render '" + scene + "' -o '" + out.string() + "' --progress none " + extra);
  }
};

TEST_F(EditLoop, ReRenderingAnEditedSceneReplacesItsFrames) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "out";
  const std::string scene = edited("duration = 0.6", "duration = 0.6");  // 7 frames
  ASSERT_EQ(render(scene, out).code, 0);
  const std::string old0 = slurp(out / "frame_000000.png");

  // Another colour, a shorter run: 4 frames.
  std::string text = slurp(kSource / "tests/app/data/tiny_render.toml");
  text.replace(text.find("color = [0.85, 0.45, 0.15]"), 26, "color = [0.15, 0.45, 0.85]");
  text.replace(text.find("duration = 0.6"), 14, "duration = 0.3");
  std::ofstream(dir_ / "edit.toml") << text;
  const Result r = render(scene, out);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("replacing the earlier render of tiny_render"), std::string::npos) << r.err;
  EXPECT_NE(slurp(out / "frame_000000.png"), old0) << "frame 0 kept the old colour";
  EXPECT_TRUE(fs::exists(out / "frame_000003.png"));
  for (const char* stale : {"frame_000004.png", "frame_000005.png", "frame_000006.png"})
    EXPECT_FALSE(fs::exists(out / stale)) << stale << " of the earlier render is still there";
  const std::string m = slurp(out / "manifest.json");
  EXPECT_NE(m.find("\"complete\": true"), std::string::npos) << m;
  EXPECT_NE(m.find("\"frame_count\": 4"), std::string::npos) << m;
  EXPECT_NE(m.find("\"replacing\": false"), std::string::npos) << m;
  // The same frames as a clean render of the edited scene, in a fresh folder.
  ASSERT_EQ(render(scene, dir_ / "clean").code, 0);
  EXPECT_EQ(names(out), names(dir_ / "clean"));
  expect_same_frames(out, dir_ / "clean", 4);
}

TEST_F(EditLoop, InterruptedReplacementResumesFromNoneOfTheOldFrames) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "out";
  const std::string slow = data("slow_render.toml");
  std::string text = slurp(slow);
  std::ofstream(dir_ / "slow.toml") << text;
  const std::string scene = (dir_ / "slow.toml").string();
  ASSERT_EQ(render(scene, out, "").code, 0);
  // Edit (the colour), start the replacement, interrupt it a few frames in.
  text.replace(text.find("color = [0.85, 0.45, 0.15]"), 26, "color = [0.15, 0.45, 0.85]");
  std::ofstream(dir_ / "slow.toml") << text;
  const auto old_mtime = fs::last_write_time(out / "frame_000004.png");
  const pid_t pid = spawn_render(scene, out);
  for (int i = 0; i < 60000 && fs::last_write_time(out / "frame_000004.png") == old_mtime; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ::kill(pid, SIGINT);
  ASSERT_EQ(wait_exit(pid), 130) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(out / "manifest.json").find("\"replacing\": true"), std::string::npos);
  // --resume must not take the unreplaced old frames for new ones.
  const Result r = render(scene, out, "--resume");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(render(scene, dir_ / "clean", "").code, 0);
  EXPECT_EQ(names(out), names(dir_ / "clean"));
  expect_same_frames(out, dir_ / "clean", 161);
}

TEST_F(EditLoop, OtherSettingsOfTheSameSceneReplaceToo) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "out";
  const std::string scene = data("tiny_render.toml");
  ASSERT_EQ(render(scene, out).code, 0);
  const Result r = render(scene, out, "--width 48 --frames 0:2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "frame_000002.png"));
  EXPECT_FALSE(fs::exists(out / "frame_000003.png")) << "a 96 px frame of the earlier render is still there";
}

}  // namespace
