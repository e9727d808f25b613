// The video is part of a complete render. An interrupted encode
// exits 130/143, a failed or missing ffmpeg exits 1; each leaves "complete":
// false with "video": null and the reason, and --resume makes the video.
// A fake ffmpeg on PATH makes each case happen on cue.
#include <sys/stat.h>

#include <cstdio>
#include <sstream>

#include "run/video.hpp"
#include "render_fixture.hpp"

namespace {

class VideoRender : public RobustRender {
 protected:
  // A folder holding an executable `ffmpeg` that runs `body` (sh).
  std::string fake_ffmpeg(const std::string& body) const {
    const fs::path bin = dir_ / "fakebin";
    fs::create_directories(bin);
    std::ofstream(bin / "ffmpeg") << "#!/bin/sh\n" << body << "\n";
    ::chmod((bin / "ffmpeg").c_str(), 0755);
    return bin.string() + ":/usr/bin:/bin";
  }
  static bool wait_for_file(pid_t pid, const fs::path& p) {
    for (int i = 0; i < 60000; ++i) {
      if (fs::exists(p)) return true;
      int st;
      if (::waitpid(pid, &st, WNOHANG) == pid) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }
  void expect_incomplete_without_video(const fs::path& out) const {
    const std::string m = slurp(out / "manifest.json");
    EXPECT_NE(m.find("\"complete\": false"), std::string::npos) << m;
    EXPECT_NE(m.find("\"video\": null"), std::string::npos) << m;
    EXPECT_NE(m.find("\"video_error\": \""), std::string::npos) << m;
    EXPECT_FALSE(fs::exists(out / "tiny_render.mp4"));
    for (const std::string& n : names(out)) EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
  }
};

// The measured x264 settings at the CRF, and NVENC only for an
// NVIDIA GPU whose ffmpeg can open it (a fake ffmpeg answers the trial).
TEST_F(VideoRender, EncoderIsChosenByGpuAndTrialEncode) {
  using tumble::run::choose_video_encoder;
  auto args = [](const tumble::run::VideoEncoder& e) {
    std::string s;
    for (const std::string& a : tumble::run::ffmpeg_output_args(tumble::scene::VideoFormat::mp4, 18, "out.tmp", e)) s += a + " ";
    return s;
  };
  const tumble::run::VideoEncoder x264 = tumble::run::x264_encoder(2);
  EXPECT_NE(args(x264).find("-c:v libx264 -pix_fmt yuv420p -crf 18 -threads 1 -preset ultrafast"), std::string::npos) << args(x264);
  EXPECT_EQ(tumble::run::x264_encoder(16).threads, 0);
  const std::string old_path = std::getenv("PATH");
  ::setenv("PATH", fake_ffmpeg("exit 0").c_str(), 1);
  const tumble::run::VideoEncoder nvidia = choose_video_encoder("NVIDIA Corporation", 16);
  const tumble::run::VideoEncoder mesa = choose_video_encoder("Mesa/X.org", 16);
  ::setenv("PATH", fake_ffmpeg("exit 1").c_str(), 1);
  const tumble::run::VideoEncoder broken = choose_video_encoder("NVIDIA Corporation", 16);
  ::setenv("PATH", old_path.c_str(), 1);
  EXPECT_EQ(nvidia.codec, "h264_nvenc");
  EXPECT_NE(args(nvidia).find("-c:v h264_nvenc"), std::string::npos) << args(nvidia);
  EXPECT_NE(args(nvidia).find("-cq 18"), std::string::npos) << args(nvidia);
  EXPECT_EQ(mesa.codec, "libx264");
  EXPECT_EQ(broken.codec, "libx264") << "NVENC listed but failing its trial must fall back";
}

TEST_F(VideoRender, InterruptedEncodeExits130ThenResumeMakesTheVideo) {
  TUMBLE_NEED_GL();
  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(sig);
    const fs::path out = dir_ / ("enc" + std::to_string(sig)), mark = dir_ / ("started" + std::to_string(sig));
    const std::string path = fake_ffmpeg("touch '" + mark.string() + "'; exec sleep 60");
    const pid_t pid = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4"}, path);
    ASSERT_TRUE(wait_for_file(pid, mark)) << slurp(dir_ / "spawn.err");
    ::kill(pid, sig);
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(wait_exit(pid), 128 + sig) << slurp(dir_ / "spawn.err");
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20)) << "did not stop the encode";
    expect_incomplete_without_video(out);
    EXPECT_NE(slurp(dir_ / "spawn.err").find("--resume"), std::string::npos) << slurp(dir_ / "spawn.err");
  }
  // The real ffmpeg now: --resume keeps the 7 frames and makes the video.
  const fs::path out = dir_ / ("enc" + std::to_string(SIGINT));
  const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out.string() + "' --video mp4 --resume --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("7 already on disk"), std::string::npos) << r.out;
  const std::string m = slurp(out / "manifest.json");
  EXPECT_NE(m.find("\"complete\": true"), std::string::npos) << m;
  EXPECT_NE(m.find("\"video\": \"tiny_render.mp4\""), std::string::npos) << m;
  EXPECT_GT(fs::file_size(out / "tiny_render.mp4"), 100u);
}

