// What a viewer sees, from the layout report (no GL, no pixels).
// Every frame of each shipped explanatory scene (every scenes/*.toml with
// [[views]]) at 640×360, 960×540 and 1920×1080: Π always visible (but under
// the title card, which covers the animation on purpose), no two
// visible text boxes overlap, no text under 1.8 % of the frame height, and
// text at 1080p twice its 540p height (± 15 %), no key over a body or Π, and
// no body label on a body, and each body's or curve's name in one place for the whole run.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "compose/layout_report.hpp"
#include "scene/scene.hpp"

namespace {

namespace fs = std::filesystem;
using tumble::compose::LayoutItem;

struct Size {
  int w, h;
};
constexpr Size kSizes[] = {{640, 360}, {960, 540}, {1920, 1080}};

// The shipped scenes with laid-out views; at least the lessons' two.
std::vector<fs::path> explained_scenes() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(TUMBLE_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".toml") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    // With laid-out views, and methods_compare, the comparison grid shown in lectures.
    if (text.str().find("[[views]]") != std::string::npos || e.path().stem() == "methods_compare") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Per scene and size: every frame's layout (none for a frame that repeats the one before).
struct Layouts {
  std::vector<std::vector<LayoutItem>> frames;
};

// A frame that only repeats the one before: the title card, or a hold (the
// same simulated time) with the same captions up. Every tenth is still laid
// out, for what changes with video time alone (a badge, a caption's fade).
// Holds are half of a lesson's frames: skipping them halves the test's time.
bool repeats_the_last(const tumble::compose::FrameBuilder& fb, long k) {
  if (k == 0 || k % 10 == 0) return false;
  const tumble::scene::FrameClock& c = fb.clock();
  if (c.on_title_card(k) && c.on_title_card(k - 1)) return true;
  const auto shown = [&](long j) {
    std::vector<std::size_t> out;
    for (const auto& [i, alpha] : fb.captions_at(j)) out.push_back(i);
    return out;
  };
  return c.in_hold(k) && c.in_hold(k - 1) && c.time(k) == c.time(k - 1) && shown(k) == shown(k - 1);
}

// One scene's layouts at the given sizes.
std::map<int, Layouts> layouts_of(const tumble::scene::Scene& s, std::initializer_list<Size> sizes) {
  std::map<int, Layouts> out;
  const double fps = s.render.output.fps;
  const long count = tumble::scene::frame_clock(s, fps).count();
  const std::vector<tumble::scene::Run> runs = tumble::scene::simulate_runs(s, count, fps);
  for (const Size& z : sizes) {
    const tumble::compose::FrameBuilder fb(s, runs, fps, z.w, z.h);
    Layouts& l = out[z.h];
    for (long k = 0; k < count; ++k)
      l.frames.push_back(repeats_the_last(fb, k) ? std::vector<LayoutItem>{}
                                                 : tumble::compose::layout_items(fb.build(k), z.w, z.h));
  }
  return out;
}

const std::map<std::string, std::map<int, Layouts>>& all_layouts() {
  static const auto layouts = [] {
    std::map<std::string, std::map<int, Layouts>> out;
    for (const fs::path& p : explained_scenes())
      out[p.stem().string()] = layouts_of(tumble::scene::load_scene(p), {kSizes[0], kSizes[1], kSizes[2]});
    return out;
  }();
  return layouts;
}

bool is_text(const LayoutItem& i) { return i.kind == "text" || i.kind == "key"; }

void covers_the_shipped_scenes() {
  const auto& l = all_layouts();
  EXPECT_TRUE(l.count("dzhanibekov_explained"));
  EXPECT_TRUE(l.count("poinsot"));
  EXPECT_TRUE(l.count("tennis_racket"));
  EXPECT_TRUE(l.count("methods_compare"));
}

void momentum_point_always_visible() {
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      int hidden = 0, seen = 0;
      std::string first;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k) {
        // The title card hides the animation on purpose while it is up.
        const auto& f = layouts.frames[k];
        if (std::any_of(f.begin(), f.end(), [](const LayoutItem& i) { return i.name == "title" && i.visible; })) continue;
        for (const LayoutItem& i : f)
          if (i.name == "momentum_point") {
            ++seen;
            if (!i.visible && hidden++ == 0) first = "frame " + std::to_string(k) + " in " + i.view;
          }
      }
      EXPECT_EQ(hidden, 0) << scene << " at " << h << "p: Π hidden in " << hidden << " of " << seen
                           << " frames, first " << first;
    }
}

