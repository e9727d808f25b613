// Readout items: the frame's overlay ([draw] overlay) and a world view's own
// readout of its body (`readout`), from one list of names; a view's `until`.
#include <array>
#include <string>
#include <utility>

#include "scene/internal.hpp"

namespace tumble::scene::detail {

namespace {

// One row per item: its name and its switch.
constexpr std::pair<const char*, bool OverlayItems::*> kItems[] = {
    {"time", &OverlayItems::time},   {"method", &OverlayItems::method}, {"step", &OverlayItems::step},
    {"energy", &OverlayItems::energy}, {"state", &OverlayItems::state}, {"angle", &OverlayItems::angle},
    {"e1_angle", &OverlayItems::e1_angle}, {"e2_angle", &OverlayItems::e2_angle}, {"e3_angle", &OverlayItems::e3_angle}};

constexpr const char* kViewItems = "\"time\", \"state\", \"angle\", \"e1_angle\", \"e2_angle\", \"e3_angle\"";

std::string item_list() {
  std::string out;
  for (const auto& [name, member] : kItems) out += std::string(out.empty() ? "\"" : ", \"") + name + "\"";
  return out;
}

}  // namespace

std::optional<OverlayItems> read_overlay_items(TableReader& r, std::string_view key) {
  const toml::node* n = r.node(key);
  if (!n || !n->is_array()) return std::nullopt;
  OverlayItems items{false, false, false, false, false, false};
  for (const std::string& item : r.strings(key).value_or(std::vector<std::string>{})) {
    bool known = false;
    for (const auto& [name, member] : kItems)
      if (item == name) items.*member = true, known = true;
    if (!known) r.error(key, "expected items from " + item_list() + ", found " + quote_token(item));
  }
  return items;
}

// A view's own readout is of its body alone: the time and that body's state
// and angles (the energy error, method and step are the frame's, of every body).
void read_view_readout(TableReader& r, const Scene& s, std::size_t body, ViewConfig& v) {
  v.until = read_time(r, "until", s, body).value_or(1e300);
  if (r.has("until") && !(v.until > v.appear)) r.error("until", "expected a time after the view's appear");
  if (!r.has("readout")) return;
  if (v.kind != ViewKind::world || v.body.empty()) {
    r.error("readout", "only a world view of one body (with `body`) has its own readout");
    return;
  }
  const auto items = read_overlay_items(r, "readout");
  if (!items) {
    r.error("readout", std::string("expected a list of items from ") + kViewItems);
    return;
  }
  if (items->method || items->step || items->energy)
    r.error("readout", std::string("a view's readout shows its own body's ") + kViewItems +
                           "; method, step and energy are the frame's overlay");
  else v.readout = items;
}

}  // namespace tumble::scene::detail