TEST_F(VideoRender, FailedFfmpegExits1AndSaysSo) {
  TUMBLE_NEED_GL();
  const std::string path = fake_ffmpeg("echo 'fake encoder failure' >&2; exit 1");
  const fs::path out = dir_ / "fail";
  const pid_t pid = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4"}, path);
  EXPECT_EQ(wait_exit(pid), 1) << slurp(dir_ / "spawn.err");
  const std::string err = slurp(dir_ / "spawn.err");
  EXPECT_NE(err.find("ffmpeg failed (exit 1)"), std::string::npos) << err;
  EXPECT_EQ(err.find("rendered frames"), std::string::npos) << err;
  expect_incomplete_without_video(out);
}

TEST_F(VideoRender, MissingFfmpegExits1ButVideoNoneExits0) {
  TUMBLE_NEED_GL();
  const fs::path out = dir_ / "missing", none = dir_ / "none";
  pid_t pid = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4"}, "/nonexistent-tumble-path");
  EXPECT_EQ(wait_exit(pid), 1) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(dir_ / "spawn.err").find("ffmpeg not found"), std::string::npos) << slurp(dir_ / "spawn.err");
  expect_incomplete_without_video(out);
  // No video asked for: no ffmpeg needed, a complete render.
  pid = spawn_render(data("tiny_render.toml"), none, {"--video", "none"}, "/nonexistent-tumble-path");
  EXPECT_EQ(wait_exit(pid), 0) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(none / "manifest.json").find("\"complete\": true"), std::string::npos);
}

TEST_F(VideoRender, EncodeShowsProgress) {
  TUMBLE_NEED_GL();
  // A fake ffmpeg that reports progress as ffmpeg's -progress does and writes its output.
  const std::string path = fake_ffmpeg("for a; do last=$a; done; printf 'frame=3\\nprogress=continue\\nframe=7\\nprogress=end\\n'; "
                                       "echo video > \"$last\"");
  // and an ffprobe that finds it whole (the video is checked before it counts as made)
  std::ofstream(dir_ / "fakebin/ffprobe") << "#!/bin/sh\nprintf 'codec_type=video\\nnb_read_frames=7\\nduration=0.7\\n'\n";
  ::chmod((dir_ / "fakebin/ffprobe").c_str(), 0755);
  const fs::path out = dir_ / "progress";
  std::vector<std::string> extra = {"--video", "mp4", "--progress", "auto"};
  const pid_t pid = spawn_render(data("tiny_render.toml"), out, extra, path);
  EXPECT_EQ(wait_exit(pid), 0) << slurp(dir_ / "spawn.err");
  EXPECT_NE(slurp(dir_ / "spawn.err").find("encoding tiny_render.mp4 from 7 frames"), std::string::npos)
      << slurp(dir_ / "spawn.err");
  EXPECT_EQ(slurp(out / "tiny_render.mp4"), "video\n");
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": true"), std::string::npos);
}

}  // namespace

// ---- --frames-out none: raw frames piped to ffmpeg, no PNG ------------------