void no_two_visible_text_boxes_overlap() {
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      int bad = 0;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k) {
        std::vector<const LayoutItem*> texts;
        for (const LayoutItem& i : layouts.frames[k])
          if (is_text(i) && i.visible) texts.push_back(&i);
        for (std::size_t a = 0; a < texts.size(); ++a)
          for (std::size_t b = a + 1; b < texts.size(); ++b) {
            tumble::viz::Box x = texts[a]->box, y = texts[b]->box;
            // Touching is fine, but two axis labels (e₁, e₂, e₃) keep a fifth of a line apart, or they read as one.
            const bool axes = texts[a]->name.rfind("axis_label", 0) == 0 && texts[b]->name.rfind("axis_label", 0) == 0;
            const float g = axes ? 0.2f * texts[a]->size_px : -0.5f;
            x.x0 -= g, x.x1 += g, x.y0 -= g, x.y1 += g;
            if (x.overlaps(y) && bad++ < 5)
              ADD_FAILURE() << scene << " at " << h << "p frame " << k << ": \"" << texts[a]->text << "\" ("
                            << texts[a]->view << ") overlaps \"" << texts[b]->text << "\" (" << texts[b]->view << ")";
          }
      }
      EXPECT_EQ(bad, 0) << scene << " at " << h << "p";
    }
}

void every_text_at_least_1_8_percent_high() {
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      float smallest = 1e9f;
      std::string which;
      for (const auto& frame : layouts.frames)
        for (const LayoutItem& i : frame)
          if (is_text(i) && i.size_px < smallest) smallest = i.size_px, which = i.name + " \"" + i.text + "\"";
      EXPECT_GE(smallest, 0.018f * static_cast<float>(h)) << scene << " at " << h << "p: " << which;
    }
}

void text_at_1080p_twice_its_540p_height() {
  for (const auto& [scene, sizes] : all_layouts()) {
    const Layouts &small = sizes.at(540), &big = sizes.at(1080);
    if (small.frames.size() != big.frames.size()) return ADD_FAILURE() << scene << ": frame counts differ";
    // Per frame, each role (view and name) by its largest size: the same text at both sizes.
    int checked = 0;
    for (std::size_t k = 0; k < small.frames.size(); ++k) {
      std::map<std::string, float> a, b;
      for (const LayoutItem& i : small.frames[k])
        if (is_text(i)) a[i.view + "/" + i.name] = std::max(a[i.view + "/" + i.name], i.size_px);
      for (const LayoutItem& i : big.frames[k])
        if (is_text(i)) b[i.view + "/" + i.name] = std::max(b[i.view + "/" + i.name], i.size_px);
      for (const auto& [role, size] : a) {
        if (!b.count(role)) continue;
        ++checked;
        const float ratio = b[role] / size;
        EXPECT_TRUE(ratio > 1.7f && ratio < 2.3f) << scene << " frame " << k << " " << role << ": 1080p/540p = " << ratio;
        if (ratio <= 1.7f || ratio >= 2.3f) return;  // one report is enough
      }
    }
    EXPECT_GT(checked, 100) << scene;
  }
}

// A key covers nothing that matters. Each key (its lines' union, per
// view and the frame's) overlaps no body's box and no Π dot, in any frame.
void keys_cover_no_body_or_momentum_point() {
  int keys = 0;
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      int bad = 0;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k) {
        std::map<std::string, tumble::viz::Box> key;  // per view
        for (const LayoutItem& i : layouts.frames[k]) {
          if (i.kind != "key" || !i.visible) continue;
          auto [it, fresh] = key.try_emplace(i.view, i.box);
          tumble::viz::Box& b = it->second;
          if (!fresh) b = {std::min(b.x0, i.box.x0), std::min(b.y0, i.box.y0), std::max(b.x1, i.box.x1), std::max(b.y1, i.box.y1)};
        }
        keys += static_cast<int>(key.size());
        for (const auto& [view, b] : key)
          for (const LayoutItem& i : layouts.frames[k])
            if ((i.kind == "body" || i.name == "momentum_point") && i.visible && b.overlaps(i.box) && bad++ < 3)
              ADD_FAILURE() << scene << " at " << h << "p frame " << k << ": the key of " << view << " covers "
                            << i.name << " of " << i.view;
      }
      EXPECT_EQ(bad, 0) << scene << " at " << h << "p";
    }
  EXPECT_GT(keys, 1000) << "keys drawn over all frames";
}

