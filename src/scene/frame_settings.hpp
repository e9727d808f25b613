// How frames are made, whatever asks for them (a scene's [output], `tumble
// render`'s options, a golden case, a manifest, the settings hash): size,
// anti-aliasing, MSAA samples, quality, video format and CRF, each named in
// one table and checked in one place.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tumble::scene {

enum class VideoFormat { mp4, gif, none };

/// Everything tumble knows of a video format, in one row: the reader, the
/// pipeline (file name, ffmpeg, ffprobe's check) and the manifest read it.
struct VideoFormatRow {
  VideoFormat value;
  std::string_view name;    ///< scene key `video`, --video, the manifest's video_format; ffmpeg's muxer (-f)
  std::string_view suffix;  ///< of the video file, "<scene name>.mp4"; "" for none
  bool every_frame;         ///< ffprobe must count every frame (GIF merges repeats: 1..frames)
  bool h264;                ///< encoded by the H.264 encoder (run::VideoEncoder: codec, CRF, preset)
  std::string_view filter;  ///< ffmpeg's -vf
  std::string_view flags;   ///< ffmpeg's output options after the encoder's, before -f (space-separated)
};

/// How frame edges are anti-aliased: FXAA (a post pass, one sample a pixel,
/// smooth lines), MSAA with `FrameSettings::msaa` samples, or not at all.
enum class Antialias { fxaa, msaa, none };

/// `tumble render --quality`: caps MSAA samples (0: no anti-aliasing at all)
/// and sets the video's H.264 CRF. FXAA costs about as much as none, so
/// medium and high keep a scene's fxaa.
enum class Quality { low, medium, high };

inline constexpr int kMinFramePx = 16, kMaxFramePx = 16384;  ///< width and height, px

struct FrameSettings {
  int width = 1280, height = 720;  ///< px, kMinFramePx..kMaxFramePx
  /// Scene key `aa`; without it, a scene's `msaa` key picks msaa (2, 4) or none (0).
  Antialias aa = Antialias::fxaa;
  int msaa = 4;                    ///< 0, 2 or 4 samples (used when aa = msaa)
  Quality quality = Quality::high;
  VideoFormat video = VideoFormat::mp4;

  /// MSAA samples the renderer is asked for (0 unless aa is msaa).
  int samples() const { return aa == Antialias::msaa ? msaa : 0; }
  bool fxaa() const { return aa == Antialias::fxaa; }
  /// The anti-aliasing case: "fxaa", "msaa2", "msaa4", or "msaa0" for none (golden file names).
  std::string aa_case() const;
  int crf() const;  ///< the video's H.264 CRF, from the quality
  /// Sets the quality and applies its cap on anti-aliasing (unless `keep_aa`: --aa or --msaa given).
  void apply_quality(Quality q, bool keep_aa);
};

/// The name tables: every spelling of these settings comes from here.
std::string_view antialias_name(Antialias a);  ///< "fxaa", "msaa", "none"
std::string_view video_format_name(VideoFormat f);  ///< "mp4", "gif", "none"
std::span<const VideoFormatRow> video_formats();     ///< one row per format, mp4 first
const VideoFormatRow& video_format(VideoFormat f);
std::string_view quality_name(Quality q);  ///< "low", "medium", "high"
std::optional<Antialias> parse_antialias(std::string_view s);
std::optional<VideoFormat> parse_video_format(std::string_view s);
std::optional<Quality> parse_quality(std::string_view s);
/// The names a table accepts for messages: "mp4, gif or none" (`quote` '"': "\"mp4\", \"gif\" or \"none\"").
std::string antialias_choices(char quote = 0);
std::string video_format_choices(char quote = 0);
std::string quality_choices(char quote = 0);

/// An anti-aliasing case by name (FrameSettings::aa_case, also "none" for
/// msaa0): sets `aa` and `msaa` of `f`. False for an unknown name.
bool parse_aa_case(std::string_view s, FrameSettings& f);
std::string aa_case_choices();  ///< "fxaa, none, msaa0, msaa2 or msaa4"
/// Whether `n` is an MSAA sample count the renderer takes (0, 2 or 4).
bool valid_msaa_samples(long long n);

}  // namespace tumble::scene
