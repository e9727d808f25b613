// One table of frame settings' names (scene/frame_settings.hpp): what the
// scene reader, the CLI, golden and the manifest all spell.
#include <gtest/gtest.h>

#include "scene/frame_settings.hpp"

namespace {

using tumble::scene::Antialias;
using tumble::scene::FrameSettings;

FrameSettings aa_case(const char* name) {
  FrameSettings f;
  EXPECT_TRUE(tumble::scene::parse_aa_case(name, f)) << name;
  return f;
}

}  // namespace

// The anti-aliasing cases of `tumble golden --aa` and their file names.
TEST(FrameSettings, ParsesAndNamesEveryAaCase) {
  const FrameSettings fx = aa_case("fxaa");
  EXPECT_TRUE(fx.fxaa());
  EXPECT_EQ(fx.samples(), 0);
  EXPECT_EQ(fx.aa_case(), "fxaa");
  const FrameSettings m4 = aa_case("msaa4");
  EXPECT_EQ(m4.aa, Antialias::msaa);
  EXPECT_EQ(m4.samples(), 4);
  EXPECT_EQ(m4.aa_case(), "msaa4");
  EXPECT_EQ(aa_case("msaa2").samples(), 2);
  // none is the old msaa0: its goldens keep their names.
  EXPECT_EQ(aa_case("none").aa_case(), "msaa0");
  EXPECT_EQ(aa_case("msaa0").aa, Antialias::none);
  // A scene's msaa count does not leak into fxaa or none.
  EXPECT_EQ((FrameSettings{.aa = Antialias::fxaa, .msaa = 4}.samples()), 0);
  EXPECT_EQ((FrameSettings{.aa = Antialias::none, .msaa = 4}.aa_case()), "msaa0");
  for (const char* bad : {"msaa3", "smaa", "", "FXAA", "msaa"}) {
    FrameSettings f;
    EXPECT_FALSE(tumble::scene::parse_aa_case(bad, f)) << bad;
  }
  EXPECT_EQ(tumble::scene::aa_case_choices(), "fxaa, none, msaa0, msaa2 or msaa4");
}

// Every name reads back as its value; the messages list the table.
TEST(FrameSettings, NamesRoundTripAndListTheirChoices) {
  using namespace tumble::scene;
  for (VideoFormat f : {VideoFormat::mp4, VideoFormat::gif, VideoFormat::none})
    EXPECT_EQ(parse_video_format(video_format_name(f)), f);
  for (Antialias a : {Antialias::fxaa, Antialias::msaa, Antialias::none})
    EXPECT_EQ(parse_antialias(antialias_name(a)), a);
  for (Quality q : {Quality::low, Quality::medium, Quality::high}) EXPECT_EQ(parse_quality(quality_name(q)), q);
  EXPECT_FALSE(parse_video_format("webm"));
  EXPECT_EQ(video_format_choices(), "mp4, gif or none");
  EXPECT_EQ(video_format_choices('"'), "\"mp4\", \"gif\" or \"none\"");
  EXPECT_EQ(quality_choices(), "low, medium or high");
}

// --quality: low drops anti-aliasing, medium caps MSAA at 2 and keeps fxaa;
// each sets the CRF; an explicit --aa/--msaa keeps the scene's anti-aliasing.
TEST(FrameSettings, QualityCapsAntiAliasingAndSetsTheCrf) {
  using tumble::scene::Quality;
  FrameSettings f{.aa = Antialias::msaa, .msaa = 4};
  f.apply_quality(Quality::medium, false);
  EXPECT_EQ(f.samples(), 2);
  EXPECT_EQ(f.crf(), 23);
  f.apply_quality(Quality::low, false);
  EXPECT_EQ(f.aa, Antialias::none);
  EXPECT_EQ(f.crf(), 28);
  FrameSettings kept{.aa = Antialias::msaa, .msaa = 4};
  kept.apply_quality(Quality::low, true);
  EXPECT_EQ(kept.samples(), 4);
  EXPECT_EQ(kept.crf(), 28);
  FrameSettings fx;
  fx.apply_quality(Quality::medium, false);
  EXPECT_TRUE(fx.fxaa());
  EXPECT_EQ(FrameSettings{}.crf(), 18);  // high
}
