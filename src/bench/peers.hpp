// Optional peers: the engines users would otherwise pick (Bullet, ODE), run on
// the T-handle. Each lives in its own file behind #if; absent ones report so.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "bench/studies.hpp"

namespace tumble::bench {

/// "bullet 3.24 (double)", ... or empty.
std::vector<std::string> peers_found();
/// One markdown bullet per peer configuration: what was set and why.
std::string peer_settings_markdown();
/// Work-precision rows (problem "t_handle", method = peer label) over a dt sweep.
std::vector<WpRow> peer_work_precision(const Problem& t_handle, const Settings& st, std::ostream& log);

// Per-engine entry points (defined only when the engine was found): the
// configuration labels, and one run to p.duration at step dt (s).
std::vector<std::string> bullet_labels();
BodyState bullet_run(const std::string& label, const Problem& p, double dt);
std::vector<std::string> ode_labels();
BodyState ode_run(const std::string& label, const Problem& p, double dt);

}  // namespace tumble::bench