namespace {

// What a command prints on stdout (e.g. ffprobe, ffmpeg -f framemd5).
std::string capture(const std::string& cmd) {
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    ::pclose(p);
  }
  return out;
}
std::string frame_count(const fs::path& video) {
  return capture("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 '" +
                 video.string() + "'");
}
// MD5 of every decoded frame, without the header (which names the input).
std::string frame_md5s(const fs::path& video) {
  std::string out;
  std::istringstream in(capture("ffmpeg -v error -i '" + video.string() + "' -f framemd5 -"));
  for (std::string l; std::getline(in, l);)
    if (!l.empty() && l[0] != '#') out += l + "\n";
  return out;
}

}  // namespace

TEST_F(VideoRender, StreamedVideoHasEveryFrameAndNoPngs) {
  TUMBLE_NEED_GL();
  const fs::path streamed = dir_ / "streamed", png = dir_ / "png";
  Result r = run("render '" + data("tiny_render.toml") + "' -o '" + streamed.string() +
                 "' --video mp4 --frames-out none --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const std::string& n : names(streamed)) EXPECT_EQ(n.find("frame_"), std::string::npos) << n;
  EXPECT_EQ(names(streamed), (std::vector<std::string>{".tumble.lock", "manifest.json", "tiny_render.mp4"}));
  EXPECT_EQ(frame_count(streamed / "tiny_render.mp4"), "7\n");
  const std::string m = slurp(streamed / "manifest.json");
  EXPECT_NE(m.find("\"complete\": true"), std::string::npos) << m;
  EXPECT_NE(m.find("\"frames_out\": \"none\""), std::string::npos) << m;
  EXPECT_NE(m.find("\"frames_written\": 7"), std::string::npos) << m;
  // The same pixels as the PNG path: every decoded frame equal.
  r = run("render '" + data("tiny_render.toml") + "' -o '" + png.string() + "' --video mp4 --progress none");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string a = frame_md5s(streamed / "tiny_render.mp4"), b = frame_md5s(png / "tiny_render.mp4");
  EXPECT_EQ(lines(a).size(), 7u) << a;
  EXPECT_EQ(a, b);
}

// Frames finish on --jobs workers in any order but reach ffmpeg in
// order, and x264's threads follow the machine, not --jobs (+bitexact: no
// encoder version in the file), so the streamed mp4's bytes do not depend on
// --jobs. FXAA and 25 frames give the workers work to finish out of order.
TEST_F(VideoRender, StreamedVideoIsByteIdenticalWhateverTheJobs) {
  TUMBLE_NEED_GL();
  std::string video[2];
  for (int i = 0; i < 2; ++i) {
    const std::string jobs = i == 0 ? "1" : "3";
    const fs::path out = dir_ / ("jobs" + jobs);
    const Result r = run("render '" + data("tiny_render.toml") + "' -o '" + out.string() +
                         "' --video mp4 --frames-out none --progress none --aa fxaa --fps 40 --width 256 --height 192 "
                         "--jobs " + jobs);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(frame_count(out / "tiny_render.mp4"), "25\n");
    video[i] = slurp(out / "tiny_render.mp4");
  }
  ASSERT_GT(video[0].size(), 1000u);
  EXPECT_TRUE(video[0] == video[1]) << "the streamed mp4 differs between --jobs 1 and --jobs 3";
}

TEST_F(VideoRender, StreamedRenderRefusesWhatItCannotDo) {
  const std::string scene = "render '" + data("tiny_render.toml") + "' -o '" + (dir_ / "x").string() + "' --progress none ";
  Result r = run(scene + "--frames-out none --video none");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nothing to write"), std::string::npos) << r.err;
  r = run(scene + "--frames-out none --video mp4 --frames 0:2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--frames needs PNG frames"), std::string::npos) << r.err;
  r = run(scene + "--frames-out jpeg");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--frames-out: expected png or none, found 'jpeg'"), std::string::npos) << r.err;
}