// A body's name sits beside its body, not on it. No
// visible body label overlaps a body's box or drawn surface (its extent on
// screen; its own or another's) in its view, in any frame.
// No shipped lesson names its bodies beside them now (poinsot's views' titles
// name its boxes), so poinsot with [draw] labels = true, its body_frame view
// made a world view, gives the check its labels: two boxes named in the view
// of both, at 960×540.
void body_labels_clear_of_bodies() {
  const fs::path poinsot = fs::path(TUMBLE_SOURCE_DIR) / "scenes" / "poinsot.toml";
  std::ifstream in(poinsot);
  std::stringstream text;
  text << in.rdbuf();
  std::string labelled = text.str();
  const std::size_t at = labelled.find("\nlabels = false");
  ASSERT_NE(at, std::string::npos) << "poinsot.toml's [draw] labels = false";
  labelled.replace(at, 15, "\nlabels = true");
  // Its box's own view made a view of both boxes in space, where they are named.
  const std::string own = "kind = \"body_frame\"\nbody = \"tumbling\"\n";
  const std::size_t view = labelled.find(own);
  ASSERT_NE(view, std::string::npos) << "poinsot.toml's body_frame view of the tumbling box";
  labelled.replace(view, own.size(), "kind = \"world\"\n");
  const std::size_t camera = labelled.find("camera = { up", view);
  ASSERT_NE(camera, std::string::npos) << "poinsot.toml's body_frame camera";
  labelled.erase(camera, labelled.find('\n', camera) - camera);
  std::map<std::string, std::map<int, Layouts>> scenes = all_layouts();
  scenes["poinsot, labels = true"] = layouts_of(
      tumble::scene::load_scene_from_string(labelled, "poinsot.toml, labels = true", poinsot.parent_path()), {kSizes[1]});
  int labels = 0;
  for (const auto& [scene, sizes] : scenes)
    for (const auto& [h, layouts] : sizes) {
      int bad = 0;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k)
        for (const LayoutItem& l : layouts.frames[k]) {
          if (l.name.rfind("label:", 0) != 0 || !l.visible) continue;
          ++labels;
          for (const LayoutItem& b : layouts.frames[k])
            if ((b.kind == "body" || b.kind == "surface") && b.visible && b.view == l.view && b.box.overlaps(l.box) &&
                bad++ < 3)
              ADD_FAILURE() << scene << " at " << h << "p frame " << k << ": \"" << l.text << "\" (" << l.view
                            << ") lies on a body's box";
        }
      EXPECT_EQ(bad, 0) << scene << " at " << h << "p";
    }
  EXPECT_GT(labels, 1000) << "body labels drawn over all frames";
}

// A name placed once per run: each body's name and each curve's name
// ("polhode", "herpolhode") has one box in every frame it shows in, so it never
// jumps while the body moves (nor when the other labels settle round it).
void names_pinned_once_per_run() {
  int pinned = 0;
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      std::map<std::string, std::vector<tumble::viz::Box>> boxes;  // per view and name: each distinct box
      for (const auto& frame : layouts.frames)
        for (const LayoutItem& l : frame) {
          if (l.name.rfind("label", 0) != 0 || !l.visible) continue;
          auto& seen = boxes[l.view + " " + l.name];
          const auto same = [&](const tumble::viz::Box& b) {
            return std::abs(b.x0 - l.box.x0) < 0.01f && std::abs(b.y0 - l.box.y0) < 0.01f &&
                   std::abs(b.x1 - l.box.x1) < 0.01f && std::abs(b.y1 - l.box.y1) < 0.01f;
          };
          if (std::none_of(seen.begin(), seen.end(), same)) seen.push_back(l.box);
        }
      for (const auto& [label, seen] : boxes) {
        ++pinned;
        EXPECT_EQ(seen.size(), 1u) << scene << " at " << h << "p: " << label << " is drawn at " << seen.size()
                                   << " places over the run";
      }
    }
  // Poinsot's five: polhode, herpolhode in both boxes' views, the plane in box 2's (box 1's view, above
  // its close-up, has no room left for it); at three sizes.
  EXPECT_GE(pinned, 3 * 5) << "names checked";
}

