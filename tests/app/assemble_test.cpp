// Shards of a render (`--frames A:B`, each with its manifest part)
// run by GNU Parallel and put together by `tumble assemble` equal a single
// run byte for byte; parts that do not add up are refused, naming the gap.
#include "render_fixture.hpp"

namespace {

class Assemble : public RobustRender {
 protected:
  // Renders tiny_render's shards `ranges` ("A:B ...") into `out` with GNU Parallel, 4 at once.
  void render_shards(const fs::path& out, const std::string& ranges) const {
    const std::string cmd = "parallel --will-cite -j4 \"'" + tumble_bin() + "' render '" + data("tiny_render.toml") +
                            "' -o '" + out.string() + "' --video mp4 --progress none --frames {}\" ::: " + ranges +
                            " >'" + (dir_ / "parallel.out").string() + "' 2>&1";
    const int st = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(dir_ / "parallel.out");
  }
};

TEST_F(Assemble, FourParallelShardsEqualASingleRunByteForByte) {
  TUMBLE_NEED_GL();
  const fs::path single = dir_ / "single", sharded = dir_ / "sharded";
  Result r = run("render '" + data("tiny_render.toml") + "' -o '" + single.string() + "' --video mp4 --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  render_shards(sharded, "0:1 2:3 4:5 6:6");
  // Each shard recorded itself; none made a video or the manifest.
  EXPECT_EQ(names(sharded),
            (std::vector<std::string>{".tumble.lock", "frame_000000.png", "frame_000001.png", "frame_000002.png",
                                      "frame_000003.png", "frame_000004.png", "frame_000005.png", "frame_000006.png",
                                      "frames.sums", "manifest.part-000000-000001.json", "manifest.part-000002-000003.json",
                                      "manifest.part-000004-000005.json", "manifest.part-000006-000006.json"}));
  r = run("assemble '" + sharded.string() + "' --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("assembled frames 0..6 from 4 parts"), std::string::npos) << r.out;
  EXPECT_EQ(names(sharded), names(single));  // the parts are gone, the video is there
  expect_same_frames(sharded, single, 7);
  const std::string a = slurp(sharded / "tiny_render.mp4"), b = slurp(single / "tiny_render.mp4");
  EXPECT_GT(a.size(), 100u);
  EXPECT_TRUE(a == b) << "the assembled video differs from the single run's (" << a.size() << " vs " << b.size()
                      << " bytes)";
  const std::string m = slurp(sharded / "manifest.json");
  EXPECT_NE(m.find("\"complete\": true"), std::string::npos) << m;
  EXPECT_NE(m.find("\"video\": \"tiny_render.mp4\""), std::string::npos) << m;
  EXPECT_NE(m.find("\"frames_written\": 7"), std::string::npos) << m;
  EXPECT_NE(m.find("\"assembled_from\""), std::string::npos) << m;
}

TEST_F(Assemble, AMissingShardFailsNamingTheGap) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "gap";
  render_shards(out, "0:1 4:6");
  const Result r = run("assemble '" + out.string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("frames 2:3 of 0:6 are missing"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "manifest.json"));
  EXPECT_FALSE(fs::exists(out / "tiny_render.mp4"));
  // Rendering the missing shard completes it.
  render_shards(out, "2:3");
  EXPECT_EQ(run("assemble '" + out.string() + "' --progress none").code, 0);
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": true"), std::string::npos);
}

TEST_F(Assemble, ShardsReplacingAnEditedRenderLeaveNothingOfIt) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "replace", narrow = dir_ / "narrow";
  ASSERT_EQ(run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --video mp4 --progress none").code, 0);
  // Other settings: the 96 px render's manifest and video go at once, its frames as the shards write theirs.
  const std::string cmd = "parallel --will-cite -j4 \"'" + tumble_bin() + "' render '" + data("tiny_render.toml") +
                          "' -o '" + out.string() + "' --video mp4 --width 48 --progress none --frames {}\" ::: 0:1 "
                          "2:3 4:5 6:6 >'" + (dir_ / "parallel.out").string() + "' 2>&1";
  const int st = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(dir_ / "parallel.out");
  EXPECT_FALSE(fs::exists(out / "manifest.json"));
  EXPECT_FALSE(fs::exists(out / "tiny_render.mp4")) << "the 96 px video is still there";
  ASSERT_EQ(run("assemble '" + out.string() + "' --progress none").code, 0);
  ASSERT_EQ(run("render '" + data("tiny_render.toml") + "' -o '" + narrow.string() +
                "' --video mp4 --width 48 --progress none").code, 0);
  EXPECT_EQ(names(out), names(narrow));
  expect_same_frames(out, narrow, 7);
  EXPECT_TRUE(slurp(out / "tiny_render.mp4") == slurp(narrow / "tiny_render.mp4"));
}

TEST_F(Assemble, AnIncompleteOrForeignPartIsNamed) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "bad";
  render_shards(out, "0:3 4:6");
  const fs::path part = out / "manifest.part-000004-000006.json";
  std::string text = slurp(part);
  const std::string done = "\"complete\": true";
  ASSERT_NE(text.find(done), std::string::npos) << text;
  std::ofstream(part) << text.replace(text.find(done), done.size(), "\"complete\": false");
  Result r = run("assemble '" + out.string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("manifest.part-000004-000006.json: incomplete"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--frames 4:6 --resume"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frames 4:6 of 0:6 are missing"), std::string::npos) << r.err;

  // Complete, but of other settings (as if rendered at another size): named with both hashes.
  const std::string hash = "\"settings_hash\": \"";
  const size_t at = text.find(hash);
  ASSERT_NE(at, std::string::npos) << text;
  std::string other = text;
  other.replace(at + hash.size(), 16, "0123456789abcdef");
  other.replace(other.find("\"complete\": false"), 17, "\"complete\": true");
  std::ofstream(part) << other;
  r = run("assemble '" + out.string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("manifest.part-000004-000006.json (scene hash"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("settings hash 0123456789abcdef"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is not a shard of the same render as manifest.part-000000-000003.json"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out / "manifest.json"));

  std::ofstream(part) << "{\"tool\": \"tumble\"}";
  r = run("assemble '" + out.string() + "' --progress none");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("manifest.part-000004-000006.json: not a manifest part written by tumble"), std::string::npos)
      << r.err;
}

TEST_F(Assemble, AFolderWithoutPartsExits2) {
  fs::create_directories(dir_ / "empty");
  const Result r = run("assemble '" + (dir_ / "empty").string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("holds no manifest.part-*.json"), std::string::npos) << r.err;
}

}  // namespace
