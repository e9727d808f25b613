// Hardening of `tumble render`: interrupted renders (SIGINT, SIGKILL)
// and --resume, output-folder safety (--force), write errors naming the path.
#include "render_fixture.hpp"

#include "io/folder_lock.hpp"
#include "io/png.hpp"

namespace {

constexpr int kSlowFrames = 161;  // slow_render.toml: 16 s at 10 fps

TEST_F(RobustRender, SigintKeepsWholeFramesAndAnIncompleteManifestThenResumeFinishes) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "int";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 3)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGINT);
  ASSERT_EQ(wait_exit(pid), 130) << slurp(dir_ / "spawn.err");
  const std::string err = slurp(dir_ / "spawn.err");
  EXPECT_NE(err.find("interrupted (SIGINT)"), std::string::npos) << err;
  EXPECT_NE(err.find("--resume"), std::string::npos) << err;
  const std::string manifest = slurp(out / "manifest.json");
  EXPECT_NE(manifest.find("\"complete\": false"), std::string::npos) << manifest;
  int frames = 0;
  for (const std::string& n : names(out)) {
    EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
    if (n.rfind("frame_", 0) == 0) {
      ++frames;
      EXPECT_TRUE(whole_png(slurp(out / n))) << n;
    }
  }
  EXPECT_GE(frames, 4);
  EXPECT_LT(frames, kSlowFrames) << "the render finished before the signal; nothing was tested";
  EXPECT_NE(manifest.find("\"frames_written\": " + std::to_string(frames) + ","), std::string::npos) << manifest;

  const Result r = run("render '" + data("slow_render.toml") + "' -o '" + out.string() + "' --resume --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("already on disk"), std::string::npos) << r.out;
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": true"), std::string::npos);
}

TEST_F(RobustRender, SigtermExits143) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "term";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 2)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGTERM);
  EXPECT_EQ(wait_exit(pid), 143) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": false"), std::string::npos);
}

TEST_F(RobustRender, KilledRenderResumesByteIdenticalToACleanRun) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "killed", clean = dir_ / "clean";
  const pid_t pid = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(pid, out, 5)) << slurp(dir_ / "spawn.err");
  ::kill(pid, SIGKILL);
  int sig = 0;
  wait_exit(pid, &sig);
  ASSERT_EQ(sig, SIGKILL);
  // What a kill -9 in the middle of a write leaves: a temp file. Resume removes it.
  std::ofstream(out / "frame_000150.png.tmp-99999") << "partial";
  std::ofstream(out / "manifest.json.tmp-99999") << "{";
  for (const std::string& n : names(out))
    if (n.rfind("frame_", 0) == 0 && n.find(".tmp") == std::string::npos) {
      EXPECT_TRUE(whole_png(slurp(out / n))) << n;
    }

  const Result r = run("render '" + data("slow_render.toml") + "' -o '" + out.string() + "' --resume --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(run("render '" + data("slow_render.toml") + "' -o '" + clean.string() + "' --progress none").code, 0);
  EXPECT_EQ(names(out), names(clean));
  expect_same_frames(out, clean, kSlowFrames);
}

TEST_F(RobustRender, RefusesAnotherScenesRenderUnlessForced) {
  TUMBLE_NEED_GL();
  const std::string out = (dir_ / "o").string();
  ASSERT_EQ(run("render '" + data("slow_render.toml") + "' -o '" + out + "' --progress none --frames 0:20").code, 0);
  Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("holds a render of another scene"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "o" / "frame_000020.png"));  // nothing touched

  // --force replaces it: the 21 old frames go, stale ones beyond the new 7 included.
  r = run("render '" + data("tiny_render.toml") + "' -o '" + out + "' --progress none --force");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "o" / "frame_000006.png"));
  EXPECT_FALSE(fs::exists(dir_ / "o" / "frame_000007.png"));
  EXPECT_FALSE(fs::exists(dir_ / "o" / "frame_000020.png"));
}

TEST_F(RobustRender, RefusesAFolderOfFramesWithoutManifest) {
  fs::create_directories(dir_ / "foreign");
  std::ofstream(dir_ / "foreign" / "frame_000000.png") << "not ours";
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "foreign").string() + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no manifest.json"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir_ / "foreign" / "frame_000000.png"), "not ours");
}