TEST_F(VideoRender, StreamedRenderWithoutWorkingFfmpegExits1) {
  TUMBLE_NEED_GL();
  const std::vector<std::string> extra = {"--video", "mp4", "--frames-out", "none"};
  // Missing: nothing drawn; failing at once: the broken pipe is an error, not a crash.
  for (const std::string& path : {std::string("/nonexistent-tumble-path"),
                                  fake_ffmpeg("echo 'fake encoder failure' >&2; exit 1")}) {
    SCOPED_TRACE(path);
    const fs::path out = dir_ / (path[1] == 'n' ? "missing" : "failing");
    const pid_t pid = spawn_render(data("tiny_render.toml"), out, extra, path);
    EXPECT_EQ(wait_exit(pid), 1) << slurp(dir_ / "spawn.err");
    expect_incomplete_without_video(out);
    EXPECT_EQ(names(out), (std::vector<std::string>{".tumble.lock", "manifest.json"}));
  }
}

TEST_F(VideoRender, InterruptedStreamExits130AndLeavesNoVideo) {
  TUMBLE_NEED_GL();
  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(sig);
    const fs::path out = dir_ / ("stream" + std::to_string(sig)), mark = dir_ / ("started" + std::to_string(sig));
    // Starts a half video, reads 3 frames of 640x480 (or all there is), then
    // nothing. SIGINT: the 7 small frames fit in the pipe, tumble waits for
    // ffmpeg to finish. SIGTERM: 640x480 frames (0.9 MB) do not: a worker's
    // write blocks on the full (1 MiB) pipe while the drawing thread, not
    // the writer, catches the signal.
    const std::string path = fake_ffmpeg("for a; do last=$a; done; echo half > \"$last\"; head -c 2764800 > /dev/null; "
                                         "touch '" + mark.string() + "'; exec sleep 60");
    std::vector<std::string> extra = {"--video", "mp4", "--frames-out", "none"};
    if (sig == SIGTERM) extra.insert(extra.end(), {"--width", "640", "--height", "480"});
    const pid_t pid = spawn_render(data("tiny_render.toml"), out, extra, path);
    ASSERT_TRUE(wait_for_file(pid, mark)) << slurp(dir_ / "spawn.err");
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let the pipe fill
    ::kill(pid, sig);
    const auto t0 = std::chrono::steady_clock::now();
    EXPECT_EQ(wait_exit(pid), 128 + sig) << slurp(dir_ / "spawn.err");
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20)) << "did not stop the stream";
    expect_incomplete_without_video(out);
    EXPECT_EQ(names(out), (std::vector<std::string>{".tumble.lock", "manifest.json"})) << "a half video or frames were left";
    EXPECT_NE(slurp(dir_ / "spawn.err").find("nothing to resume"), std::string::npos) << slurp(dir_ / "spawn.err");
  }
}

TEST_F(VideoRender, AVideoFfmpegCallsDoneIsCheckedAndNeverReplacesAGoodOne) {
  TUMBLE_NEED_GL();
  // On a full disk ffmpeg failed writing the trailer, yet its
  // truncated mp4 was renamed into place and called complete.
  const fs::path out = dir_ / "o";
  ASSERT_EQ(wait_exit(spawn_render(data("tiny_render.toml"), out, {"--video", "mp4"})), 0) << slurp(dir_ / "spawn.err");
  const std::string good = slurp(out / "tiny_render.mp4");
  ASSERT_GT(good.size(), 100u);
  // An ffmpeg that writes half a video and exits 0.
  const std::string path = fake_ffmpeg("for a; do last=$a; done; /usr/bin/ffmpeg \"$@\" && head -c 300 \"$last\" > \"$last.h\" && mv \"$last.h\" \"$last\"");
  fs::remove(out / "frame_000003.png");  // so the render has work and encodes again
  const pid_t pid = spawn_render(data("tiny_render.toml"), out, {"--video", "mp4", "--resume"}, path);
  EXPECT_EQ(wait_exit(pid), 1) << slurp(dir_ / "spawn.err");
  const std::string err = slurp(dir_ / "spawn.err");
  EXPECT_NE(err.find("ffmpeg's tiny_render.mp4 failed its check ("), std::string::npos) << err;
  EXPECT_NE(err.find("the earlier video is kept"), std::string::npos) << err;
  EXPECT_EQ(slurp(out / "tiny_render.mp4"), good) << "a bad video replaced the good one";
  EXPECT_NE(slurp(out / "manifest.json").find("\"complete\": false"), std::string::npos);
  for (const std::string& n : names(out)) EXPECT_EQ(n.find(".tmp"), std::string::npos) << n;
}
