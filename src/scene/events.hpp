// Times anchored to events of the simulated motion: a caption's or
// slow-motion segment's `start`/`end` may be "flip N", "flip N + S" or
// "flip N - S" instead of simulated seconds, so the text stays on the flip
// when a user edits ω. Flip N is the N-th sign change of the body's Π₂
// (core/flip_events.hpp), found once at load.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tumble::scene {

struct Scene;

/// A parsed time: `flip` = 0 for plain simulated seconds (`offset`), else
/// the flip's index (1-based) and a signed offset in simulated s.
struct EventTime {
  int flip = 0;
  double offset = 0;
};

/// Parses "flip N", "flip N + S", "flip N - S" (N ≥ 1, S ≥ 0 in decimal or
/// exponent notation, spaces optional around the sign); nullopt otherwise.
std::optional<EventTime> parse_event_time(std::string_view text);

/// Flip times (simulated s, ascending) of body `body` over the scene's duration,
/// stepped as the body's own run would be (closed form when torque-free).
std::vector<double> body_flip_times(const Scene& s, std::size_t body);

/// The form a scene file accepts, for error messages.
inline constexpr const char* kEventTimeForms =
    "simulated seconds (a number) or \"flip N\", \"flip N + S\", \"flip N - S\" (N = 1, 2, …; S in s)";

}  // namespace tumble::scene
