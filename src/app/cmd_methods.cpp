// `tumble methods [--markdown]`: the integration methods as core's table
// (MethodInfo) describes them, so the documentation's list of methods is
// generated from the table (tumble_docs methods), never kept by hand.
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "core/integrator.hpp"

namespace tumble::app {

namespace {

struct MethodsOptions {
  bool markdown = false;
};

/// "4", "5(4)" for an adaptive pair (its solution's order, then the embedded
/// estimate's), "—" for a closed form.
std::string order_text(const MethodInfo& i) {
  if (i.closed_form_if_free) return "—";
  return std::to_string(i.order) + (i.adaptive ? "(" + std::to_string(i.order - 1) + ")" : "");
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
  cmd->add_flag("--markdown", o->markdown, "Print a markdown table instead (as docs/methods.md shows it)");
  cmd->callback([o, &action] {
    action = [o]() -> int {
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
