// `tumble methods [--markdown | --readme FILE]`: the integration methods as
// core's table (MethodInfo) describes them, so the README's list of methods is
// generated from the table, never kept by hand.
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "bench/bench.hpp"
#include "core/input_file.hpp"
#include "core/integrator.hpp"
#include "io/atomic_file.hpp"

namespace tumble::app {

namespace {

constexpr const char* kMarker = "methods";
constexpr std::size_t kMaxReadmeBytes = std::size_t{16} << 20;

struct MethodsOptions {
  bool markdown = false;
  std::string readme;
};

/// "4", "5(4)" for an adaptive pair (its solution's order, then the embedded
/// estimate's), "—" for a closed form.
std::string order_text(const MethodInfo& i) {
  if (i.closed_form_if_free) return "—";
  return std::to_string(i.order) + (i.adaptive ? "(" + std::to_string(i.order - 1) + ")" : "");
}

int rewrite_readme(const std::string& file) {
  const std::string text = read_input_file(file, kMaxReadmeBytes, "--readme file", ReadRole::own_output);  // rewritten in place
  std::string updated;
  try {
    updated = bench::replace_between_markers(text, kMarker, methods_markdown());
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  io::atomic_write_file(file, updated);
  std::cout << "wrote the methods table into " << file << "\n";
  return kOk;
}

}  // namespace

std::string methods_markdown() {
  std::string o = "| name | order | what |\n|---|---|---|\n";
  for (const MethodInfo& i : method_table()) {
    std::string what;
    for (char c : i.description) what += c == '|' ? std::string("\\|") : std::string(1, c);
    o += "| `" + std::string(i.name) + "` | " + order_text(i) + " | " + what + " |\n";
  }
  return o;
}

void add_methods_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<MethodsOptions>();
  CLI::App* cmd = app.add_subcommand("methods", "List the integration methods (name, order, what each integrates)");
  auto* md = cmd->add_flag("--markdown", o->markdown, "Print the README's markdown table instead");
  cmd->add_option("--readme", o->readme,
                  "Write the markdown table between the <!-- BEGIN/END methods --> lines of this file")
      ->excludes(md)
      ->check(kPath);
  cmd->callback([o, &action] {
    action = [o]() -> int {
      if (!o->readme.empty()) return rewrite_readme(o->readme);
      if (o->markdown) {
        std::cout << methods_markdown();
        return kOk;
      }
      for (const MethodInfo& i : method_table())
        std::cout << std::left << std::setw(20) << i.name << " " << std::setw(5) << order_text(i) << " "
                  << i.description << "\n";
      return kOk;
    };
  });
}

}  // namespace tumble::app
