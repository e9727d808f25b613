#include "scene/events.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "core/flip_events.hpp"
#include "scene/scene.hpp"

namespace tumble::scene {

namespace {

void skip_spaces(std::string_view& s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
}

}  // namespace

std::optional<EventTime> parse_event_time(std::string_view s) {
  skip_spaces(s);
  if (s.substr(0, 4) != "flip") return std::nullopt;
  s.remove_prefix(4);
  if (s.empty() || (s.front() != ' ' && s.front() != '\t')) return std::nullopt;
  skip_spaces(s);
  EventTime e;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), e.flip);
  if (ec != std::errc() || e.flip < 1 || end == s.data()) return std::nullopt;
  s.remove_prefix(static_cast<std::size_t>(end - s.data()));
  skip_spaces(s);
  if (s.empty()) return e;
  const char sign = s.front();
  if (sign != '+' && sign != '-') return std::nullopt;
  s.remove_prefix(1);
  skip_spaces(s);
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s.front())) || s.front() == '.')) return std::nullopt;
  double v = 0;
  const auto [end2, ec2] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec2 != std::errc() || !std::isfinite(v)) return std::nullopt;
  s.remove_prefix(static_cast<std::size_t>(end2 - s.data()));
  skip_spaces(s);
  if (!s.empty()) return std::nullopt;
  e.offset = sign == '-' ? -v : v;
  return e;
}

std::vector<double> body_flip_times(const Scene& s, std::size_t body) {
  const Body& b = s.bodies.at(body);
  return flip_times(b.model, b.initial, step_config(s.simulation, b.model), s.simulation.duration);
}

}  // namespace tumble::scene