TEST_F(RobustRender, CreatesMissingOutputFolders) {
  TUMBLE_NEED_GL();
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "a/b/c").string() + "' --progress none --frames 0:0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "a/b/c/frame_000000.png"));
}

TEST_F(RobustRender, UncreatableOutputFolderNamesThePathAndExits1) {
  std::ofstream(dir_ / "file") << "x";
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "file/sub").string() + "' --progress none");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find((dir_ / "file/sub").string()), std::string::npos) << r.err;
}

TEST_F(RobustRender, FullDiskNamesTheFrameAndExits1) {
  TUMBLE_NEED_GL();
  // RLIMIT_FSIZE with SIGXFSZ ignored: writes past 4 KiB fail with EFBIG, like a full disk.
  const fs::path out = dir_ / "full";
  const std::string cmd = "ulimit -f 4; trap '' XFSZ; '" + tumble_bin() + "' render '" +
                          data("slow_render.toml") + "' -o '" + out.string() + "' --progress none >'" +
                          (dir_ / "o").string() + "' 2>'" + (dir_ / "e").string() + "'";
  const int st = std::system(("bash -c \"" + cmd + "\"").c_str());
  ASSERT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 1) << slurp(dir_ / "e");
  const std::string err = slurp(dir_ / "e");
  EXPECT_NE(err.find(out.string() + "/frame_"), std::string::npos) << err;
  EXPECT_EQ(err.find("internal error"), std::string::npos) << err;
  for (const std::string& n : names(out)) EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
}

TEST_F(RobustRender, SceneNameCannotLeaveTheOutputFolder) {
  std::ofstream(dir_ / "evil.toml") << "name = \"../../escape\"\n[[bodies]]\n"
                                       "particles = [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 0.5], [0, -1, 0, 0.5]]\n";
  const Result r = run("render '" + (dir_ / "evil.toml").string() + "' --progress none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("evil.toml:1:8: error: name: expected 1-64 characters"), std::string::npos) << r.err;
}

// ---- one writer per folder, nothing on disk trusted unchecked ---------------

using tumble::io::FolderLock;

TEST_F(RobustRender, ASecondWriterIsRefusedNamingTheHolder) {
  const fs::path out = dir_ / "o";
  fs::create_directories(out);
  const std::string tiny = "render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --progress none";
  const std::string me = "pid " + std::to_string(::getpid()) + ", tumble render other.toml";
  {
    const FolderLock held(out, FolderLock::Mode::exclusive, "tumble render other.toml", "k");
    for (const std::string& cmd : {tiny, tiny + " --frames 0:2", "assemble '" + out.string() + "'"}) {
      SCOPED_TRACE(cmd);
      const Result r = run(cmd);
      EXPECT_EQ(r.code, 2) << r.err;
      EXPECT_NE(r.err.find("output folder " + out.string() + " is in use by " + me), std::string::npos) << r.err;
    }
  }
  {
    // A shard of another render: other shards of that render may join, nothing else.
    const FolderLock shard(out, FolderLock::Mode::shared, "tumble render other.toml --frames 0:3", "other");
    const Result r = run(tiny + " --frames 4:6");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("(rendering another scene or other settings there)"), std::string::npos) << r.err;
  }
  // Released (as a kill -9 releases it): the note left behind stops no one.
  const Result r = run("assemble '" + out.string() + "'");
  EXPECT_EQ(r.err.find("in use"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("holds no manifest.part"), std::string::npos) << r.err;
}

TEST_F(RobustRender, TwoScenesAtOnceIntoOneFolderAndAKilledHolder) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "o";
  const pid_t slow = spawn_render(data("slow_render.toml"), out);
  ASSERT_TRUE(wait_for_frame(slow, out, 1)) << slurp(dir_ / "spawn.err");
  Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --progress none --force");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("is in use by pid " + std::to_string(slow) + ", tumble render "), std::string::npos) << r.err;
  ::kill(slow, SIGKILL);
  wait_exit(slow);
  r = run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --progress none --force");
  EXPECT_EQ(r.code, 0) << r.err;  // the dead holder's lock is free
}

