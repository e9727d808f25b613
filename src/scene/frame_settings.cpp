#include "scene/frame_settings.hpp"

#include <algorithm>

namespace tumble::scene {

namespace {

template <class E>
struct Name {
  E value;
  std::string_view name;
};

constexpr Name<Antialias> kAntialias[] = {{Antialias::fxaa, "fxaa"}, {Antialias::msaa, "msaa"}, {Antialias::none, "none"}};
// yuv420p needs even sizes; +faststart puts the index first for streaming.
// +bitexact (no encoder version in the file): the same frames give the same bytes.
constexpr VideoFormatRow kVideoFormats[] = {
    {.value = VideoFormat::mp4, .name = "mp4", .suffix = ".mp4", .every_frame = true, .h264 = true,
     .filter = "pad=ceil(iw/2)*2:ceil(ih/2)*2", .flags = "-fflags +bitexact -flags:v +bitexact -movflags +faststart"},
    {.value = VideoFormat::gif, .name = "gif", .suffix = ".gif", .every_frame = false, .h264 = false,
     .filter = "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", .flags = "-fflags +bitexact"},
    {.value = VideoFormat::none, .name = "none", .suffix = "", .every_frame = false, .h264 = false, .filter = "", .flags = ""}};

/// --quality: the MSAA cap (0: no anti-aliasing) and the CRF of each level.
struct QualityRow {
  Quality value;
  std::string_view name;
  int msaa_cap, crf;
};
constexpr QualityRow kQualities[] = {{Quality::low, "low", 0, 28}, {Quality::medium, "medium", 2, 23},
                                     {Quality::high, "high", 4, 18}};

/// Anti-aliasing cases (golden names). `alias` rows are read, never written.
struct AaCase {
  std::string_view name;
  Antialias aa;
  int samples;
  bool alias = false;
};
constexpr AaCase kAaCases[] = {{"fxaa", Antialias::fxaa, 0},
                               {"none", Antialias::none, 0, true},
                               {"msaa0", Antialias::none, 0},
                               {"msaa2", Antialias::msaa, 2},
                               {"msaa4", Antialias::msaa, 4}};
constexpr int kMsaaSamples[] = {0, 2, 4};

template <class Row, std::size_t N, class E>
std::string_view name_of(const Row (&table)[N], E v) {
  for (const Row& r : table)
    if (r.value == v) return r.name;
  return "?";
}

template <class Row, std::size_t N>
auto parse_name(const Row (&table)[N], std::string_view s) -> std::optional<decltype(Row::value)> {
  for (const Row& r : table)
    if (r.name == s) return r.value;
  return std::nullopt;
}

/// "a, b or c", each name in `quote` (none when 0).
template <class Row, std::size_t N>
std::string choices(const Row (&table)[N], char quote) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += i + 1 == N ? " or " : ", ";
    if (quote) out += quote;
    out += table[i].name;
    if (quote) out += quote;
  }
  return out;
}

const QualityRow& quality_row(Quality q) {
  return *std::find_if(std::begin(kQualities), std::end(kQualities), [&](const QualityRow& r) { return r.value == q; });
}

}  // namespace

std::string FrameSettings::aa_case() const {
  for (const AaCase& c : kAaCases)
    if (!c.alias && c.aa == aa && c.samples == samples()) return std::string(c.name);
  return "msaa" + std::to_string(samples());
}

int FrameSettings::crf() const { return quality_row(quality).crf; }

void FrameSettings::apply_quality(Quality q, bool keep_aa) {
  quality = q;
  if (keep_aa) return;
  const int cap = quality_row(q).msaa_cap;
  if (cap == 0) aa = Antialias::none;
  msaa = std::min(msaa, cap);
}

std::string_view antialias_name(Antialias a) { return name_of(kAntialias, a); }
std::string_view video_format_name(VideoFormat f) { return name_of(kVideoFormats, f); }
std::span<const VideoFormatRow> video_formats() { return kVideoFormats; }
const VideoFormatRow& video_format(VideoFormat f) {
  return *std::find_if(std::begin(kVideoFormats), std::end(kVideoFormats), [&](const VideoFormatRow& r) { return r.value == f; });
}
std::string_view quality_name(Quality q) { return name_of(kQualities, q); }
std::optional<Antialias> parse_antialias(std::string_view s) { return parse_name(kAntialias, s); }
std::optional<VideoFormat> parse_video_format(std::string_view s) { return parse_name(kVideoFormats, s); }
std::optional<Quality> parse_quality(std::string_view s) { return parse_name(kQualities, s); }
std::string antialias_choices(char quote) { return choices(kAntialias, quote); }
std::string video_format_choices(char quote) { return choices(kVideoFormats, quote); }
std::string quality_choices(char quote) { return choices(kQualities, quote); }

bool parse_aa_case(std::string_view s, FrameSettings& f) {
  for (const AaCase& c : kAaCases)
    if (c.name == s) {
      f.aa = c.aa;
      if (c.aa == Antialias::msaa) f.msaa = c.samples;
      return true;
    }
  return false;
}

std::string aa_case_choices() { return choices(kAaCases, 0); }

bool valid_msaa_samples(long long n) {
  return std::find(std::begin(kMsaaSamples), std::end(kMsaaSamples), n) != std::end(kMsaaSamples);
}

}  // namespace tumble::scene
