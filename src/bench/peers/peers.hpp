// The registry of peers (peer.hpp): the engines in a fixed order, run next to
// tumble's own methods. Each engine describes itself in its own file; Bullet
// and ODE sit behind #if there (odeint ships with Boost).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "bench/peers/peer.hpp"
#include "bench/studies.hpp"

namespace tumble::bench {

/// Every compiled-in peer configuration, odeint first.
std::vector<PeerConfig> peer_configs();

/// Something that steps at a fixed h: every tumble method, then every peer.
struct Contender {
  std::string name;
  MakeStepper make;
};
std::vector<Contender> stepped_contenders();

/// "Boost.odeint 1.81 (header-only)", "Bullet 3.24 (double)", ...
std::vector<std::string> peers_found();
/// One markdown bullet per engine: what was set and why.
std::string peer_settings_markdown();
/// Work-precision rows of every peer configuration that runs p (forced
/// problems: those with PeerConfig::forces), over a dt or rtol sweep.
std::vector<WpRow> peer_work_precision(const Problem& p, const Settings& st, std::ostream& log);

}  // namespace tumble::bench