// Layout by construction: every reported 3D item (arrow whole, marker, body
// box corners, curve points) lies inside its view's content rectangle, in
// every frame: nothing is clipped at a view's edge or reaches a title or key.
void no_3d_item_leaves_its_content() {
  int items = 0;
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      int bad = 0;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k) {
        std::map<std::string, tumble::viz::Box> content;
        for (const LayoutItem& i : layouts.frames[k])
          if (i.kind == "content") content[i.view] = i.box;
        for (const LayoutItem& i : layouts.frames[k]) {
          if (i.kind != "arrow" && i.kind != "marker" && i.kind != "body" && i.kind != "curve") continue;
          ++items;
          const tumble::viz::Box c = content.at(i.view);
          tumble::viz::Box extent = i.box;  // an arrow's whole extent, a marker's dot
          if (i.kind == "body" || i.kind == "curve") extent = {1e9f, 1e9f, -1e9f, -1e9f};
          for (const glm::vec2 p : i.path)
            extent = {std::min(extent.x0, p.x), std::min(extent.y0, p.y), std::max(extent.x1, p.x), std::max(extent.y1, p.y)};
          if (extent.x0 > extent.x1) continue;  // behind the camera
          const bool in = extent.x0 >= c.x0 - 0.5f && extent.y0 >= c.y0 - 0.5f && extent.x1 <= c.x1 + 0.5f &&
                          extent.y1 <= c.y1 + 0.5f;
          if (!in && bad++ < 5)
            ADD_FAILURE() << scene << " at " << h << "p frame " << k << ": " << i.kind << " " << i.name << " of "
                          << i.view << " reaches (" << extent.x0 << ", " << extent.y0 << ")-(" << extent.x1 << ", "
                          << extent.y1 << "), its content is (" << c.x0 << ", " << c.y0 << ")-(" << c.x1 << ", " << c.y1 << ")";
        }
      }
      EXPECT_EQ(bad, 0) << scene << " at " << h << "p";
    }
  EXPECT_GT(items, 10000) << "3D items checked over all frames";
}

// Does segment a-b, thickened by `r` px, cross box `b`?
bool segment_hits(glm::vec2 a, glm::vec2 e, float r, const tumble::viz::Box& b) {
  constexpr int kSteps = 24;
  for (int s = 0; s <= kSteps; ++s) {
    const glm::vec2 p = a + (e - a) * (static_cast<float>(s) / kSteps);
    if (p.x + r > b.x0 && p.x - r < b.x1 && p.y + r > b.y0 && p.y - r < b.y1) return true;
  }
  return false;
}

// Text and 3D content never share pixels: no visible text box (titles,
// overlay, keys, labels, captions) overlaps an arrow (along its shaft), a
// marker, a body's box or a named curve of any view, in any frame.
void no_text_on_a_3d_item() {
  for (const auto& [scene, sizes] : all_layouts())
    for (const auto& [h, layouts] : sizes) {
      int bad = 0;
      for (std::size_t k = 0; k < layouts.frames.size(); ++k) {
        const auto& f = layouts.frames[k];
        for (const LayoutItem& t : f) {
          if (!is_text(t) || !t.visible) continue;
          for (const LayoutItem& i : f) {
            if (!i.visible || (i.kind != "arrow" && i.kind != "marker" && i.kind != "body" && i.kind != "curve")) continue;
            bool hit = false;
            if (i.kind == "marker" || i.kind == "body") hit = t.box.overlaps(i.box);
            for (std::size_t j = 1; !hit && j < i.path.size() && i.kind != "body"; ++j)
              hit = segment_hits(i.path[j - 1], i.path[j], i.kind == "arrow" ? 2.0f : 1.0f, t.box);
            if (hit && bad++ < 5)
              ADD_FAILURE() << scene << " at " << h << "p frame " << k << ": \"" << t.text << "\" (" << t.view
                            << ") lies on " << i.kind << " " << i.name << " of " << i.view;
          }
        }
      }
      EXPECT_EQ(bad, 0) << scene << " at " << h << "p";
    }
}

// One test: ctest runs each test in its own process, and the layouts (every
// frame of every scene at three sizes, a few seconds) are made once.
TEST(Layout, ShippedExplanatoryScenesReadAsAViewerNeeds) {
  covers_the_shipped_scenes();
  momentum_point_always_visible();
  no_two_visible_text_boxes_overlap();
  every_text_at_least_1_8_percent_high();
  text_at_1080p_twice_its_540p_height();
  keys_cover_no_body_or_momentum_point();
  body_labels_clear_of_bodies();
  names_pinned_once_per_run();
  no_3d_item_leaves_its_content();
  no_text_on_a_3d_item();
}

}  // namespace