TEST_F(RobustRender, DamagedFramesAreDrawnAgainOnResumeAndAssembleRefusesThem) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "o", clean = dir_ / "clean";
  const std::string render = "render '" + data("tiny_render.toml") + "' --progress none -o '";
  ASSERT_EQ(run(render + clean.string() + "'").code, 0);
  for (const char* shard : {"0:3", "4:6"}) ASSERT_EQ(run(render + out.string() + "' --frames " + shard).code, 0);
  auto frame = [&](int k) { return out / ("frame_00000" + std::to_string(k) + ".png"); };
  fs::resize_file(frame(2), 100);                          // truncated
  std::ofstream(frame(3), std::ios::trunc).close();        // empty
  fs::remove(frame(4));
  fs::create_symlink(frame(0), frame(4));                  // a link to another frame
  std::string bytes = slurp(frame(5));
  bytes[bytes.size() / 2] ^= 1;                            // same size, other content
  std::ofstream(frame(5), std::ios::binary | std::ios::trunc) << bytes;
  // assemble trusts none of them.
  Result r = run("assemble '" + out.string() + "' --video none");
  EXPECT_EQ(r.code, 2) << r.err;
  for (const char* why : {"frame_000002.png fails its check: 100 bytes, recorded", "frame_000003.png fails its check: 0 bytes",
                          "frame_000004.png fails its check: a symbolic link",
                          "frame_000005.png fails its check: its content changed"})
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  // Each shard's resume draws its two again.
  for (const char* shard : {"0:3", "4:6"}) {
    r = run(render + out.string() + "' --resume --frames " + shard);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("tumble: 2 frame(s) on disk failed their check"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::is_symlink(frame(4)));
  expect_same_frames(out, clean, 7);
  EXPECT_EQ(run("assemble '" + out.string() + "' --video none").code, 0);
}

TEST_F(RobustRender, AnyLegalFolderNameWorksEndToEnd) {
  TUMBLE_NEED_GL();
  // '%' was read by ffmpeg as a pattern; quotes, spaces and non-ASCII too.
  const fs::path out = dir_ / "100%d 'q\" \xc3\xa9t\xc3\xa9";
  const pid_t pid = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4"});
  ASSERT_EQ(wait_exit(pid), 0) << slurp(dir_ / "spawn.err");
  EXPECT_GT(fs::file_size(out / "tiny_render.mp4"), 100u);
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": true"), std::string::npos);
  // The --resume a stopped render suggests works there too (it failed the same way).
  fs::remove(out / "frame_000003.png");
  fs::remove(out / "tiny_render.mp4");
  const pid_t again = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4", "--resume"});
  ASSERT_EQ(wait_exit(again), 0) << slurp(dir_ / "spawn.err");
  EXPECT_TRUE(fs::exists(out / "frame_000003.png"));
  EXPECT_GT(fs::file_size(out / "tiny_render.mp4"), 100u);
}

TEST_F(RobustRender, ATopDownCameraDrawsTheBodyNotABlankFrame) {
  TUMBLE_NEED_GL();
  // Looking straight down along the default up (+z) drew blank frames.
  std::string scene = slurp(data("tiny_render.toml"));
  scene += "\n[camera]\nposition = [0, 0, 3]\ntarget = [0, 0, 0]\n";
  std::ofstream(dir_ / "top.toml") << scene;
  const fs::path out = dir_ / "o";
  const Result r = run("render '" + (dir_ / "top.toml").string() + "' -o '" + out.string() + "' --progress none --frames 0:0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: camera.up: parallel to the view direction"), std::string::npos) << r.err;
  const tumble::io::Image im = tumble::io::read_png(out / "frame_000000.png");
  // The body, in the middle, unlike the background at the row's left edge
  // (the captions above and below would not tell a blank frame from a drawn one).
  long differing = 0;
  for (int y = im.height / 4; y < 3 * im.height / 4; ++y)
    for (int x = im.width / 4; x < 3 * im.width / 4; ++x) {
      const std::uint8_t *p = im.pixel(x, y), *bg = im.pixel(1, y);
      differing += std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 30;
    }
  EXPECT_GT(differing, 40) << "a blank frame";
}

}  // namespace
