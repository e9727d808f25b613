// Hostile inputs to `tumble render` and `assemble`, round two: a damaged font,
// a video named like the scene file, a bad TUMBLE_GPU_PATHS over a finished
// render, forged shard parts. Each case failed on the code before its fix.
#include "render_fixture.hpp"

namespace {

class HostileRender : public RobustRender {
 protected:
  // A copy of tumble in DIR/bin whose resource folder (the first parent with
  // shaders/) is DIR, holding fonts/DejaVuSans.ttf = `font`.
  std::string tumble_with_font(const std::string& font) const {
    fs::create_directories(dir_ / "bin");
    fs::create_directories(dir_ / "fonts");
    fs::copy_file(tumble_bin(), dir_ / "bin" / "tumble", fs::copy_options::overwrite_existing);
    fs::copy(kSource / "shaders", dir_ / "shaders", fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    std::ofstream(dir_ / "fonts" / "DejaVuSans.ttf", std::ios::binary) << font;
    return (dir_ / "bin" / "tumble").string();
  }
  Result run_with(const std::string& bin, const std::string& args) const {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
    const int st = std::system(("'" + bin + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'").c_str());
    return {WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st), slurp(out), slurp(err)};
  }
};

TEST_F(HostileRender, ADamagedFontIsNamedWithItsPackageNotACrash) {
  TUMBLE_NEED_GL();
  const std::string font = slurp("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  ASSERT_GT(font.size(), 100000u) << "fonts-dejavu-core is not installed";
  std::string garbage(font.size(), '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 2654435761u) >> 13);
  std::string truncated_tables = font;  // the directory intact, the tables cut short
  truncated_tables.resize(font.size() / 3);
  const std::pair<std::string, std::string> cases[] = {
      {font.substr(0, 2000), "damaged font"}, {truncated_tables, "damaged font"}, {garbage, "damaged font"}, {"", "damaged font"}};
  for (const auto& [bytes, what] : cases) {
    SCOPED_TRACE(bytes.size());
    const std::string bin = tumble_with_font(bytes);
    const Result r = run_with(bin, "render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "out").string() +
                                       "' --progress none");
    EXPECT_EQ(r.code, 1) << r.err;  // 139: SIGSEGV
    EXPECT_NE(r.err.find((dir_ / "fonts" / "DejaVuSans.ttf").string() + ": " + what), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("fonts-dejavu-core"), std::string::npos) << r.err;
  }
  const Result ok = run_with(tumble_with_font(font), "render '" + data("tiny_render.toml") + "' -o '" +
                                                         (dir_ / "good").string() + "' --progress none");
  EXPECT_EQ(ok.code, 0) << ok.err;  // the check passes the real font
}

TEST_F(HostileRender, AVideoNamedLikeTheSceneFileIsRefusedBeforeAnyWork) {
  TUMBLE_NEED_GL();
  // The scene tiny_render, kept as OUT/tiny_render.mp4: its video would replace it.
  fs::create_directories(dir_ / "out");
  const fs::path scene = dir_ / "out" / "tiny_render.mp4";
  fs::copy_file(data("tiny_render.toml"), scene);
  const Result r = run("render '" + scene.string() + "' -o '" + (dir_ / "out").string() +
                       "' --video mp4 --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("the video " + scene.string() + ": refusing to write over scene file"), std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(scene), slurp(data("tiny_render.toml")));
  EXPECT_EQ(names(dir_ / "out"), std::vector<std::string>{"tiny_render.mp4"}) << "something was written first";
}

TEST_F(HostileRender, ABadGpuPathsSettingFailsBeforeTheFinishedRenderIsTouched) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "done";
  ASSERT_EQ(run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --progress none").code, 0);
  const std::vector<std::string> before = names(out);
  const std::string sums = slurp(out / "frames.sums");
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --progress none",
                       "TUMBLE_GPU_PATHS=bogus");
  EXPECT_EQ(r.code, 2) << r.err;  // was 1, "internal error", with frames.sums gone
  EXPECT_NE(r.err.find("TUMBLE_GPU_PATHS = 'bogus'"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(names(out), before);
  EXPECT_EQ(slurp(out / "frames.sums"), sums);
}

TEST_F(HostileRender, AssembleRefusesPartsThatDisagreeOnWhatTheHashDoesNotCover) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "shards";
  for (const char* range : {"0:3", "4:6"})
    ASSERT_EQ(run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --frames " + range +
                  " --video gif --progress none").code, 0);
  const fs::path part = out / "manifest.part-000004-000006.json";
  std::string text = slurp(part);
  const std::string fps = "\"fps\": 10";
  ASSERT_NE(text.find(fps), std::string::npos) << text;
  std::ofstream(part) << text.replace(text.find(fps), fps.size(), "\"fps\": 25");  // same hashes, other frame rate
  const Result r = run("assemble '" + out.string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("at 25 fps"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is not a shard of the same render"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "manifest.json"));
}

}  // namespace
