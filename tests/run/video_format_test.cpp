// A video format's row (scene::video_formats) is what the pipeline reads:
// its file name, ffmpeg's arguments and the stale-temp rule follow the row.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "run/render_output.hpp"
#include "run/video.hpp"

namespace tumble::run {
namespace {

using scene::VideoFormat;

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) s += (s.empty() ? "" : " ") + a;
  return s;
}

// The whole command tail, as written before the formats were a table.
TEST(VideoFormatRow, FfmpegArgumentsPerFormat) {
  const VideoEncoder x264{"libx264", "ultrafast", 1};
  EXPECT_EQ(joined(ffmpeg_output_args(VideoFormat::mp4, 18, "d/v.tmp", x264)),
            "-vf pad=ceil(iw/2)*2:ceil(ih/2)*2 -c:v libx264 -pix_fmt yuv420p -crf 18 -threads 1 -preset ultrafast "
            "-fflags +bitexact -flags:v +bitexact -movflags +faststart -f mp4 d/v.tmp");
  const VideoEncoder nvenc{"h264_nvenc", "p4", 0};
  EXPECT_EQ(joined(ffmpeg_output_args(VideoFormat::mp4, 23, "v.tmp", nvenc)),
            "-vf pad=ceil(iw/2)*2:ceil(ih/2)*2 -c:v h264_nvenc -pix_fmt yuv420p -rc vbr -b:v 0 -cq 23 -preset p4 "
            "-fflags +bitexact -flags:v +bitexact -movflags +faststart -f mp4 v.tmp");
  EXPECT_EQ(joined(ffmpeg_output_args(VideoFormat::gif, 18, "v.tmp", x264)),
            "-vf split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer -fflags +bitexact "
            "-f gif v.tmp");
}

TEST(VideoFormatRow, EveryFormatHasOneRowNamingItsFile) {
  std::vector<std::string> names;
  for (const scene::VideoFormatRow& r : scene::video_formats()) {
    EXPECT_EQ(&scene::video_format(r.value), &r);
    EXPECT_EQ(scene::video_format_name(r.value), r.name);
    names.emplace_back(r.name);
    if (r.value == VideoFormat::none) continue;
    EXPECT_EQ(video_file_name("spin", r.value), "spin" + std::string(r.suffix));
    EXPECT_TRUE(is_stale_temp("spin" + std::string(r.suffix) + ".tmp-12")) << r.name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"mp4", "gif", "none"}));
  EXPECT_EQ(video_file_name("spin", VideoFormat::mp4), "spin.mp4");
  EXPECT_EQ(video_file_name("spin", VideoFormat::gif), "spin.gif");
  EXPECT_TRUE(scene::video_format(VideoFormat::mp4).every_frame);   // H.264 keeps every frame
  EXPECT_FALSE(scene::video_format(VideoFormat::gif).every_frame);  // GIF merges repeats
  EXPECT_FALSE(is_stale_temp("spin.webm.tmp-12-3"));
}

}  // namespace
}  // namespace tumble::run
