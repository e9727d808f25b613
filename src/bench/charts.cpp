#include "bench/charts.hpp"

#include "bench/peers/peers.hpp"

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <map>
#include <sstream>

namespace tumble::bench {

namespace {

// Curves as gnuplot data blocks (separated by two blank lines, addressed by
// `index`), in first-seen order, plus the space-separated list of their names.
struct Blocks {
  std::vector<std::string> names;
  std::map<std::string, std::string> data;
  void add(const std::string& name, const std::string& line) {
    if (!data.count(name)) names.push_back(name);
    data[name] += line + "\n";
  }
  std::string text() const {
    std::string s;
    for (const auto& n : names) s += "# " + n + "\n" + data.at(n) + "\n\n";
    return s;
  }
  std::string words() const {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
    return s;
  }
};

std::string num(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

// Zero errors cannot sit on a log axis: draw them at the floor (noted on the chart).
double floor_log(double v) { return v > 1e-17 ? v : 1e-17; }

// 24 distinct colours; peers (Boost.odeint, Bullet, ODE) are drawn dashed.
std::string linetypes() {
  static const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                  "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#000080", "#ff1493",
                                  "#556b2f", "#b8860b", "#00ced1", "#8b0000", "#4b0082", "#2f4f4f",
                                  "#ff4500", "#006400", "#a0522d", "#708090", "#c71585", "#000000"};
  std::string s;
  for (int i = 0; i < 24; ++i)
    s += "set linetype " + std::to_string(i + 1) + " lc rgb '" + colours[i] + "' pt " + std::to_string(i % 13 + 1) +
         " lw 1.5\n";
  return s;
}

const std::string kHeader =
    "set terminal pngcairo size 1500,650 font 'sans,11'\n"
    "set grid\nset key outside right top spacing 1.1\n"
    "set style data linespoints\nset pointsize 0.8\n"
    "set format y '10^{%L}'\nset format x '10^{%L}'\nset logscale xy\n" +
    linetypes();

bool is_peer(const std::string& curve) {
  static const std::vector<std::string> labels = [] {
    std::vector<std::string> v;
    for (const PeerConfig& c : peer_configs()) v.push_back(c.label);
    return v;
  }();
  for (const std::string& l : labels)
    if (curve.rfind(l, 0) == 0) return true;
  return false;
}

// Writes NAME.dat and NAME.gp into dir and runs gnuplot there.
std::vector<std::filesystem::path> draw(const std::filesystem::path& dir, const std::string& name,
                                        const std::string& dat, const std::string& gp, std::ostream& log) {
  write_text(dir / (name + ".dat"), dat);
  write_text(dir / (name + ".gp"), "set output '" + name + ".png'\n" + gp);
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + name + ".gp' 2> '" + name + ".gnuplot.log'";
  if (std::system(cmd.c_str()) != 0) {
    log << "  gnuplot failed on " << name << ".gp (see " << name << ".gnuplot.log)\n";
    return {};
  }
  std::error_code ec;
  std::filesystem::remove(dir / (name + ".gnuplot.log"), ec);
  return {dir / (name + ".png")};
}

// One curve per block, each with its own linetype (dashed for peers).
std::string plot_blocks(const std::string& file, const Blocks& b, const std::string& cols) {
  std::string s = "plot ";
  for (size_t i = 0; i < b.names.size(); ++i)
    s += std::string(i ? ", \\\n  " : "") + "'" + file + "' index " + std::to_string(i) + " using " + cols + " lt " +
         std::to_string(i % 24 + 1) + (is_peer(b.names[i]) ? " dt 2" : " dt 1") + " title '" + b.names[i] +
         "' noenhanced";
  return s + "\n";
}

}  // namespace

bool gnuplot_available() { return std::system("gnuplot --version > /dev/null 2>&1") == 0; }

std::vector<std::filesystem::path> chart_work_precision(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                        std::ostream& log) {
  std::map<std::string, Blocks> per_problem;
  for (const WpRow& r : rows)
    if (std::isfinite(r.cpu_s) && std::isfinite(r.angle))
      per_problem[r.problem].add(r.method, num(r.cpu_s) + " " + num(floor_log(r.angle)) + " " +
                                               num(floor_log(r.energy)) + " " + num(r.param));
  std::vector<std::filesystem::path> out;
  for (const auto& [problem, b] : per_problem) {
    const std::string name = "work_precision_" + problem, dat = name + ".dat";
    std::string gp = std::string(kHeader) + "set multiplot layout 1,2 title 'Work-precision: " + problem +
                     " (error at the end of the run; peers dashed; lower-left is better; errors of 0 drawn at 1e-17)' noenhanced\n";
    gp += "set xlabel 'CPU time per run (s)'\nset ylabel 'orientation error (rad)'\nunset key\n";
    gp += plot_blocks(dat, b, "1:2");
    gp += "set ylabel 'relative energy error |E-E_{ref}|/E_{ref}'\nset key outside right top noenhanced\n";
    gp += plot_blocks(dat, b, "1:3") + "unset multiplot\n";
    auto png = draw(dir, name, b.text(), gp, log);
    out.insert(out.end(), png.begin(), png.end());
  }
  return out;
}

std::vector<std::filesystem::path> chart_convergence(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                     const std::vector<OrderFit>& fits, std::ostream& log) {
  std::map<std::pair<std::string, std::string>, std::string> label;
  for (const OrderFit& f : fits) {
    std::ostringstream o;
    o.precision(2);
    o << std::fixed << f.method << "_(order_" << f.order_angle << ")";
    label[{f.problem, f.method}] = std::isfinite(f.order_angle) ? o.str() : f.method + "_(round-off)";
  }
  std::map<std::string, Blocks> per_problem;
  for (const WpRow& r : rows)
    if (r.param_name == "dt" && std::isfinite(r.angle))
      per_problem[r.problem].add(label[{r.problem, r.method}],
                                 num(r.param) + " " + num(floor_log(r.angle)) + " " + num(floor_log(r.energy)));
  std::vector<std::filesystem::path> out;
  for (const auto& [problem, b] : per_problem) {
    const std::string name = "convergence_" + problem;
    std::string gp = std::string(kHeader) + "set multiplot layout 1,2 title 'Convergence: " + problem +
                     " (fitted slope over errors in (1e-11, 1e-2) printed in the key)' noenhanced\n";
    gp += "set xlabel 'step dt (s)'\nset ylabel 'orientation error at the end (rad)'\nunset key\n";
    gp += plot_blocks(name + ".dat", b, "1:2");
    gp += "set ylabel 'relative energy error at the end'\nset key outside right top noenhanced\n";
    gp += plot_blocks(name + ".dat", b, "1:3") + "unset multiplot\n";
    auto png = draw(dir, name, b.text(), gp, log);
    out.insert(out.end(), png.begin(), png.end());
  }
  return out;
}

std::vector<std::filesystem::path> chart_stability(const std::filesystem::path& dir,
                                                   const std::vector<StabilityRow>& rows, std::ostream& log) {
  // Cells as boxes spanning half a grid step either side on log axes.
  // Half grid steps: the smallest ratio between neighbouring dt (spin) values.
  double fx = 1e300, fy = 1e300;
  for (const StabilityRow& a : rows)
    for (const StabilityRow& c : rows) {
      if (c.dt > a.dt * 1.001) fx = std::min(fx, std::sqrt(c.dt / a.dt));
      if (c.spin > a.spin * 1.001) fy = std::min(fy, std::sqrt(c.spin / a.spin));
    }
  if (fx > 1e299) fx = 2;
  if (fy > 1e299) fy = 2;
  Blocks b;
  for (const StabilityRow& r : rows) {
    b.add(r.method, num(r.dt) + " " + num(r.spin) + " " + num(r.dt / fx) + " " + num(r.dt * fx) + " " +
                        num(r.spin / fy) + " " + num(r.spin * fy) + " " + std::to_string(static_cast<int>(r.cell)));
  }
  const size_t panel_cols = b.names.size() > 8 ? 6 : 4, panel_rows = (b.names.size() + panel_cols - 1) / panel_cols;
  std::string gp =
      "set terminal pngcairo size " + std::to_string(panel_cols * 400 + 200) + "," + std::to_string(panel_rows * 420 + 60) +
      " font 'sans,11'\nset logscale xy\nset format x '10^{%L}'\n"
      "set cbrange [-0.5:3.5]\nset palette maxcolors 4\n"
      "set palette defined (0 '#2ca02c', 1 '#f2c80f', 2 '#ff7f0e', 3 '#d62728')\n"
      "set cbtics ('ok' 0, 'inaccurate (>1%%)' 1, 'wrong (flips/axis)' 2, 'diverged' 3)\nunset key\n"
      "set xrange [3e-5:1]\nset yrange [0.5:200]\n"
      "set xlabel 'step dt (s)'\nset ylabel 'spin rate {/Symbol W} (rad/s)'\nset style fill solid 1.0 border lc 'white'\n"
      "set multiplot layout " + std::to_string(panel_rows) + "," + std::to_string(panel_cols) +
      " margins 0.04,0.9,0.06,0.93 spacing 0.045,0.1 title 'Stability map: T-handle (moments 1, 2, 3 kg m^2) spun at {/Symbol W} about "
      "the intermediate axis (flip count, error at about 10 s) and the major/minor axes (tip-over)'\n";
  for (size_t i = 0; i < b.names.size(); ++i) {
    gp += "set title '" + b.names[i] + "' noenhanced\n";
    // The colour key sits in the right margin, so every panel keeps its size.
    gp += i + 1 == b.names.size() ? "set colorbox user origin screen 0.915, screen 0.3 size screen 0.012, screen 0.4\n"
                                  : "unset colorbox\n";
    gp += "plot 'stability_map.dat' index " + std::to_string(i) + " using 1:2:3:4:5:6:7 with boxxyerror lc palette\n";
  }
  gp += "unset multiplot\n";
  return draw(dir, "stability_map", b.text(), gp, log);
}

std::vector<std::filesystem::path> chart_drift(const std::filesystem::path& dir, const std::vector<DriftRow>& rows,
                                               std::ostream& log) {
  Blocks b;
  for (const DriftRow& r : rows)
    if (std::isfinite(r.energy))
      b.add(r.method, std::to_string(r.step) + " " + num(floor_log(r.energy)) + " " + num(floor_log(r.momentum)));
  std::string gp = std::string(kHeader) +
                   "set multiplot layout 1,2 title 'Long-run drift: T-handle, dt = 1 ms (zeros drawn at 10^{-17})'\n"
                   "set xlabel 'steps'\nset ylabel 'relative energy error |E-E_0|/E_0'\nunset key\n";
  gp += plot_blocks("drift.dat", b, "1:2");
  gp += "set ylabel 'relative error of |{/Symbol P}| = |q^* L q| (|q| drift)'\nset key outside right top noenhanced\n";
  gp += plot_blocks("drift.dat", b, "1:3") + "unset multiplot\n";
  return draw(dir, "drift", b.text(), gp, log);
}

std::vector<std::filesystem::path> chart_flips(const std::filesystem::path& dir, const std::vector<FlipRow>& rows,
                                               std::ostream& log) {
  Blocks b;
  double first_exact = 0;
  int flips_exact = 0;
  for (const FlipRow& r : rows) {
    b.add(r.method, num(r.dt) + " " + num(r.first_flip) + " " + std::to_string(r.flips));
    first_exact = r.first_flip_exact;
    flips_exact = r.flips_exact;
  }
  std::string gp = std::string(kHeader) + "unset logscale y\nset format y '%g'\n" +
                   "set multiplot layout 1,2 title 'Dzhanibekov flips of the T-handle over 10 s (exact: " +
                   std::to_string(flips_exact) + " flips, first at " + num(first_exact) + " s)'\n" +
                   "set xlabel 'step dt (s)'\nset ylabel 'first flip time (s; -1 = none)'\nunset key\n";
  gp += "set arrow 1 from graph 0, first " + num(first_exact) + " to graph 1, first " + num(first_exact) +
        " nohead dt 2 lc 'black'\n";
  gp += plot_blocks("dzhanibekov.dat", b, "1:2");
  gp += "set arrow 1 from graph 0, first " + std::to_string(flips_exact) + " to graph 1, first " +
        std::to_string(flips_exact) + " nohead dt 2 lc 'black'\n";
  gp += "set ylabel 'flip count in 10 s'\nset key outside right top noenhanced\n";
  gp += plot_blocks("dzhanibekov.dat", b, "1:3") + "unset multiplot\n";
  return draw(dir, "dzhanibekov", b.text(), gp, log);
}

}  // namespace tumble::bench

namespace tumble::bench {

std::vector<std::filesystem::path> chart_tolerance(const std::filesystem::path& dir, const std::vector<WpRow>& rows,
                                                   std::ostream& log) {
  Blocks b;
  for (const WpRow& r : rows)
    if (r.param_name == "rtol" && std::isfinite(r.angle))
      b.add(r.problem + " " + r.method, num(r.param) + " " + num(floor_log(r.angle)));
  if (b.names.empty()) return {};
  const std::string name = "tolerance";
  std::string gp = std::string(kHeader) +
                   "set title 'Tolerance proportionality: orientation error at the end against rtol (atol = rtol; "
                   "grey: rtol/10, rtol, 10 rtol; peers dashed)' noenhanced\n"
                   "set xlabel 'rtol'\nset ylabel 'orientation error at the end (rad)'\nset key noenhanced\n";
  std::string plot = plot_blocks(name + ".dat", b, "1:2");
  plot.pop_back();
  plot += ", \\\n  x/10 lc rgb '#bbbbbb' dt 3 notitle, x lc rgb '#888888' dt 1 notitle, 10*x lc rgb '#bbbbbb' dt 3 notitle\n";
  return draw(dir, name, b.text(), gp + plot, log);
}

}  // namespace tumble::bench
